#include "depletion/CaptureLimit.hpp"
#include "depletion/SelfShadow.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
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
    excessDemanded += other.excessDemanded;
    return *this;
}

SampleCapture attributeSample(const DensityGrid& grid, const CornerWeights& corners,
                              const double* cornerTotals, double sampleMass, const Eigen::Vector3d& velocity,
                              const Eigen::Vector3d& strip)
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
    const std::array<double, 8> sigma = selfShadow(grid.spec(), corners, strip);
    for (int c = 0; c < corners.count; ++c)
    {
        const auto u = static_cast<std::size_t>(c);
        if (parts[u] > 0.0)
        {
            const auto n = static_cast<std::size_t>(capture.count++);
            capture.node[n] = corners.node[u];
            capture.mass[n] = sampleMass * (parts[u] / sum);
            capture.shadow[n] = sigma[u];
        }
    }
    return capture;
}

SampleCapture attributeOwnedCorners(const DensityGrid& grid, const CornerWeights& corners, double massShare,
                                    const Eigen::Vector3d& velocity, const Eigen::Vector3d& strip)
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
    const std::array<double, 8> sigma = selfShadow(grid.spec(), corners, strip);
    for (int c = 0; c < corners.count; ++c)
    {
        const auto u = static_cast<std::size_t>(c);
        if (parts[u] > 0.0)
        {
            const auto n = static_cast<std::size_t>(capture.count++);
            capture.node[n] = corners.node[u];
            capture.mass[n] = massShare * parts[u];
            capture.shadow[n] = sigma[u];
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
            // P21: the strip eq. 9 swept, across the droplets' velocity relative to the fiber
            const double meanRadius
                = options.radiusAverage == RadiusAverage::Mass ? fields[s].rMeanMass : fields[s].rMeanNumber;
            const Eigen::Vector3d strip = stripAcrossFlow(2.0 * (fiberRadius + meanRadius), b - a,
                                                          fields[s].velocity - segmentVelocity);
            result.samples.push_back(
                attributeSample(grid, corners[s], totals[s].data(), masses[s], fields[s].velocity, strip));
        }
    }
    return result;
}

void CaptureLimit::clear()
{
    demand_.clear();
    granted_.clear();
    depth_.clear();
    depthNodes_.assign({}, gridNodes_);
    removed_.clear();
    saturated_.clear();
    removalScale_.clear();
    shortfall_.clear();
    takenBox_ = IndexBox{};
    forgetTakenBricks();
}

void CaptureLimit::addDemand(const SampleCapture& sample, double interceptors)
{
    for (int c = 0; c < sample.count; ++c)
    {
        const auto u = static_cast<std::size_t>(c);
        addDemand(sample.node[u], sample.mass[u], sample.shadow[u], interceptors);
    }
}

void CaptureLimit::addDemand(const SegmentCapture& segment, double interceptors)
{
    for (const SampleCapture& sample : segment.samples)
    {
        addDemand(sample, interceptors);
    }
}

void CaptureLimit::addDemand(std::size_t node, double mass, double shadow, double interceptors)
{
    if (!(mass >= 0.0))
    {
        throw std::invalid_argument("CaptureLimit::addDemand: mass at node " + std::to_string(node)
                                    + " must be >= 0, got " + std::to_string(mass));
    }
    if (!(interceptors > 0.0) || !std::isfinite(interceptors))
    {
        throw std::invalid_argument("CaptureLimit::addDemand: interceptors at node " + std::to_string(node)
                                    + " must be finite and > 0, got " + std::to_string(interceptors));
    }
    NodeDemand& entry = demand_[node];
    entry.total += interceptors * mass;
    entry.parts.push_back(DemandPart{mass, shadow, interceptors});
}

void CaptureLimit::addSpread(std::size_t node, double share, double depth)
{
    if (!(share >= 0.0) || !(depth >= 0.0) || !std::isfinite(share) || !std::isfinite(depth))
    {
        throw std::invalid_argument("CaptureLimit::addSpread: share and depth at node " + std::to_string(node)
                                    + " must be finite and >= 0, got " + std::to_string(share) + " and "
                                    + std::to_string(depth));
    }
    NodeDemand& entry = demand_[node];
    entry.spreadShare += share;
    entry.spreadDepth += depth;
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
        for (const DemandPart& part : entry->second.parts)
        {
            foreign.push_back(NodeMass{entry->first, part.mass, part.shadow, part.interceptors});
        }
        entry = demand_.erase(entry);
    }
    std::stable_sort(foreign.begin(), foreign.end(),
                     [](const NodeMass& x, const NodeMass& y) { return x.node < y.node; });
    return foreign;
}

