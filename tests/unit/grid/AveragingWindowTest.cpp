// AveragingWindow: the window total is the chronological sum of the last W steps, bit
// for bit, whether it is read node by node while stale (nodeTotal, what sampling uses
// every step) or as the whole array (total, what output uses at write times). The
// expected sums are formed here from the pushed arrays, oldest to newest.
#include "grid/AveragingWindow.hpp"

#include <gtest/gtest.h>

#include <deque>
#include <memory>
#include <random>

using namespace dropletFiber;

namespace
{

constexpr int nq = 3;
const std::array<int, 3> nodes{{7, 5, 4}};

std::size_t flat(int i, int j, int k)
{
    return static_cast<std::size_t>(i + nodes[0] * (j + nodes[1] * k));
}

// A step array that is random inside `box` and zero outside.
std::vector<double> randomStep(const IndexBox& box, std::mt19937& rng)
{
    std::uniform_real_distribution<double> value(1e-3, 1.0);
    std::vector<double> step(static_cast<std::size_t>(nodes[0] * nodes[1] * nodes[2] * nq), 0.0);
    for (int k = box.lo[2]; k <= box.hi[2]; ++k)
        for (int j = box.lo[1]; j <= box.hi[1]; ++j)
            for (int i = box.lo[0]; i <= box.hi[0]; ++i)
                for (int q = 0; q < nq; ++q)
                    step[flat(i, j, k) * nq + static_cast<std::size_t>(q)] = value(rng);
    return step;
}

IndexBox randomBox(std::mt19937& rng)
{
    IndexBox box;
    for (int d = 0; d < 3; ++d)
    {
        std::uniform_int_distribution<int> index(0, nodes[static_cast<std::size_t>(d)] - 1);
        int a = index(rng), b = index(rng);
        box.lo[static_cast<std::size_t>(d)] = std::min(a, b);
        box.hi[static_cast<std::size_t>(d)] = std::max(a, b);
    }
    return box;
}

} // namespace

TEST(AveragingWindow, NodeTotalAndTotalAreTheChronologicalSumBitForBit)
{
    const int length = 4;
    AveragingWindow window(nodes, nq, length);
    std::deque<std::vector<double>> history; // the last `length` steps, oldest first
    std::mt19937 rng(7);
    for (int step = 0; step < 11; ++step)
    {
        const IndexBox box = randomBox(rng);
        history.push_back(randomStep(box, rng));
        if (static_cast<int>(history.size()) > length)
            history.pop_front();
        window.push(history.back(), box);

        // Read node by node first (the window is stale here; twice, the second time from
        // what the first read kept), then as the whole array on every other step, so both
        // orders of use are covered.
        const std::size_t nodeCount = static_cast<std::size_t>(nodes[0] * nodes[1] * nodes[2]);
        for (int read = 0; read < 2; ++read)
        {
            for (std::size_t n = 0; n < nodeCount; ++n)
            {
                double sums[nq];
                window.nodeTotal(n, sums);
                for (std::size_t q = 0; q < nq; ++q)
                {
                    double expected = 0.0;
                    for (const auto& s : history)
                        expected += s[n * nq + q];
                    ASSERT_EQ(sums[q], expected)
                        << "step " << step << " read " << read << " node " << n << " quantity " << q;
                }
            }
        }
        if (step % 2 == 1)
        {
            const NodeValueArray& total = window.total();
            for (std::size_t v = 0; v < total.size(); ++v)
            {
                double expected = 0.0;
                for (const auto& s : history)
                    expected += s[v];
                ASSERT_EQ(total[v], expected) << "step " << step << " value " << v;
            }
        }
    }
}

