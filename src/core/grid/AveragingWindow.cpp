#include "grid/AveragingWindow.hpp"
#include "grid/WindowTransfer.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace dropletFiber
{

namespace
{
constexpr std::int64_t formatVersion = 1;      // the whole grid
constexpr std::int64_t blockFormatVersion = 2; // a block of it: its box after the header


[[noreturn]] void failRestart(const std::string& what)
{
    throw std::invalid_argument("averaging window restart: " + what);
}
} // namespace

bool AveragingWindow::boxHolds(const IndexBox& box, std::size_t node) const
{
    const std::array<int, 3> index = nodeIndicesOfFlat(nodes_, node);
    return box.holds(index[0], index[1], index[2]);
}

AveragingWindow::AveragingWindow(const std::array<int, 3>& nodes, int nQuantities, int length)
    : AveragingWindow(nodes, wholeBox(nodes), nQuantities, length)
{
}

AveragingWindow::AveragingWindow(const std::array<int, 3>& gridNodes, const IndexBox& region, int nQuantities,
                                 int length)
    : gridNodes_(gridNodes), region_(region), nodes_(region.extents()), nQuantities_(nQuantities),
      length_(length)
{
    if (length < 1)
    {
        throw std::invalid_argument("averaging window: length must be at least 1 step, got "
                                    + std::to_string(length));
    }
    if (region.empty() || region.intersected(wholeBox(gridNodes)) != region)
    {
        throw std::invalid_argument("averaging window: region " + boxText(region)
                                    + " is not a block of the grid");
    }
    const std::size_t size = region.nodeCount() * static_cast<std::size_t>(nQuantities);
    slots_.resize(static_cast<std::size_t>(length));
    slotBoxes_.resize(static_cast<std::size_t>(length));
    total_ = zeroedNodeValues(size);
    summedAt_.assign(size / static_cast<std::size_t>(nQuantities), -1);
}

bool AveragingWindow::wholeGrid() const
{
    return region_ == wholeBox(gridNodes_);
}

IndexBox AveragingWindow::toRegion(const IndexBox& box) const
{
    if (box.empty())
    {
        return IndexBox{};
    }
    IndexBox local;
    for (int d = 0; d < 3; ++d)
    {
        local.lo[d] = box.lo[d] - region_.lo[d];
        local.hi[d] = box.hi[d] - region_.lo[d];
    }
    return local;
}

IndexBox AveragingWindow::toGrid(const IndexBox& box) const
{
    if (box.empty())
    {
        return IndexBox{};
    }
    IndexBox global;
    for (int d = 0; d < 3; ++d)
    {
        global.lo[d] = box.lo[d] + region_.lo[d];
        global.hi[d] = box.hi[d] + region_.lo[d];
    }
    return global;
}

// Calls f(offset, count) for each contiguous row (fixed j, k) of the box, in values.
template <class F>
void AveragingWindow::forEachBoxRow(const IndexBox& box, F&& f) const
{
    const std::size_t q = static_cast<std::size_t>(nQuantities_);
    forEachRow(box, nodes_, [&](const IndexRow& row) { f(row.first * q, row.length * q); });
}

void AveragingWindow::push(const std::vector<double>& step, const IndexBox& box)
{
    if (step.size() != region_.nodeCount() * static_cast<std::size_t>(nQuantities_))
    {
        throw std::invalid_argument("averaging window: step array has the wrong size");
    }
    push(step.data(), region_, box);
}

void AveragingWindow::checkStepBox(const IndexBox& box, const IndexBox& stepRegion) const
{
    if (!box.empty() && (box.intersected(region_) != box || box.intersected(stepRegion) != box))
    {
        throw std::invalid_argument("averaging window: step box " + boxText(box)
                                    + " outside the window's region " + boxText(region_)
                                    + " or the step array's " + boxText(stepRegion));
    }
}

std::size_t AveragingWindow::takeSlot(IndexBox& evicted)
{
    if (filled_ < length_)
    {
        // Not used since the construction or the restore: empty (allocated on first use).
        const std::size_t slot = slotIndex(filled_);
        ++filled_;
        return slot;
    }
    const std::size_t slot = static_cast<std::size_t>(head_);
    evicted = slotBoxes_[slot];
    head_ = (head_ + 1) % length_;
    return slot;
}

void AveragingWindow::filledSlot(std::size_t slot, const IndexBox& local, const IndexBox& evicted)
{
    slotBoxes_[slot] = local;
    ++committed_;
    staleBox_ = staleBox_.united(evicted.united(local));
}

void AveragingWindow::push(const double* step, const IndexBox& stepRegion, const IndexBox& box)
{
    checkStepBox(box, stepRegion);
    IndexBox evicted;
    const std::size_t slot = takeSlot(evicted);
    NodeValueArray& target = slots_[slot];
    if (target.empty())
    {
        // Not used yet
        target = zeroedNodeValues(total_.size());
    }
    else
    {
        forEachBoxRow(evicted,
                      [&](std::size_t offset, std::size_t count)
                      {
                          std::fill(target.begin() + static_cast<std::ptrdiff_t>(offset),
                                    target.begin() + static_cast<std::ptrdiff_t>(offset + count), 0.0);
                      });
    }
    const std::size_t q = static_cast<std::size_t>(nQuantities_);
    forEachRowIn(box, stepRegion,
                 [&](const IndexRow& row)
                 {
                     const std::size_t to = flatIndexInBox(region_, box.lo[0], row.j + stepRegion.lo[1],
                                                           row.k + stepRegion.lo[2]);
                     std::copy(step + row.first * q, step + (row.first + row.length) * q,
                               target.begin() + static_cast<std::ptrdiff_t>(to * q));
                 });
    filledSlot(slot, toRegion(box), evicted);
}

void AveragingWindow::pushSwappingUncleared(NodeValueArray& step, const IndexBox& box, IndexBox& dirty)
{
    if (step.size() != total_.size())
    {
        throw std::invalid_argument("averaging window: step array has the wrong size");
    }
    checkStepBox(box, region_);
    IndexBox evicted;
    const std::size_t slot = takeSlot(evicted);
    // The slot is zero outside the evicted step's box, or not allocated yet: it becomes
    // the caller's next step array, to be cleared over that box by the caller.
    slots_[slot].swap(step);
    dirty = toGrid(evicted);
    if (step.empty())
    {
        // Not used yet: a new array, zero everywhere
        step = zeroedNodeValues(total_.size());
        dirty = IndexBox{};
    }
    filledSlot(slot, toRegion(box), evicted);
}

double AveragingWindow::newestStepValue(std::size_t node, int q) const
{
    if (filled_ == 0)
    {
        return 0.0;
    }
    // A slot is zero outside its box (push clears the evicted box, pushSwappingUncleared's
    // caller does), so any node reads it.
    const NodeValueArray& newest = slots_[slotIndex(filled_ - 1)];
    return newest[node * static_cast<std::size_t>(nQuantities_) + static_cast<std::size_t>(q)];
}

const NodeValueArray& AveragingWindow::total() const
{
    if (!staleBox_.empty())
    {
        recomputeTotal(staleBox_);
        staleBox_ = IndexBox{};
    }
    return total_;
}

void AveragingWindow::nodeTotal(std::size_t node, double* sums) const
{
    const std::size_t q = static_cast<std::size_t>(nQuantities_);
    const std::size_t offset = node * q;
    double* total = total_.data() + offset;
    if (summedAt_[node] != committed_ && boxHolds(staleBox_, node))
    {
        // The same additions in the same order as recomputeTotal.
        std::fill(total, total + q, 0.0);
        for (int age = 0; age < filled_; ++age)
        {
            const double* slot = slots_[slotIndex(age)].data() + offset;
            for (std::size_t n = 0; n < q; ++n)
            {
                total[n] += slot[n];
            }
        }
        summedAt_[node] = committed_;
    }
    std::copy(total, total + q, sums);
}

void AveragingWindow::prefetchNodeTotal(std::size_t node) const
{
    const std::size_t q = static_cast<std::size_t>(nQuantities_);
    const std::size_t offset = node * q;
    const auto request = [q](const double* values)
    {
        // A node's values may straddle two cache lines
        __builtin_prefetch(values);
        __builtin_prefetch(values + q - 1);
    };
    if (summedAt_[node] == committed_ || !boxHolds(staleBox_, node))
    {
        request(total_.data() + offset);
        return;
    }
    for (int age = 0; age < filled_; ++age)
    {
        request(slots_[slotIndex(age)].data() + offset);
    }
}

void AveragingWindow::recomputeTotal(const IndexBox& box) const
{
    forEachBoxRow(box,
                  [&](std::size_t offset, std::size_t count)
                  {
                      double* total = total_.data() + offset;
                      std::fill(total, total + count, 0.0);
                      // Oldest to newest: the same order in a continuous and a restored run.
                      for (int age = 0; age < filled_; ++age)
                      {
                          const double* slot = slots_[slotIndex(age)].data() + offset;
                          for (std::size_t n = 0; n < count; ++n)
                          {
                              total[n] += slot[n];
                          }
                      }
                  });
}

IndexBox AveragingWindow::box() const
{
    IndexBox result;
    for (int age = 0; age < filled_; ++age)
    {
        result = result.united(slotBoxes_[slotIndex(age)]);
    }
    return result;
}

std::size_t AveragingWindow::savedValueCount() const
{
    std::size_t count = 0;
    for (int age = 0; age < filled_; ++age)
    {
        count += slotBoxes_[slotIndex(age)].nodeCount() * static_cast<std::size_t>(nQuantities_);
    }
    return count;
}

WindowState AveragingWindow::save() const
{
    WindowState state;
    const bool block = !wholeGrid();
    state.counters = {block ? blockFormatVersion : formatVersion,
                      gridNodes_[0],
                      gridNodes_[1],
                      gridNodes_[2],
                      nQuantities_,
                      length_,
                      filled_,
                      committed_};
    if (block)
    {
        state.counters.insert(
            state.counters.end(),
            {region_.lo[0], region_.lo[1], region_.lo[2], region_.hi[0], region_.hi[1], region_.hi[2]});
    }
    state.values.reserve(savedValueCount());
    for (int age = 0; age < filled_; ++age)
    {
        const IndexBox& b = slotBoxes_[slotIndex(age)];
        const IndexBox g = toGrid(b);
        state.counters.insert(state.counters.end(), {g.lo[0], g.lo[1], g.lo[2], g.hi[0], g.hi[1], g.hi[2]});
        appendSlotValues(slotIndex(age), g, state.values);
    }
    return state;
}

void AveragingWindow::appendSlotValues(std::size_t slot, const IndexBox& box,
                                       std::vector<double>& values) const
{
    const std::size_t q = static_cast<std::size_t>(nQuantities_);
    const NodeValueArray& from = slots_[slot];
    forEachRowIn(box, region_,
                 [&](const IndexRow& row)
                 {
                     values.insert(values.end(), from.begin() + static_cast<std::ptrdiff_t>(row.first * q),
                                   from.begin() + static_cast<std::ptrdiff_t>((row.first + row.length) * q));
                 });
}

WindowState AveragingWindow::savePart(const IndexBox& part) const
{
    if (part.empty() || part.intersected(region_) != part)
    {
        throw std::invalid_argument("averaging window: part " + boxText(part) + " outside the region "
                                    + boxText(region_));
    }
    WindowState state;
    state.counters = {blockFormatVersion, gridNodes_[0], gridNodes_[1], gridNodes_[2],
                      nQuantities_,       length_,       filled_,       committed_,
                      part.lo[0],         part.lo[1],    part.lo[2],    part.hi[0],
                      part.hi[1],         part.hi[2]};
    // Reserved: a part is up to a window's size, and growing by doubling would copy and
    // fault it in about twice over
    std::size_t count = 0;
    for (int age = 0; age < filled_; ++age)
    {
        count += toGrid(slotBoxes_[slotIndex(age)]).intersected(part).nodeCount();
    }
    state.values.reserve(count * static_cast<std::size_t>(nQuantities_));
    for (int age = 0; age < filled_; ++age)
    {
        const IndexBox kept = toGrid(slotBoxes_[slotIndex(age)]).intersected(part);
        const IndexBox g = kept.empty() ? IndexBox{} : kept;
        state.counters.insert(state.counters.end(), {g.lo[0], g.lo[1], g.lo[2], g.hi[0], g.hi[1], g.hi[2]});
        appendSlotValues(slotIndex(age), g, state.values);
    }
    return state;
}

std::size_t readWindowStateHeader(const std::vector<std::int64_t>& c, std::int64_t wholeVersion,
                                  std::int64_t blockVersion, const std::array<int, 3>& gridNodes,
                                  int nQuantities, const IndexBox& region, const std::string& context,
                                  IndexBox& saved)
{
    const auto fail
        = [&context](const std::string& what) { throw std::invalid_argument(context + ": " + what); };
    if (c.size() < windowStateHeaderSize || (c[0] != wholeVersion && c[0] != blockVersion))
    {
        fail("unknown format");
    }
    if (c[1] != gridNodes[0] || c[2] != gridNodes[1] || c[3] != gridNodes[2])
    {
        fail("saved for a grid of " + std::to_string(c[1]) + "x" + std::to_string(c[2]) + "x"
             + std::to_string(c[3]) + " nodes, this grid has " + std::to_string(gridNodes[0]) + "x"
             + std::to_string(gridNodes[1]) + "x" + std::to_string(gridNodes[2]));
    }
    if (c[4] != nQuantities)
    {
        fail("different number of quantities per node");
    }
    saved = wholeBox(gridNodes);
    const std::size_t size = c[0] == blockVersion ? windowStateHeaderSize + 6 : windowStateHeaderSize;
    if (c[0] == blockVersion)
    {
        if (c.size() < size)
        {
            fail("unknown format");
        }
        for (std::size_t d = 0; d < 3; ++d)
        {
            saved.lo[d] = static_cast<int>(c[windowStateHeaderSize + d]);
            saved.hi[d] = static_cast<int>(c[windowStateHeaderSize + 3 + d]);
        }
    }
    // A state of a larger region (the whole grid of a serial run, decomposed) gives this
    // window its part; a smaller or another block cannot.
    if (saved.empty() || saved.intersected(region) != region)
    {
        fail("saved for the block " + boxText(saved) + " of the grid's nodes, this window holds "
             + boxText(region));
    }
    return size;
}

std::vector<IndexBox> AveragingWindow::savedSlotBoxes(const WindowState& state) const
{
    IndexBox saved;
    const std::size_t header
        = readWindowStateHeader(state.counters, formatVersion, blockFormatVersion, gridNodes_, nQuantities_,
                                region_, "averaging window restart", saved);
    const std::vector<std::int64_t>& c = state.counters;
    const std::int64_t savedFilled = c[6];
    if (savedFilled < 0 || savedFilled > c[5]
        || c.size() != header + 6 * static_cast<std::size_t>(savedFilled))
    {
        failRestart("inconsistent slot count");
    }
    std::vector<IndexBox> boxes(static_cast<std::size_t>(savedFilled));
    std::size_t expectedValues = 0;
    for (std::size_t s = 0; s < boxes.size(); ++s)
    {
        for (int d = 0; d < 3; ++d)
        {
            boxes[s].lo[d] = static_cast<int>(c[header + 6 * s + static_cast<std::size_t>(d)]);
            boxes[s].hi[d] = static_cast<int>(c[header + 6 * s + 3 + static_cast<std::size_t>(d)]);
        }
        if (!boxes[s].empty() && boxes[s].intersected(saved) != boxes[s])
        {
            failRestart("slot box outside the grid");
        }
        expectedValues += boxes[s].nodeCount() * static_cast<std::size_t>(nQuantities_);
    }
    if (expectedValues != state.values.size())
    {
        failRestart("value count does not match the slot boxes");
    }
    return boxes;
}

void AveragingWindow::restore(const WindowState& state)
{
    // All boxes (in the grid's indices) read and the value count checked before touching
    // this window.
    const std::vector<IndexBox> boxes = savedSlotBoxes(state);

    // Keep the newest min(saved slots, length) steps.
    const std::size_t skip = boxes.size() > static_cast<std::size_t>(length_)
        ? boxes.size() - static_cast<std::size_t>(length_)
        : 0;
    clear(state.counters[7]);
    std::size_t position = 0;
    for (std::size_t s = 0; s < boxes.size(); ++s)
    {
        if (s >= skip)
        {
            NodeValueArray& slot = slots_[static_cast<std::size_t>(filled_)];
            slot = zeroedNodeValues(total_.size());
            const IndexBox kept = boxes[s].intersected(region_);
            copySavedSlot(state.values.data() + position, boxes[s], kept, slot);
            slotBoxes_[static_cast<std::size_t>(filled_)] = kept.empty() ? IndexBox{} : toRegion(kept);
            ++filled_;
        }
        position += boxes[s].nodeCount() * static_cast<std::size_t>(nQuantities_);
    }
    recomputeTotal(box());
}

void AveragingWindow::restoreParts(std::vector<WindowState>& parts)
{
    checkWindowParts(parts, region_);
    const std::vector<std::int64_t>& first = parts.front().counters;
    if (first[1] != gridNodes_[0] || first[2] != gridNodes_[1] || first[3] != gridNodes_[2]
        || first[4] != nQuantities_ || first[6] > length_)
    {
        failRestart("window parts of another grid, quantities or a longer window");
    }
    const std::size_t filled = static_cast<std::size_t>(first[6]);
    // Every slot's box: the union of the parts' (zero between them)
    std::vector<IndexBox> boxes(filled);
    for (const WindowState& part : parts)
    {
        for (std::size_t s = 0; s < filled; ++s)
        {
            boxes[s] = boxes[s].united(windowPartSlotBox(part, s));
        }
    }
    clear(first[7]);
    for (std::size_t s = 0; s < filled; ++s)
    {
        slots_[s] = zeroedNodeValues(total_.size());
        slotBoxes_[s] = boxes[s].empty() ? IndexBox{} : toRegion(boxes[s]);
    }
    filled_ = static_cast<int>(filled);
    for (WindowState& part : parts)
    {
        std::size_t position = 0;
        for (std::size_t s = 0; s < filled; ++s)
        {
            const IndexBox from = windowPartSlotBox(part, s);
            copySavedSlot(part.values.data() + position, from, from, slots_[s]);
            position += from.nodeCount() * static_cast<std::size_t>(nQuantities_);
        }
        part.values.clear();
        part.values.shrink_to_fit();
    }
    recomputeTotal(box());
}

void AveragingWindow::clear(std::int64_t committed)
{
    for (auto& slot : slots_)
    {
        slot.clear();
    }
    std::fill(slotBoxes_.begin(), slotBoxes_.end(), IndexBox{});
    std::fill(total_.begin(), total_.end(), 0.0);
    head_ = 0;
    filled_ = 0;
    committed_ = committed;
    staleBox_ = IndexBox{};
    std::fill(summedAt_.begin(), summedAt_.end(), -1);
}

void AveragingWindow::copySavedSlot(const double* saved, const IndexBox& savedBox, const IndexBox& kept,
                                    NodeValueArray& slot) const
{
    // The saved slot's values cover savedBox (i fastest); this window keeps the part in its
    // region, row by row.
    const std::size_t q = static_cast<std::size_t>(nQuantities_);
    forEachRowIn(
        kept, region_,
        [&](const IndexRow& row)
        {
            const double* from = saved
                + flatIndexInBox(savedBox, kept.lo[0], row.j + region_.lo[1], row.k + region_.lo[2]) * q;
            std::copy(from, from + row.length * q, slot.begin() + static_cast<std::ptrdiff_t>(row.first * q));
        });
}

void AveragingWindow::makeResident(const IndexBox& box)
{
    const std::size_t q = static_cast<std::size_t>(nQuantities_);
    for (std::size_t s = 0; s < slots_.size(); ++s)
    {
        if (!slots_[s].empty())
        {
            makeBoxResident(slots_[s], region_, box, q);
        }
    }
    makeBoxResident(total_, region_, box, q);
}

void AveragingWindow::releasePages(const IndexBox& box)
{
    const std::size_t q = static_cast<std::size_t>(nQuantities_);
    for (std::size_t s = 0; s < slots_.size(); ++s)
    {
        if (!slots_[s].empty())
        {
            releaseBoxPages(slots_[s], region_, box, q);
        }
    }
    releaseBoxPages(total_, region_, box, q);
}

} // namespace dropletFiber
