// LatticeWeights: the exact weights omega_g (eq. 23, PathWeight) of the lattice nodes in
// a box around one parcel's path (docs/model.md sec. 4, eqs. 23-24), and their sum over
// the lattice: batched (AVX2 + FMA, PathWeightBatch) for moving parcels where the CPU has
// it and the box is large enough, else node by node (the same nodes, weights equal to ~1
// ulp of exp/erfc). Ghost nodes beyond the faces are folded onto their mirror images
// (docs/model.md sec. 4, edge nodes). The result is the list of nodes with omega > 0 in
// node order, for a WeightSink. No storage beyond the current parcel's.
#pragma once

#include "grid/NodeLattice.hpp"
#include "grid/PathWeight.hpp"
#include "grid/PathWeightBatch.hpp"
#include "grid/WeightSink.hpp"

#include <Eigen/Core>

#include <vector>

namespace dropletFiber
{

class LatticeWeights
{
public:
    // batched: the batched loop may be used (KernelSettings::vectorised and a CPU with it).
    explicit LatticeWeights(bool batched) : batched_(batched) {}

    // omega of every lattice node of the box (path from start); nodes() then lists the
    // nodes with omega > 0 in node order, ghost nodes folded onto their mirror images
    // (weightedBox: the box holding the listed nodes). Returns sum omega over the lattice
    // nodes (eq. 24's normalising sum).
    double weigh(const NodeLattice& lattice, const PathWeight& pathWeight, const Eigen::Vector3d& start,
                 const IndexBox& box, IndexBox& weightedBox);
    // The current parcel's weighted nodes (valid until the next weigh()).
    const NodeOmegas& nodes() const { return nodes_; }

private:
    // The box's omegas (i fastest) -> nodes_ (omega > 0, node order; box inside the
    // grid). Returns their sum.
    double listWeighted(const NodeLattice& lattice, const double* boxOmega, const IndexBox& box);
    // Node by node, for boxes inside the grid (stationary parcels, small boxes, no AVX2).
    double weighNodesOneByOne(const NodeLattice& lattice, const PathWeight& pathWeight,
                              const Eigen::Vector3d& start, const IndexBox& box);
    // omega of every lattice node of the box node by node (i fastest), valid until the next call.
    const double* latticeOmegas(const NodeLattice& lattice, const PathWeight& pathWeight,
                                const Eigen::Vector3d& start, const IndexBox& box);
    // Sums omega over the lattice box whose mirror images are mirror_ and folds it onto
    // foldedBox's nodes (listed in nodes_).
    double foldOntoNodes(const NodeLattice& lattice, const double* omega, const IndexBox& foldedBox);

    bool batched_;
    PathWeightBatch batch_;            // the batched loop's buffers (unused where not batched)
    NodeOmegas nodes_;                 // (node, omega) of the current parcel
    std::vector<double> latticeOmega_; // folded kernels: the lattice omegas node by node
    MirrorImages mirror_;              // the mirror image of each lattice index of the box
    std::vector<double> foldedOmega_;  // the omegas folded onto the nodes
};

} // namespace dropletFiber
