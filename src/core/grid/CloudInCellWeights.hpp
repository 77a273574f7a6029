// CloudInCellWeights: the multilinear (cloud-in-cell) weights of one parcel's path on the
// corners of the cells it crosses (docs/model.md sec. 4): the deposit's fallback when the
// kernel reaches no node (sum omega == 0: r_max smaller than the distance from the path
// to every node, e.g. n = 1, or only weights that underflow; step 6), and the whole
// deposit of kernels narrower than KernelSettings::cloudInCellBelow times the largest
// spacing (not resolved by the grid). The weights are averaged over points spaced at most
// half a node spacing along the path (1/16 where the path's cells touch a face node,
// faceRefinement); they sum to 1, so mass is conserved, and need no folding (the corners
// of a point inside the box are nodes). No storage beyond the current parcel's.
#pragma once

#include "grid/NodeLattice.hpp"
#include "grid/WeightSink.hpp"

#include <Eigen/Core>

#include <vector>

namespace dropletFiber
{

class CloudInCellWeights
{
public:
    // The nodes weigh() weighs for this path (grid indices).
    IndexBox box(const NodeLattice& lattice, const Eigen::Vector3d& start,
                 const Eigen::Vector3d& displacement) const;
    // The path's weights into the sink (nothing where the sink does not want its box),
    // booked in the sink's statistics (nodes visited and weighted).
    void weigh(const NodeLattice& lattice, const Eigen::Vector3d& start, const Eigen::Vector3d& displacement,
               WeightSink& sink);

private:
    // Paths whose cells touch a face node: points faceRefinement times closer (the
    // midpoint rule's error along diagonal paths cancels between the cells around an
    // interior node, not at a face; docs/model.md sec. 4, edge nodes).
    static constexpr double faceRefinement = 8.0;
    // Weights of the path summed per node of its box first, for boxes up to this many
    // nodes (a 2D path across ~30 cells; longer ones go straight to the sink point by point).
    static constexpr std::size_t maximumPathBoxNodes = 1024;
    std::vector<double> pathWeights_;
};

} // namespace dropletFiber