TEST(AveragingWindow, RestoredWindowGivesTheSameTotals)
{
    AveragingWindow continuous(nodes, nq, 3);
    std::mt19937 rng(11);
    std::vector<std::pair<IndexBox, std::vector<double>>> steps;
    for (int s = 0; s < 8; ++s)
    {
        const IndexBox box = randomBox(rng);
        steps.emplace_back(box, randomStep(box, rng));
    }
    for (int s = 0; s < 5; ++s)
        continuous.push(steps[s].second, steps[s].first);

    AveragingWindow restored(nodes, nq, 3);
    restored.restore(continuous.save());
    for (int s = 5; s < 8; ++s)
    {
        continuous.push(steps[s].second, steps[s].first);
        restored.push(steps[s].second, steps[s].first);
        double a[nq], b[nq];
        continuous.nodeTotal(flat(3, 2, 1), a);
        restored.nodeTotal(flat(3, 2, 1), b);
        for (int q = 0; q < nq; ++q)
            EXPECT_EQ(a[q], b[q]);
    }
    EXPECT_TRUE(continuous.total() == restored.total());
}

// A window restored from a state of fewer committed steps than it had: the node totals it
// kept from its own later steps must not be taken for the restored window's.
TEST(AveragingWindow, RestoreForgetsTheNodeTotalsOfTheWindowsOwnSteps)
{
    std::mt19937 rng(23);
    const std::size_t nodeCount = static_cast<std::size_t>(nodes[0] * nodes[1] * nodes[2]);
    IndexBox whole;
    whole.lo = {0, 0, 0};
    whole.hi = {nodes[0] - 1, nodes[1] - 1, nodes[2] - 1};
    AveragingWindow ahead(nodes, nq, 3);
    for (int s = 0; s < 8; ++s)
    {
        ahead.push(randomStep(whole, rng), whole);
        double sums[nq];
        for (std::size_t n = 0; n < nodeCount; ++n)
            ahead.nodeTotal(n, sums);
    }
    AveragingWindow behind(nodes, nq, 3);
    for (int s = 0; s < 7; ++s)
        behind.push(randomStep(whole, rng), whole);

    // ahead goes back to step 7 of another history; the same step 8 enters both
    ahead.restore(behind.save());
    const std::vector<double> next = randomStep(whole, rng);
    ahead.push(next, whole);
    behind.push(next, whole);
    for (std::size_t n = 0; n < nodeCount; ++n)
    {
        double a[nq], b[nq];
        ahead.nodeTotal(n, a);
        behind.nodeTotal(n, b);
        for (int q = 0; q < nq; ++q)
            ASSERT_EQ(a[q], b[q]) << "node " << n << " quantity " << q;
    }
}

namespace
{
// The array pushSwappingUncleared hands back must be zero outside its dirty box (grid
// indices); the caller then clears that box, as DensityGrid does row by row.
void expectZeroOutsideThenClear(NodeValueArray& step, const IndexBox& region, const IndexBox& dirty)
{
    forEachRowIn(region, region,
                 [&](const IndexRow& row)
                 {
                     for (std::size_t i = 0; i < row.length; ++i)
                     {
                         const int gi = region.lo[0] + static_cast<int>(i);
                         const bool inDirty = dirty.holds(gi, region.lo[1] + row.j, region.lo[2] + row.k);
                         double* values = step.data() + (row.offsetInBox + i) * nq;
                         for (std::size_t q = 0; q < nq; ++q)
                         {
                             ASSERT_TRUE(inDirty || values[q] == 0.0) << "node " << row.offsetInBox + i;
                             values[q] = 0.0;
                         }
                     }
                 });
}
} // namespace

