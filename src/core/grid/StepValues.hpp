// StepValues: the values one time step's deposits add up on the nodes a block of the grid
// stores (the step accumulator, docs/model.md sec. 4, eq. 25 per step before eq. 26's
// average): per node the seven quantities of GridQuantities.hpp, w f times the parcel's
// mass, droplet count, count*radius, mass*radius and mass*velocity. It adds the weights a
// WeightSink receives (StepDeposit, the deposit's sink), keeps the box of nodes the step
// touched, copies boxes out and in for the exchange between blocks (pack / unpack), and
// hands the step to the averaging window at the commit.
//
// The commit gives the filled array to the window as its newest slot when the stored box
// is the owned one (AveragingWindow::pushSwappingUncleared), and takes the evicted slot
// back as the next step's array without clearing it: clearing its box at the commit
// (about the whole grid, 4.8 MB, in the spray3D case) brings every line of it into the
// caches, and the next step's deposits bring them in again; a row zeroed just before a
// deposit's first write into it is brought in once. dirty_ (storage indices) holds the
// evicted step's values; rowPending_ (per storage row, storageRow) marks its rows whose
// dirty part is not yet zeroed. Every write into the array zeroes its row first (the
// separable rows one by one, the other paths over the rows of the parcel's box, unpack
// over its box), every read too, and the commit the rows no deposit reached: the array
// holds to the bit what clearing the slot at once gave. Empty (no pending row) for blocks
// whose storage is not the owned box (they copy the step into the window).
//
// Memory: nQuantities = 7 doubles (56 bytes) per stored node.
#pragma once

#include "grid/AveragingWindow.hpp"
#include "grid/GridQuantities.hpp"
#include "grid/GridSpec.hpp"
#include "grid/WeightSink.hpp"

#include <array>
#include <cstddef>
#include <vector>

namespace dropletFiber
{

// A parcel's quantities on the grid (parcelTotals, ParcelPath.hpp).
using ParcelTotals = std::array<double, nQuantities>;

class StepValues
{
public:
    // gridNodes: the grid's node counts; storage: the nodes stored (grid indices).
    StepValues(const std::array<int, 3>& gridNodes, const IndexBox& storage);

    const IndexBox& storageBox() const { return storage_; }
    // True when some node of the box (grid indices) is stored here: a deposit whose nodes
    // all lie in other blocks adds nothing here, and is not evaluated (StepDeposit::wants).
    bool storesAnyOf(const IndexBox& box) const { return !box.intersected(storage_).empty(); }
    // The stored nodes the step touched (grid indices).
    const IndexBox& touchedBox() const { return stepBox_; }
    // The array's pages of the nodes of `box` (grid indices) resident, values kept.
    void makeResident(const IndexBox& box) { makeBoxResident(step_, storage_, box, nQuantities); }
    // storageBox().nodeCount() * nQuantities doubles over the storage box (flatIndexInBox),
    // zero outside touchedBox(); the pending rows cleared first.
    NodeValueArray& values()
    {
        clearPendingRows();
        return step_;
    }
    const NodeValueArray& values() const
    {
        clearPendingRows();
        return step_;
    }

    // --- the deposit's weights (StepDeposit) ---------------------------------------------
    // The weights that follow lie in box: its pending rows are cleared, the touched box grows.
    void prepare(const IndexBox& box)
    {
        clearPendingRowsOf(box);
        touch(box);
    }
    // One node's weight times the parcel's quantities (nothing for a node not stored here:
    // another block deposits the parcel there).
    void add(std::size_t node, double weight, const ParcelTotals& totals)
    {
        double* values = valuesOf(node);
        if (values == nullptr)
        {
            return;
        }
        for (int q = 0; q < nQuantities; ++q)
        {
            values[q] += weight * totals[static_cast<std::size_t>(q)];
        }
    }
    // The listed nodes (inside box) with weights omega * inverseSum.
    void addListed(const NodeOmegas& nodes, double inverseSum, const ParcelTotals& totals,
                   const IndexBox& box);
    // The stored part of the box row by row from the separable rows, times inverseSum,
    // into contiguous values (evaluation and accumulation fused). inLanes: AVX2 + FMA
    // adding (SeparableLanes). Returns the nodes weighted.
    std::size_t addSeparable(SeparableWeight& rows, double inverseSum, const ParcelTotals& totals,
                             const IndexBox& box, bool inLanes);

