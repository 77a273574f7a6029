#include "grid/DensityGrid.hpp"
#include "grid/KernelExtent.hpp"

#include "grid/MultilinearWeights.hpp"
#include "grid/PathWeight.hpp"
#include "grid/SeparableLanes.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <stdexcept>
#include <string>
#include <tuple>

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

// Step 7: what the parcel puts on the grid per quantity (GridQuantities.hpp), for the
// fraction of the step it spends inside the box.
std::array<double, nQuantities> parcelTotals(const Parcel& parcel, double mass, double fraction)
{
    const double massInside = fraction * mass;
    const double radius = 0.5 * parcel.diameter;
    const double nParticle = parcel.nParticle;
    return {{massInside, fraction * nParticle, fraction * nParticle * radius, massInside * radius,
             massInside * parcel.velocity.x(), massInside * parcel.velocity.y(),
             massInside * parcel.velocity.z()}};
}

// Cloud-in-cell: points at most half the smallest node spacing apart along the path (at
// least one, at most 4096), at the middles of equal parts; each carries `share` of the parcel.
struct PathPoints
{
    PathPoints(const Eigen::Vector3d& pathStart, const Eigen::Vector3d& pathDisplacement,
               double smallestSpacing)
        : start(pathStart), displacement(pathDisplacement),
          count(static_cast<int>(
              std::min(4096.0, std::max(1.0, std::ceil(2.0 * pathDisplacement.norm() / smallestSpacing))))),
          share(1.0 / count)
    {
    }

    Eigen::Vector3d at(int p) const { return start + ((p + 0.5) * share) * displacement; }

    Eigen::Vector3d start;
    Eigen::Vector3d displacement;
    int count;
    double share;
};

// The box of the cells' corners of all points of a path, with its strides (i fastest).
struct PathCells
{
    IndexBox box;
    std::array<std::size_t, 3> stride{};
    std::size_t nodeCount = 1;
};

// The corners of all points lie in the box spanned by the cells of the first and the last
// point: along a straight path the cell is non-decreasing or non-increasing per direction
// (axisCell). Summing the points' weights per node of that box first, and adding the
// parcel's seven quantities once per node that got weight, makes a path of 10 points touch
// ~12 distinct nodes of a 2D grid instead of 40 corner updates.
PathCells pathCells(const GridSpec& spec, const std::array<double, 3>& spacing, const PathPoints& points)
{
    const Eigen::Vector3d firstPoint = points.at(0);
    const Eigen::Vector3d lastPoint = points.at(points.count - 1);
    PathCells cells;
    for (int d = 0; d < 3; ++d)
    {
        const auto u = static_cast<std::size_t>(d);
        if (spec.flat(d))
        {
            cells.box.lo[u] = cells.box.hi[u] = 0;
        }
        else
        {
            const AxisCell first = axisCell(firstPoint[d], spec.lower[d], spacing[u], spec.nodes[d]);
            const AxisCell last = axisCell(lastPoint[d], spec.lower[d], spacing[u], spec.nodes[d]);
            cells.box.lo[u] = std::min(first.cell, last.cell);
            cells.box.hi[u] = std::max(first.cell, last.cell) + 1;
        }
        cells.stride[u] = cells.nodeCount;
        cells.nodeCount *= static_cast<std::size_t>(cells.box.hi[u] - cells.box.lo[u] + 1);
    }
    return cells;
}

// Adds share times the multilinear weights of the point's cell corners to weights (one
// value per node of cells.box): the same products, in the same order, as multilinearWeights.
void addCornerWeights(const GridSpec& spec, const std::array<double, 3>& spacing, const PathCells& cells,
                      const Eigen::Vector3d& point, double share, double* weights)
{
    // Per direction: the weights of the lower and upper corner and the offset of the lower
    // corner in the box (flat directions: one corner of weight 1)
    std::array<double, 3> lowerWeight{{1.0, 1.0, 1.0}}, upperWeight{{0.0, 0.0, 0.0}};
    std::size_t offset = 0;
    for (int d = 0; d < 3; ++d)
    {
        const auto u = static_cast<std::size_t>(d);
        if (spec.flat(d))
        {
            continue;
        }
        const AxisCell position = axisCell(point[d], spec.lower[d], spacing[u], spec.nodes[d]);
        lowerWeight[u] = 1.0 - position.fraction;
        upperWeight[u] = position.fraction;
        offset += cells.stride[u] * static_cast<std::size_t>(position.cell - cells.box.lo[u]);
    }
    const int extentZ = spec.flat(2) ? 1 : 2;
    const int extentY = spec.flat(1) ? 1 : 2;
    const int extentX = spec.flat(0) ? 1 : 2;
    for (int c = 0; c < extentZ; ++c)
    {
        const double wz = c == 0 ? lowerWeight[2] : upperWeight[2];
        for (int b = 0; b < extentY; ++b)
        {
            const double wy = b == 0 ? lowerWeight[1] : upperWeight[1];
            double* row = weights + offset + cells.stride[2] * static_cast<std::size_t>(c)
                + cells.stride[1] * static_cast<std::size_t>(b);
            row[0] += share * (lowerWeight[0] * wy * wz);
            if (extentX == 2)
            {
                row[1] += share * (upperWeight[0] * wy * wz);
            }
        }
    }
}

// Step 7 for a row of nodes with contiguous values: node i gets weight omega[i] inverseSum
// times the parcel's quantities. inLanes (batchedKernel()): four nodes' 28 values at a time
// in AVX2 + FMA registers (SeparableLanes). Otherwise two nodes at a time as 14 consecutive values (whole
// vector registers, 7 pairs, where one node's 7 values leave one over), each value the
// same product and sum as node by node.
void addWeightedRow(const double* omega, std::size_t length, double inverseSum,
                    const std::array<double, nQuantities>& totals, double* values, bool inLanes)
{
    static_assert(SeparableLanes::quantities == nQuantities, "SeparableLanes adds 7 values per node");
    if (inLanes)
    {
        SeparableLanes::addWeightedRow(omega, length, inverseSum, totals.data(), values);
        return;
    }
    constexpr std::size_t pair = 2 * nQuantities;
    std::array<double, pair> pairTotals{};
    for (std::size_t m = 0; m < pair; ++m)
    {
        pairTotals[m] = totals[m % nQuantities];
    }
    std::size_t i = 0;
    for (; i + 1 < length; i += 2, values += pair)
    {
        const double first = omega[i] * inverseSum;
        const double second = omega[i + 1] * inverseSum;
        std::array<double, pair> weight{};
        for (std::size_t m = 0; m < pair; ++m)
        {
            weight[m] = m < nQuantities ? first : second;
        }
        for (std::size_t m = 0; m < pair; ++m)
        {
            values[m] += weight[m] * pairTotals[m];
        }
    }
    if (i < length)
    {
        const double weight = omega[i] * inverseSum;
        for (std::size_t q = 0; q < nQuantities; ++q)
        {
            values[q] += weight * totals[q];
        }
    }
}

