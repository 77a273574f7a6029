// AveragingWindow: the per-node sums of the last W committed time steps (the averaging
// window [t_min, t_max] of eq. 26), and their total.
//
// Storage: a ring of W slots, each a full per-node array (GridQuantities layout), filled
// as steps are committed (a slot is allocated when first used, its pages zero until
// touched: NodeValueArray), plus the window total.
// Memory: (filled slots + 1) * nodes * nQuantities * 8 bytes, e.g. 56 bytes per node
// and slot for the 7 quantities. Every slot is zero outside its step's box.
//
// Committing a step: push() copies the step's box into the slot (after clearing the
// evicted step's box there). pushSwappingUncleared() takes the caller's step array itself
// as the slot (std::vector::swap) and hands back the evicted slot as the caller's next
// step array, NOT cleared, with the box where it may be non-zero: no copy, and the caller
// clears that box as it goes. A step of wide kernels touches about the whole grid
// (bench/spray3D: 85,000 nodes, 4.8 MB per step): clearing it here would send it through
// the caches once more, while the caller clears each row as its first deposit brings it
// into cache (DensityGrid, storage box = owned box).
//
// Exact, drift-free total: instead of a running sum with add-new/subtract-oldest (whose
// round-off residue leaves small negative masses in empty regions and would make a
// restarted run differ from a continuous one), the total is the sum of the slots, oldest
// to newest, recomputed over the index boxes touched by the new and by the evicted steps
// (outside them both steps are zero, so the total there is unchanged). So the total is
// always, bit for bit, the chronological sum of the slots, and a restored window
// reproduces it exactly.
//
// Lazily: push() only marks those boxes stale. total() brings the whole array up to
// date (cost: |stale box| * nQuantities * W, paid by output at write times), while
// nodeTotal() sums the slots of one node in the same order (bit-identical to total()),
// so the per-step sampling along the fibers does not pay for the whole box every step.
// nodeTotal() keeps what it summed (in the total array, stamped with the step count):
// the collision samples of one step share most of their nodes (neighbouring samples of
// a fiber, 1-4 corners each), and each node's W slots are far apart in memory.
//
// Region: a window may hold a block of the grid only (the nodes a processor owns,
// DensityGrid's owned box): node indices of nodeTotal() are those of the block
// (flatIndexInBox), and the boxes given to push() are in the grid's indices. The whole
// grid is the default.
#pragma once

