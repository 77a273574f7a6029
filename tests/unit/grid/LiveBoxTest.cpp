// Blocks that store only their live box (GridBlock::live, LiveBox.hpp) against the same
// blocks stored dense (the second method: every slot of every owned node allocated from
// the start). A spray that moves and spreads over the steps (so the live box regrows
// several times), 2D and 3D, W = 1 and W > 1, exact and separable kernels: window totals,
// node values, the newest step, corner sums, window mass, depositedShare and the saved
// states (node values and deposit logs) are equal BIT FOR BIT after every step; restores
// of either format and a window moved to a re-partitioned block (savePart,
// joinedWindowState) too. Memory: the live box is the union of the touched boxes grown by
// the rule, restated here (a hand-computed case checks the restatement), and the bytes
// held are its nodes times (W + 2) * 56 + 8 once the window is full.
#include "grid/DensityGrid.hpp"
#include "grid/LiveBox.hpp"
#include "grid/WindowTransfer.hpp"

#include "TestGrids.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

using namespace dropletFiber;

namespace
{

constexpr double stepDt = 1e-3;

constexpr std::size_t bytesPerNode(int window)
{
    return static_cast<std::size_t>(window + 2) * nQuantities * sizeof(double) + sizeof(std::int64_t);
}

// The rule of LiveBox.hpp in words: each side the touched nodes push out moves past the
// union by max(2, extent / 2) of the union in that direction, clipped to the block.
IndexBox expectedGrowth(const IndexBox& live, const IndexBox& touched, const IndexBox& block)
{
    const IndexBox inside = touched.intersected(block);
    if (inside.empty() || inside.intersected(live) == inside)
    {
        return live;
    }
    IndexBox result = live.united(inside);
    const std::array<int, 3> extent = result.extents();
    for (int d = 0; d < 3; ++d)
    {
        const int margin = extent[d] / 2 > 2 ? extent[d] / 2 : 2;
        if (live.empty() || inside.lo[d] < live.lo[d])
        {
            result.lo[d] = std::max(result.lo[d] - margin, block.lo[d]);
        }
        if (live.empty() || inside.hi[d] > live.hi[d])
        {
            result.hi[d] = std::min(result.hi[d] + margin, block.hi[d]);
        }
    }
    return result;
}

IndexBox box(std::array<int, 3> lo, std::array<int, 3> hi)
{
    IndexBox b;
    b.lo = lo;
    b.hi = hi;
    return b;
}

TEST(LiveBox, GrowthRuleByHand)
{
    const IndexBox block = box({{0, 0, 0}}, {{40, 30, 0}});
    // Empty: 4 x 4 nodes, margins max(2, 4 / 2) = 2 on every side (the flat z clipped)
    const IndexBox first = grownLiveBox(IndexBox{}, box({{10, 5, 0}}, {{13, 8, 0}}), block);
    EXPECT_EQ(first, box({{8, 3, 0}}, {{15, 10, 0}}));
    // Inside: unchanged
    EXPECT_EQ(grownLiveBox(first, box({{9, 4, 0}}, {{15, 10, 0}}), block), first);
    // Pushed out in +x only: the union is 8..23 (16 nodes), that side moves 8 past it
    const IndexBox second = grownLiveBox(first, box({{20, 6, 0}}, {{23, 9, 0}}), block);
    EXPECT_EQ(second, box({{8, 3, 0}}, {{31, 10, 0}}));
    // Pushed in -y and +x: y 0..10 (11 nodes, margin 5, clipped at 0), x 8..34 (27, margin 13,
    // clipped at 40)
    EXPECT_EQ(grownLiveBox(second, box({{30, 0, 0}}, {{34, 2, 0}}), block), box({{8, 0, 0}}, {{40, 10, 0}}));
    // Outside the block: nothing
    EXPECT_EQ(grownLiveBox(second, box({{41, 0, 0}}, {{45, 2, 0}}), block), second);
}

struct Case
{
    const char* name;
    bool threeD;
    int window;
    bool separable; // wide parcels too, method Automatic (2D: the separable tables)
};

// Step s's parcels: a cloud whose centre moves in +x and whose size grows.
std::vector<Parcel> sprayOfStep(const GridSpec& spec, int s, bool separable)
{
    std::mt19937_64 rng(1000u + static_cast<unsigned>(s));
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<Parcel> parcels;
    for (int n = 0; n < 30; ++n)
    {
        Parcel p;
        for (int d = 0; d < 3; ++d)
        {
            const double size = spec.upper[d] - spec.lower[d];
            const double centre = d == 0 ? 0.1 + 0.06 * s : 0.4;
            const double half = 0.02 + 0.015 * s;
            p.position[d] = spec.flat(d) ? 0.5 * (spec.lower[d] + spec.upper[d])
                                         : spec.lower[d] + size * (centre + half * (2.0 * unit(rng) - 1.0));
            p.velocity[d] = spec.flat(d) ? 0.0 : 2.0 * (unit(rng) - 0.3);
        }
        p.diameter = 2e-5 * (0.5 + unit(rng));
        const bool wide = separable && n % 6 == 0;
        p.nParticle = wide ? 2e5 : 20.0 + 200.0 * unit(rng);
        if (wide)
        {
            p.velocity = Eigen::Vector3d::Zero(); // still: the separable tables apply
        }
        p.rhoDroplet = 1000.0;
        parcels.push_back(p);
    }
    return parcels;
}

KernelSettings kernelOf(const Case& c)
{
    KernelSettings k;
    k.cloudInCellBelow = 0.0;
    k.rMaxCap = c.threeD ? 4e-3 : 2.5e-3; // the wide kernels: 4-5 spacings, not the whole block
    k.method = c.separable ? DepositMethod::Automatic : DepositMethod::Exact;
    return k;
}

// Window values, totals, node values, the newest step and corner sums: to the bit.
void expectSameFields(const DensityGrid& live, const DensityGrid& dense)
{
    const WindowState a = live.saveWindowValues();
    const WindowState b = dense.saveWindowValues();
    ASSERT_EQ(a.counters, b.counters);
    ASSERT_TRUE(a.values == b.values) << "window slots differ";
    const GridSpec& spec = dense.spec();
    const IndexBox owned = dense.ownedBox();
    forEachRow(owned, spec.nodes,
               [&](const IndexRow& row)
               {
                   for (std::size_t n = row.first; n < row.first + row.length; ++n)
                   {
                       double x[nQuantities], y[nQuantities];
                       live.windowTotal(n, x);
                       dense.windowTotal(n, y);
                       for (int q = 0; q < nQuantities; ++q)
                       {
                           ASSERT_EQ(x[q], y[q]) << "node " << n;
                           ASSERT_EQ(live.lastStepValue(n, q), dense.lastStepValue(n, q));
                       }
                       ASSERT_EQ(live.nodeValue(n).rho, dense.nodeValue(n).rho);
                   }
               });
    ASSERT_EQ(live.windowMassPerStep(), dense.windowMassPerStep());
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int n = 0; n < 50; ++n)
    {
        const Eigen::Vector3d point = spec.lower
            + (spec.upper - spec.lower).cwiseProduct(Eigen::Vector3d(unit(rng), unit(rng), unit(rng)));
        const CornerWeights corners = multilinearWeights(spec, point);
        std::array<double, nQuantities> x{}, y{};
        live.addOwnedCornerSums(corners, x);
        dense.addOwnedCornerSums(corners, y);
        ASSERT_EQ(x, y);
    }
}

