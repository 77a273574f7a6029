// DepositedShare: the sinks of the deposit's weights re-evaluated for depletion
// (docs/model.md sec. 7; DensityGrid::depositedShare): one parcel's weights w_n f (eq. 24,
// folded, or cloud-in-cell, times the part f of the step inside the box) summed with a
// fraction per node, sum_n w_n f_n, instead of being added to the grid. The weights come
// from the deposit's own code (ParcelWeights), so they are the deposit's to the bit.
//   FractionSum: a fraction for any node (a function of the node), over the nodes of a region.
//   SparseFractionSum: the fractions of a few nodes (SparseNodeValues, 0 elsewhere), visiting
//     those nodes only; the sum skips only terms that are 0 and adds the others in the
//     same order, so it equals FractionSum's to the bit. It can also keep the parcel's
//     weight at each of those nodes (NodeWeight: the per-parcel removal of depletion
//     attributes a parcel's loss to the nodes by them).
#pragma once

#include "grid/SparseNodeValues.hpp"
#include "grid/WeightSink.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace dropletFiber
{

// A value per global flat node index.
using NodeFraction = std::function<double(std::size_t)>;
// True when a box of nodes (grid indices) may hold a node whose fraction is not 0.
using NodeBoxTest = std::function<bool(const IndexBox&)>;

// A parcel's deposit weight w_n f at one of a SparseNodeValues' nodes (its place in nodes()).
struct NodeWeight
{
    std::uint32_t position = 0;
    double weight = 0.0;
};

class FractionSum final : public WeightSink
{
public:
    // region: holds every node whose fraction may be non-zero (separable weights are
    // evaluated there only). gridNodes: the grid's node counts.
    FractionSum(StepStatistics& statistics, const NodeBoxTest& asks, const NodeFraction& fraction,
                const IndexBox& region, const std::array<int, 3>& gridNodes)
        : WeightSink(statistics), asks_(asks), fraction_(fraction), region_(region), gridNodes_(gridNodes)
    {
    }
    double sum() const { return sum_; }

    bool wants(const IndexBox& box) const override { return !box.empty() && asks_(box); }
    void addListed(const NodeOmegas& nodes, double inverseSum, const IndexBox& box) override;
    void addSeparable(SeparableWeight& rows, const SeparableTables& tables, double inverseSum,
                      const IndexBox& box) override;
    void add(std::size_t node, double weight) override { sum_ += weight * fraction_(node); }

private:
    const NodeBoxTest& asks_;
    const NodeFraction& fraction_;
    IndexBox region_;
    std::array<int, 3> gridNodes_;
    double sum_ = 0.0;
};

class SparseFractionSum final : public WeightSink
{
public:
    SparseFractionSum(StepStatistics& statistics, const NodeBoxTest& asks, const SparseNodeValues& fractions,
                      const std::array<int, 3>& gridNodes)
        : WeightSink(statistics), asks_(asks), fractions_(fractions), gridNodes_(gridNodes)
    {
    }
    double sum() const { return sum_; }
    // From now on each weight added is also appended to weights (node by node, in the order
    // added; a node reached twice through the grid's folds appears twice).
    void keepWeights(std::vector<NodeWeight>* weights) { weights_ = weights; }

    const SparseNodeValues* sparse() const override { return &fractions_; }
    bool wants(const IndexBox& box) const override { return !box.empty() && asks_(box); }
    // The listed nodes merged with the sink's (both in node order).
    void addListed(const NodeOmegas& nodes, double inverseSum, const IndexBox& box) override;
    // omega at the sink's nodes inside the box only, from the tables.
    void addSeparable(SeparableWeight& rows, const SeparableTables& tables, double inverseSum,
                      const IndexBox& box) override;
    void add(std::size_t node, double weight) override;

private:
    void keep(std::size_t position, double weight)
    {
        if (weights_ != nullptr)
        {
            weights_->push_back(NodeWeight{static_cast<std::uint32_t>(position), weight});
        }
    }
    const NodeBoxTest& asks_;
    const SparseNodeValues& fractions_;
    std::vector<NodeWeight>* weights_ = nullptr;
    std::array<int, 3> gridNodes_;
    double sum_ = 0.0;
};

} // namespace dropletFiber