// pushSwappingUncleared: the caller's step array becomes the newest slot and the caller
// gets back the evicted slot, zero outside the box handed back with it (checked), to clear
// and accumulate the next step in. The reference is independent of the window: a plain
// list of the last W step arrays, summed oldest to newest. The steps are added (+=) into
// the array the window handed back, as DensityGrid's deposit does, so a returned array
// not zero outside its box shows. Boxes of different sizes and positions, more than W
// steps, a window of a block of the grid and one of the whole grid, and a restore from a
// saved state midway whose window goes on swapping.
TEST(AveragingWindow, SwappedStepArraysGiveTheChronologicalSumBitForBit)
{
    IndexBox whole;
    whole.lo = {0, 0, 0};
    whole.hi = {nodes[0] - 1, nodes[1] - 1, nodes[2] - 1};
    IndexBox block;
    block.lo = {1, 1, 0};
    block.hi = {6, 3, 2};
    for (const IndexBox& region : {whole, block})
    {
        const int length = 3;
        const std::size_t regionValues = region.nodeCount() * nq;
        AveragingWindow window(nodes, region, nq, length);
        std::unique_ptr<AveragingWindow> restored;
        NodeValueArray accumulator(regionValues, 0.0);
        NodeValueArray restoredAccumulator(regionValues, 0.0);
        std::deque<std::vector<double>> history; // the last `length` steps, oldest first
        std::deque<IndexBox> boxes;              // their boxes
        std::mt19937 rng(31);
        for (int step = 0; step < 13; ++step)
        {
            const IndexBox box = randomBox(rng).intersected(region);
            // This step's values over the region's nodes (zero outside box).
            const std::vector<double> values = randomStep(box, rng);
            std::vector<double> local(regionValues, 0.0);
            forEachRowIn(region, whole,
                         [&](const IndexRow& row)
                         {
                             std::copy(values.begin() + static_cast<std::ptrdiff_t>(row.first * nq),
                                       values.begin()
                                           + static_cast<std::ptrdiff_t>((row.first + row.length) * nq),
                                       local.begin() + static_cast<std::ptrdiff_t>(row.offsetInBox * nq));
                         });
            history.push_back(local);
            if (static_cast<int>(history.size()) > length)
                history.pop_front();
            for (std::size_t v = 0; v < regionValues; ++v)
                accumulator[v] += local[v];
            IndexBox dirty;
            window.pushSwappingUncleared(accumulator, box, dirty);
            ASSERT_EQ(accumulator.size(), regionValues);
            // The evicted step's box (none while the window fills)
            boxes.push_back(box);
            const IndexBox evicted = static_cast<int>(boxes.size()) > length ? boxes.front() : IndexBox{};
            if (static_cast<int>(boxes.size()) > length)
                boxes.pop_front();
            ASSERT_TRUE(dirty == evicted || (dirty.empty() && evicted.empty())) << "step " << step;
            expectZeroOutsideThenClear(accumulator, region, dirty);
            if (restored)
            {
                for (std::size_t v = 0; v < regionValues; ++v)
                    restoredAccumulator[v] += local[v];
                IndexBox restoredDirty;
                restored->pushSwappingUncleared(restoredAccumulator, box, restoredDirty);
                expectZeroOutsideThenClear(restoredAccumulator, region, restoredDirty);
            }
            else if (step == 5)
            {
                // A restarted run: a new window from the state saved after this step.
                restored = std::make_unique<AveragingWindow>(nodes, region, nq, length);
                restored->restore(window.save());
            }

            for (const AveragingWindow* w : {&window, restored.get()})
            {
                if (w == nullptr)
                    continue;
                for (std::size_t n = 0; n < region.nodeCount(); ++n)
                {
                    double sums[nq];
                    w->nodeTotal(n, sums);
                    for (std::size_t q = 0; q < nq; ++q)
                    {
                        double expected = 0.0;
                        for (const auto& s : history)
                            expected += s[n * nq + q];
                        ASSERT_EQ(sums[q], expected) << "step " << step << " node " << n << " quantity " << q;
                        ASSERT_EQ(w->newestStepValue(n, static_cast<int>(q)), history.back()[n * nq + q]);
                    }
                }
                const NodeValueArray& total = w->total();
                for (std::size_t v = 0; v < regionValues; ++v)
                {
                    double expected = 0.0;
                    for (const auto& s : history)
                        expected += s[v];
                    ASSERT_EQ(total[v], expected) << "step " << step << " value " << v;
                }
            }
        }
    }
}