// Restores of the dense block's node values and of the live block's log, into fresh
// live and dense blocks: the same windows; the live box then the saved slots' union.
void expectSameRestores(const GridSpec& spec, const Case& c, const GridBlock& block, const DensityGrid& live,
                        const DensityGrid& dense)
{
    const WindowState values = dense.saveWindowValues();
    DensityGrid fromValues(spec, kernelOf(c), c.window, GridBlock{block.owned, block.owned, true});
    fromValues.restoreWindow(values);
    expectSameFields(fromValues, dense);
    IndexBox slots;
    for (std::size_t s = 0; s < static_cast<std::size_t>(values.counters[6]); ++s)
    {
        const auto* b = &values.counters[windowStateHeaderSize + 6 + 6 * s];
        slots = slots.united(box({{int(b[0]), int(b[1]), int(b[2])}}, {{int(b[3]), int(b[4]), int(b[5])}}));
    }
    EXPECT_EQ(fromValues.windowLiveBox(), slots);

    const WindowState log = live.saveWindow(DensityGrid::WindowStateFormat::DepositLog);
    const WindowState denseLog = dense.saveWindow(DensityGrid::WindowStateFormat::DepositLog);
    EXPECT_EQ(log.counters, denseLog.counters);
    EXPECT_TRUE(log.values == denseLog.values);
    DensityGrid liveFromLog(spec, kernelOf(c), c.window, GridBlock{block.owned, block.owned, true});
    DensityGrid denseFromLog(spec, kernelOf(c), c.window, GridBlock{block.owned, block.owned});
    liveFromLog.restoreWindow(log);
    denseFromLog.restoreWindow(log);
    expectSameFields(liveFromLog, dense);
    expectSameFields(denseFromLog, dense);
}

