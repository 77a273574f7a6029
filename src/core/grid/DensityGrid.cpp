#include "grid/DensityGrid.hpp"

#include "grid/MultilinearWeights.hpp"
#include "grid/PathWeight.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <stdexcept>
#include <string>

namespace dropletFiber
{

namespace
{

int resolveDimension(const GridSpec& spec, KernelDimension dimension)
{
    switch (dimension)
    {
    case KernelDimension::TwoD:
        return 2;
    case KernelDimension::ThreeD:
        return 3;
    case KernelDimension::Automatic:
    default:
        return spec.activeDimensions() == 3 ? 3 : 2;
    }
}

const GridSpec& validated(const GridSpec& spec)
{
    spec.validate();
    return spec;
}

bool finite(const Eigen::Vector3d& v)
{
    return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z());
}

void checkParcel(const Parcel& p, double dt)
{
    auto fail = [](const std::string& what) { throw std::invalid_argument("DensityGrid::deposit: " + what); };
    if (!finite(p.position))
    {
        fail("parcel position is not finite");
    }
    if (!finite(p.velocity))
    {
        fail("parcel velocity is not finite");
    }
    if (!(p.diameter >= 0.0) || !std::isfinite(p.diameter))
    {
        fail("parcel diameter must be finite and >= 0, got " + std::to_string(p.diameter));
    }
    if (!(p.nParticle >= 0.0) || !std::isfinite(p.nParticle))
    {
        fail("parcel nParticle must be finite and >= 0, got " + std::to_string(p.nParticle));
    }
    if (!(p.rhoDroplet >= 0.0) || !std::isfinite(p.rhoDroplet))
    {
        fail("droplet density must be finite and >= 0, got " + std::to_string(p.rhoDroplet));
    }
    if (!(dt >= 0.0) || !std::isfinite(dt))
    {
        fail("time step must be finite and >= 0, got " + std::to_string(dt));
    }
}

// Liang-Barsky: the part [t0, t1] of start + t displacement, t in [0, 1], inside the closed
// box. Returns false when nothing is inside.
bool clipToBox(const GridSpec& spec, const Eigen::Vector3d& start, const Eigen::Vector3d& displacement,
               double& t0, double& t1)
{
    t0 = 0.0;
    t1 = 1.0;
    for (int d = 0; d < 3; ++d)
    {
        const double lo = spec.lower[d] - start[d];
        const double hi = spec.upper[d] - start[d];
        const double v = displacement[d];
        if (v == 0.0)
        {
            if (lo > 0.0 || hi < 0.0)
            {
                return false;
            }
            continue;
        }
        double a = lo / v;
        double b = hi / v;
        if (a > b)
        {
            std::swap(a, b);
        }
        t0 = std::max(t0, a);
        t1 = std::min(t1, b);
        if (t0 > t1)
        {
            return false;
        }
    }
    return true;
}

} // namespace

DensityGrid::DensityGrid(const GridSpec& spec, const KernelSettings& kernel, int windowLength)
    : spec_(validated(spec)),
      kernelSettings_(kernel),
      kernelDimension_(resolveDimension(spec, kernel.dimension)),
      batched_(kernel.vectorised && PathWeightBatch::cpuSupported()),
      nodeVolume_(spec.nodeVolume()),
      window_(spec.nodes, nQuantities, windowLength)
{
    kernelSettings_.validate();
    for (int d = 0; d < 3; ++d)
    {
        coordinates_[d].resize(static_cast<std::size_t>(spec.nodes[d]));
        for (int i = 0; i < spec.nodes[d]; ++i)
        {
            coordinates_[d][static_cast<std::size_t>(i)] = spec.nodeCoordinate(d, i);
        }
        inverseSpacing_[d] = spec.flat(d) ? 0.0 : 1.0 / spec.spacing(d);
        spacing_[d] = spec.flat(d) ? 0.0 : spec.spacing(d);
        largestSpacing_ = spec.flat(d) ? largestSpacing_ : std::max(largestSpacing_, spec.spacing(d));
        if (!spec.flat(d))
        {
            smallestSpacing_ = smallestSpacing_ > 0.0 ? std::min(smallestSpacing_, spec.spacing(d)) : spec.spacing(d);
        }
        halfCellDiagonal_ += spec.flat(d) ? 0.0 : 0.25 * spec.spacing(d) * spec.spacing(d);
    }
    halfCellDiagonal_ = std::sqrt(halfCellDiagonal_);
    step_.assign(spec.nodeCount() * nQuantities, 0.0);
}