// Requests the cache lines of a row of `length` nodes' values (for writing), where they
// exist; a hint only, without effect on the values.
void prefetchRow(const double* values, std::size_t length)
{
    constexpr std::size_t valuesPerLine = 8; // 64-byte cache lines
    for (std::size_t m = 0; m < length * nQuantities; m += valuesPerLine)
    {
        __builtin_prefetch(values + m, 1);
    }
}

GridBlock checkedBlock(const GridSpec& spec, const GridBlock& block)
{
    spec.validate();
    const IndexBox grid = spec.fullBox();
    if (block.owned.empty() || block.storage.intersected(grid) != block.storage
        || block.owned.intersected(block.storage) != block.owned)
    {
        throw std::invalid_argument(
            "DensityGrid: a block's owned nodes must be a non-empty box inside its storage "
            "box, inside the grid");
    }
    return block;
}

// True when [lo, hi] holds an index congruent to offset modulo period (> 0).
bool holdsMultiple(int lo, int hi, int period, int offset)
{
    const int ahead = ((offset - lo) % period + period) % period; // from lo to the next one
    return lo + ahead <= hi;
}

} // namespace

DensityGrid::DensityGrid(const GridSpec& spec, const KernelSettings& kernel, int windowLength)
    : DensityGrid(spec, kernel, windowLength, GridBlock{validated(spec).fullBox(), spec.fullBox()})
{
}

DensityGrid::DensityGrid(const GridSpec& spec, const KernelSettings& kernel, int windowLength,
                         const GridBlock& block)
    : spec_(validated(spec)), kernelSettings_(kernel),
      kernelDimension_(resolveDimension(spec, kernel.dimension)),
      batched_(kernel.vectorised && PathWeightBatch::cpuSupported()), nodeVolume_(spec.nodeVolume()),
      owned_(checkedBlock(spec, block).owned), storage_(block.storage),
      storesWholeGrid_(block.storage == spec.fullBox()), ownsWholeGrid_(block.owned == spec.fullBox()),
      window_(spec.nodes, block.owned, nQuantities, windowLength), log_(windowLength), separable_(batched_)
{
    kernelSettings_.validate();
    for (int d = 0; d < 3; ++d)
    {
        // The lattice lower + i h, from one grid length before the box to one after it
        // (ghost nodes of the folded kernels); the nodes keep GridSpec's coordinates.
        const int nodes = spec.nodes[d];
        ghostLayers_[d] = spec.flat(d) ? 0 : nodes - 1;
        coordinates_[d].resize(static_cast<std::size_t>(nodes + 2 * ghostLayers_[d]));
        for (int i = -ghostLayers_[d]; i < nodes + ghostLayers_[d]; ++i)
        {
            const bool node = i >= 0 && i < nodes;
            coordinates_[d][static_cast<std::size_t>(i + ghostLayers_[d])]
                = node ? spec.nodeCoordinate(d, i) : spec.lower[d] + i * spec.spacing(d);
        }
        inverseSpacing_[d] = spec.flat(d) ? 0.0 : 1.0 / spec.spacing(d);
        spacing_[d] = spec.flat(d) ? 0.0 : spec.spacing(d);
        largestSpacing_ = spec.flat(d) ? largestSpacing_ : std::max(largestSpacing_, spec.spacing(d));
        if (!spec.flat(d))
        {
            smallestSpacing_
                = smallestSpacing_ > 0.0 ? std::min(smallestSpacing_, spec.spacing(d)) : spec.spacing(d);
        }
        halfCellDiagonal_ += spec.flat(d) ? 0.0 : 0.25 * spec.spacing(d) * spec.spacing(d);
    }
    halfCellDiagonal_ = std::sqrt(halfCellDiagonal_);
    step_.assign(storage_.nodeCount() * nQuantities, 0.0);
    rowPending_.assign(storageRow(0, storage_.hi[2] - storage_.lo[2] + 1), 0);
}

void DensityGrid::deposit(const Parcel& parcel, double dt)
{
    checkParcel(parcel, dt);
    if (keptStepCommitted_)
    {
        // A new step: the last one's kept tables are no longer asked for
        kept_.clear();
        keptStepCommitted_ = false;
    }
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
    ClippedPath path;
    if (!clipPath(parcel, dt, mass, stats, path))
    {
        return;
    }
    // The window's restart state: what is deposited, as given (depletion changes the
    // parcel's nParticle after this)
    log_.record(parcel, dt);
    // 3-7. The weights of the nodes, onto the step accumulator.
    const std::array<double, nQuantities> totals = parcelTotals(parcel, mass, path.fraction);
    WeightSink sink{stats, &totals, nullptr, nullptr, 0.0, IndexBox{}};
    weighPath(parcel, path, sink);
}

double DensityGrid::depositedShare(const Parcel& parcel, double dt, const NodeBoxTest& asks,
                                   const NodeFraction& fraction, const IndexBox& region)
{
    StepStatistics unused;
    WeightSink sink{unused, nullptr, &asks, &fraction, 0.0, region};
    return shareOf(parcel, dt, sink);
}

double DensityGrid::depositedShare(const Parcel& parcel, double dt, const NodeBoxTest& asks,
                                   const SparseNodeValues& fractions)
{
    StepStatistics unused;
    const NodeFraction fraction = [&fractions](std::size_t node) { return fractions.at(node); };
    WeightSink sink{unused, nullptr, &asks, &fraction, 0.0, fractions.box(), &fractions};
    return shareOf(parcel, dt, sink);
}

double DensityGrid::shareOf(const Parcel& parcel, double dt, WeightSink& sink)
{
    checkParcel(parcel, dt);
    if (parcel.nParticle == 0.0 || parcel.diameter == 0.0)
    {
        return 0.0;
    }
    // deposit()'s steps on their own statistics, the weights into the sum.
    ClippedPath path;
    if (!clipPath(parcel, dt, parcelMass(parcel), sink.statistics, path))
    {
        return 0.0;
    }
    weighPath(parcel, path, sink);
    return path.fraction * sink.sum;
}

IndexBox DensityGrid::depositBox(const Parcel& parcel, double dt) const
{
    checkParcel(parcel, dt);
    StepStatistics unused;
    ClippedPath path;
    if (parcel.nParticle == 0.0 || parcel.diameter == 0.0
        || !clipPath(parcel, dt, parcelMass(parcel), unused, path))
    {
        return IndexBox{};
    }
    // weighPath's choices: cloud-in-cell, or the kernel's nodes with the fallback's.
    const IndexBox cloudInCell = cloudInCellBox(path.start, path.displacement);
    const ParcelKernel kernel(0.5 * parcel.diameter, parcel.nParticle, kernelSettings_, kernelDimension_);
    if (kernel.width() < kernelSettings_.cloudInCellBelow * largestSpacing_)
    {
        return cloudInCell;
    }
    const double reach = negligibleDistance(kernel, path.displacement.norm());
    const IndexBox box = nodeBox(path, reach);
    return (withinGrid(box) ? box : foldedBox(box)).united(cloudInCell);
}

