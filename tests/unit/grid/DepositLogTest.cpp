// The window's restart state as a deposit log (DepositLog): a grid fed random parcels
// (wide separable kernels, narrow ones, cloud-in-cell, at and beyond the faces, moving and
// still) over more than W steps, saved and restored into a fresh grid or into blocks of the
// grid, has the same window slots and total BIT FOR BIT (the second method: the original
// grid's own slots, read as node values by saveWindowValues). The order of the parcels and
// every parcel matter: a log with two parcels swapped, or one dropped, restores another
// window (checked here, so the comparison can fail).
#include "grid/DensityGrid.hpp"
#include "grid/GridPartition.hpp"

#include "TestGrids.hpp"

#include <gtest/gtest.h>

#include <random>

using namespace dropletFiber;
using test::grid3D;
using test::randomParcels;

namespace
{

constexpr int window = 4;
constexpr auto asLog = DensityGrid::WindowStateFormat::DepositLog;

KernelSettings kernel()
{
    KernelSettings k;
    k.cloudInCellBelow = 0.5; // the narrowest kernels go to the cell corners
    return k;
}

// Step s's parcels: random ones (narrow, fallback, beyond the faces) and wide ones.
std::vector<Parcel> parcelsOfStep(const GridSpec& spec, int s)
{
    std::vector<Parcel> parcels = randomParcels(spec, 40, 11u + static_cast<unsigned>(s));
    std::vector<Parcel> wide = randomParcels(spec, 8, 101u + static_cast<unsigned>(s));
    for (Parcel& p : wide)
    {
        p.nParticle = 2e5; // kernels of several spacings: separable weights
    }
    parcels.insert(parcels.end(), wide.begin(), wide.end());
    return parcels;
}

// One step on a grid: the first half of the parcels with one dt, the rest with another
// (two runs in the log).
void runStep(DensityGrid& grid, int s)
{
    const std::vector<Parcel> parcels = parcelsOfStep(grid.spec(), s);
    for (std::size_t n = 0; n < parcels.size(); ++n)
    {
        grid.deposit(parcels[n], n < parcels.size() / 2 ? 1e-3 : 5e-4 * (1 + s % 3));
    }
    grid.commitStep();
}

// Slots (boxes and values) and total of two grids' windows, to the bit.
void expectSameWindow(const DensityGrid& a, const DensityGrid& b)
{
    const WindowState x = a.saveWindowValues();
    const WindowState y = b.saveWindowValues();
    EXPECT_EQ(x.counters, y.counters);
    EXPECT_TRUE(x.values == y.values) << "window slots differ";
    EXPECT_TRUE(a.windowTotals() == b.windowTotals()) << "window totals differ";
}

// The window totals of the nodes a block owns equal the whole grid's, to the bit.
bool blockTotalsEqual(const DensityGrid& whole, const DensityGrid& block)
{
    const GridSpec& spec = whole.spec();
    const IndexBox owned = block.ownedBox();
    for (int k = owned.lo[2]; k <= owned.hi[2]; ++k)
        for (int j = owned.lo[1]; j <= owned.hi[1]; ++j)
            for (int i = owned.lo[0]; i <= owned.hi[0]; ++i)
            {
                double a[nQuantities], b[nQuantities];
                whole.windowTotal(spec.flatIndex(i, j, k), a);
                block.windowTotal(spec.flatIndex(i, j, k), b);
                for (int q = 0; q < nQuantities; ++q)
                {
                    if (a[q] != b[q])
                    {
                        return false;
                    }
                }
            }
    return true;
}

// The step views' first parcel values position in a saved log: header, block, then per
// step (parcels, runs).
std::size_t firstParcelOfNewestStep(const WindowState& state, std::size_t& parcels)
{
    const std::size_t header = state.counters[0] == 4 ? 14 : 8;
    const std::size_t steps = static_cast<std::size_t>(state.counters[6]);
    std::size_t position = 0;
    for (std::size_t s = 0; s < steps; ++s)
    {
        parcels = static_cast<std::size_t>(state.counters[header + 2 * s]);
        const std::size_t runs = static_cast<std::size_t>(state.counters[header + 2 * s + 1]);
        if (s + 1 == steps)
        {
            return position + 2 * runs;
        }
        position += 2 * runs + DepositLog::parcelValues * parcels;
    }
    return position;
}

} // namespace

