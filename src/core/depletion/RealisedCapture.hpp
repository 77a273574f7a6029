// RealisedCapture: with discrete hits (collision mode discrete, docs/model.md sec. 3 and 7,
// P31-P32) the fibers catch N m_hit per sample instead of its granted mass; depletion
// removes what was caught. Per sample the ratio r_s = realised / granted is attributed to
// its nodes in proportion to their granted parts d_sc g_n (CaptureLimit.hpp, P12-P14):
//     realised_n = sum_s r_s d_sc g_n,   granted_n = sum_s d_sc g_n = R_n = sum_p r_pn,
//     q_n = realised_n / R_n                                                      (P31)
// and every parcel's part r_pn of node n's removal is scaled by q_n: parcel p loses
//     c'_p = sum_n r_pn q_n / m_p    (CaptureLimit::removedFraction; c_p where all q_n = 1)
// so the parcels lose sum_n q_n R_n = sum_s N_s m_hit,s: the realised capture. The split
// of a node's loss over its parcels is the per-parcel rule's (P14), only its size changes.
// The owner of node n forms q_n (its samples' ratios come from the processors holding
// the fibers, scaleRemoval); the parts of c'_p add up over the blocks p's deposit reached.
//
// Whole droplets from a smeared deposit: a node may lose less than one droplet's mass
// this step (R_n < m_hit), so x_p = sum_n r_pn q_n / m_p may exceed 1. Each parcel gives
// at most all it has (realisedRemoval, P32), and the fibers get what was given (P33): the
// parcel's shortfall m_p (x_p - 1) is spread over its parts r_pn q_n (unremovedMass,
// CaptureLimit::addShortfall), node n's realised mass is cut by its share s_n of it, and
// each sample's by sum_c r_s d_sc g_n s_n (unremovedOfSample): captured = removed.
#pragma once

#include "depletion/CaptureLimit.hpp"

#include <cstddef>
#include <map>
#include <utility>
#include <vector>

namespace dropletFiber
{

class RealisedCapture
{
public:
    void clear()
    {
        nodes_.clear();
        spread_.clear();
    }
    // Sample's realised over granted mass (>= 0), over its nodes' granted parts (every
    // node of sample must have a granted ratio in limit: the owned part of a sample).
    // interceptors: the physical fibers behind the sample (its demand's weight in
    // CaptureLimit::addDemand): each realises the same hits, N times one fiber's (P41).
    void add(const SampleCapture& sample, double realisedOverGranted, const CaptureLimit& limit,
             double interceptors = 1.0);
    // A node's part that no sample carries: the spread populations' granted and realised
    // mass there (SpreadPopulations.hpp; kg), one call per node in increasing node order.
    // Throws std::invalid_argument out of order.
    void addNode(std::size_t node, double granted, double realised);
    // q_n on every node a sample was added for (CaptureLimit::scaleRemoval; all samples of
    // the step must have been added, with ratio 0 for those that caught nothing).
    void scaleRemoval(CaptureLimit& limit) const;
    // sum_n realised_n over the nodes added (the removal to come), kg.
    double realisedMass() const;
    // realised_n at one node (0 where no sample was added), kg.
    double realisedAt(std::size_t node) const;

private:
    struct NodeParts
    {
        double realised = 0.0;
        double granted = 0.0;
    };
    // Per node its samples' (granted, realised) terms; summed in value order (the samples
    // come in a different order in serial and parallel runs; sorted, the same sums)
    using Terms = std::vector<std::pair<double, double>>;
    static NodeParts summed(Terms terms);
    std::map<std::size_t, Terms> nodes_; // node order: the same sums on every run
    // The populations' parts (addNode), by node in increasing order
    std::vector<std::pair<std::size_t, NodeParts>> spread_;
    // The populations' part at a node (zero where none)
    NodeParts spreadAt(std::size_t node) const;
};

// The fraction a parcel loses from its summed parts of sum_n r_pn q_n / m_p: at most 1,
// and 1 within 1e-12 of it (CaptureLimit::capturedFraction's rule).
double realisedRemoval(double summedParts);

// m_p (1 - 1 / x_p) where the parcel's parts x_p = summedParts ask more than it holds
// (x_p > 1), else 0: the kg per unit of x_p it keeps back (CaptureLimit::addShortfall).
double unremovedMass(double summedParts, double mass);

// sum_c d_sc g_n s_n over the sample's nodes here (s_n: CaptureLimit::unremovedShare): times
// the sample's realised over granted ratio, the part of its realised mass not given.
double unremovedOfSample(const SampleCapture& sample, const CaptureLimit& limit);

// Serial runs (one grid; reaches as CaptureLimit::removeFromParcels kept them, whole
// A_p and X_p): c'_p of every parcel after scaleRemoval.
std::vector<double> realisedFractions(const CaptureLimit& limit, const ParcelReaches& reaches);

// Serial runs, the whole of P31-P33 after CaptureLimit::removeFromParcels (reaches kept):
// samples (every sample of the step) caught realisedMass[s] (N_s m_hit, granted > 0 where
// realised > 0); returns c'_p per parcel (parcelMasses: m_p) and the samples' masses
// given, so that sum_s given_s = sum_p c'_p m_p to round-off.
struct RealisedRemoval
{
    std::vector<double> fraction;   // c'_p
    std::vector<double> sampleMass; // realised less what the parcels could not give, kg
    int emptied = 0;                // parcels whose parts asked more than they held
};
// interceptors (empty: one each): the physical fibers behind each sample; realisedMass and
// the masses given are one physical fiber's.
RealisedRemoval realiseCapture(CaptureLimit& limit, const ParcelReaches& reaches,
                               const std::vector<double>& parcelMasses,
                               const std::vector<SampleCapture>& samples,
                               const std::vector<double>& realisedMass,
                               const std::vector<double>& interceptors = {});

} // namespace dropletFiber