IndexBox DensityGrid::foldedBox(const IndexBox& box) const
{
    // The mirror image is a tent of period 2 last: rising from 0 at the even multiples of
    // last to last at the odd ones. Over [lo, hi] its least value is 0 where the range holds
    // an even multiple, else at an end; its largest is last where it holds an odd one.
    IndexBox folded;
    for (int d = 0; d < 3; ++d)
    {
        if (box.lo[d] > box.hi[d])
        {
            folded.lo[d] = spec_.nodes[d];
            folded.hi[d] = -1;
            continue;
        }
        const int a = spec_.mirrorIndex(d, box.lo[d]);
        const int b = spec_.mirrorIndex(d, box.hi[d]);
        const int last = spec_.nodes[d] - 1;
        const bool holdsEven = last > 0 && holdsMultiple(box.lo[d], box.hi[d], 2 * last, 0);
        const bool holdsOdd = last > 0 && holdsMultiple(box.lo[d], box.hi[d], 2 * last, last);
        folded.lo[d] = holdsEven ? 0 : std::min(a, b);
        folded.hi[d] = holdsOdd ? last : std::max(a, b);
    }
    return folded;
}

void DensityGrid::weighPath(const Parcel& parcel, const ClippedPath& path, WeightSink& sink)
{
    StepStatistics& stats = sink.statistics;
    // 3. Kernel; unresolved ones go to the cell corners.
    const double radius = 0.5 * parcel.diameter;
    const ParcelKernel kernel(radius, parcel.nParticle, kernelSettings_, kernelDimension_);
    if (kernel.capped())
    {
        ++stats.parcelsCapped;
    }
    if (kernel.width() < kernelSettings_.cloudInCellBelow * largestSpacing_)
    {
        ++stats.parcelsCloudInCell;
        weighCloudInCell(path.start, path.displacement, sink);
        return;
    }
    PathWeight pathWeight(kernel, path.start, path.displacement);
    const double reach = negligibleDistance(kernel, path.displacement.norm());
    pathWeight.limitTo(reach);
    // The widest kernel weighed this step, in largest spacings (the deposit report)
    stats.widestKernelWidth = std::max(stats.widestKernelWidth, kernel.width() / largestSpacing_);
    stats.widestKernelReach = std::max(stats.widestKernelReach, reach / largestSpacing_);

    // 4. Weights of the lattice nodes in the bounding box of the swept capsule; ghost
    // nodes beyond the faces are folded onto their mirror images.
    const IndexBox box = nodeBox(path, reach);
    if (!sink.wants(withinGrid(box) ? box : foldedBox(box))
        && !sink.wants(cloudInCellBox(path.start, path.displacement)))
    {
        return; // depositedShare: neither these nodes nor the fallback's are asked for
    }
    IndexBox weightedBox = box;
    // The removal: the deposit's tables of this parcel where kept (a sparse sink), with
    // the points Q the deposit chose for them
    const KeptTables::Key key(path.start, path.displacement, parcel.diameter, parcel.nParticle);
    const KeptTables::Entry* kept = sink.sparse != nullptr ? kept_.find(key) : nullptr;
    const int points = kept != nullptr ? kept->points : separablePoints(pathWeight, box.nodeCount());
    if (points > 0)
    {
        ++stats.parcelsSeparable;
    }
    SeparableTables tables;
    const double omegaSum = points > 0
        ? separableTables(key, kept, pathWeight, path, box, points, sink, weightedBox, tables)
        : weighLattice(pathWeight, path, box, weightedBox);
    stats.nodesVisited += static_cast<std::int64_t>(box.nodeCount());

    // 5-6. Normalise (eq. 24), or fall back to cloud-in-cell weights.
    if (!(omegaSum >= DBL_MIN))
    {
        ++stats.parcelsFallback;
        weighCloudInCell(path.start, path.displacement, sink);
        return;
    }
    if (points > 0 && sink.sparse != nullptr)
    {
        shareSeparable(tables, 1.0 / omegaSum, weightedBox, sink);
        return;
    }
    if (points > 0)
    {
        sendSeparable(1.0 / omegaSum, weightedBox, sink);
        return;
    }
    sendWeighted(1.0 / omegaSum, weightedBox, sink);
}

void DensityGrid::depositCopy(const Parcel& parcel, double dt)
{
    // deposit() books into stepStatistics_: swapped, so that it books into the copies'
    // statistics and the parcel's mass is counted once, by the block that holds it
    std::swap(stepStatistics_, copyStatistics_);
    try
    {
        deposit(parcel, dt);
    }
    catch (...)
    {
        std::swap(stepStatistics_, copyStatistics_);
        throw;
    }
    std::swap(stepStatistics_, copyStatistics_);
}

bool DensityGrid::clipPath(const Parcel& parcel, double dt, double mass, StepStatistics& stats,
                           ClippedPath& path) const
{
    const Eigen::Vector3d displacement = parcel.velocity * dt;
    const Eigen::Vector3d start = parcel.position - displacement;
    double t0 = 0.0, t1 = 1.0;
    if (!clipToBox(spec_, start, displacement, t0, t1))
    {
        ++stats.parcelsOutside;
        stats.massOutside += mass;
        return false;
    }
    path.fraction = (displacement.squaredNorm() > 0.0) ? t1 - t0 : 1.0;
    if (path.fraction < 1.0)
    {
        ++stats.parcelsPartlyOutside;
    }
    const double massInside = path.fraction * mass;
    stats.massDeposited += massInside;
    stats.massOutside += mass - massInside;
    if (!(path.fraction > 0.0))
    {
        return false; // touches the box in a single point: measure zero
    }
    // Projected into the active directions (flat: on the node layer).
    path.start = start + t0 * displacement;
    path.displacement = (t1 - t0) * displacement;
    for (int d = 0; d < 3; ++d)
    {
        if (spec_.flat(d))
        {
            path.start[d] = latticeCoordinates(d)[0];
            path.displacement[d] = 0.0;
        }
    }
    return true;
}

