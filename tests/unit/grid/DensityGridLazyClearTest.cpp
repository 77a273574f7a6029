// The step accumulator's lazy clearing (DensityGrid, storage box = owned box): commitStep()
// takes the evicted window slot back uncleared and each row is zeroed at the step's first
// write into it. Over more steps than the window holds, random parcels of every kind (wide
// separable kernels, exact kernels, cloud-in-cell; moving and still) land in boxes that
// move and change size from step to step (evicted boxes larger than, smaller than and
// offset from the new ones; steps with no parcel; steps of one kind only, so that no other
// path clears a row first). A whole grid must give BIT FOR BIT the window totals and
// newest-step values of two references that never hold stale values: blocks of the grid
// whose storage box differs from their owned box (they copy the step into the window and
// clear it in place), and a fresh grid fed only the window's steps (no slot ever evicted);
// so must blocks that store what they own (they clear lazily too, in block indices).
// The step's values read mid-step (packStep, stepValues) and written (unpackStep), and a
// deposit log replayed into a grid with pending rows, are checked the same way.
#include "grid/DensityGrid.hpp"

#include "TestGrids.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

using namespace dropletFiber;
using test::grid3D;

namespace
{

constexpr int window = 3;
constexpr int steps = 12;
constexpr double dt = 1e-3;            // s
constexpr double dropletRadius = 1e-5; // m
constexpr double spacing = 1e-3;       // grid3D's node spacing, m

KernelSettings kernel()
{
    KernelSettings k;
    k.cloudInCellBelow = 0.25; // the narrowest kernels go to the cell corners
    return k;
}

std::uint64_t bits(double value)
{
    std::uint64_t b = 0;
    std::memcpy(&b, &value, sizeof b);
    return b;
}

enum class StepKinds
{
    Mixed,
    WideOnly,
    NarrowOnly // exact kernels and cloud-in-cell
};

// Step s's parcels: in a random box of random size (a part of the grid's box, now and then
// reaching beyond its faces), none in steps 4 and 9.
std::vector<Parcel> parcelsOfStep(const GridSpec& spec, int s)
{
    std::vector<Parcel> parcels;
    if (s == 4 || s == 9)
    {
        return parcels;
    }
    std::mt19937_64 random(1234u + static_cast<unsigned>(s));
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const StepKinds kinds
        = s % 3 == 0 ? StepKinds::Mixed : (s % 3 == 1 ? StepKinds::WideOnly : StepKinds::NarrowOnly);
    Eigen::Vector3d lower;
    Eigen::Vector3d upper;
    for (int d = 0; d < 3; ++d)
    {
        const double size = spec.upper[d] - spec.lower[d];
        const double half = size * (0.05 + 0.45 * unit(random));
        const double centre = spec.lower[d] + 0.1 * size + 0.8 * size * unit(random);
        lower[d] = centre - half;
        upper[d] = centre + half;
    }
    const int count = 20 + static_cast<int>(30 * unit(random));
    for (int n = 0; n < count; ++n)
    {
        Parcel p;
        const bool still = n % 4 == 0;
        for (int d = 0; d < 3; ++d)
        {
            p.position[d] = lower[d] + (upper[d] - lower[d]) * unit(random);
            // up to 4 spacings per step along each axis
            p.velocity[d] = still ? 0.0 : 8.0 * spacing / dt * (unit(random) - 0.5);
        }
        const bool wide = kinds == StepKinds::WideOnly || (kinds == StepKinds::Mixed && n % 2 == 0);
        // Kernel widths (eqs. 13-17, r_p = 10 um, 1 mm spacing): wide ones 0.6-5 spacings
        // (separable weights), then 0.25-0.35 (exact code), below 0.25 (cloud-in-cell)
        p.nParticle = wide ? 3000.0 + 17000.0 * unit(random)
                           : (n % 3 == 0 ? 20.0 + 280.0 * unit(random) : 700.0 + 300.0 * unit(random));
        p.diameter = 2.0 * dropletRadius;
        p.rhoDroplet = 1000.0;
        parcels.push_back(p);
    }
    return parcels;
}

// Values of a node whose bits differ between two grids: its window totals and its newest
// step's values.
std::size_t differingAt(const DensityGrid& a, const DensityGrid& b, std::size_t node)
{
    double x[nQuantities];
    double y[nQuantities];
    a.windowTotal(node, x);
    b.windowTotal(node, y);
    std::size_t differing = 0;
    for (int q = 0; q < nQuantities; ++q)
    {
        differing += bits(x[q]) != bits(y[q]) ? 1 : 0;
        differing += bits(a.lastStepValue(node, q)) != bits(b.lastStepValue(node, q)) ? 1 : 0;
    }
    return differing;
}

// The whole grid's window at every node (totals and newest step) bit for bit that of the
// reference blocks (each node from the block that owns it).
void expectSameWindow(const DensityGrid& grid, const std::vector<DensityGrid>& blocks, int step)
{
    std::size_t differing = 0;
    for (std::size_t node = 0; node < grid.spec().nodeCount(); ++node)
    {
        for (const DensityGrid& block : blocks)
        {
            differing += block.owns(node) ? differingAt(grid, block, node) : 0;
        }
    }
    EXPECT_EQ(differing, 0u) << "after step " << step;
}

// Bit for bit the same window totals and newest step at every node of the whole grid.
void expectSameWindow(const DensityGrid& a, const DensityGrid& b, int step)
{
    std::size_t differing = 0;
    for (std::size_t node = 0; node < a.spec().nodeCount(); ++node)
    {
        differing += differingAt(a, b, node);
    }
    EXPECT_EQ(differing, 0u) << "after step " << step;
}

template <class A, class B>
std::size_t differingValues(const A& a, const B& b)
{
    std::size_t differing = a.size() == b.size() ? 0 : 1;
    for (std::size_t n = 0; n < std::min(a.size(), b.size()); ++n)
    {
        differing += bits(a[n]) != bits(b[n]) ? 1 : 0;
    }
    return differing;
}

// Reference blocks of the grid: owned halves (in x), each storing the whole grid.
std::vector<DensityGrid> referenceBlocks(const GridSpec& spec)
{
    std::vector<DensityGrid> blocks;
    const IndexBox all = spec.fullBox();
    IndexBox left = all;
    left.hi[0] = spec.nodes[0] / 2 - 1;
    IndexBox right = all;
    right.lo[0] = spec.nodes[0] / 2;
    blocks.emplace_back(spec, kernel(), window, GridBlock{left, all});
    blocks.emplace_back(spec, kernel(), window, GridBlock{right, all});
    return blocks;
}

// Blocks that store what they own (2 x 2 in x and y, the function object's layout): their
// step arrays swap with the window's slots and clear lazily in block indices too.
std::vector<DensityGrid> swappingBlocks(const GridSpec& spec)
{
    std::vector<DensityGrid> blocks;
    for (int b = 0; b < 4; ++b)
    {
        IndexBox owned = spec.fullBox();
        owned.lo[0] = b % 2 == 0 ? 0 : 8;
        owned.hi[0] = b % 2 == 0 ? 7 : spec.nodes[0] - 1;
        owned.lo[1] = b / 2 == 0 ? 0 : 9;
        owned.hi[1] = b / 2 == 0 ? 8 : spec.nodes[1] - 1;
        blocks.emplace_back(spec, kernel(), window, GridBlock{owned, owned});
    }
    return blocks;
}

} // namespace

