#include "grid/LatticeWeights.hpp"

#include <algorithm>

namespace dropletFiber
{

double LatticeWeights::weigh(const NodeLattice& lattice, const PathWeight& pathWeight,
                             const Eigen::Vector3d& start, const IndexBox& box, IndexBox& weightedBox)
{
    const double* omega = nullptr; // the whole box's omegas, where computed at once
    if (batched_ && !pathWeight.stationary() && box.nodeCount() >= PathWeightBatch::minimumBoxNodes)
    {
        omega = batch_.boxOmegas(pathWeight, start, lattice.coordinates(0), lattice.coordinates(1),
                                 lattice.coordinates(2), box.lo, box.hi);
    }
    if (!lattice.withinGrid(box))
    {
        omega = omega ? omega : latticeOmegas(lattice, pathWeight, start, box);
        weightedBox = lattice.mirror(box, mirror_);
        return foldOntoNodes(lattice, omega, weightedBox);
    }
    weightedBox = box;
    return omega ? listWeighted(lattice, omega, box) : weighNodesOneByOne(lattice, pathWeight, start, box);
}

double LatticeWeights::listWeighted(const NodeLattice& lattice, const double* boxOmega, const IndexBox& box)
{
    // List the nodes with omega > 0 without a branch: each node is written at the end of
    // the list and kept by advancing the count (omega <= 0 adds 0 to the sum).
    nodes_.clear();
    nodes_.resize(box.nodeCount());
    std::size_t weighted = 0;
    double omegaSum = 0.0;
    forEachRow(box, lattice.nodes(),
               [&](const IndexRow& row)
               {
                   for (std::size_t i = 0; i < row.length; ++i)
                   {
                       const double omega = std::max(boxOmega[row.offsetInBox + i], 0.0);
                       nodes_[weighted] = {row.first + i, omega};
                       weighted += omega > 0.0 ? 1 : 0;
                       omegaSum += omega;
                   }
               });
    nodes_.resize(weighted);
    return omegaSum;
}

double LatticeWeights::weighNodesOneByOne(const NodeLattice& lattice, const PathWeight& pathWeight,
                                          const Eigen::Vector3d& start, const IndexBox& box)
{
    // Vectorised off, CPUs without AVX2 + FMA, other architectures; stationary parcels and
    // small boxes always.
    nodes_.clear();
    double omegaSum = 0.0;
    const double* x = lattice.coordinates(0) + box.lo[0]; // lo >= 0 (withinGrid)
    forEachRow(box, lattice.nodes(),
               [&](const IndexRow& row)
               {
                   const double oz = lattice.coordinates(2)[row.k] - start.z();
                   const double oy = lattice.coordinates(1)[row.j] - start.y();
                   for (std::size_t i = 0; i < row.length; ++i)
                   {
                       const Eigen::Vector3d offset(x[i] - start.x(), oy, oz);
                       const double omega = pathWeight.omegaFromOffset(offset);
                       if (omega > 0.0)
                       {
                           nodes_.emplace_back(row.first + i, omega);
                           omegaSum += omega;
                       }
                   }
               });
    return omegaSum;
}

const double* LatticeWeights::latticeOmegas(const NodeLattice& lattice, const PathWeight& pathWeight,
                                            const Eigen::Vector3d& start, const IndexBox& box)
{
    latticeOmega_.resize(box.nodeCount());
    std::size_t n = 0;
    for (int k = box.lo[2]; k <= box.hi[2]; ++k)
    {
        const double oz = lattice.coordinates(2)[k] - start.z();
        for (int j = box.lo[1]; j <= box.hi[1]; ++j)
        {
            const double oy = lattice.coordinates(1)[j] - start.y();
            for (int i = box.lo[0]; i <= box.hi[0]; ++i, ++n)
            {
                latticeOmega_[n] = pathWeight.omegaFromOffset(
                    Eigen::Vector3d(lattice.coordinates(0)[i] - start.x(), oy, oz));
            }
        }
    }
    return latticeOmega_.data();
}

double LatticeWeights::foldOntoNodes(const NodeLattice& lattice, const double* omega,
                                     const IndexBox& foldedBox)
{
    // Every lattice node's omega is summed (eq. 24 over the unbounded lattice, in node
    // order) and added to its mirror image (mirror_, set by NodeLattice::mirror).
    foldedOmega_.assign(foldedBox.nodeCount(), 0.0);
    const std::size_t foldedRow = static_cast<std::size_t>(foldedBox.hi[0] - foldedBox.lo[0] + 1);
    const std::size_t foldedLayer
        = foldedRow * static_cast<std::size_t>(foldedBox.hi[1] - foldedBox.lo[1] + 1);
    double omegaSum = 0.0;
    std::size_t n = 0;
    for (const int k : mirror_[2])
    {
        for (const int j : mirror_[1])
        {
            double* row = foldedOmega_.data() + foldedLayer * static_cast<std::size_t>(k - foldedBox.lo[2])
                + foldedRow * static_cast<std::size_t>(j - foldedBox.lo[1]);
            for (const int i : mirror_[0])
            {
                const double weight = std::max(omega[n++], 0.0);
                omegaSum += weight;
                row[i - foldedBox.lo[0]] += weight;
            }
        }
    }
    // The weighted nodes in node order, as the unfolded boxes list them.
    nodes_.clear();
    forEachRow(foldedBox, lattice.nodes(),
               [&](const IndexRow& row)
               {
                   for (std::size_t i = 0; i < row.length; ++i)
                   {
                       const double weight = foldedOmega_[row.offsetInBox + i];
                       if (weight > 0.0)
                       {
                           nodes_.emplace_back(row.first + i, weight);
                       }
                   }
               });
    return omegaSum;
}

} // namespace dropletFiber
