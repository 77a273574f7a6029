#include "grid/ParcelWeights.hpp"

#include "grid/KernelExtent.hpp"
#include "grid/PathWeight.hpp"
#include "grid/PathWeightBatch.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>

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

const KernelSettings& validated(const KernelSettings& kernel)
{
    kernel.validate();
    return kernel;
}

} // namespace

ParcelWeights::ParcelWeights(const GridSpec& spec, const KernelSettings& kernel)
    : lattice_(spec), kernelSettings_(validated(kernel)),
      kernelDimension_(resolveDimension(spec, kernel.dimension)),
      batched_(kernel.vectorised && PathWeightBatch::cpuSupported()), exact_(batched_), separable_(batched_)
{
}

void ParcelWeights::weigh(const Parcel& parcel, const ClippedPath& path, WeightSink& sink)
{
    StepStatistics& stats = sink.statistics();
    // 3. Kernel; unresolved ones go to the cell corners.
    const double radius = 0.5 * parcel.diameter;
    const ParcelKernel kernel(radius, parcel.nParticle, kernelSettings_, kernelDimension_);
    if (kernel.capped())
    {
        ++stats.parcelsCapped;
    }
    const double largestSpacing = lattice_.largestSpacing();
    if (kernel.width() < kernelSettings_.cloudInCellBelow * largestSpacing)
    {
        ++stats.parcelsCloudInCell;
        cloudInCell_.weigh(lattice_, path.start, path.displacement, sink);
        return;
    }
    PathWeight pathWeight(kernel, path.start, path.displacement);
    const double reach = negligibleDistance(kernel, path.displacement.norm());
    pathWeight.limitTo(reach);
    // The widest kernel weighed this step, in largest spacings (the deposit report)
    stats.widestKernelWidth = std::max(stats.widestKernelWidth, kernel.width() / largestSpacing);
    stats.widestKernelReach = std::max(stats.widestKernelReach, reach / largestSpacing);

    // 4. Weights of the lattice nodes in the bounding box of the swept capsule; ghost
    // nodes beyond the faces are folded onto their mirror images.
    const IndexBox box = lattice_.nodeBox(path, reach);
    if (!sink.wants(lattice_.withinGrid(box) ? box : lattice_.foldedBox(box))
        && !sink.wants(cloudInCell_.box(lattice_, path.start, path.displacement)))
    {
        return; // depositedShare: neither these nodes nor the fallback's are asked for
    }
    IndexBox weightedBox = box;
    // The removal: the deposit's tables of this parcel where kept (a sparse sink), with
    // the points Q the deposit chose for them
    const KeptTables::Key key(path.start, path.displacement, parcel.diameter, parcel.nParticle);
    const KeptTables::Entry* kept = sink.sparse() != nullptr ? kept_.find(key) : nullptr;
    const int points = kept != nullptr ? kept->points : separablePoints(pathWeight, box.nodeCount());
    if (points > 0)
    {
        ++stats.parcelsSeparable;
    }
    SeparableTables tables;
    const double omegaSum = points > 0
        ? separableTables(key, kept, pathWeight, path, box, points, sink, weightedBox, tables)
        : exact_.weigh(lattice_, pathWeight, path.start, box, weightedBox);
    stats.nodesVisited += static_cast<std::int64_t>(box.nodeCount());

    // 5-6. Normalise (eq. 24), or fall back to cloud-in-cell weights.
    if (!(omegaSum >= DBL_MIN))
    {
        ++stats.parcelsFallback;
        cloudInCell_.weigh(lattice_, path.start, path.displacement, sink);
        return;
    }
    if (points > 0)
    {
        sink.addSeparable(separable_, tables, 1.0 / omegaSum, weightedBox);
        return;
    }
    sink.addListed(exact_.nodes(), 1.0 / omegaSum, weightedBox);
}

IndexBox ParcelWeights::box(const Parcel& parcel, const ClippedPath& path) const
{
    // weigh()'s choices: cloud-in-cell, or the kernel's nodes with the fallback's.
    const IndexBox cloudInCell = cloudInCell_.box(lattice_, path.start, path.displacement);
    const ParcelKernel kernel(0.5 * parcel.diameter, parcel.nParticle, kernelSettings_, kernelDimension_);
    if (kernel.width() < kernelSettings_.cloudInCellBelow * lattice_.largestSpacing())
    {
        return cloudInCell;
    }
    const double reach = negligibleDistance(kernel, path.displacement.norm());
    const IndexBox box = lattice_.nodeBox(path, reach);
    return (lattice_.withinGrid(box) ? box : lattice_.foldedBox(box)).united(cloudInCell);
}

double ParcelWeights::negligibleDistance(const ParcelKernel& kernel, double pathLength) const
{
    // P10 (KernelExtent.hpp)
    return negligibleReach(kernel, pathLength, lattice_.halfCellDiagonal(), kernelSettings_.negligibleWeight);
}

int ParcelWeights::separablePoints(const PathWeight& pathWeight, std::size_t boxNodes) const
{
    const double reach = std::sqrt(pathWeight.cutoffSquared()); // after the negligible-weight cut
    if (kernelSettings_.method != DepositMethod::Automatic
        || reach < separableFromSpacings * lattice_.largestSpacing())
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
    const double largestWeightBound = kernel.phi(lattice_.halfCellDiagonal() + 0.5 * pathWeight.length());
    const double k = std::sqrt(kernel.gamma()) * pathWeight.length();
    return SeparableWeight::chooseQuadrature(k, kernel.edgeValue(), 0.0, largestWeightBound, boxNodes);
}

double ParcelWeights::separableTables(const KeptTables::Key& key, const KeptTables::Entry* kept,
                                      const PathWeight& pathWeight, const ClippedPath& path,
                                      const IndexBox& box, int points, WeightSink& sink,
                                      IndexBox& weightedBox, SeparableTables& tables)
{
    if (kept != nullptr)
    {
        // The deposit's tables of this parcel: what the build below would give again
        weightedBox = kept->box;
        tables = kept_.tables(*kept);
        return kept->omegaSum;
    }
    separable_.prepare(pathWeight, path.start, path.displacement, points,
                       {{lattice_.coordinates(0), lattice_.coordinates(1), lattice_.coordinates(2)}}, box.lo,
                       box.hi);
    weightedBox = box;
    if (!lattice_.withinGrid(box))
    {
        // Folded kernels: the tables fold axis by axis (SeparableWeight.hpp).
        weightedBox = lattice_.mirror(box, separableMirror_);
        separable_.fold(separableMirror_, weightedBox.lo, weightedBox.hi);
    }
    const double omegaSum = separable_.sum();
    tables = separable_.tables();
    if (sink.accumulates() && omegaSum >= DBL_MIN && kept_.keeps(weightedBox))
    {
        kept_.keep(key, separable_, omegaSum, weightedBox);
    }
    return omegaSum;
}

} // namespace dropletFiber