TEST(DensityGridLazyClear, WindowBitForBitAsGridsThatNeverHoldStaleValues)
{
    const GridSpec spec = grid3D();
    DensityGrid grid(spec, kernel(), window);
    std::vector<DensityGrid> blocks = referenceBlocks(spec);
    std::vector<DensityGrid> swapping = swappingBlocks(spec);
    StepStatistics seen;
    for (int s = 0; s < steps; ++s)
    {
        for (const Parcel& p : parcelsOfStep(spec, s))
        {
            grid.deposit(p, dt);
            for (DensityGrid& block : blocks)
            {
                block.depositCopy(p, dt);
            }
            for (DensityGrid& block : swapping)
            {
                block.depositCopy(p, dt);
            }
        }
        grid.commitStep();
        for (DensityGrid& block : blocks)
        {
            block.commitStep();
        }
        for (DensityGrid& block : swapping)
        {
            block.commitStep();
        }
        seen += grid.lastStepStatistics();
        expectSameWindow(grid, blocks, s);
        expectSameWindow(grid, swapping, s);

        // A fresh grid fed the window's steps only: its slots are new arrays, never evicted
        DensityGrid fresh(spec, kernel(), window);
        for (int t = std::max(0, s - window + 1); t <= s; ++t)
        {
            for (const Parcel& p : parcelsOfStep(spec, t))
            {
                fresh.deposit(p, dt);
            }
            fresh.commitStep();
        }
        expectSameWindow(grid, fresh, s);
    }
    // Every path deposited: wide (separable), cloud-in-cell and exact kernels
    EXPECT_GT(seen.parcelsSeparable, 0);
    EXPECT_GT(seen.parcelsCloudInCell, 0);
    EXPECT_GT(seen.parcels - seen.parcelsSeparable - seen.parcelsCloudInCell - seen.parcelsOutside, 0);
    EXPECT_GT(seen.parcelsPartlyOutside, 0);
}

