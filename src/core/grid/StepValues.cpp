#include "grid/StepValues.hpp"

#include "grid/SeparableLanes.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace dropletFiber
{

namespace
{

// A row of nodes with contiguous values: node i gets weight omega[i] inverseSum times the
// parcel's quantities. inLanes: four nodes' 28 values at a time in AVX2 + FMA registers
// (SeparableLanes). Otherwise two nodes at a time as 14 consecutive values (whole vector
// registers, 7 pairs, where one node's 7 values leave one over), each value the same
// product and sum as node by node.
void addWeightedRow(const double* omega, std::size_t length, double inverseSum, const ParcelTotals& totals,
                    double* values, bool inLanes)
{
    static_assert(SeparableLanes::quantities == nQuantities, "SeparableLanes adds 7 values per node");
    if (inLanes)
    {
        SeparableLanes::addWeightedRow(omega, length, inverseSum, totals.data(), values);
        return;
    }
    constexpr std::size_t pair = 2 * nQuantities;
    std::array<double, pair> pairTotals{};
    for (std::size_t m = 0; m < pair; ++m)
    {
        pairTotals[m] = totals[m % nQuantities];
    }
    std::size_t i = 0;
    for (; i + 1 < length; i += 2, values += pair)
    {
        const double first = omega[i] * inverseSum;
        const double second = omega[i + 1] * inverseSum;
        std::array<double, pair> weight{};
        for (std::size_t m = 0; m < pair; ++m)
        {
            weight[m] = m < nQuantities ? first : second;
        }
        for (std::size_t m = 0; m < pair; ++m)
        {
            values[m] += weight[m] * pairTotals[m];
        }
    }
    if (i < length)
    {
        const double weight = omega[i] * inverseSum;
        for (std::size_t q = 0; q < nQuantities; ++q)
        {
            values[q] += weight * totals[q];
        }
    }
}

// Requests the cache lines of a row of `length` nodes' values (for writing), where they
// exist; a hint only, without effect on the values.
void prefetchRow(const double* values, std::size_t length)
{
    constexpr std::size_t valuesPerLine = 8; // 64-byte cache lines
    for (std::size_t m = 0; m < length * nQuantities; m += valuesPerLine)
    {
        __builtin_prefetch(values + m, 1);
    }
}

void checkStored(const IndexBox& box, const IndexBox& storage, const char* what)
{
    if (!box.empty() && box.intersected(storage) != box)
    {
        throw std::invalid_argument(std::string("DensityGrid::") + what + ": box outside the nodes stored");
    }
}

} // namespace

StepValues::StepValues(const std::array<int, 3>& gridNodes, const IndexBox& storage)
    : gridNodes_(gridNodes), storage_(storage), storesWholeGrid_(storage == wholeBox(gridNodes))
{
    step_ = zeroedNodeValues(storage_.nodeCount() * nQuantities);
    rowPending_.assign(storage_.empty() ? 0 : storageRow(0, storage_.hi[2] - storage_.lo[2] + 1), 0);
}

double* StepValues::valuesOfBlockNode(std::size_t node)
{
    const std::array<int, 3> n = nodeIndicesOfFlat(gridNodes_, node);
    return storage_.holds(n[0], n[1], n[2])
        ? step_.data() + flatIndexInBox(storage_, n[0], n[1], n[2]) * nQuantities
        : nullptr;
}

void StepValues::addListed(const NodeOmegas& nodes, double inverseSum, const ParcelTotals& totals,
                           const IndexBox& box)
{
    clearPendingRowsOf(box); // the weighted nodes lie inside it
    if (storesWholeGrid_)
    {
        // Serial runs: the nodes' values straight from the array, each node's cache lines
        // requested prefetchDistance nodes ahead (wide kernels touch thousands of nodes per
        // parcel, mostly not in cache: the deposit's floor, docs/performance.md).
        const std::size_t count = nodes.size();
        for (std::size_t n = 0; n < count; ++n)
        {
            if (n + prefetchDistance < count)
            {
                const double* ahead = step_.data() + nodes[n + prefetchDistance].first * nQuantities;
                __builtin_prefetch(ahead, 1);
                __builtin_prefetch(ahead + nQuantities - 1, 1);
            }
            double* values = step_.data() + nodes[n].first * nQuantities;
            const double weight = nodes[n].second * inverseSum;
            for (int q = 0; q < nQuantities; ++q)
            {
                values[q] += weight * totals[static_cast<std::size_t>(q)];
            }
        }
    }
    else
    {
        for (const auto& [node, omega] : nodes)
        {
            add(node, omega * inverseSum, totals);
        }
    }
    touch(box);
}

std::size_t StepValues::addSeparable(SeparableWeight& rows, double inverseSum, const ParcelTotals& totals,
                                     const IndexBox& box, bool inLanes)
{
    // The stored part of the box only: no node list, no per-node index arithmetic (a block
    // evaluates only its part of a copy).
    const IndexBox stored = box.intersected(storage_);
    const auto first = static_cast<std::size_t>(stored.lo[0] - box.lo[0]);
    // The values of the row rowsAhead further in j (the next layer's at a layer's end: a
    // wasted request), requested while this one is added: rows of a few dozen nodes are too
    // short for the hardware's prefetcher, on grids beyond the caches.
    const std::size_t rowAhead
        = rowsAhead * static_cast<std::size_t>(storage_.hi[0] - storage_.lo[0] + 1) * nQuantities;
    if (inLanes && rows.vectorised() && !stored.empty())
    {
        addSeparableInLanes(rows, inverseSum, totals, box, stored, rowAhead);
        touch(box);
        return stored.nodeCount();
    }
    forEachRowIn(stored, storage_,
                 [&](const IndexRow& row)
                 {
                     const int j = row.j + storage_.lo[1] - box.lo[1];
                     const int k = row.k + storage_.lo[2] - box.lo[2];
                     // First write into the row this step: the evicted step's values go
                     // (the row is being brought into cache by this parcel anyway)
                     const std::size_t rowIndex = storageRow(row.j, row.k);
                     if (rowPending_[rowIndex] != 0)
                     {
                         zeroPendingRow(rowIndex);
                     }
                     double* values = step_.data() + row.first * nQuantities;
                     if ((row.first + row.length) * nQuantities + rowAhead <= step_.size())
                     {
                         prefetchRow(values + rowAhead, row.length);
                     }
                     addWeightedRow(rows.row(j, k, first, row.length), row.length, inverseSum, totals, values,
                                    inLanes);
                 });
    touch(box); // the stored part of it
    return stored.empty() ? 0 : stored.nodeCount();
}

void StepValues::addSeparableInLanes(SeparableWeight& rows, double inverseSum, const ParcelTotals& totals,
                                     const IndexBox& box, const IndexBox& stored, std::size_t rowAhead)
{
    // addSeparable's rows a run at a time, omega in registers: the same values to the bit. A
    // run is a layer's rows up to the next pending row, which is zeroed and starts the next
    // run: its values are added while still in cache (one call per layer once the step's
    // rows are cleared, one per row where all are pending, as addSeparable).
    const std::array<int, 3> extents = storage_.extents();
    SeparableLanes::BoxRows to;
    to.rowStride = static_cast<std::size_t>(extents[0]) * nQuantities;
    to.layerStride = to.rowStride * static_cast<std::size_t>(extents[1]);
    to.prefetchAhead = rowAhead;
    std::array<int, 3> lo{}, hi{};
    lo[0] = stored.lo[0] - box.lo[0];
    hi[0] = stored.hi[0] - box.lo[0];
    auto addRun = [&](int k, int jFirst, int jLast)
    {
        const std::size_t first = flatIndexInBox(storage_, stored.lo[0], jFirst, k) * nQuantities;
        to.values = step_.data() + first;
        to.available = step_.size() - first;
        lo[1] = jFirst - box.lo[1];
        hi[1] = jLast - box.lo[1];
        lo[2] = hi[2] = k - box.lo[2];
        rows.addRowsInLanes(lo, hi, inverseSum, totals.data(), to);
    };
    for (int k = stored.lo[2]; k <= stored.hi[2]; ++k)
    {
        int runFirst = stored.lo[1];
        for (int j = stored.lo[1]; j <= stored.hi[1]; ++j)
        {
            const std::size_t rowIndex = storageRow(j - storage_.lo[1], k - storage_.lo[2]);
            if (rowPending_[rowIndex] != 0)
            {
                if (j > runFirst)
                {
                    addRun(k, runFirst, j - 1);
                }
                zeroPendingRow(rowIndex);
                runFirst = j;
            }
        }
        addRun(k, runFirst, stored.hi[1]);
    }
}

void StepValues::pack(const IndexBox& box, double* values) const
{
    checkStored(box, storage_, "packStep");
    clearPendingRowsOf(box);
    forEachRowIn(box, storage_,
                 [&](const IndexRow& row)
                 {
                     const double* first = step_.data() + row.first * nQuantities;
                     std::copy(first, first + row.length * nQuantities,
                               values + row.offsetInBox * nQuantities);
                 });
}

void StepValues::unpack(const IndexBox& box, const double* values, std::size_t count)
{
    if (box.empty())
    {
        return;
    }
    checkStored(box, storage_, "unpackStep");
    if (count != box.nodeCount() * nQuantities)
    {
        throw std::invalid_argument("DensityGrid::unpackStep: value count does not match the box");
    }
    clearPendingRowsOf(box); // the rows' parts outside the box keep the step's values
    forEachRowIn(box, storage_,
                 [&](const IndexRow& row)
                 {
                     const double* first = values + row.offsetInBox * nQuantities;
                     std::copy(first, first + row.length * nQuantities,
                               step_.data() + row.first * nQuantities);
                 });
    stepBox_ = stepBox_.united(box);
}

void StepValues::commitTo(AveragingWindow& window, const IndexBox& owned)
{
    if (storage_ == owned)
    {
        // The array has the window's layout (serial runs; blocks of the function object
        // store their owned nodes only): it becomes the newest slot (zero outside stepBox_
        // once the rows no deposit reached are cleared) and the evicted slot the next array,
        // cleared row by row as the next step's deposits reach it. No copy (the spray3D
        // case's steps touch about the whole grid, 4.8 MB).
        clearPendingRows();
        IndexBox evicted;
        window.pushSwappingUncleared(step_, stepBox_, evicted);
        markDirty(evicted);
    }
    else
    {
        window.push(step_.data(), storage_, stepBox_.intersected(owned));
        forEachRowIn(stepBox_, storage_,
                     [&](const IndexRow& row)
                     {
                         double* values = step_.data() + row.first * nQuantities;
                         std::fill(values, values + row.length * nQuantities, 0.0);
                     });
    }
    stepBox_ = IndexBox{};
}

void StepValues::zeroPendingRow(std::size_t row) const
{
    const auto rowNodes = static_cast<std::size_t>(storage_.hi[0] - storage_.lo[0] + 1);
    const auto dirtyNodes = static_cast<std::size_t>(dirty_.hi[0] - dirty_.lo[0] + 1);
    double* first = step_.data() + (row * rowNodes + static_cast<std::size_t>(dirty_.lo[0])) * nQuantities;
    std::fill(first, first + dirtyNodes * nQuantities, 0.0);
    rowPending_[row] = 0;
}

void StepValues::clearPendingRowsOf(const IndexBox& box) const
{
    if (dirty_.empty() || box.empty())
    {
        return;
    }
    // The box's rows in storage indices, within the dirty rows
    const int jLo = std::max(box.lo[1] - storage_.lo[1], dirty_.lo[1]);
    const int jHi = std::min(box.hi[1] - storage_.lo[1], dirty_.hi[1]);
    const int kLo = std::max(box.lo[2] - storage_.lo[2], dirty_.lo[2]);
    const int kHi = std::min(box.hi[2] - storage_.lo[2], dirty_.hi[2]);
    for (int k = kLo; k <= kHi; ++k)
    {
        for (int j = jLo; j <= jHi; ++j)
        {
            const std::size_t row = storageRow(j, k);
            if (rowPending_[row] != 0)
            {
                zeroPendingRow(row);
            }
        }
    }
}

void StepValues::clearPendingRows() const
{
    for (int k = dirty_.lo[2]; k <= dirty_.hi[2]; ++k)
    {
        for (int j = dirty_.lo[1]; j <= dirty_.hi[1]; ++j)
        {
            const std::size_t row = storageRow(j, k);
            if (rowPending_[row] != 0)
            {
                zeroPendingRow(row);
            }
        }
    }
    dirty_ = IndexBox{};
}

void StepValues::markDirty(const IndexBox& dirty)
{
    dirty_ = IndexBox{};
    if (dirty.empty())
    {
        return;
    }
    for (int d = 0; d < 3; ++d)
    {
        dirty_.lo[d] = dirty.lo[d] - storage_.lo[d];
        dirty_.hi[d] = dirty.hi[d] - storage_.lo[d];
    }
    for (int k = dirty_.lo[2]; k <= dirty_.hi[2]; ++k)
    {
        for (int j = dirty_.lo[1]; j <= dirty_.hi[1]; ++j)
        {
            rowPending_[storageRow(j, k)] = 1;
        }
    }
}

void StepDeposit::addListed(const NodeOmegas& nodes, double inverseSum, const IndexBox& box)
{
    values_.addListed(nodes, inverseSum, totals_, box);
    statistics().nodesWeighted += static_cast<std::int64_t>(nodes.size());
}

void StepDeposit::addSeparable(SeparableWeight& rows, const SeparableTables& tables, double inverseSum,
                               const IndexBox& box)
{
    // From the rows (the removal's kept copies are read by the sparse sinks only)
    const std::size_t weighted = values_.addSeparable(rows, inverseSum, totals_, box, inLanes_);
    statistics().nodesWeighted += static_cast<std::int64_t>(weighted);
}

} // namespace dropletFiber