#include "grid/GridSpec.hpp"
#include "grid/NodeValueArray.hpp"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace dropletFiber
{

// Restart state of a window, flat (to be written by the caller in any format). These
// node values (formats 1 and 2) are what a window holds; DensityGrid saves its window as
// the parcels deposited in its steps instead (DepositLog.hpp, formats 3 and 4: far
// smaller where kernels touch many nodes) unless a step was not deposited:

//   counters = {format version 1, nx, ny, nz, nQuantities, window length, filled slots,
//               committed steps, then per filled slot, oldest first: lo x y z, hi x y z}
//   values   = per filled slot, oldest first, that slot's box, nQuantities per node,
//              i fastest (only the touched box is stored).
// A window of a block (not the whole grid) writes format version 2: the same, with the
// block's lo x y z, hi x y z after the committed steps; slot boxes in grid indices.
// It restores a state of the same block, or of a block holding it (the whole grid of a
// serial run decomposed onto processors: each keeps its part).
struct WindowState
{
    std::vector<std::int64_t> counters;
    std::vector<double> values;
};

// The header both restart formats of a window begin with (AveragingWindow's node values,
// DepositLog's parcels): {format version, nx, ny, nz, nQuantities, length, filled steps,
// committed steps}, in the block version followed by the saved block's lo x y z hi x y z.
constexpr std::size_t windowStateHeaderSize = 8;
// That header checked against a grid of gridNodes nodes, nQuantities and a window over
// `region` (the saved block must hold it: the same block, or the whole grid of a serial
// run); `saved`: the saved block. Returns the counters' length up to the per-step entries.
// Throws std::invalid_argument, its message starting with `context`.
std::size_t readWindowStateHeader(const std::vector<std::int64_t>& counters, std::int64_t wholeVersion,
                                  std::int64_t blockVersion, const std::array<int, 3>& gridNodes,
                                  int nQuantities, const IndexBox& region, const std::string& context,
                                  IndexBox& saved);

class AveragingWindow
{
public:
    AveragingWindow(const std::array<int, 3>& nodes, int nQuantities, int length);
    // A window of the nodes of `region` (a non-empty box of the grid of gridNodes nodes).
    AveragingWindow(const std::array<int, 3>& gridNodes, const IndexBox& region, int nQuantities, int length);

    // Commit one step: `step` is a full per-node array that is zero outside `box`.
    void push(const std::vector<double>& step, const IndexBox& box);
    // The same from an array laid out over stepRegion (which holds box; box within
    // region()): the block's part of a larger step array.
    void push(const double* step, const IndexBox& stepRegion, const IndexBox& box);
    // The same as push(step, box) without copying: `step` (laid out over region(), zero
    // outside box) becomes the newest slot, and the caller gets back in `step` an array
    // of the same size (the evicted slot; a new one, all zero, while the window fills)
    // that is zero outside `dirty` (grid indices; empty: zero everywhere) and holds the
    // evicted step's values inside it: the caller zeroes that box before it accumulates
    // the next step there, and before it pushes the array again.
    void pushSwappingUncleared(NodeValueArray& step, const IndexBox& box, IndexBox& dirty);
    // The block of the grid this window holds (grid indices).
    const IndexBox& region() const { return region_; }
    // The pages of the nodes of `box` (grid indices; the part in the region) resident
    // in every allocated slot and the total, values kept (makeBoxResident).
    void makeResident(const IndexBox& box);
    // The pages wholly inside the rows of `box` given back in every slot and the total:
    // their values become zero (the slots' boxes are kept): for a window whose part in
    // box was saved (savePart) and that is to be discarded.
    void releasePages(const IndexBox& box);

    // The window total of every node of the region, laid out over it (brings the stale box
    // up to date first).
    const NodeValueArray& total() const;
    // The window total of one node (index in the region), nQuantities values into `sums`
    // (no full update).
    void nodeTotal(std::size_t node, double* sums) const;
    // Requests the memory nodeTotal(node) will read (its W slots' values when they are to
    // be summed), so that the reads of several nodes overlap instead of waiting for each
    // cache miss in turn: the collision's sample corners are scattered over slots of
    // megabytes. No effect on any value.
    void prefetchNodeTotal(std::size_t node) const;
    // Quantity q of the newest committed step at a node of the region (0 before any).
    double newestStepValue(std::size_t node, int q) const;
    int length() const { return length_; }
    int filled() const { return filled_; } // steps in the window, <= length
    std::int64_t committedSteps() const { return committed_; }
    // Union of the boxes of the steps in the window (where total can be non-zero), in the
    // region's indices.
    IndexBox box() const;

    WindowState save() const;
    // The part of save() over `part` (grid indices, inside region()): format 2 with `part`
    // as the block, each slot's box cut to it. Moving nodes to another window (grid blocks
    // re-partitioned): the parts of the old blocks joined (joinedWindowState) restore the
    // new block's window with the same slots and total, bit for bit.
    WindowState savePart(const IndexBox& part) const;
    // The number of values save() gives (the filled slots' boxes).
    std::size_t savedValueCount() const;
    // Throws std::invalid_argument when the state does not fit this grid. A state saved
    // with a different window length is accepted: the newest min(filled, length) steps
    // are kept.
    void restore(const WindowState& state);
    // restore(joinedWindowState(parts, region())) without the joined state: each part's
    // slot values copied straight into the slots, and the part freed (its values emptied)
    // once copied; the same slots, boxes and total, bit for bit. The parts as for
    // joinedWindowState (WindowTransfer.hpp; throws std::invalid_argument before this
    // window changes), a window length of at least theirs.
    void restoreParts(std::vector<WindowState>& parts);
    // Empties the window (no step in it), with `committed` steps counted as committed
    // before (a replay of the steps that follow rebuilds the rest: DepositLog).
    void clear(std::int64_t committed);

private:
    std::size_t slotIndex(int age) const { return static_cast<std::size_t>((head_ + age) % length_); }
    void recomputeTotal(const IndexBox& box) const;
    // The slot's values of the nodes of box (grid indices, inside the region) appended, i
    // fastest.
    void appendSlotValues(std::size_t slot, const IndexBox& box, std::vector<double>& values) const;
    // push(): throws unless box (grid indices) lies in region() and in stepRegion.
    void checkStepBox(const IndexBox& box, const IndexBox& stepRegion) const;
    // The slot the next step goes to: the next unused one while the window fills (not
    // allocated), else the oldest, whose box (region indices) is returned in `evicted`:
    // every slot is zero outside its box, so the slot is zero outside `evicted`.
    std::size_t takeSlot(IndexBox& evicted);
    // The step in `slot` covers `local` (region indices): counts it and marks the boxes
    // whose total changed stale.
    void filledSlot(std::size_t slot, const IndexBox& local, const IndexBox& evicted);
    // The slot boxes of a saved state, checked against this grid and the state's value
    // count; throws std::invalid_argument naming what does not fit.
    std::vector<IndexBox> savedSlotBoxes(const WindowState& state) const;
    // The part `kept` of a saved slot whose values cover savedBox, into slot (this region).
    void copySavedSlot(const double* saved, const IndexBox& savedBox, const IndexBox& kept,
                       NodeValueArray& slot) const;
    bool boxHolds(const IndexBox& box, std::size_t node) const;
    template <class F>
    void forEachBoxRow(const IndexBox& box, F&& f) const;

    // Slot boxes, lo and hi of the region: grid indices <-> indices in the region
    IndexBox toRegion(const IndexBox& box) const;
    IndexBox toGrid(const IndexBox& box) const;
    bool wholeGrid() const;

    std::array<int, 3> gridNodes_;
    IndexBox region_;
    std::array<int, 3> nodes_; // of the region (its node indices: flatIndexInBox)
    int nQuantities_;
    int length_;
    std::vector<NodeValueArray> slots_;
    std::vector<IndexBox> slotBoxes_;
    int head_ = 0; // slot of the oldest step
    int filled_ = 0;
    std::int64_t committed_ = 0;
    // total_ is a cache of the slots' sum, valid outside staleBox_, and inside it at the
    // nodes whose summedAt_ equals committed_ (summed by nodeTotal since the last push).
    mutable NodeValueArray total_;
    mutable IndexBox staleBox_;
    mutable std::vector<std::int64_t> summedAt_;
};

} // namespace dropletFiber