double CaptureLimit::depthOf(const std::vector<DemandPart>& parts, double supply)
{
    double depth = 0.0;
    for (const DemandPart& part : parts)
    {
        if (part.mass >= supply)
        {
            return std::numeric_limits<double>::infinity(); // one interceptor takes all
        }
        // N physical fibers asking the same part independently, each shadowing itself:
        // N times one fiber's depth (P40)
        depth += part.interceptors * shadowedDepth(part.mass / supply, part.shadow);
    }
    return depth;
}

void CaptureLimit::sortParts(NodeDemand& entry)
{
    // The parts come in the order the samples were attributed, which differs between
    // serial and parallel runs (local samples first, then other processors'): in value
    // order, their sum and product are the same bits on every run
    std::sort(entry.parts.begin(), entry.parts.end());
    entry.total = 0.0;
    for (const DemandPart& part : entry.parts)
    {
        entry.total += part.interceptors * part.mass;
    }
}

CaptureLimitReport CaptureLimit::limit(const DensityGrid& grid)
{
    CaptureLimitReport report;
    depth_.clear();
    granted_.clear();
    takenBox_ = IndexBox{};
    forgetTakenBricks();
    const std::array<int, 3> nodes = grid.spec().nodes;
    gridNodes_ = nodes;
    for (int d = 0; d < 3; ++d)
    {
        bricks_[static_cast<std::size_t>(d)]
            = static_cast<std::size_t>((nodes[d] + brickSize - 1) / brickSize);
    }
    std::vector<NodeValue> list;
    for (auto& [node, entry] : demand_)
    {
        sortParts(entry);
        if (!grid.owns(node))
        {
            throw std::logic_error("CaptureLimit::limit: demand at node " + std::to_string(node)
                                   + ", which this grid does not own (takeForeignDemand first)");
        }
        // s_n: the mass per step eq. 9 read at the node (the window's mean). Each sample's
        // part d_sn / s_n is the fraction of the node's droplets it intercepts over the
        // step; independent interceptors leave prod (1 - d_sn / s_n) (P13): exp(-x_n), x_n
        // = d_n / s_n, for many thin fibers. The parcels cross these depths (remove).
        double sums[nQuantities];
        grid.windowTotal(node, sums);
        const int steps = grid.stepsInWindow();
        const double supply = steps > 0 ? sums[quantityMass] / steps : 0.0;
        double depth = supply > 0.0 ? depthOf(entry.parts, supply) : 0.0;
        entry.supply = supply;
        if (entry.spreadShare > 0.0)
        {
            // The populations' parts, linear (P50): demand s_n P_n, depth P'_n
            entry.total += supply * entry.spreadShare;
            depth += supply > 0.0 ? entry.spreadDepth : 0.0;
        }
        report.massDemanded += entry.total;
        report.nodesDemanded += entry.total > 0.0 ? 1 : 0;
        report.nodesLimited += entry.total > supply ? 1 : 0;
        report.excessDemanded += entry.total > supply ? entry.total - supply : 0.0;
        if (depth > 0.0)
        {
            depth_[node] = depth;
            list.push_back(NodeValue{node, {}, std::isinf(depth) ? 0.0 : depth});
            markTaken(node, nodes);
        }
    }
    depthNodes_.assign(std::move(list), nodes);
    const std::size_t held = depthNodes_.nodes().size();
    removed_.assign(held, 0.0);
    removedTerms_.clear();
    removalScale_.assign(held, 1.0);
    shortfall_.assign(held, 0.0);
    saturated_.assign(held, 0);
    for (std::size_t i = 0; i < held; ++i)
    {
        saturated_[i] = std::isinf(depth_.at(depthNodes_.nodes()[i].node)) ? 1 : 0;
    }
    return report;
}

void CaptureLimit::markTaken(std::size_t node, const std::array<int, 3>& nodes)
{
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

double CaptureLimit::grantedRatio(std::size_t node) const
{
    const auto entry = granted_.find(node);
    if (entry == granted_.end())
    {
        throw std::out_of_range("CaptureLimit: no granted ratio for node " + std::to_string(node)
                                + " (no demand there, or grant() not called)");
    }
    return entry->second;
}

void CaptureLimit::grantedSupplies(const IndexBox& region, bool unremoved, std::vector<double>& values) const
{
    values.assign(region.empty() ? 0 : region.nodeCount(), 0.0);
    for (const auto& [node, entry] : demand_)
    {
        const std::array<int, 3> at = nodeIndicesOfFlat(gridNodes_, node);
        const auto ratio = granted_.find(node);
        if (!region.holds(at[0], at[1], at[2]) || ratio == granted_.end())
        {
            continue;
        }
        const double supply = entry.supply * ratio->second;
        values[flatIndexInBox(region, at[0], at[1], at[2])]
            = unremoved ? supply * unremovedShare(node) : supply;
    }
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

double CaptureLimit::opticalDepth(std::size_t node) const
{
    const auto entry = depth_.find(node);
    return entry == depth_.end() ? 0.0 : entry->second;
}

} // namespace dropletFiber