TEST(DepositLog, ReplayRestoresTheWindowBitForBit)
{
    const GridSpec spec = grid3D();
    DensityGrid original(spec, kernel(), window);
    StepStatistics seen;
    for (int s = 0; s < 2 * window + 1; ++s)
    {
        runStep(original, s);
        const StepStatistics& last = original.lastStepStatistics();
        seen.parcelsSeparable += last.parcelsSeparable;
        seen.parcelsCloudInCell += last.parcelsCloudInCell;
        seen.parcelsPartlyOutside += last.parcelsPartlyOutside;
    }
    // Every kind of deposit is in the window
    ASSERT_GT(seen.parcelsSeparable, 0);
    ASSERT_GT(seen.parcelsCloudInCell, 0);
    ASSERT_GT(seen.parcelsPartlyOutside, 0);

    const WindowState state = original.saveWindow(asLog);
    EXPECT_EQ(state.counters[0], 3); // a log, the whole grid
    EXPECT_EQ(state.counters[6], window);
    DensityGrid restored(spec, kernel(), window);
    restored.restoreWindow(state);
    EXPECT_EQ(restored.committedSteps(), original.committedSteps());
    EXPECT_EQ(restored.stepsInWindow(), window);
    expectSameWindow(original, restored);
    // The log is rebuilt too: the next write holds the same state
    const WindowState again = restored.saveWindow(asLog);
    EXPECT_EQ(again.counters, state.counters);
    EXPECT_TRUE(again.values == state.values);
    // ...and both continue alike
    for (int s = 2 * window + 1; s < 2 * window + 3; ++s)
    {
        runStep(original, s);
        runStep(restored, s);
        expectSameWindow(original, restored);
    }
}

TEST(DepositLog, ParcelOrderAndEveryParcelMatter)
{
    const GridSpec spec = grid3D();
    DensityGrid original(spec, kernel(), window);
    for (int s = 0; s < window + 2; ++s)
    {
        runStep(original, s);
    }
    const WindowState state = original.saveWindow(asLog);
    std::size_t parcels = 0;
    const std::size_t first = firstParcelOfNewestStep(state, parcels);
    ASSERT_GT(parcels, 2u);
    // The two wide parcels at the end of the newest step swapped: the same sums in
    // another order, which round-off tells apart somewhere
    WindowState swapped = state;
    const std::size_t last = first + (parcels - 1) * DepositLog::parcelValues;
    std::swap_ranges(swapped.values.begin() + static_cast<std::ptrdiff_t>(last),
                     swapped.values.begin() + static_cast<std::ptrdiff_t>(last + DepositLog::parcelValues),
                     swapped.values.begin() + static_cast<std::ptrdiff_t>(last - DepositLog::parcelValues));
    DensityGrid fromSwapped(spec, kernel(), window);
    fromSwapped.restoreWindow(swapped);
    EXPECT_FALSE(fromSwapped.windowTotals() == original.windowTotals());
    // The newest step's last parcel dropped (one parcel fewer in the step and its last run)
    WindowState dropped = state;
    dropped.values.resize(dropped.values.size() - DepositLog::parcelValues);
    const std::size_t header = 8 + 2 * static_cast<std::size_t>(window - 1);
    --dropped.counters[header];
    const std::size_t runs = static_cast<std::size_t>(dropped.counters[header + 1]);
    dropped.values[first - 2 * runs + 2 * (runs - 1) + 1] -= 1.0;
    DensityGrid fromDropped(spec, kernel(), window);
    fromDropped.restoreWindow(dropped);
    EXPECT_FALSE(fromDropped.windowTotals() == original.windowTotals());
}

// A serial run's log decomposed onto processors: each block replays it (the parcels that
// reach its nodes) and holds the whole grid's window at its nodes, to the bit.
TEST(DepositLog, WholeGridLogRestoresOntoEachBlock)
{
    const GridSpec spec = grid3D();
    DensityGrid whole(spec, kernel(), window);
    for (int s = 0; s < window + 3; ++s)
    {
        runStep(whole, s);
    }
    const WindowState state = whole.saveWindow(asLog);
    const GridPartition three = GridPartition::bisection(spec, 3);
    for (int p = 0; p < 3; ++p)
    {
        DensityGrid block(spec, kernel(), window, GridBlock{three.owned(p), three.owned(p)});
        block.restoreWindow(state);
        EXPECT_EQ(block.committedSteps(), whole.committedSteps());
        EXPECT_LT(block.loggedParcels(), whole.loggedParcels()); // only those reaching it
        // Each slot: the window's steps evicted one by one (empty steps), the totals
        // compared after each
        DensityGrid wholeCopy(spec, kernel(), window);
        wholeCopy.restoreWindow(state);
        for (int evicted = 0; evicted < window; ++evicted)
        {
            ASSERT_TRUE(blockTotalsEqual(wholeCopy, block)) << "block " << p << ", " << evicted << " evicted";
            wholeCopy.commitStep();
            block.commitStep();
        }
        // A block's log is a block's state (format 4), restored on the same block
        DensityGrid fresh(spec, kernel(), window, GridBlock{three.owned(p), three.owned(p)});
        block.restoreWindow(state);
        const WindowState blockState = block.saveWindow(asLog);
        EXPECT_EQ(blockState.counters[0], 4);
        fresh.restoreWindow(blockState);
        expectSameWindow(block, fresh);
        DensityGrid other(spec, kernel(), window,
                          GridBlock{three.owned((p + 1) % 3), three.owned((p + 1) % 3)});
        EXPECT_THROW(other.restoreWindow(blockState), std::invalid_argument);
    }
}