void DensityGrid::deposit(const Parcel& parcel, double dt)
{
    checkParcel(parcel, dt);
    StepStatistics& stats = stepStatistics_;
    ++stats.parcels;
    if (parcel.nParticle == 0.0 || parcel.diameter == 0.0)
    {
        ++stats.parcelsEmpty;
        return;
    }
    const double mass = parcelMass(parcel);
    stats.massIn += mass;

    // 1-2. Path during the step, clipped to the grid box.
    const Eigen::Vector3d displacement = parcel.velocity * dt;
    const Eigen::Vector3d start = parcel.position - displacement;
    double t0 = 0.0, t1 = 1.0;
    if (!clipToBox(spec_, start, displacement, t0, t1))
    {
        ++stats.parcelsOutside;
        stats.massOutside += mass;
        return;
    }
    const double fraction = (displacement.squaredNorm() > 0.0) ? t1 - t0 : 1.0;
    if (fraction < 1.0)
    {
        ++stats.parcelsPartlyOutside;
    }
    const double massInside = fraction * mass;
    stats.massDeposited += massInside;
    stats.massOutside += mass - massInside;
    if (!(fraction > 0.0))
    {
        return; // touches the box in a single point: measure zero
    }

    // Clipped path, projected into the active directions (flat: on the node layer).
    Eigen::Vector3d clipStart = start + t0 * displacement;
    Eigen::Vector3d clipDisplacement = (t1 - t0) * displacement;
    for (int d = 0; d < 3; ++d)
    {
        if (spec_.flat(d))
        {
            clipStart[d] = coordinates_[d][0];
            clipDisplacement[d] = 0.0;
        }
    }

    const double radius = 0.5 * parcel.diameter;
    const double nParticle = parcel.nParticle;
    const std::array<double, nQuantities> totals{{massInside, fraction * nParticle, fraction * nParticle * radius,
                                                  massInside * radius, massInside * parcel.velocity.x(),
                                                  massInside * parcel.velocity.y(), massInside * parcel.velocity.z()}};

    // 3. Kernel.
    const ParcelKernel kernel(radius, nParticle, kernelSettings_, kernelDimension_);
    if (kernel.capped())
    {
        ++stats.parcelsCapped;
    }
    if (kernel.width() < kernelSettings_.cloudInCellBelow * largestSpacing_)
    {
        ++stats.parcelsCloudInCell;
        depositFallback(clipStart, clipDisplacement, totals);
        return;
    }
    PathWeight pathWeight(kernel, clipStart, clipDisplacement);
    const double reach = negligibleDistance(kernel, clipDisplacement.norm());
    pathWeight.limitTo(reach);

    // 4. Nodes in the bounding box of the swept capsule.
    std::array<int, 3> lo{}, hi{};
    for (int d = 0; d < 3; ++d)
    {
        if (spec_.flat(d))
        {
            lo[d] = hi[d] = 0;
            continue;
        }
        const double a = std::min(clipStart[d], clipStart[d] + clipDisplacement[d]) - reach;
        const double b = std::max(clipStart[d], clipStart[d] + clipDisplacement[d]) + reach;
        const double last = spec_.nodes[d] - 1;
        const double first = std::ceil((a - spec_.lower[d]) * inverseSpacing_[d]);
        const double lastReached = std::floor((b - spec_.lower[d]) * inverseSpacing_[d]);
        lo[d] = static_cast<int>(std::min(std::max(first, 0.0), last));
        hi[d] = static_cast<int>(std::min(std::max(lastReached, -1.0), last));
    }
    scratch_.clear();
    double omegaSum = 0.0;
    std::int64_t visited = 0;
    const std::size_t nx = static_cast<std::size_t>(spec_.nodes[0]);
    const std::size_t ny = static_cast<std::size_t>(spec_.nodes[1]);
    const std::size_t boxNodes = static_cast<std::size_t>(std::max(hi[0] - lo[0] + 1, 0))
        * static_cast<std::size_t>(std::max(hi[1] - lo[1] + 1, 0))
        * static_cast<std::size_t>(std::max(hi[2] - lo[2] + 1, 0));
    if (batched_ && !pathWeight.stationary() && boxNodes >= PathWeightBatch::minimumBoxNodes)
    {
        // CPU with AVX2 + FMA (KernelBuild.hpp): project every node of the box, then omega
        // of all of them four at a time without branches (PathWeightBatch); the same sums
        // and the same list of weighted nodes, in node order, as the per-node loop below.
        const double* boxOmega = batch_.boxOmegas(pathWeight, clipStart, coordinates_[0].data(),
                                                  coordinates_[1].data(), coordinates_[2].data(), lo, hi);
        // List the nodes with omega > 0 without a branch: each node is written at the end of
        // the list and kept by advancing the count (omega <= 0 adds 0 to the sum).
        scratch_.resize(boxNodes);
        std::size_t weighted = 0;
        std::size_t n = 0;
        for (int k = lo[2]; k <= hi[2]; ++k)
        {
            for (int j = lo[1]; j <= hi[1]; ++j)
            {
                const std::size_t row = nx * (static_cast<std::size_t>(j) + ny * static_cast<std::size_t>(k));
                for (int i = lo[0]; i <= hi[0]; ++i, ++n)
                {
                    const double omega = std::max(boxOmega[n], 0.0);
                    scratch_[weighted] = {row + static_cast<std::size_t>(i), omega};
                    weighted += omega > 0.0 ? 1 : 0;
                    omegaSum += omega;
                }
            }
        }
        scratch_.resize(weighted);
        visited = static_cast<std::int64_t>(boxNodes);
    }
    else
    {
        // Per-node loop (vectorised off, CPUs without AVX2 + FMA, other architectures;
        // stationary parcels and small boxes always).
        for (int k = lo[2]; k <= hi[2]; ++k)
        {
            const double oz = coordinates_[2][static_cast<std::size_t>(k)] - clipStart.z();
            for (int j = lo[1]; j <= hi[1]; ++j)
            {
                const double oy = coordinates_[1][static_cast<std::size_t>(j)] - clipStart.y();
                const std::size_t row = nx * (static_cast<std::size_t>(j) + ny * static_cast<std::size_t>(k));
                for (int i = lo[0]; i <= hi[0]; ++i)
                {
                    const Eigen::Vector3d offset(coordinates_[0][static_cast<std::size_t>(i)] - clipStart.x(), oy, oz);
                    const double omega = pathWeight.omegaFromOffset(offset);
                    if (omega > 0.0)
                    {
                        scratch_.emplace_back(row + static_cast<std::size_t>(i), omega);
                        omegaSum += omega;
                    }
                }
                visited += hi[0] >= lo[0] ? hi[0] - lo[0] + 1 : 0;
            }
        }
    }
    stats.nodesVisited += visited;

    // 5-6. Normalise (eq. 24), or fall back to cloud-in-cell weights.
    if (!(omegaSum >= DBL_MIN))
    {
        ++stats.parcelsFallback;
        depositFallback(clipStart, clipDisplacement, totals);
        return;
    }
    const double inverseSum = 1.0 / omegaSum;
    for (const auto& [node, omega] : scratch_)
    {
        accumulate(node, omega * inverseSum, totals);
    }
    stats.nodesWeighted += static_cast<std::int64_t>(scratch_.size());
    // The touched box: the weighted nodes lie inside [lo, hi].
    IndexBox box;
    box.lo = lo;
    box.hi = hi;
    stepBox_ = stepBox_.united(box);
}