IndexBox DensityGrid::nodeBox(const ClippedPath& path, double reach) const
{
    IndexBox box;
    for (int d = 0; d < 3; ++d)
    {
        if (spec_.flat(d))
        {
            box.lo[d] = box.hi[d] = 0;
            continue;
        }
        // Lattice indices, ghost nodes included (at most ghostLayers_ beyond each face).
        const double a = std::min(path.start[d], path.start[d] + path.displacement[d]) - reach;
        const double b = std::max(path.start[d], path.start[d] + path.displacement[d]) + reach;
        const double lowest = -ghostLayers_[d];
        const double highest = spec_.nodes[d] - 1 + ghostLayers_[d];
        const double first = std::ceil((a - spec_.lower[d]) * inverseSpacing_[d]);
        const double lastReached = std::floor((b - spec_.lower[d]) * inverseSpacing_[d]);
        box.lo[d] = static_cast<int>(std::min(std::max(first, lowest), highest));
        box.hi[d] = static_cast<int>(std::min(std::max(lastReached, lowest - 1.0), highest));
    }
    return box;
}

bool DensityGrid::touchesFace(const IndexBox& box) const
{
    for (int d = 0; d < 3; ++d)
    {
        if (!spec_.flat(d) && (box.lo[d] == 0 || box.hi[d] == spec_.nodes[d] - 1))
        {
            return true;
        }
    }
    return false;
}

bool DensityGrid::withinGrid(const IndexBox& box) const
{
    for (int d = 0; d < 3; ++d)
    {
        if (box.lo[d] < 0 || box.hi[d] > spec_.nodes[d] - 1)
        {
            return false;
        }
    }
    return true;
}

double DensityGrid::weighLattice(const PathWeight& pathWeight, const ClippedPath& path, const IndexBox& box,
                                 IndexBox& weightedBox)
{
    const double* omega = nullptr; // the whole box's omegas, where computed at once
    if (batched_ && !pathWeight.stationary() && box.nodeCount() >= PathWeightBatch::minimumBoxNodes)
    {
        omega = batch_.boxOmegas(pathWeight, path.start, latticeCoordinates(0), latticeCoordinates(1),
                                 latticeCoordinates(2), box.lo, box.hi);
    }
    if (!withinGrid(box))
    {
        omega = omega ? omega : latticeOmegas(pathWeight, path.start, box);
        weightedBox = mirrorBox(box);
        return foldOntoNodes(omega, weightedBox);
    }
    weightedBox = box;
    return omega ? listWeighted(omega, box) : weighNodesOneByOne(pathWeight, path.start, box);
}

int DensityGrid::separablePoints(const PathWeight& pathWeight, std::size_t boxNodes) const
{
    const double reach = std::sqrt(pathWeight.cutoffSquared()); // after the negligible-weight cut
    if (kernelSettings_.method != DepositMethod::Automatic || reach < separableFromSpacings * largestSpacing_)
    {
        return 0;
    }
    // The parcel's largest omega is at least phi(c + L/2) (negligibleDistance). Every node of
    // the cut's box is weighed (no threshold: t = 0), so the separable weights stay within
    // the bound of the untruncated integral, and within the bound plus the cut's own error
    // (docs/model.md P10: 5e-8 of the largest node value at 1e-8) of the exact code. (A
    // threshold t would count once per node of the box, (2N + 1) t / P: the cut's
    // negligibleWeight cannot be one.)
    const ParcelKernel& kernel = pathWeight.kernel();
    const double largestWeightBound = kernel.phi(halfCellDiagonal_ + 0.5 * pathWeight.length());
    const double k = std::sqrt(kernel.gamma()) * pathWeight.length();
    return SeparableWeight::chooseQuadrature(k, kernel.edgeValue(), 0.0, largestWeightBound, boxNodes);
}

double DensityGrid::prepareSeparable(const PathWeight& pathWeight, const ClippedPath& path,
                                     const IndexBox& box, int points, IndexBox& weightedBox)
{
    separable_.prepare(pathWeight, path.start, path.displacement, points,
                       {{latticeCoordinates(0), latticeCoordinates(1), latticeCoordinates(2)}}, box.lo,
                       box.hi);
    weightedBox = box;
    if (!withinGrid(box))
    {
        // Folded kernels: the tables fold axis by axis (SeparableWeight.hpp).
        weightedBox = mirrorBox(box);
        separable_.fold(mirrorImage_, weightedBox.lo, weightedBox.hi);
    }
    return separable_.sum();
}

double DensityGrid::separableTables(const KeptTables::Key& key, const KeptTables::Entry* kept,
                                    const PathWeight& pathWeight, const ClippedPath& path,
                                    const IndexBox& box, int points, WeightSink& sink, IndexBox& weightedBox,
                                    SeparableTables& tables)
{
    if (kept != nullptr)
    {
        // The deposit's tables of this parcel: what prepareSeparable would build again
        weightedBox = kept->box;
        tables = kept_.tables(*kept);
        return kept->omegaSum;
    }
    const double omegaSum = prepareSeparable(pathWeight, path, box, points, weightedBox);
    tables = separable_.tables();
    if (sink.accumulates() && omegaSum >= DBL_MIN && kept_.keeps(weightedBox))
    {
        kept_.keep(key, separable_, omegaSum, weightedBox);
    }
    return omegaSum;
}

void DensityGrid::sendSeparable(double inverseSum, const IndexBox& box, WeightSink& sink)
{
    if (!sink.accumulates())
    {
        // depositedShare: the nodes of the (folded) box that may have a fraction, the
        // deposit's weights to the bit (a part of a row is that part of the whole row).
        std::int64_t weighted = 0;
        const IndexBox asked = box.intersected(sink.region);
        const auto first = static_cast<std::size_t>(asked.lo[0] - box.lo[0]);
        forEachRow(asked, spec_.nodes,
                   [&](const IndexRow& row)
                   {
                       const double* omega
                           = separable_.row(row.j - box.lo[1], row.k - box.lo[2], first, row.length);
                       for (std::size_t i = 0; i < row.length; ++i)
                       {
                           const double weight = omega[i] * inverseSum;
                           if (weight > 0.0)
                           {
                               send(sink, row.first + i, weight);
                               ++weighted;
                           }
                       }
                   });
        sink.statistics.nodesWeighted += weighted;
        return;
    }
    // The stored part of the box only, row by row into contiguous accumulator values: no
    // node list, no per-node index arithmetic (a block evaluates only its part of a copy).
    const IndexBox stored = box.intersected(storage_);
    const std::array<double, nQuantities>& parcelTotals = *sink.totals;
    const auto first = static_cast<std::size_t>(stored.lo[0] - box.lo[0]);
    // The values of the row rowsAhead further in j (the next layer's at a layer's end: a
    // wasted request), requested while this one is added: rows of a few dozen nodes are too
    // short for the hardware's prefetcher, on grids beyond the caches.
    const std::size_t rowAhead
        = rowsAhead * static_cast<std::size_t>(storage_.hi[0] - storage_.lo[0] + 1) * nQuantities;
    forEachRowIn(stored, storage_,
                 [&](const IndexRow& row)
                 {
                     const double* omega
                         = separable_.row(row.j + storage_.lo[1] - box.lo[1],
                                          row.k + storage_.lo[2] - box.lo[2], first, row.length);
                     // First write into the row this step: the evicted step's values go
                     // (the row is being brought into cache by this parcel anyway)
                     const std::size_t rowIndex = storageRow(row.j, row.k);
                     if (rowPending_[rowIndex] != 0)
                     {
                         zeroPendingRow(rowIndex);
                     }
                     double* values = step_.data() + row.first * nQuantities;
                     if ((row.first + row.length) * nQuantities + rowAhead <= step_.size())
                     {
                         prefetchRow(values + rowAhead, row.length);
                     }
                     addWeightedRow(omega, row.length, inverseSum, parcelTotals, values, batched_);
                 });
    sink.statistics.nodesWeighted += static_cast<std::int64_t>(stored.empty() ? 0 : stored.nodeCount());
    touch(box); // the stored part of it
}

