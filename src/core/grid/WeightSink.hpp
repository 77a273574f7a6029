// WeightSink: where the weights of one parcel on the nodes go (the deposit's steps 5-7,
// docs/model.md sec. 4, eqs. 24-25). ParcelWeights computes them and hands them over in
// the form it has them: a list of weighted nodes (exact kernel, eq. 23), the rows of
// separable tables (wide kernels, P16), or one node at a time (cloud-in-cell). Two kinds of
// sink take them: the step's node values (StepValues.hpp: the deposit adds the parcel's
// quantities times each weight) and the sums of depletion (DepositedShare.hpp: weight times
// a fraction per node, the same weights to the bit). The calls are per parcel, except add().
#pragma once

#include "grid/GridSpec.hpp"
#include "grid/SeparableWeight.hpp"
#include "grid/StepStatistics.hpp"

#include <cstddef>
#include <utility>
#include <vector>

namespace dropletFiber
{

class SparseNodeValues;

// Weighted nodes of one parcel: (global flat node index, omega > 0), in node order.
using NodeOmegas = std::vector<std::pair<std::size_t, double>>;

class WeightSink
{
public:
    explicit WeightSink(StepStatistics& statistics) : statistics_(statistics) {}
    virtual ~WeightSink() = default;
    WeightSink(const WeightSink&) = delete;
    WeightSink& operator=(const WeightSink&) = delete;

    // The statistics the parcel's weighing is booked in (nodes visited and weighted, ...).
    StepStatistics& statistics() { return statistics_; }
    // True for the deposit itself (the separable tables may then be kept for the removal).
    virtual bool accumulates() const { return false; }
    // The fractions of a sparse sink (the kept tables are looked up for it), else nullptr.
    virtual const SparseNodeValues* sparse() const { return nullptr; }
    // False when no node of the box (grid indices) can matter: the weights are then not
    // evaluated.
    virtual bool wants(const IndexBox& /*box*/) const { return true; }

    // The nodes listed (node order; inside box) with weights omega * inverseSum.
    virtual void addListed(const NodeOmegas& nodes, double inverseSum, const IndexBox& box) = 0;
    // Every node of the (folded) box with weight omega * inverseSum, omega from the rows of
    // `rows` or, the same values, from `tables` (a kept copy where the removal found one).
    virtual void addSeparable(SeparableWeight& rows, const SeparableTables& tables, double inverseSum,
                              const IndexBox& box)
        = 0;
    // Cloud-in-cell: the weights that follow (add) lie in box.
    virtual void beginCells(const IndexBox& /*box*/) {}
    // One node's weight (global flat node index).
    virtual void add(std::size_t node, double weight) = 0;

private:
    StepStatistics& statistics_;
};

} // namespace dropletFiber
