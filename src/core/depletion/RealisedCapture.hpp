// RealisedCapture: with discrete hits (collision mode discrete, docs/model.md sec. 3 and 7,
// P31-P32) the fibers catch N m_hit per sample instead of its granted mass; depletion
// removes what was caught. Per sample the ratio r_s = realised / granted is attributed to
// its nodes in proportion to their granted parts d_sc g_n (CaptureLimit.hpp, P12-P13):
//     realised_n = sum_s r_s d_sc g_n,   granted_n = sum_s d_sc g_n = f_n h_n,
//     q_n = realised_n / granted_n,      f_n <- q_n f_n = realised_n / h_n        (P31)
// so the parcels (P14) lose sum_n realised_n = sum_s N_s m_hit,s: the realised capture.
// The owner of node n forms q_n (its samples' ratios come from the processors holding
// the fibers). The removal rule itself is not touched: only f_n is scaled, one call
// (scaleRemoval) between CaptureLimit::limit and the removal.
//
// Whole droplets from a smeared deposit: a node may hold less than one droplet's mass
// this step (h_n < m_hit), so f_n may exceed 1 after the scaling (P32). The parcels that
// reached the node give the droplets, each at most all it has (c_p <= 1, P14): the
// balance is exact unless a parcel is emptied, where the rest stays with the fiber
// uncounted by the removal (removedStep < capturedStep in the table).
#pragma once

#include "depletion/CaptureLimit.hpp"

#include <cstddef>
#include <map>

namespace dropletFiber
{

class RealisedCapture
{
public:
    void clear() { nodes_.clear(); }
    // Sample's realised over granted mass (>= 0), over its nodes' granted parts (every
    // node of sample must have a granted ratio in limit: the owned part of a sample).
    void add(const SampleCapture& sample, double realisedOverGranted, const CaptureLimit& limit);
    // f_n <- q_n f_n at every node a sample was added for (all samples of the step must
    // have been added, with ratio 0 for those that caught nothing).
    void scaleRemoval(CaptureLimit& limit) const;
    // sum_n realised_n over the nodes added (the removal to come), kg.
    double realisedMass() const;

private:
    struct NodeParts
    {
        double realised = 0.0;
        double granted = 0.0;
    };
    std::map<std::size_t, NodeParts> nodes_; // node order: the same sums on every run
};

} // namespace dropletFiber