void DensityGrid::shareSeparable(const SeparableTables& tables, double inverseSum, const IndexBox& box,
                                 WeightSink& sink)
{
    // The sink's nodes inside the (folded) box, in node order: the terms the row-by-row
    // sum over the box adds where the fraction is not 0, each weight the row's to the bit.
    sink.sparse->forEachIn(box, spec_.nodes,
                           [&](const NodeValue& node)
                           {
                               const double weight
                                   = tables.omega(node.index[0] - box.lo[0], node.index[1] - box.lo[1],
                                                  node.index[2] - box.lo[2])
                                   * inverseSum;
                               if (weight > 0.0)
                               {
                                   sink.sum += weight * node.value;
                                   ++sink.statistics.nodesWeighted;
                               }
                           });
}

void DensityGrid::shareWeighted(double inverseSum, WeightSink& sink)
{
    // scratch_ and the sink's nodes are both in node order: one pass over each.
    const std::vector<NodeValue>& nodes = sink.sparse->nodes();
    auto next = nodes.begin();
    for (const auto& [node, omega] : scratch_)
    {
        while (next != nodes.end() && next->node < node)
        {
            ++next;
        }
        if (next == nodes.end())
        {
            break;
        }
        if (next->node == node)
        {
            sink.sum += omega * inverseSum * next->value;
        }
    }
    sink.statistics.nodesWeighted += static_cast<std::int64_t>(scratch_.size());
}

double DensityGrid::listWeighted(const double* boxOmega, const IndexBox& box)
{
    // List the nodes with omega > 0 without a branch: each node is written at the end of
    // the list and kept by advancing the count (omega <= 0 adds 0 to the sum).
    scratch_.clear();
    scratch_.resize(box.nodeCount());
    std::size_t weighted = 0;
    double omegaSum = 0.0;
    forEachRow(box, spec_.nodes,
               [&](const IndexRow& row)
               {
                   for (std::size_t i = 0; i < row.length; ++i)
                   {
                       const double omega = std::max(boxOmega[row.offsetInBox + i], 0.0);
                       scratch_[weighted] = {row.first + i, omega};
                       weighted += omega > 0.0 ? 1 : 0;
                       omegaSum += omega;
                   }
               });
    scratch_.resize(weighted);
    return omegaSum;
}

double DensityGrid::weighNodesOneByOne(const PathWeight& pathWeight, const Eigen::Vector3d& start,
                                       const IndexBox& box)
{
    // Vectorised off, CPUs without AVX2 + FMA, other architectures; stationary parcels and
    // small boxes always.
    scratch_.clear();
    double omegaSum = 0.0;
    const double* x = latticeCoordinates(0) + box.lo[0]; // lo >= 0 (withinGrid)
    forEachRow(box, spec_.nodes,
               [&](const IndexRow& row)
               {
                   const double oz = latticeCoordinates(2)[row.k] - start.z();
                   const double oy = latticeCoordinates(1)[row.j] - start.y();
                   for (std::size_t i = 0; i < row.length; ++i)
                   {
                       const Eigen::Vector3d offset(x[i] - start.x(), oy, oz);
                       const double omega = pathWeight.omegaFromOffset(offset);
                       if (omega > 0.0)
                       {
                           scratch_.emplace_back(row.first + i, omega);
                           omegaSum += omega;
                       }
                   }
               });
    return omegaSum;
}

const double* DensityGrid::latticeOmegas(const PathWeight& pathWeight, const Eigen::Vector3d& start,
                                         const IndexBox& box)
{
    latticeOmega_.resize(box.nodeCount());
    std::size_t n = 0;
    for (int k = box.lo[2]; k <= box.hi[2]; ++k)
    {
        const double oz = latticeCoordinates(2)[k] - start.z();
        for (int j = box.lo[1]; j <= box.hi[1]; ++j)
        {
            const double oy = latticeCoordinates(1)[j] - start.y();
            for (int i = box.lo[0]; i <= box.hi[0]; ++i, ++n)
            {
                latticeOmega_[n] = pathWeight.omegaFromOffset(
                    Eigen::Vector3d(latticeCoordinates(0)[i] - start.x(), oy, oz));
            }
        }
    }
    return latticeOmega_.data();
}

IndexBox DensityGrid::mirrorBox(const IndexBox& box)
{
    IndexBox folded;
    for (int d = 0; d < 3; ++d)
    {
        std::vector<int>& image = mirrorImage_[static_cast<std::size_t>(d)];
        image.clear();
        folded.lo[d] = spec_.nodes[d];
        folded.hi[d] = -1;
        for (int i = box.lo[d]; i <= box.hi[d]; ++i)
        {
            image.push_back(spec_.mirrorIndex(d, i));
            folded.lo[d] = std::min(folded.lo[d], image.back());
            folded.hi[d] = std::max(folded.hi[d], image.back());
        }
    }
    return folded;
}

double DensityGrid::foldOntoNodes(const double* omega, const IndexBox& foldedBox)
{
    // Every lattice node's omega is summed (eq. 24 over the unbounded lattice, in node
    // order) and added to its mirror image (mirrorImage_, set by mirrorBox).
    foldedOmega_.assign(foldedBox.nodeCount(), 0.0);
    const std::size_t foldedRow = static_cast<std::size_t>(foldedBox.hi[0] - foldedBox.lo[0] + 1);
    const std::size_t foldedLayer
        = foldedRow * static_cast<std::size_t>(foldedBox.hi[1] - foldedBox.lo[1] + 1);
    double omegaSum = 0.0;
    std::size_t n = 0;
    for (const int k : mirrorImage_[2])
    {
        for (const int j : mirrorImage_[1])
        {
            double* row = foldedOmega_.data() + foldedLayer * static_cast<std::size_t>(k - foldedBox.lo[2])
                + foldedRow * static_cast<std::size_t>(j - foldedBox.lo[1]);
            for (const int i : mirrorImage_[0])
            {
                const double weight = std::max(omega[n++], 0.0);
                omegaSum += weight;
                row[i - foldedBox.lo[0]] += weight;
            }
        }
    }
    // The weighted nodes in node order, as the other weighNodes functions list them.
    scratch_.clear();
    forEachRow(foldedBox, spec_.nodes,
               [&](const IndexRow& row)
               {
                   for (std::size_t i = 0; i < row.length; ++i)
                   {
                       const double weight = foldedOmega_[row.offsetInBox + i];
                       if (weight > 0.0)
                       {
                           scratch_.emplace_back(row.first + i, weight);
                       }
                   }
               });
    return omegaSum;
}

