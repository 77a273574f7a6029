#include "depletion/CaptureLimit.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace dropletFiber
{

CaptureLimitReport& CaptureLimitReport::operator+=(const CaptureLimitReport& other)
{
    nodesDemanded += other.nodesDemanded;
    nodesLimited += other.nodesLimited;
    massDemanded += other.massDemanded;
    massGranted += other.massGranted;
    return *this;
}

SampleCapture attributeSample(const DensityGrid& grid, const CornerWeights& corners,
                              const double* cornerTotals, double sampleMass, const Eigen::Vector3d& velocity)
{
    SampleCapture capture;
    capture.velocity = velocity;
    std::array<double, 8> parts{};
    // The parts of the interpolated mass sum that rho is formed from (DensityGrid::interpolated).
    const double sum = grid.densityParts(corners, cornerTotals, parts.data());
    if (!(sampleMass > 0.0) || !(sum > 0.0))
    {
        return capture;
    }
    for (int c = 0; c < corners.count; ++c)
    {
        const auto u = static_cast<std::size_t>(c);
        if (parts[u] > 0.0)
        {
            const auto n = static_cast<std::size_t>(capture.count++);
            capture.node[n] = corners.node[u];
            capture.mass[n] = sampleMass * (parts[u] / sum);
        }
    }
    return capture;
}

SampleCapture attributeOwnedCorners(const DensityGrid& grid, const CornerWeights& corners, double massShare,
                                    const Eigen::Vector3d& velocity)
{
    SampleCapture capture;
    capture.velocity = velocity;
    if (!(massShare > 0.0))
    {
        return capture;
    }
    // The corners owned elsewhere read as empty: their parts are their owners' business.
    std::array<double, 8 * nQuantities> totals{};
    for (int c = 0; c < corners.count; ++c)
    {
        const std::size_t node = corners.node[static_cast<std::size_t>(c)];
        if (grid.owns(node))
        {
            grid.windowTotal(node, totals.data() + c * nQuantities);
        }
    }
    std::array<double, 8> parts{};
    grid.densityParts(corners, totals.data(), parts.data());
    for (int c = 0; c < corners.count; ++c)
    {
        const auto u = static_cast<std::size_t>(c);
        if (parts[u] > 0.0)
        {
            const auto n = static_cast<std::size_t>(capture.count++);
            capture.node[n] = corners.node[u];
            capture.mass[n] = massShare * parts[u];
        }
    }
    return capture;
}

SegmentCapture segmentCapture(const DensityGrid& grid, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                              double fiberRadius, const Eigen::Vector3d& segmentVelocity, double dt,
                              const CollisionOptions& options)
{
    const int samples = collisionSamples(grid, a, b, options);
    const auto count = static_cast<std::size_t>(samples);
    std::vector<CornerWeights> corners(count);
    std::vector<std::array<double, 8 * nQuantities>> totals(count);
    std::vector<DropletFieldValue> fields(count);
    for (std::size_t s = 0; s < count; ++s)
    {
        // DensityGrid::sample's steps, keeping the corners and their sums.
        const Eigen::Vector3d point = samplePoint(a, b, samples, static_cast<int>(s));
        if (!insideActiveBox(grid.spec(), point))
        {
            fields[s].inside = false;
            continue;
        }
        corners[s] = multilinearWeights(grid.spec(), point);
        for (int c = 0; c < corners[s].count; ++c)
        {
            grid.windowTotal(corners[s].node[static_cast<std::size_t>(c)],
                             totals[s].data() + c * nQuantities);
        }
        fields[s] = grid.interpolated(corners[s], totals[s].data());
    }
    SegmentCapture result;
    std::vector<double> masses(count);
    result.collision = collisionMassFromSamples(fields.data(), samples, a, b, fiberRadius, segmentVelocity,
                                                dt, options, masses.data());
    for (std::size_t s = 0; s < count; ++s)
    {
        if (masses[s] > 0.0)
        {
            result.samples.push_back(
                attributeSample(grid, corners[s], totals[s].data(), masses[s], fields[s].velocity));
        }
    }
    return result;
}

void CaptureLimit::clear()
{
    demand_.clear();
    granted_.clear();
    taken_.clear();
    takenNodesStale_ = true;
    takenBox_ = IndexBox{};
    forgetTakenBricks();
}

void CaptureLimit::addDemand(const SampleCapture& sample)
{
    for (int c = 0; c < sample.count; ++c)
    {
        addDemand(sample.node[static_cast<std::size_t>(c)], sample.mass[static_cast<std::size_t>(c)]);
    }
}

void CaptureLimit::addDemand(const SegmentCapture& segment)
{
    for (const SampleCapture& sample : segment.samples)
    {
        addDemand(sample);
    }
}

void CaptureLimit::addDemand(std::size_t node, double mass)
{
    if (!(mass >= 0.0))
    {
        throw std::invalid_argument("CaptureLimit::addDemand: mass at node " + std::to_string(node)
                                    + " must be >= 0, got " + std::to_string(mass));
    }
    NodeDemand& entry = demand_[node];
    entry.total += mass;
    entry.parts.push_back(mass);
}

std::vector<NodeMass> CaptureLimit::takeForeignDemand(const DensityGrid& grid)
{
    std::vector<NodeMass> foreign;
    for (auto entry = demand_.begin(); entry != demand_.end();)
    {
        if (grid.owns(entry->first))
        {
            ++entry;
            continue;
        }
        // Each interceptor apart (P13 multiplies their survivals), in the order added
        for (const double mass : entry->second.parts)
        {
            foreign.push_back(NodeMass{entry->first, mass});
        }
        entry = demand_.erase(entry);
    }
    std::stable_sort(foreign.begin(), foreign.end(),
                     [](const NodeMass& x, const NodeMass& y) { return x.node < y.node; });
    return foreign;
}

double CaptureLimit::interceptedFraction(const std::vector<double>& parts, double supply)
{
    double logSurvival = 0.0;
    for (const double part : parts)
    {
        if (part >= supply)
        {
            return 1.0; // one interceptor takes all the node holds
        }
        logSurvival += std::log1p(-part / supply);
    }
    return -std::expm1(logSurvival);
}

CaptureLimitReport CaptureLimit::limit(const DensityGrid& grid)
{
    CaptureLimitReport report;
    taken_.clear();
    takenNodesStale_ = true;
    takenBox_ = IndexBox{};
    forgetTakenBricks();
    const std::array<int, 3> nodes = grid.spec().nodes;
    gridNodes_ = nodes;
    for (int d = 0; d < 3; ++d)
    {
        bricks_[static_cast<std::size_t>(d)]
            = static_cast<std::size_t>((nodes[d] + brickSize - 1) / brickSize);
    }
    for (const auto& [node, entry] : demand_)
    {
        if (!grid.owns(node))
        {
            throw std::logic_error("CaptureLimit::limit: demand at node " + std::to_string(node)
                                   + ", which this grid does not own (takeForeignDemand first)");
        }
        // s_n: the mass per step eq. 9 read at the node (the window's mean); h_n: what
        // this step's parcels hold there. Each sample's part d_sn / s_n is the fraction of
        // the node's droplets it intercepts over the step; independent interceptors leave
        // prod (1 - min(1, d_sn / s_n)) (P13): exp(-x_n) for many thin fibers (x_n = d_n /
        // s_n, the step's optical depth), 0 where one sample alone sweeps the node's mass.
        // f_n of h_n is taken: eq. 9 to first order in x_n, in the mean over steps (h_n
        // fluctuates about s_n in a sparse spray), exact in a uniform dense region (the
        // linear min(1, x_n) lost kappa v dt / 2 too much), never more than the parcels hold.
        const double demand = entry.total;
        double sums[nQuantities];
        grid.windowTotal(node, sums);
        const int steps = grid.stepsInWindow();
        const double supply = steps > 0 ? sums[quantityMass] / steps : 0.0;
        const double held = grid.lastStepValue(node, quantityMass);
        const double taken = supply > 0.0 ? interceptedFraction(entry.parts, supply) : 0.0;
        const double granted = taken * held;
        granted_[node] = demand > 0.0 ? granted / demand : 1.0;
        report.massDemanded += demand;
        report.massGranted += granted;
        report.nodesDemanded += demand > 0.0 ? 1 : 0;
        report.nodesLimited += demand > supply ? 1 : 0;
        if (granted > 0.0)
        {
            taken_[node] = taken;
            markTaken(node, nodes);
        }
    }
    return report;
}

void CaptureLimit::markTaken(std::size_t node, const std::array<int, 3>& nodes)
{
    takenNodesStale_ = true;
    IndexBox one;
    one.lo = one.hi = nodeIndicesOfFlat(nodes, node);
    takenBox_ = takenBox_.united(one);
    const std::size_t brick = brickIndex(one.lo[0] / brickSize, one.lo[1] / brickSize, one.lo[2] / brickSize);
    takenBrick_.resize(bricks_[0] * bricks_[1] * bricks_[2], 0);
    if (takenBrick_[brick] == 0)
    {
        takenBrick_[brick] = 1;
        takenBrickList_.push_back(brick);
    }
}

void CaptureLimit::forgetTakenBricks()
{
    // Only the bricks set (a dense map over the grid's bricks: mayTake() is asked per parcel)
    for (const std::size_t brick : takenBrickList_)
    {
        takenBrick_[brick] = 0;
    }
    takenBrickList_.clear();
}

bool CaptureLimit::mayTake(const IndexBox& box) const
{
    const IndexBox candidates = box.intersected(takenBox_);
    if (candidates.empty())
    {
        return false;
    }
    for (int k = candidates.lo[2] / brickSize; k <= candidates.hi[2] / brickSize; ++k)
    {
        for (int j = candidates.lo[1] / brickSize; j <= candidates.hi[1] / brickSize; ++j)
        {
            for (int i = candidates.lo[0] / brickSize; i <= candidates.hi[0] / brickSize; ++i)
            {
                if (takenBrick_[brickIndex(i, j, k)] != 0)
                {
                    return true;
                }
            }
        }
    }
    return false;
}

void CaptureLimit::scaleTakenFraction(std::size_t node, double q)
{
    const auto entry = taken_.find(node);
    if (entry == taken_.end())
    {
        return; // nothing granted here: nothing realised either
    }
    takenNodesStale_ = true;
    entry->second = q * entry->second;
    if (!(entry->second > 0.0))
    {
        taken_.erase(entry); // its brick stays marked: mayTake() is a bound
    }
}

double CaptureLimit::grantedRatio(std::size_t node) const
{
    const auto entry = granted_.find(node);
    if (entry == granted_.end())
    {
        throw std::out_of_range("CaptureLimit: no granted ratio for node " + std::to_string(node)
                                + " (no demand there, or its owner's answer was not set)");
    }
    return entry->second;
}

void CaptureLimit::setGrantedRatio(std::size_t node, double ratio)
{
    if (!(ratio >= 0.0 && ratio <= 1.0))
    {
        throw std::invalid_argument("CaptureLimit::setGrantedRatio: ratio at node " + std::to_string(node)
                                    + " must be in [0, 1], got " + std::to_string(ratio));
    }
    granted_[node] = ratio;
}

double CaptureLimit::grantedMass(const SampleCapture& sample) const
{
    double mass = 0.0;
    for (int c = 0; c < sample.count; ++c)
    {
        const auto u = static_cast<std::size_t>(c);
        mass += sample.mass[u] * grantedRatio(sample.node[u]);
    }
    return mass;
}

SegmentCollision CaptureLimit::granted(const SegmentCapture& segment) const
{
    SegmentCollision result = segment.collision;
    result.mass = 0.0;
    result.momentum.setZero();
    for (const SampleCapture& sample : segment.samples)
    {
        const double mass = grantedMass(sample);
        result.mass += mass;
        result.momentum += mass * sample.velocity;
    }
    return result;
}

double CaptureLimit::takenFraction(std::size_t node) const
{
    const auto entry = taken_.find(node);
    return entry == taken_.end() ? 0.0 : entry->second;
}

std::vector<NodeMass> CaptureLimit::takenFractions() const
{
    // taken_ in node order, as the sparse sums keep it
    std::vector<NodeMass> fractions;
    for (const NodeValue& entry : takenNodes().nodes())
    {
        fractions.push_back(NodeMass{entry.node, entry.value});
    }
    return fractions;
}

void CaptureLimit::setTakenFraction(std::size_t node, double fraction, const std::array<int, 3>& gridNodes)
{
    // Above 1 after discrete hits (RealisedCapture.hpp)
    if (!(fraction > 0.0 && std::isfinite(fraction)))
    {
        throw std::invalid_argument("CaptureLimit::setTakenFraction: fraction at node " + std::to_string(node)
                                    + " must be finite and > 0, got " + std::to_string(fraction));
    }
    for (int d = 0; d < 3; ++d)
    {
        bricks_[static_cast<std::size_t>(d)]
            = static_cast<std::size_t>((gridNodes[d] + brickSize - 1) / brickSize);
    }
    taken_[node] = fraction;
    gridNodes_ = gridNodes;
    markTaken(node, gridNodes);
}

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

double CaptureLimit::capturedFraction(DensityGrid& grid, const Parcel& parcel, double dt) const
{
    if (taken_.empty())
    {
        return 0.0;
    }
    if (!mayReach(grid.spec(), grid.kernelSettings(), parcel, dt))
    {
        return 0.0;
    }
    const DensityGrid::NodeBoxTest asks = [this](const IndexBox& box) { return mayTake(box); };
    return std::min(1.0, grid.depositedShare(parcel, dt, asks, takenNodes()));
}

const SparseNodeValues& CaptureLimit::takenNodes() const
{
    if (takenNodesStale_)
    {
        std::vector<NodeValue> nodes;
        nodes.reserve(taken_.size());
        for (const auto& [node, fraction] : taken_)
        {
            nodes.push_back(NodeValue{node, {}, fraction});
        }
        takenNodes_.assign(std::move(nodes), gridNodes_);
        takenNodesStale_ = false;
    }
    return takenNodes_;
}

} // namespace dropletFiber