double DensityGrid::negligibleDistance(const ParcelKernel& kernel, double pathLength) const
{
    // A node farther than d from the path has omega < exp(-gamma d^2) (phi is below that at
    // every point of the path). Some node lies within c = half the cell diagonal of the
    // path's midpoint (the clipped path is inside the box), so within c + L/2 of every point
    // of the path: its omega, the mean of phi along the path, is at least phi(c + L/2), and
    // so is the parcel's largest. Nodes with exp(-gamma d^2) <= negligibleWeight phi(c + L/2)
    // therefore hold less than negligibleWeight times the largest weight.
    const double epsilon = kernelSettings_.negligibleWeight;
    const double reach = kernel.reach();
    // The cut binds only if exp(-gamma reach^2) < epsilon (phi <= 1).
    if (!(epsilon > 0.0) || !(kernel.edgeExponent() > -std::log(epsilon)))
    {
        return reach;
    }
    const double best = kernel.phi(halfCellDiagonal_ + 0.5 * pathLength);
    if (!(best > 0.0))
    {
        return reach;
    }
    const double cutoffSquared = (-std::log(epsilon) - std::log(best)) / kernel.gamma();
    return cutoffSquared < reach * reach ? std::sqrt(cutoffSquared) : reach;
}

void DensityGrid::accumulate(std::size_t node, double weight, const std::array<double, nQuantities>& parcelTotals)
{
    double* values = step_.data() + node * nQuantities;
    for (int q = 0; q < nQuantities; ++q)
    {
        values[q] += weight * parcelTotals[static_cast<std::size_t>(q)];
    }
}