// The blocks of a split of the grid at node `cut` in x.
std::vector<GridBlock> splitAt(const GridSpec& spec, int cut, bool live)
{
    IndexBox left = spec.fullBox();
    IndexBox right = spec.fullBox();
    left.hi[0] = cut - 1;
    right.lo[0] = cut;
    return {GridBlock{left, left, live}, GridBlock{right, right, live}};
}

// Deposits step s on a block: the parcels whose deposit reaches its owned nodes. The
// expected live box follows each parcel's touched box (a dense probe's step box).
void depositStep(DensityGrid& grid, const std::vector<Parcel>& parcels, DensityGrid* probe,
                 IndexBox* expected)
{
    for (const Parcel& p : parcels)
    {
        if (grid.depositBox(p, stepDt).intersected(grid.ownedBox()).empty())
        {
            continue;
        }
        grid.deposit(p, stepDt);
        if (probe != nullptr)
        {
            probe->deposit(p, stepDt);
            *expected = expectedGrowth(*expected, probe->stepBox(), grid.ownedBox());
            probe->commitStep();
        }
    }
    grid.commitStep();
}

class LiveBoxBlocks : public ::testing::TestWithParam<Case>
{
};

TEST_P(LiveBoxBlocks, SameAsDenseAndSized)
{
    const Case c = GetParam();
    const GridSpec spec = c.threeD ? test::grid3D() : test::grid2D(61, 41);
    const KernelSettings kernel = kernelOf(c);
    const int cut = spec.nodes[0] / 2;
    std::vector<GridBlock> blocks = splitAt(spec, cut, true);
    std::vector<DensityGrid> live, dense, probes;
    live.reserve(blocks.size());
    dense.reserve(blocks.size());
    probes.reserve(blocks.size());
    std::vector<IndexBox> expected(blocks.size());
    for (const GridBlock& b : blocks)
    {
        live.emplace_back(spec, kernel, c.window, b);
        dense.emplace_back(spec, kernel, c.window, GridBlock{b.owned, b.owned});
        probes.emplace_back(spec, kernel, 1, GridBlock{b.owned, b.owned});
    }
    constexpr int steps = 7;
    std::vector<int> regrowths(blocks.size(), 0);
    std::int64_t separableParcels = 0;
    std::vector<int> lastRegrowth(blocks.size(), -1);
    int fullChecks = 0;
    for (int s = 0; s < steps; ++s)
    {
        const std::vector<Parcel> parcels = sprayOfStep(spec, s, c.separable);
        for (std::size_t b = 0; b < blocks.size(); ++b)
        {
            const IndexBox before = live[b].liveBox();
            depositStep(live[b], parcels, &probes[b], &expected[b]);
            depositStep(dense[b], parcels, nullptr, nullptr);
            regrowths[b] += live[b].liveBox() != before ? 1 : 0;
            separableParcels += live[b].lastStepStatistics().parcelsSeparable;
            SCOPED_TRACE(std::string(c.name) + " step " + std::to_string(s) + " block " + std::to_string(b));
            expectSameFields(live[b], dense[b]);
            ASSERT_EQ(live[b].liveBox(), expected[b]);
            ASSERT_EQ(live[b].windowLiveBox(), live[b].liveBox());
            if (live[b].liveBox() != before)
            {
                lastRegrowth[b] = s;
            }
            // Once the window is full and every slot has taken a step since the last
            // regrowth (a slot keeps the layout it was filled in), each array covers the
            // live box; before, the slots cover less
            const std::size_t bound = expected[b].nodeCount() * bytesPerNode(c.window);
            if (live[b].stepsInWindow() == c.window && s - lastRegrowth[b] >= c.window)
            {
                EXPECT_EQ(live[b].heldBytes(), bound);
                ++fullChecks;
            }
            EXPECT_LE(live[b].heldBytes(), bound);
            if (dense[b].stepsInWindow() == c.window)
            {
                EXPECT_EQ(dense[b].heldBytes(), blocks[b].owned.nodeCount() * bytesPerNode(c.window));
            }
        }
    }
    // The spray spread: the left block regrew several times, and holds part of its box
    EXPECT_GE(regrowths[0], 2);
    EXPECT_GT(fullChecks, 0);
    for (std::size_t b = 0; b < blocks.size(); ++b)
    {
        SCOPED_TRACE(b);
        expectSameRestores(spec, c, blocks[b], live[b], dense[b]);
        // The owned nodes outside the live box read zero (and are held nowhere)
        const IndexBox held = live[b].windowLiveBox();
        int outside = 0;
        forEachRow(blocks[b].owned, spec.nodes,
                   [&](const IndexRow& row)
                   {
                       for (std::size_t n = row.first; n < row.first + row.length; ++n)
                       {
                           const std::array<int, 3> ijk = nodeIndicesOfFlat(spec.nodes, n);
                           if (held.holds(ijk[0], ijk[1], ijk[2]))
                           {
                               continue;
                           }
                           ++outside;
                           double sums[nQuantities];
                           std::fill(sums, sums + nQuantities, -1.0);
                           live[b].windowTotal(n, sums);
                           ASSERT_TRUE(
                               std::all_of(sums, sums + nQuantities, [](double v) { return v == 0.0; }));
                       }
                   });
        EXPECT_EQ(static_cast<std::size_t>(outside), blocks[b].owned.nodeCount() - held.nodeCount());
    }
    EXPECT_LT(live[0].storedNodes(), blocks[0].owned.nodeCount());
    // The 2D wide kernels take the separable tables (in 3D these stay exact: r_min of eq. 15)
    EXPECT_EQ(separableParcels > 0, c.separable && !c.threeD);

    // The windows moved to a re-partition (cut one third further), then two more steps
    const int newCut = cut + spec.nodes[0] / 6;
    const std::vector<GridBlock> next = splitAt(spec, newCut, true);
    for (const GridBlock& b : next)
    {
        std::vector<WindowState> liveParts, denseParts;
        for (std::size_t o = 0; o < blocks.size(); ++o)
        {
            const IndexBox part = blocks[o].owned.intersected(b.owned);
            if (!part.empty())
            {
                liveParts.push_back(live[o].saveWindowPart(part));
                denseParts.push_back(dense[o].saveWindowPart(part));
                EXPECT_EQ(liveParts.back().counters, denseParts.back().counters);
                EXPECT_TRUE(liveParts.back().values == denseParts.back().values);
            }
        }
        DensityGrid moved(spec, kernel, c.window, b);
        DensityGrid reference(spec, kernel, c.window, GridBlock{b.owned, b.owned});
        moved.restoreWindow(joinedWindowState(liveParts, b.owned));
        reference.restoreWindow(joinedWindowState(denseParts, b.owned));
        expectSameFields(moved, reference);
        for (int s = steps; s < steps + 2; ++s)
        {
            const std::vector<Parcel> parcels = sprayOfStep(spec, s, c.separable);
            depositStep(moved, parcels, nullptr, nullptr);
            depositStep(reference, parcels, nullptr, nullptr);
            expectSameFields(moved, reference);
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Sprays, LiveBoxBlocks,
                         ::testing::Values(Case{"2D W=1 exact", false, 1, false},
                                           Case{"2D W=3 separable", false, 3, true},
                                           Case{"3D W=1 wide", true, 1, true},
                                           Case{"3D W=4 exact", true, 4, false}),
                         [](const ::testing::TestParamInfo<Case>& info)
                         {
                             std::string name = info.param.name;
                             std::replace_if(
                                 name.begin(), name.end(), [](char ch) { return !std::isalnum(ch); }, '_');
                             return name;
                         });

} // namespace