// A step whose values were written (unpackStep), not deposited, cannot be replayed: the
// window is saved as node values (format 1) until W deposited steps have followed; a
// state of node values is read as before.
TEST(DepositLog, NodeValuesWhereTheLogCannotReplay)
{
    const GridSpec spec = grid3D();
    DensityGrid grid(spec, kernel(), window);
    runStep(grid, 0);
    grid.unpackStep(spec.fullBox(), std::vector<double>(spec.nodeCount() * nQuantities, 1.0));
    grid.commitStep();
    for (int s = 1; s < window; ++s)
    {
        runStep(grid, s);
        EXPECT_EQ(grid.saveWindow(asLog).counters[0], 1) << "step " << s;
    }
    const WindowState values = grid.saveWindow(asLog);
    DensityGrid restored(spec, kernel(), window);
    restored.restoreWindow(values);
    expectSameWindow(grid, restored);
    for (int s = window; s < 2 * window; ++s)
    {
        EXPECT_EQ(restored.saveWindow(asLog).counters[0], 1) << "step " << s;
        runStep(grid, s);
        runStep(restored, s);
    }
    EXPECT_EQ(grid.saveWindow(asLog).counters[0], 3);
    EXPECT_EQ(restored.saveWindow(asLog).counters[0], 3);
    expectSameWindow(grid, restored);
}

TEST(DepositLog, DamagedLogIsRefused)
{
    const GridSpec spec = grid3D();
    DensityGrid grid(spec, kernel(), window);
    for (int s = 0; s < 2; ++s)
    {
        runStep(grid, s);
    }
    const WindowState state = grid.saveWindow(asLog);
    std::size_t parcels = 0;
    const std::size_t first = firstParcelOfNewestStep(state, parcels);
    auto refused = [&](WindowState damaged, const char* what)
    {
        DensityGrid fresh(spec, kernel(), window);
        try
        {
            fresh.restoreWindow(damaged);
        }
        catch (const std::invalid_argument& e)
        {
            EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
            EXPECT_EQ(fresh.committedSteps(), 0); // untouched
            return;
        }
        ADD_FAILURE() << "accepted: " << what;
    };
    WindowState negative = state;
    negative.values[first + 6] = -1e-5;
    refused(negative, "parcel 1, diameter) is -1.0000000000000001e-05");
    WindowState notFinite = state;
    notFinite.values[first + 1] = std::nan("");
    refused(notFinite, "position y) is nan");
    WindowState shorter = state;
    shorter.values.pop_back();
    refused(shorter, "does not match");
    WindowState negativeDt = state;
    negativeDt.values[0] = -1.0;
    refused(negativeDt, "the time step of run 1) is -1");
    WindowState otherGrid = state;
    otherGrid.counters[1] = 20;
    refused(otherGrid, "saved for a grid of 20x16x11 nodes");
}

// By default the smaller of the two: the log where kernels touch many nodes per parcel,
// node values where many parcels share few nodes; either restores the same window.
TEST(DepositLog, TheSmallerStateByDefault)
{
    const GridSpec spec = grid3D();
    DensityGrid few(spec, kernel(), window);
    runStep(few, 0);
    EXPECT_EQ(few.saveWindow().counters[0], 3);
    EXPECT_LT(few.saveWindow().values.size(), few.saveWindowValues().values.size());
    EXPECT_EQ(few.saveWindow(DensityGrid::WindowStateFormat::NodeValues).counters[0], 1);

    GridSpec tiny = spec;
    tiny.nodes = {{3, 3, 3}};
    DensityGrid many(tiny, kernel(), window);
    runStep(many, 0); // 48 parcels on 27 nodes
    const WindowState state = many.saveWindow();
    EXPECT_EQ(state.counters[0], 1);
    EXPECT_LT(state.values.size(), many.saveWindow(asLog).values.size());
    DensityGrid fromValues(tiny, kernel(), window);
    fromValues.restoreWindow(state);
    DensityGrid fromLog(tiny, kernel(), window);
    fromLog.restoreWindow(many.saveWindow(asLog));
    expectSameWindow(many, fromValues);
    expectSameWindow(many, fromLog);
}