void DensityGrid::depositFallback(const Eigen::Vector3d& start, const Eigen::Vector3d& displacement,
                                  const std::array<double, nQuantities>& parcelTotals)
{
    // Points at most half a node spacing apart along the path (at least one, at most 4096),
    // each spreading its share of the parcel over the corners of its cell (multilinear).
    const double length = displacement.norm();
    const int points = static_cast<int>(std::min(4096.0, std::max(1.0, std::ceil(2.0 * length / smallestSpacing_))));
    const double share = 1.0 / points;
    const auto pointAt = [&](int p) -> Eigen::Vector3d { return start + ((p + 0.5) * share) * displacement; };

    // The corners of all points lie in the box spanned by the cells of the first and the last
    // point: along a straight path the cell is non-decreasing or non-increasing per direction
    // (axisCell). The weights of the points are summed per node in that box first, and the
    // parcel's seven quantities added once per node that got weight: a path of 10 points
    // touches ~12 distinct nodes of a 2D grid instead of 40 corner updates.
    std::array<AxisCell, 3> first{}, last{};
    const Eigen::Vector3d firstPoint = pointAt(0);
    const Eigen::Vector3d lastPoint = pointAt(points - 1);
    IndexBox box;
    std::array<std::size_t, 3> stride{};
    std::size_t boxNodes = 1;
    for (int d = 0; d < 3; ++d)
    {
        const auto u = static_cast<std::size_t>(d);
        if (spec_.flat(d))
        {
            box.lo[u] = box.hi[u] = 0;
        }
        else
        {
            first[u] = axisCell(firstPoint[d], spec_.lower[d], spacing_[u], spec_.nodes[d]);
            last[u] = axisCell(lastPoint[d], spec_.lower[d], spacing_[u], spec_.nodes[d]);
            box.lo[u] = std::min(first[u].cell, last[u].cell);
            box.hi[u] = std::max(first[u].cell, last[u].cell) + 1;
        }
        stride[u] = boxNodes;
        boxNodes *= static_cast<std::size_t>(box.hi[u] - box.lo[u] + 1);
    }
    stepBox_ = stepBox_.united(box);
    const int corners = (spec_.flat(0) ? 1 : 2) * (spec_.flat(1) ? 1 : 2) * (spec_.flat(2) ? 1 : 2);
    stepStatistics_.nodesVisited += static_cast<std::int64_t>(points) * corners;

    if (boxNodes > maximumPathBoxNodes)
    {
        // A path across many cells (rare: parcels move a few cells per step at most): each
        // point's corners straight onto the grid.
        for (int p = 0; p < points; ++p)
        {
            const CornerWeights cornerWeights = multilinearWeights(spec_, pointAt(p));
            for (int c = 0; c < cornerWeights.count; ++c)
            {
                const auto u = static_cast<std::size_t>(c);
                accumulate(cornerWeights.node[u], share * cornerWeights.weight[u], parcelTotals);
            }
        }
        stepStatistics_.nodesWeighted += static_cast<std::int64_t>(points) * corners;
        return;
    }

    pathWeights_.assign(boxNodes, 0.0);
    for (int p = 0; p < points; ++p)
    {
        const Eigen::Vector3d point = pointAt(p);
        // Per direction: the weights of the lower and upper corner and the offset of the
        // lower corner in the box (flat directions: one corner of weight 1)
        std::array<double, 3> lowerWeight{{1.0, 1.0, 1.0}}, upperWeight{{0.0, 0.0, 0.0}};
        std::size_t offset = 0;
        for (int d = 0; d < 3; ++d)
        {
            const auto u = static_cast<std::size_t>(d);
            if (spec_.flat(d))
            {
                continue;
            }
            const AxisCell position = axisCell(point[d], spec_.lower[d], spacing_[u], spec_.nodes[d]);
            lowerWeight[u] = 1.0 - position.fraction;
            upperWeight[u] = position.fraction;
            offset += stride[u] * static_cast<std::size_t>(position.cell - box.lo[u]);
        }
        // The same products, in the same order, as multilinearWeights
        const int extentZ = spec_.flat(2) ? 1 : 2;
        const int extentY = spec_.flat(1) ? 1 : 2;
        const int extentX = spec_.flat(0) ? 1 : 2;
        for (int c = 0; c < extentZ; ++c)
        {
            const double wz = c == 0 ? lowerWeight[2] : upperWeight[2];
            for (int b = 0; b < extentY; ++b)
            {
                const double wy = b == 0 ? lowerWeight[1] : upperWeight[1];
                double* row = pathWeights_.data() + offset + stride[2] * static_cast<std::size_t>(c)
                    + stride[1] * static_cast<std::size_t>(b);
                row[0] += share * (lowerWeight[0] * wy * wz);
                if (extentX == 2)
                {
                    row[1] += share * (upperWeight[0] * wy * wz);
                }
            }
        }
    }

    std::size_t n = 0;
    std::int64_t weighted = 0;
    for (int k = box.lo[2]; k <= box.hi[2]; ++k)
    {
        for (int j = box.lo[1]; j <= box.hi[1]; ++j)
        {
            const std::size_t row = spec_.flatIndex(0, j, k);
            for (int i = box.lo[0]; i <= box.hi[0]; ++i, ++n)
            {
                const double weight = pathWeights_[n];
                if (weight > 0.0)
                {
                    accumulate(row + static_cast<std::size_t>(i), weight, parcelTotals);
                    ++weighted;
                }
            }
        }
    }
    stepStatistics_.nodesWeighted += weighted;
}