    // --- the exchange between blocks -----------------------------------------------------
    // Copies the box's values (nQuantities per node, i fastest; the box inside the storage
    // box) into values[0 .. box.nodeCount() * nQuantities).
    void pack(const IndexBox& box, double* values) const;
    // ...and back: overwrites the box; the touched box grows by it.
    void unpack(const IndexBox& box, const double* values, std::size_t count);

    // Ends the step: its owned part enters the window and the array is cleared (lazily
    // where it becomes the evicted slot).
    void commitTo(AveragingWindow& window, const IndexBox& owned);

private:
    // The step values of a node (global flat index); nullptr when not stored here.
    double* valuesOf(std::size_t node)
    {
        // Inline for the whole grid (a serial run): one call per weighted node
        return storesWholeGrid_ ? step_.data() + node * nQuantities : valuesOfBlockNode(node);
    }
    double* valuesOfBlockNode(std::size_t node);
    // addSeparable's rows in AVX2 + FMA, runs of a layer's rows of the stored part of the box.
    void addSeparableInLanes(SeparableWeight& rows, double inverseSum, const ParcelTotals& totals,
                             const IndexBox& box, const IndexBox& stored, std::size_t rowAhead);
    void touch(const IndexBox& box) { stepBox_ = stepBox_.united(box.intersected(storage_)); }
    // A storage row's index: j + ny k (storage indices).
    std::size_t storageRow(int j, int k) const
    {
        return static_cast<std::size_t>(j)
            + static_cast<std::size_t>(storage_.hi[1] - storage_.lo[1] + 1) * static_cast<std::size_t>(k);
    }
    // Zeroes the dirty part of a pending row (storageRow) and marks it cleared.
    void zeroPendingRow(std::size_t row) const;
    // Zeroes the pending rows that meet the box (grid indices): before writing into it.
    void clearPendingRowsOf(const IndexBox& box) const;
    // Zeroes every pending row: the array then holds the step's values only.
    void clearPendingRows() const;
    // The evicted slot that became the array holds its values in `dirty` (grid indices):
    // every row of it pending.
    void markDirty(const IndexBox& dirty);

    // Rows ahead in addSeparable whose values are prefetched (wideKernelBench, 0.5 mm
    // grid: 1 row 1.1-1.6x, 2 rows 1.2-2.1x faster than none; 4 rows within 5 % of 2).
    static constexpr std::size_t rowsAhead = 2;
    // Nodes ahead in addListed's list whose values are prefetched.
    static constexpr std::size_t prefetchDistance = 32;

    std::array<int, 3> gridNodes_;
    IndexBox storage_;
    bool storesWholeGrid_; // flat node index = storage index
    // mutable: the lazy clearing gives the same values, so const readers may clear first
    mutable NodeValueArray step_;
    IndexBox stepBox_;
    mutable IndexBox dirty_;
    mutable std::vector<unsigned char> rowPending_;
};

// The deposit's sink: the parcel's quantities times each weight into the step values.
class StepDeposit final : public WeightSink
{
public:
    StepDeposit(StepValues& values, const ParcelTotals& totals, bool inLanes, StepStatistics& statistics)
        : WeightSink(statistics), values_(values), totals_(totals), inLanes_(inLanes)
    {
    }
    bool accumulates() const override { return true; }
    // A parcel held here whose deposit reaches other blocks only (balanced blocks: the
    // spray's nodes owned elsewhere): its copies are deposited there, its statistics and
    // deposit log kept here, and its weights not evaluated here (docs/scaleOut.md).
    bool wants(const IndexBox& box) const override { return values_.storesAnyOf(box); }
    void addListed(const NodeOmegas& nodes, double inverseSum, const IndexBox& box) override;
    void addSeparable(SeparableWeight& rows, const SeparableTables& tables, double inverseSum,
                      const IndexBox& box) override;
    void beginCells(const IndexBox& box) override { values_.prepare(box); }
    void add(std::size_t node, double weight) override { values_.add(node, weight, totals_); }

private:
    StepValues& values_;
    const ParcelTotals& totals_;
    bool inLanes_;
};

} // namespace dropletFiber