void DensityGrid::sendWeighted(double inverseSum, const IndexBox& box, WeightSink& sink)
{
    if (sink.accumulates())
    {
        clearPendingRowsOf(box); // the weighted nodes lie inside it
    }
    if (sink.accumulates() && storesWholeGrid_)
    {
        // Serial runs: the nodes' values straight from the accumulator, each node's cache
        // lines requested prefetchDistance nodes ahead (wide kernels touch thousands of
        // nodes per parcel, mostly not in cache: the deposit's floor, docs/performance.md).
        const std::array<double, nQuantities>& parcelTotals = *sink.totals;
        const std::size_t count = scratch_.size();
        for (std::size_t n = 0; n < count; ++n)
        {
            if (n + prefetchDistance < count)
            {
                const double* ahead = step_.data() + scratch_[n + prefetchDistance].first * nQuantities;
                __builtin_prefetch(ahead, 1);
                __builtin_prefetch(ahead + nQuantities - 1, 1);
            }
            double* values = step_.data() + scratch_[n].first * nQuantities;
            const double weight = scratch_[n].second * inverseSum;
            for (int q = 0; q < nQuantities; ++q)
            {
                values[q] += weight * parcelTotals[static_cast<std::size_t>(q)];
            }
        }
    }
    else if (sink.sparse != nullptr)
    {
        shareWeighted(inverseSum, sink);
        return;
    }
    else
    {
        for (const auto& [node, omega] : scratch_)
        {
            send(sink, node, omega * inverseSum);
        }
    }
    sink.statistics.nodesWeighted += static_cast<std::int64_t>(scratch_.size());
    // The touched box: the weighted nodes lie inside it.
    if (sink.accumulates())
    {
        touch(box);
    }
}

double DensityGrid::negligibleDistance(const ParcelKernel& kernel, double pathLength) const
{
    // P10 (KernelExtent.hpp)
    return negligibleReach(kernel, pathLength, halfCellDiagonal_, kernelSettings_.negligibleWeight);
}

std::array<int, 3> DensityGrid::nodeIndices(std::size_t node) const
{
    return nodeIndicesOfFlat(spec_.nodes, node);
}

double* DensityGrid::stepValuesOfBlockNode(std::size_t node)
{
    const std::array<int, 3> n = nodeIndices(node);
    return storage_.holds(n[0], n[1], n[2])
        ? step_.data() + flatIndexInBox(storage_, n[0], n[1], n[2]) * nQuantities
        : nullptr;
}

void DensityGrid::send(WeightSink& sink, std::size_t node, double weight)
{
    if (sink.accumulates())
    {
        accumulate(node, weight, *sink.totals);
        return;
    }
    sink.sum += weight * (*sink.fraction)(node);
}

void DensityGrid::accumulate(std::size_t node, double weight,
                             const std::array<double, nQuantities>& parcelTotals)
{
    double* values = stepValuesOf(node);
    if (values == nullptr)
    {
        return; // another block's node: that block deposits the parcel too
    }
    for (int q = 0; q < nQuantities; ++q)
    {
        values[q] += weight * parcelTotals[static_cast<std::size_t>(q)];
    }
}

IndexBox DensityGrid::cloudInCellBox(const Eigen::Vector3d& start, const Eigen::Vector3d& displacement) const
{
    // The box weighCloudInCell's points weigh: that of the half-spacing points holds that of
    // the finer points near a face (both span the cells of the path's first and last point).
    const PathPoints points(start, displacement, smallestSpacing_);
    const PathCells coarse = pathCells(spec_, spacing_, points);
    if (displacement.squaredNorm() > 0.0 && touchesFace(coarse.box))
    {
        return pathCells(spec_, spacing_, PathPoints(start, displacement, smallestSpacing_ / faceRefinement))
            .box;
    }
    return coarse.box;
}

void DensityGrid::weighCloudInCell(const Eigen::Vector3d& start, const Eigen::Vector3d& displacement,
                                   WeightSink& sink)
{
    PathPoints points(start, displacement, smallestSpacing_);
    PathCells cells = pathCells(spec_, spacing_, points);
    if (displacement.squaredNorm() > 0.0 && touchesFace(cells.box))
    {
        // Near a face: finer points (faceRefinement; a stationary parcel is one point).
        points = PathPoints(start, displacement, smallestSpacing_ / faceRefinement);
        cells = pathCells(spec_, spacing_, points);
    }
    if (!sink.wants(cells.box))
    {
        return;
    }
    if (sink.accumulates())
    {
        clearPendingRowsOf(cells.box);
        touch(cells.box);
    }
    const int corners = (spec_.flat(0) ? 1 : 2) * (spec_.flat(1) ? 1 : 2) * (spec_.flat(2) ? 1 : 2);
    sink.statistics.nodesVisited += static_cast<std::int64_t>(points.count) * corners;

    if (cells.nodeCount > maximumPathBoxNodes)
    {
        // A path across many cells (rare: parcels move a few cells per step at most): each
        // point's corners straight onto the grid.
        for (int p = 0; p < points.count; ++p)
        {
            sendCorners(points.at(p), points.share, sink);
        }
        sink.statistics.nodesWeighted += static_cast<std::int64_t>(points.count) * corners;
        return;
    }
    pathWeights_.assign(cells.nodeCount, 0.0);
    for (int p = 0; p < points.count; ++p)
    {
        addCornerWeights(spec_, spacing_, cells, points.at(p), points.share, pathWeights_.data());
    }
    sendPathWeights(cells.box, sink);
}

void DensityGrid::sendCorners(const Eigen::Vector3d& point, double share, WeightSink& sink)
{
    const CornerWeights cornerWeights = multilinearWeights(spec_, point);
    for (int c = 0; c < cornerWeights.count; ++c)
    {
        const auto u = static_cast<std::size_t>(c);
        send(sink, cornerWeights.node[u], share * cornerWeights.weight[u]);
    }
}