void DensityGrid::commitStep()
{
    window_.push(step_, stepBox_);
    const IndexBox box = stepBox_;
    if (!box.empty())
    {
        for (int k = box.lo[2]; k <= box.hi[2]; ++k)
        {
            for (int j = box.lo[1]; j <= box.hi[1]; ++j)
            {
                const std::size_t first = spec_.flatIndex(box.lo[0], j, k) * nQuantities;
                const std::size_t last = spec_.flatIndex(box.hi[0], j, k) * nQuantities + nQuantities;
                std::fill(step_.begin() + static_cast<std::ptrdiff_t>(first),
                          step_.begin() + static_cast<std::ptrdiff_t>(last), 0.0);
            }
        }
    }
    stepBox_ = IndexBox{};
    lastStepStatistics_ = stepStatistics_;
    stepStatistics_ = StepStatistics{};
}

std::vector<double> DensityGrid::packStep(const IndexBox& box) const
{
    std::vector<double> values(box.empty() ? 0 : box.nodeCount() * nQuantities);
    packStep(box, values.data());
    return values;
}

void DensityGrid::packStep(const IndexBox& box, double* values) const
{
    if (box.empty())
    {
        return;
    }
    for (int k = box.lo[2]; k <= box.hi[2]; ++k)
    {
        for (int j = box.lo[1]; j <= box.hi[1]; ++j)
        {
            const std::size_t first = spec_.flatIndex(box.lo[0], j, k) * nQuantities;
            const std::size_t last = spec_.flatIndex(box.hi[0], j, k) * nQuantities + nQuantities;
            values = std::copy(step_.begin() + static_cast<std::ptrdiff_t>(first),
                               step_.begin() + static_cast<std::ptrdiff_t>(last), values);
        }
    }
}

