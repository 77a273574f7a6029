// CaptureLimit's removal and grant (docs/model.md sec. 7, P14): each parcel crosses the
// optical depths of the nodes its step's deposit reached, c_p = 1 - (1 - A_p) exp(-X_p), its
// loss is attributed to those nodes in proportion to F_p w_pn x_n (the whole share on a
// saturated node), and the fibers are granted what their nodes lost, g_n = R_n / d_n.
#include "depletion/CaptureLimit.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace dropletFiber
{

namespace
{
// A parcel whose captured fraction is this close to 1 has lost all its droplets (the
// weights of a parcel whose nodes all gave everything sum to 1 within ~1e-16).
constexpr double allCapturedWithin = 1e-12;
} // namespace

bool CaptureLimit::mayReach(const GridSpec& spec, const KernelSettings& kernel, const Parcel& parcel,
                            double dt) const
{
    // Before the parcel's kernel is built: its nodes lie within r_max (or the cap) of its
    // whole path, its cloud-in-cell corners within a spacing; mirrored ghost nodes are
    // nearer still. So a parcel whose path, grown by that, misses takenBox() takes nothing.
    double margin = influenceRadiusMax(0.5 * parcel.diameter, parcel.nParticle);
    margin = kernel.rMaxCap > 0.0 ? std::min(margin, kernel.rMaxCap) : margin;
    const Eigen::Vector3d end = parcel.position;
    const Eigen::Vector3d start = parcel.position - parcel.velocity * dt;
    IndexBox reached;
    for (int d = 0; d < 3; ++d)
    {
        if (spec.flat(d))
        {
            reached.lo[d] = reached.hi[d] = 0;
            continue;
        }
        const double h = spec.spacing(d);
        const double grown = std::max(margin, h);
        const double a = (std::min(start[d], end[d]) - grown - spec.lower[d]) / h;
        const double b = (std::max(start[d], end[d]) + grown - spec.lower[d]) / h;
        reached.lo[d] = static_cast<int>(std::max(std::floor(a), -1.0));
        reached.hi[d] = static_cast<int>(std::min(std::ceil(b), static_cast<double>(spec.nodes[d])));
        if (reached.hi[d] < takenBox_.lo[d] || reached.lo[d] > takenBox_.hi[d])
        {
            return false; // most parcels, far from the fibers: no box arithmetic
        }
    }
    return mayTake(reached.intersected(spec.fullBox()));
}

void CaptureLimit::reach(DensityGrid& grid, const Parcel& parcel, double dt, ParcelReaches& reaches) const
{
    ParcelReach entry;
    entry.first = reaches.weights.size();
    if (!depth_.empty() && mayReach(grid.spec(), grid.kernelSettings(), parcel, dt))
    {
        const DensityGrid::NodeBoxTest asks = [this](const IndexBox& box) { return mayTake(box); };
        // The weights at the nodes with depth (x_n, 0 on saturated nodes, counted apart)
        grid.depositedShare(parcel, dt, asks, depthNodes_, reaches.weights);
        entry.count = reaches.weights.size() - entry.first;
        sumReach(reaches.weights, entry);
    }
    reaches.parcels.push_back(entry);
}

void CaptureLimit::sumReach(const std::vector<NodeWeight>& weights, ParcelReach& entry) const
{
    // Exact sums of the terms F w_pn x_n and F w_pn: the same bits however the nodes are
    // split over blocks and in whatever order each block meets them
    const std::vector<NodeValue>& nodes = depthNodes_.nodes();
    for (std::size_t k = entry.first; k < entry.first + entry.count; ++k)
    {
        const NodeWeight& w = weights[k];
        if (saturated_[w.position] != 0)
        {
            entry.saturatedSum.add(w.weight);
        }
        else
        {
            entry.depthSum.add(w.weight * nodes[w.position].value);
        }
    }
    entry.saturated = entry.saturatedSum.value();
    entry.depth = entry.depthSum.value();
}

double CaptureLimit::capturedFraction(double saturated, double depth)
{
    // The droplets off the saturated nodes' share survive the depth of the others
    const double kept = std::max(0.0, 1.0 - saturated) * std::exp(-depth);
    return kept < allCapturedWithin ? 1.0 : std::min(1.0, saturated) + capturedOffSaturated(saturated, depth);
}

double CaptureLimit::capturedOffSaturated(double saturated, double depth)
{
    // (1 - A)(1 - e^-X) through expm1: 1 - e^-X would keep only eps / X of its digits
    // for the small depths of a sparse spray, and the removal would then differ from the
    // grants formed from the same shares by more than round-off
    return -std::max(0.0, 1.0 - saturated) * std::expm1(-depth);
}

template <class F>
void CaptureLimit::forEachRemovalShare(const ParcelReaches& reaches, std::size_t i, double saturated,
                                       double depth, F&& f) const
{
    // r_pn / m_p: F w on a saturated node; the rest of c_p, (1 - A)(1 - e^-X), in
    // proportion to F w x_n over the others. Their sum is c_p (to round-off).
    const ParcelReach& entry = reaches.parcels[i];
    const double captured = capturedFraction(saturated, depth);
    const double rest
        = captured == 1.0 ? 1.0 - std::min(1.0, saturated) : capturedOffSaturated(saturated, depth);
    const double perDepth = depth > 0.0 ? std::max(0.0, rest) / depth : 0.0;
    const std::vector<NodeValue>& nodes = depthNodes_.nodes();
    for (std::size_t k = entry.first; k < entry.first + entry.count; ++k)
    {
        const NodeWeight& w = reaches.weights[k];
        f(w.position, saturated_[w.position] != 0 ? w.weight : perDepth * w.weight * nodes[w.position].value);
    }
}

void CaptureLimit::remove(const ParcelReaches& reaches, std::size_t i, double mass, double saturated,
                          double depth)
{
    forEachRemovalShare(reaches, i, saturated, depth,
                        [&](std::uint32_t place, double share) {
                            removedTerms_.push_back({place, mass * share});
                        });
}

double CaptureLimit::removedFraction(const ParcelReaches& reaches, std::size_t i, double saturated,
                                     double depth) const
{
    return removedFractionSum(reaches, i, saturated, depth).value();
}

FixedPointSum CaptureLimit::removedFractionSum(const ParcelReaches& reaches, std::size_t i, double saturated,
                                               double depth) const
{
    // A term above largestRemovalTerm makes the fraction 1 whatever the others
    // (realisedRemoval): clamped there, the exact sum stays within its range, and
    // addShortfall takes the clamp into account
    FixedPointSum fraction;
    forEachRemovalShare(reaches, i, saturated, depth,
                        [&](std::uint32_t place, double share)
                        { fraction.add(std::min(largestRemovalTerm, share * removalScale_[place])); });
    return fraction;
}

void CaptureLimit::scaleRemoval(std::size_t node, double q)
{
    const std::size_t place = depthNodes_.position(node);
    if (!(q >= 0.0) || place >= removalScale_.size())
    {
        throw std::invalid_argument("CaptureLimit::scaleRemoval: node " + std::to_string(node)
                                    + " has no optical depth here, or q = " + std::to_string(q) + " < 0");
    }
    removalScale_[place] = q;
}

void CaptureLimit::sumRemovedTerms()
{
    // R_n = sum_p r_pn with its terms in value order: the parcels (own and copies) reach a
    // node in an order that differs between serial and parallel runs, the sorted terms not
    std::sort(removedTerms_.begin(), removedTerms_.end());
    std::fill(removed_.begin(), removed_.end(), 0.0);
    for (const auto& [place, term] : removedTerms_)
    {
        removed_[place] += term;
    }
    removedTerms_.clear();
}

void CaptureLimit::addShortfall(const ParcelReaches& reaches, std::size_t i, double saturated, double depth,
                                double unremoved, double summedParts)
{
    // The parcel gives node n m_p min(t_n, T) / x' (x' the clamped sum removedFractionSum
    // gave, T = largestRemovalTerm, t_n = r_pn q_n / m_p) and node n asked m_p t_n: the
    // shortfall there, with m_p = u x' / (x' - 1), is u t_n below T and
    // u (x' t_n - T) / (x' - 1) above; over the nodes it adds up to m_p (x_p - 1), the
    // whole excess of the unclamped x_p (P33)
    const double overExcess = summedParts / (summedParts - 1.0);
    forEachRemovalShare(reaches, i, saturated, depth,
                        [&](std::uint32_t place, double share)
                        {
                            const double t = share * removalScale_[place];
                            shortfall_[place] += t <= largestRemovalTerm
                                ? unremoved * t
                                : unremoved * overExcess * (t - largestRemovalTerm / summedParts);
                        });
}

double CaptureLimit::unremovedShare(std::size_t node) const
{
    const std::size_t place = depthNodes_.position(node);
    if (place >= shortfall_.size() || shortfall_[place] == 0.0)
    {
        return 0.0;
    }
    // realised_n = q_n R_n (RealisedCapture's granted_n is R_n to round-off)
    const double realised = removalScale_[place] * removed_[place];
    return realised > 0.0 ? std::clamp(shortfall_[place] / realised, 0.0, 1.0) : 0.0;
}

void CaptureLimit::grant(CaptureLimitReport& report)
{
    sumRemovedTerms();
    report.massGranted = 0.0;
    for (const auto& [node, entry] : demand_)
    {
        const std::size_t place = depthNodes_.position(node);
        const double removed = place < removed_.size() ? removed_[place] : 0.0;
        granted_[node] = entry.total > 0.0 ? removed / entry.total : 1.0;
        report.massGranted += removed;
    }
}

std::vector<double> CaptureLimit::removeFromParcels(DensityGrid& grid, const std::vector<Parcel>& parcels,
                                                    double dt, CaptureLimitReport& report,
                                                    ParcelReaches* kept)
{
    ParcelReaches local;
    ParcelReaches& reaches = kept != nullptr ? *kept : local;
    reaches.clear();
    std::vector<double> fraction(parcels.size(), 0.0);
    for (std::size_t p = 0; p < parcels.size(); ++p)
    {
        reach(grid, parcels[p], dt, reaches);
        const ParcelReach& entry = reaches.parcels[p];
        if (entry.count > 0)
        {
            fraction[p] = capturedFraction(entry.saturated, entry.depth);
            remove(reaches, p, parcelMass(parcels[p]), entry.saturated, entry.depth);
        }
    }
    grant(report);
    return fraction;
}

} // namespace dropletFiber