void DensityGrid::sendPathWeights(const IndexBox& box, WeightSink& sink)
{
    std::int64_t weighted = 0;
    forEachRow(box, spec_.nodes,
               [&](const IndexRow& row)
               {
                   for (std::size_t i = 0; i < row.length; ++i)
                   {
                       const double weight = pathWeights_[row.offsetInBox + i];
                       if (weight > 0.0)
                       {
                           send(sink, row.first + i, weight);
                           ++weighted;
                       }
                   }
               });
    sink.statistics.nodesWeighted += weighted;
}

void DensityGrid::zeroPendingRow(std::size_t row) const
{
    const auto rowNodes = static_cast<std::size_t>(storage_.hi[0] - storage_.lo[0] + 1);
    const auto dirtyNodes = static_cast<std::size_t>(dirty_.hi[0] - dirty_.lo[0] + 1);
    double* first = step_.data() + (row * rowNodes + static_cast<std::size_t>(dirty_.lo[0])) * nQuantities;
    std::fill(first, first + dirtyNodes * nQuantities, 0.0);
    rowPending_[row] = 0;
}

void DensityGrid::clearPendingRowsOf(const IndexBox& box) const
{
    if (dirty_.empty() || box.empty())
    {
        return;
    }
    // The box's rows in storage indices, within the dirty rows
    const int jLo = std::max(box.lo[1] - storage_.lo[1], dirty_.lo[1]);
    const int jHi = std::min(box.hi[1] - storage_.lo[1], dirty_.hi[1]);
    const int kLo = std::max(box.lo[2] - storage_.lo[2], dirty_.lo[2]);
    const int kHi = std::min(box.hi[2] - storage_.lo[2], dirty_.hi[2]);
    for (int k = kLo; k <= kHi; ++k)
    {
        for (int j = jLo; j <= jHi; ++j)
        {
            const std::size_t row = storageRow(j, k);
            if (rowPending_[row] != 0)
            {
                zeroPendingRow(row);
            }
        }
    }
}

void DensityGrid::clearPendingRows() const
{
    for (int k = dirty_.lo[2]; k <= dirty_.hi[2]; ++k)
    {
        for (int j = dirty_.lo[1]; j <= dirty_.hi[1]; ++j)
        {
            const std::size_t row = storageRow(j, k);
            if (rowPending_[row] != 0)
            {
                zeroPendingRow(row);
            }
        }
    }
    dirty_ = IndexBox{};
}

void DensityGrid::markDirty(const IndexBox& dirty)
{
    dirty_ = IndexBox{};
    if (dirty.empty())
    {
        return;
    }
    for (int d = 0; d < 3; ++d)
    {
        dirty_.lo[d] = dirty.lo[d] - storage_.lo[d];
        dirty_.hi[d] = dirty.hi[d] - storage_.lo[d];
    }
    for (int k = dirty_.lo[2]; k <= dirty_.hi[2]; ++k)
    {
        for (int j = dirty_.lo[1]; j <= dirty_.hi[1]; ++j)
        {
            rowPending_[storageRow(j, k)] = 1;
        }
    }
}

void DensityGrid::commitStep()
{
    if (storage_ == owned_)
    {
        // The accumulator has the window's layout (serial runs; blocks of the function
        // object store their owned nodes only): it becomes the newest slot (zero outside
        // stepBox_ once the rows no deposit reached are cleared) and the evicted slot the
        // next accumulator, cleared row by row as the next step's deposits reach it. No copy
        // (the spray3D case's steps touch about the whole grid, 4.8 MB).
        clearPendingRows();
        IndexBox evicted;
        window_.pushSwappingUncleared(step_, stepBox_, evicted);
        markDirty(evicted);
    }
    else
    {
        window_.push(step_.data(), storage_, stepBox_.intersected(owned_));
        forEachRowIn(stepBox_, storage_,
                     [&](const IndexRow& row)
                     {
                         double* values = step_.data() + row.first * nQuantities;
                         std::fill(values, values + row.length * nQuantities, 0.0);
                     });
    }
    stepBox_ = IndexBox{};
    lastStepStatistics_ = stepStatistics_;
    stepStatistics_ = StepStatistics{};
    copyStatistics_ = StepStatistics{};
    log_.commit();
    keptStepCommitted_ = true; // kept_ stays for this step's removal
}

WindowState DensityGrid::saveWindow(WindowStateFormat format) const
{
    const int filled = window_.filled();
    // Node values where a step was not deposited (unpackStep), or restored from node values
    const bool log = log_.complete(filled)
        && (format == WindowStateFormat::DepositLog
            || (format == WindowStateFormat::Smaller
                && log_.savedValueCount(filled) <= window_.savedValueCount()));
    return log ? log_.save(spec_.nodes, owned_, nQuantities, filled, window_.committedSteps())
               : window_.save();
}

void DensityGrid::restoreWindow(const WindowState& state)
{
    if (DepositLog::holdsLog(state))
    {
        replayLog(state);
        return;
    }
    window_.restore(state);
    log_.clear(); // node values: no log of these steps
}

void DensityGrid::replayLog(const WindowState& state)
{
    // Everything checked before this grid changes
    const DepositLog::Saved saved = DepositLog::read(state, spec_.nodes, owned_, nQuantities);
    if (!stepBox_.empty() || stepStatistics_.parcels != 0 || copyStatistics_.parcels != 0)
    {
        throw std::invalid_argument(
            "DensityGrid::restoreWindow: the step has deposits (restore before them)");
    }
    // The newest min(saved, W) steps, oldest first
    const std::size_t kept = std::min(saved.steps.size(), static_cast<std::size_t>(window_.length()));
    const bool sameRegion = saved.region == owned_;
    const StepStatistics last = lastStepStatistics_;
    log_.clear();
    window_.clear(saved.committed - static_cast<std::int64_t>(kept));
    for (std::size_t s = saved.steps.size() - kept; s < saved.steps.size(); ++s)
    {
        const DepositLog::StepView& step = saved.steps[s];
        std::size_t p = 0;
        for (std::size_t r = 0; r < step.runCount; ++r)
        {
            const double dt = step.runs[2 * r];
            const std::size_t end = p + static_cast<std::size_t>(step.runs[2 * r + 1]);
            for (; p < end; ++p)
            {
                const Parcel parcel = DepositLog::parcel(step, p);
                // A larger region's log (a serial run's, decomposed): the parcels that reach
                // none of the nodes stored here add nothing, and are not logged again
                if (sameRegion || !depositBox(parcel, dt).intersected(storage_).empty())
                {
                    depositCopy(parcel, dt);
                }
            }
        }
        commitStep();
    }
    lastStepStatistics_ = last;
}

namespace
{
void checkStored(const IndexBox& box, const IndexBox& storage, const char* what)
{
    if (!box.empty() && box.intersected(storage) != box)
    {
        throw std::invalid_argument(std::string("DensityGrid::") + what + ": box outside the nodes stored");
    }
}
} // namespace

