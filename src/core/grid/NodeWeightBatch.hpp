// NodeWeightBatch: PathWeight::omegaFromOffset for all nodes of one parcel's box, with the
// nodes sorted by regime first, so that each regime runs as its own loop.
//
// Why: per weighted node the one-node code spends about a third of its time in
// mispredicted branches (docs/performance.md, "Roofline and profile": which side of the
// closest point the path lies on, whether its ends are within reach, the range of each
// scaled erfc). Those choices depend on the node's geometry and change from node to node
// without a pattern the predictor learns. Here they are made once per node with selects
// and the node is appended to the list of its class (compaction without branches); the
// loops over one class then have no data-dependent branch left (one-sided closed form,
// two-sided closed form, each erfc range).
//
// Exactness: the same formulas as PathWeight, in the same order of operations, so the
// weights are bit-identical to omegaFromOffset (NodeWeightBatchTest checks it node by
// node). The rare regimes (edge quadrature, Taylor series: ~1 node per parcel) and
// stationary parcels call PathWeight itself.
//
// Use: start(path, nodeCount), add(offset) per node in any order (slot = order of add),
// then evaluate(): omega per slot (0 for nodes out of reach). No allocation once the
// scratch has grown to the largest box.
#pragma once

#include "grid/PathWeight.hpp"

#include <Eigen/Core>

#include <cmath>
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
    // A row of nodes at offsets (x[i] - startX, offsetY, offsetZ), i < count (the grid
    // loop: one call per row, the per-node work inlined).
    void addRow(const double* x, std::size_t count, double startX, double offsetY, double offsetZ);

    // Weights of the added nodes by slot; valid until the next start().
    const double* evaluate();

private:
    // Closed-form node (regime C of PathWeight::integralAlongPath). One-sided: the two erfc
    // arguments are the near and the far end; two-sided: start (-x1) and end (x2).
    struct ClosedFormNode
    {
        std::size_t slot;
        double d0Squared;
        double uFirst;  // offset from lambdaM of the near end (one-sided) or the start
        double uSecond; // of the far end (one-sided) or the end
        double width;   // lambda2 - lambda1
        double xFirst;  // erfc argument of the first end: x_near (one-sided) or -x1
        double xSecond; // of the second: x_far (one-sided) or x2
        bool clippedFirst;
        bool clippedSecond;
    };
    struct RareNode
    {
        std::size_t slot;
        double lambdaM;
        double d0Squared;
    };

    // The path's constants and the list ends in locals (registers), not members that
    // every store through a list pointer could alias.
    struct Cursor
    {
        Eigen::Vector3d direction;
        double gamma, length, reachSquared, cutoffSquared, sqrtGamma;
        double* omega;
        ClosedFormNode* oneSided;
        ClosedFormNode* twoSided;
        RareNode* rare;
    };
    Cursor cursor() const;
    void store(const Cursor& c);
    static void classify(Cursor& cur, std::size_t slot, const Eigen::Vector3d& offset); // branch-free
    void evaluateScaledErfc(std::size_t count);

    const PathWeight* path_ = nullptr;
    std::size_t added_ = 0;
    std::size_t oneSidedCount_ = 0;
    std::size_t twoSidedCount_ = 0;
    std::size_t rareCount_ = 0;
    std::vector<double> omega_;              // by slot
    std::vector<ClosedFormNode> oneSided_;
    std::vector<ClosedFormNode> twoSided_;
    std::vector<RareNode> rare_;
    std::vector<double> argument_;           // erfc arguments: 2 per closed-form node
    std::vector<double> numerator_;          // erfcScaled(argument_) as a fraction
    std::vector<double> denominator_;
    std::vector<std::size_t> byRange_[3];    // argument indices per erfc range
};

} // namespace dropletFiber