// The step read (packStep, the const stepValues) and overwritten in part (unpackStep)
// while rows are pending: the values of a reference block storing the whole
// grid, whose step array is cleared at each commit.
TEST(DensityGridLazyClear, StepValuesReadAndWrittenMidStep)
{
    const GridSpec spec = grid3D();
    DensityGrid grid(spec, kernel(), window);
    std::vector<DensityGrid> blocks = referenceBlocks(spec);
    DensityGrid& reference = blocks.front(); // stores the whole grid
    const IndexBox all = spec.fullBox();
    for (int s = 0; s < steps; ++s)
    {
        // A box overwritten, then the whole step read: before the step's first deposit (every
        // row of the evicted box pending) or halfway through it
        const auto writeAndRead = [&]()
        {
            IndexBox part = all;
            part.lo = {{3, 2 + s % 5, 1}};
            part.hi = {{12, 9, 4 + s % 4}};
            const std::vector<double> written(part.nodeCount() * nQuantities, 0.25 * (s + 1));
            grid.unpackStep(part, written);
            for (DensityGrid& block : blocks)
            {
                block.unpackStep(part, written);
            }
            EXPECT_EQ(differingValues(grid.packStep(all), reference.packStep(all)), 0u) << "step " << s;
        };
        if (s % 2 == 1)
        {
            writeAndRead();
        }
        const std::vector<Parcel> parcels = parcelsOfStep(spec, s);
        for (std::size_t n = 0; n < parcels.size(); ++n)
        {
            grid.deposit(parcels[n], dt);
            for (DensityGrid& block : blocks)
            {
                block.depositCopy(parcels[n], dt);
            }
            if (n == parcels.size() / 2 && s % 2 == 0)
            {
                writeAndRead();
            }
        }
        if (s % 3 == 1)
        {
            const DensityGrid& constGrid = grid;
            EXPECT_EQ(differingValues(constGrid.stepValues(), reference.packStep(all)), 0u) << "step " << s;
        }
        else
        {
            EXPECT_EQ(differingValues(grid.packStep(all), reference.packStep(all)), 0u) << "step " << s;
        }
        grid.commitStep();
        for (DensityGrid& block : blocks)
        {
            block.commitStep();
        }
        expectSameWindow(grid, blocks, s);
    }
}

// A deposit log replayed (restoreWindow) into a grid whose step array holds an evicted
// slot's values: the original window bit for bit, and so is the step after it.
TEST(DensityGridLazyClear, ReplayIntoAGridWithPendingRows)
{
    const GridSpec spec = grid3D();
    DensityGrid original(spec, kernel(), window);
    DensityGrid restored(spec, kernel(), window);
    for (int s = 0; s < steps; ++s)
    {
        for (const Parcel& p : parcelsOfStep(spec, s))
        {
            original.deposit(p, dt);
        }
        original.commitStep();
        // Other steps on the grid to restore into: its window full, the evicted slot pending
        for (const Parcel& p : parcelsOfStep(spec, (s + 5) % steps))
        {
            restored.deposit(p, dt);
        }
        restored.commitStep();
    }
    restored.restoreWindow(original.saveWindow(DensityGrid::WindowStateFormat::DepositLog));
    expectSameWindow(original, restored, steps);
    for (const Parcel& p : parcelsOfStep(spec, 3))
    {
        original.deposit(p, dt);
        restored.deposit(p, dt);
    }
    original.commitStep();
    restored.commitStep();
    expectSameWindow(original, restored, steps + 1);
}
