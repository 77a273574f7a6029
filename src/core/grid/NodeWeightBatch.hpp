// NodeWeightBatch: PathWeight::omegaFromOffset for all nodes of one parcel's box,
// computed stage by stage over the nodes instead of node by node.
//
// Why: one node's closed-form weight is ~500 instructions with a long dependent chain
// (projection -> interval -> exp and scaled erfc -> division), longer than the CPU's
// reorder window, so node after node runs at the chain's latency, and each mispredicted
// regime branch empties the window again (docs/performance.md, "Roofline and profile").
// Split into short loops (projection and reach test; interval and regime; the
// Gaussians at the ends; the scaled erfc of both ends; the combination), the
// iterations of each loop are independent and overlap, and the branches left are
// mostly in loops whose bodies are short.
//
// Exactness: the same formulas as PathWeight::integralAlongPath, same order of
// operations (regime C's three cases as one signed formula, exact), so the weights are bit-identical to omegaFromOffset (NodeWeightBatchTest
// checks it node by node). The rare regimes (edge quadrature, Taylor series: ~1 node
// per parcel) and stationary parcels call PathWeight itself.
//
// Use: start(path, nodeCount), addRow(...) for the rows of the box (slot = order of the
// nodes), then evaluate(): omega per slot (0 for nodes out of reach). No allocation once
// the scratch has grown to the largest box.
#pragma once

#include "grid/PathWeight.hpp"

#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace dropletFiber
{

class NodeWeightBatch
{
public:
    // Begins a parcel: at most `nodeCount` nodes will be added.
    void start(const PathWeight& path, std::size_t nodeCount);

    // The node at offset = node - path start.
    void add(const Eigen::Vector3d& offset);
    // A row of nodes at offsets (x[i] - startX, offsetY, offsetZ), i < count.
    void addRow(const double* x, std::size_t count, double startX, double offsetY, double offsetZ);

    // Weights of the added nodes by slot; valid until the next start().
    const double* evaluate();

private:
    const PathWeight* path_ = nullptr;
    std::size_t added_ = 0;
    std::vector<double> omega_; // by slot

    // Nodes within reach of the path segment (stage 1).
    std::size_t candidates_ = 0;
    std::vector<std::size_t> candidateSlot_;
    std::vector<double> lambdaM_;
    std::vector<double> d0Squared_;

    // Closed-form nodes (regime C, stage 2), one entry per node, structure of arrays.
    std::vector<std::size_t> slot_;
    std::vector<double> closedD0Squared_;
    std::vector<double> u1_, u2_, width_;
    std::vector<unsigned char> clipped1_, clipped2_;
    std::vector<double> g1_, g2_;                   // Gaussians at the ends (stage 3)
    std::vector<double> argument_;                  // |x1|, |x2| of closed-form node c at 2c, 2c + 1
    std::vector<double> numerator_, denominator_;   // erfcScaled(argument_) (stage 4)
    std::vector<std::size_t> byRange_[3];           // argument indices per erfc range
    std::vector<double> ends_;                      // the end terms (stage 5)
    std::vector<std::size_t> twoSided_;             // indices of two-sided closed-form nodes
};

} // namespace dropletFiber