std::vector<double> DensityGrid::packStep(const IndexBox& box) const
{
    std::vector<double> values(box.empty() ? 0 : box.nodeCount() * nQuantities);
    packStep(box, values.data());
    return values;
}

void DensityGrid::packStep(const IndexBox& box, double* values) const
{
    checkStored(box, storage_, "packStep");
    clearPendingRowsOf(box);
    forEachRowIn(box, storage_,
                 [&](const IndexRow& row)
                 {
                     const double* first = step_.data() + row.first * nQuantities;
                     std::copy(first, first + row.length * nQuantities,
                               values + row.offsetInBox * nQuantities);
                 });
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
    checkStored(box, storage_, "unpackStep");
    if (count != box.nodeCount() * nQuantities)
    {
        throw std::invalid_argument("DensityGrid::unpackStep: value count does not match the box");
    }
    clearPendingRowsOf(box); // the rows' parts outside the box keep the step's values
    forEachRowIn(box, storage_,
                 [&](const IndexRow& row)
                 {
                     const double* first = values + row.offsetInBox * nQuantities;
                     std::copy(first, first + row.length * nQuantities,
                               step_.data() + row.first * nQuantities);
                 });
    stepBox_ = stepBox_.united(box);
    log_.markIncomplete(); // values that no logged deposit gives
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
        value.velocity
            = Eigen::Vector3d(s[quantityMomentumX], s[quantityMomentumY], s[quantityMomentumZ]) / mass;
    }
    if (count > 0.0)
    {
        value.numberDensity = count / volumeSteps;
        value.rMeanNumber = s[quantityCountRadius] / count;
    }
    return value;
}

double DensityGrid::cellsPerNodeVolume(std::size_t flatIndex) const
{
    const std::array<int, 3> n = nodeIndices(flatIndex);
    return std::ldexp(1.0, spec_.boundaryDirections(n[0], n[1], n[2]));
}

bool DensityGrid::owns(std::size_t node) const
{
    const std::array<int, 3> n = nodeIndices(node);
    return node < spec_.nodeCount() && owned_.holds(n[0], n[1], n[2]);
}

void DensityGrid::windowTotal(std::size_t node, double* sums) const
{
    if (ownsWholeGrid_)
    {
        window_.nodeTotal(node, sums);
        return;
    }
    const std::array<int, 3> n = nodeIndices(node);
    if (node >= spec_.nodeCount() || !owned_.holds(n[0], n[1], n[2]))
    {
        throw std::out_of_range("DensityGrid: node " + std::to_string(node) + " is not owned by this block");
    }
    window_.nodeTotal(flatIndexInBox(owned_, n[0], n[1], n[2]), sums);
}

DropletFieldValue DensityGrid::nodeValue(std::size_t flatIndex) const
{
    std::array<double, nQuantities> sums{};
    windowTotal(flatIndex, sums.data());
    return nodeValueFromTotals(flatIndex, sums.data());
}

DropletFieldValue DensityGrid::nodeValueFromTotals(std::size_t flatIndex, const double* totals) const
{
    std::array<double, nQuantities> sums{};
    std::copy(totals, totals + nQuantities, sums.begin());
    // Sums per whole cell (a power of two: exact; the means are unchanged).
    const double scale = cellsPerNodeVolume(flatIndex);
    for (double& sum : sums)
    {
        sum *= scale;
    }
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
    double total[nQuantities];
    for (int c = 0; c < corners.count; ++c)
    {
        // windowTotal throws for a corner owned elsewhere
        windowTotal(corners.node[static_cast<std::size_t>(c)], total);
        addCornerSum(corners, c, total, sums);
    }
    return fieldFromSums(sums);
}

void DensityGrid::addOwnedCornerSums(const CornerWeights& corners,
                                     std::array<double, nQuantities>& sums) const
{
    double total[nQuantities];
    for (int c = 0; c < corners.count; ++c)
    {
        const std::size_t node = corners.node[static_cast<std::size_t>(c)];
        if (owns(node))
        {
            windowTotal(node, total);
            addCornerSum(corners, c, total, sums);
        }
    }
}

void DensityGrid::prefetchOwnedCornerSums(const CornerWeights& corners) const
{
    for (int c = 0; c < corners.count; ++c)
    {
        const std::size_t node = corners.node[static_cast<std::size_t>(c)];
        if (ownsWholeGrid_)
        {
            window_.prefetchNodeTotal(node);
        }
        else if (owns(node))
        {
            const std::array<int, 3> n = nodeIndices(node);
            window_.prefetchNodeTotal(flatIndexInBox(owned_, n[0], n[1], n[2]));
        }
    }
}

DropletFieldValue DensityGrid::interpolated(const CornerWeights& corners, const double* cornerTotals) const
{
    std::array<double, nQuantities> sums{};
    for (int c = 0; c < corners.count; ++c)
    {
        addCornerSum(corners, c, cornerTotals + c * nQuantities, sums);
    }
    return fieldFromSums(sums);
}

void DensityGrid::addCornerSum(const CornerWeights& corners, int c, const double* total,
                               std::array<double, nQuantities>& sums) const
{
    // Densities are interpolated: the sums per whole cell (scale 1 inside the box).
    const double w = corners.weight[static_cast<std::size_t>(c)];
    const double scale = cellsPerNodeVolume(corners.node[static_cast<std::size_t>(c)]);
    for (int q = 0; q < nQuantities; ++q)
    {
        sums[static_cast<std::size_t>(q)] += w * (scale * total[q]);
    }
}

double DensityGrid::lastStepValue(std::size_t node, int q) const
{
    if (ownsWholeGrid_)
    {
        return window_.newestStepValue(node, q);
    }
    const std::array<int, 3> n = nodeIndices(node);
    if (node >= spec_.nodeCount() || !owned_.holds(n[0], n[1], n[2]))
    {
        throw std::out_of_range("DensityGrid: node " + std::to_string(node) + " is not owned by this block");
    }
    return window_.newestStepValue(flatIndexInBox(owned_, n[0], n[1], n[2]), q);
}

double DensityGrid::densityParts(const CornerWeights& corners, const double* cornerTotals,
                                 double* parts) const
{
    double sum = 0.0;
    for (int c = 0; c < corners.count; ++c)
    {
        const std::size_t node = corners.node[static_cast<std::size_t>(c)];
        const double w = corners.weight[static_cast<std::size_t>(c)];
        parts[c] = w * (cellsPerNodeVolume(node) * cornerTotals[c * nQuantities + quantityMass]);
        sum += parts[c];
    }
    return sum;
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
    for (std::size_t n = 0; n < owned_.nodeCount(); ++n)
    {
        mass += total[n * nQuantities + quantityMass];
    }
    return mass / steps;
}

} // namespace dropletFiber