void DensityGrid::unpackStep(const IndexBox& box, const std::vector<double>& values)
{
    unpackStep(box, values.data(), values.size());
}

void DensityGrid::unpackStep(const IndexBox& box, const double* values, std::size_t count)
{
    if (box.empty())
    {
        return;
    }
    for (int d = 0; d < 3; ++d)
    {
        if (box.lo[d] < 0 || box.hi[d] >= spec_.nodes[d])
        {
            throw std::invalid_argument("DensityGrid::unpackStep: box outside the grid");
        }
    }
    if (count != box.nodeCount() * nQuantities)
    {
        throw std::invalid_argument("DensityGrid::unpackStep: value count does not match the box");
    }
    const std::size_t rowValues = static_cast<std::size_t>(box.hi[0] - box.lo[0] + 1) * nQuantities;
    for (int k = box.lo[2]; k <= box.hi[2]; ++k)
    {
        for (int j = box.lo[1]; j <= box.hi[1]; ++j)
        {
            const std::size_t first = spec_.flatIndex(box.lo[0], j, k) * nQuantities;
            std::copy(values, values + rowValues, step_.begin() + static_cast<std::ptrdiff_t>(first));
            values += rowValues;
        }
    }
    stepBox_ = stepBox_.united(box);
}

DropletFieldValue DensityGrid::fieldFromSums(const std::array<double, nQuantities>& s) const
{
    DropletFieldValue value;
    const int steps = window_.filled();
    if (steps == 0)
    {
        return value;
    }
    const double volumeSteps = nodeVolume_ * steps;
    const double mass = s[quantityMass];
    const double count = s[quantityCount];
    if (mass > 0.0)
    {
        value.rho = mass / volumeSteps;
        value.rMeanMass = s[quantityMassRadius] / mass;
        value.velocity = Eigen::Vector3d(s[quantityMomentumX], s[quantityMomentumY], s[quantityMomentumZ]) / mass;
    }
    if (count > 0.0)
    {
        value.numberDensity = count / volumeSteps;
        value.rMeanNumber = s[quantityCountRadius] / count;
    }
    return value;
}

DropletFieldValue DensityGrid::nodeValue(std::size_t flatIndex) const
{
    std::array<double, nQuantities> sums{};
    window_.nodeTotal(flatIndex, sums.data());
    return fieldFromSums(sums);
}

DropletFieldValue DensityGrid::nodeValue(int i, int j, int k) const
{
    return nodeValue(spec_.flatIndex(i, j, k));
}

DropletFieldValue DensityGrid::sample(const Eigen::Vector3d& point) const
{
    if (!insideActiveBox(spec_, point))
    {
        DropletFieldValue outside;
        outside.inside = false;
        return outside;
    }
    const CornerWeights corners = multilinearWeights(spec_, point);
    std::array<double, nQuantities> sums{};
    std::array<double, nQuantities> total{};
    for (int c = 0; c < corners.count; ++c)
    {
        window_.nodeTotal(corners.node[static_cast<std::size_t>(c)], total.data());
        const double w = corners.weight[static_cast<std::size_t>(c)];
        for (int q = 0; q < nQuantities; ++q)
        {
            sums[static_cast<std::size_t>(q)] += w * total[static_cast<std::size_t>(q)];
        }
    }
    return fieldFromSums(sums);
}

double DensityGrid::windowMassPerStep() const
{
    const int steps = window_.filled();
    if (steps == 0)
    {
        return 0.0;
    }
    double mass = 0.0;
    const std::vector<double>& total = window_.total();
    for (std::size_t n = 0; n < spec_.nodeCount(); ++n)
    {
        mass += total[n * nQuantities + quantityMass];
    }
    return mass / steps;
}

} // namespace dropletFiber
