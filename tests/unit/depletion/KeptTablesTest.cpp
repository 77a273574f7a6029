// The removal with the deposit's kept separable tables (DensityGrid::keepTablesNear,
// KeptTables) against the removal that rebuilds them (a grid that keeps none): c_p
// (CaptureLimit::reach: X_p, A_p and the weights) to the bit, parcel by parcel, on 2D and 3D grids,
// stationary and moving parcels, folded kernels at the faces, the whole grid and blocks,
// the region of the whole grid and a small one. The spray holds twins: parcels on the same
// path as another with only nParticle, or only the diameter, changed (a depleted parcel's
// next deposit; their tables differ, so a key that missed either would hand one the
// other's). Each comparison also asks that kept tables were found and used.
#include "depletion/CaptureLimit.hpp"

#include "grid/GridPartition.hpp"

#include "../grid/TestGrids.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <random>

using namespace dropletFiber;

namespace
{

constexpr double dt = 1e-4;

::testing::AssertionResult sameBits(double a, double b)
{
    if (std::memcmp(&a, &b, sizeof a) == 0)
    {
        return ::testing::AssertionSuccess();
    }
    return ::testing::AssertionFailure() << a << " and " << b << " differ by " << a - b;
}

// Wide kernels (hundreds to thousands of droplets: separable weights), anywhere in the box
// and a little beyond (folded), moving at up to speed / 2 per axis (0: stationary), with
// twins.
std::vector<Parcel> wideParcels(const GridSpec& spec, double speed, int count, unsigned seed)
{
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<Parcel> parcels;
    for (int n = 0; n < count; ++n)
    {
        Parcel p;
        test::placeRandomly(spec, speed, rng, p);
        p.diameter = 2e-5 + 6e-5 * unit(rng);
        p.nParticle = 300.0 + 3000.0 * unit(rng);
        p.rhoDroplet = 1000.0;
        parcels.push_back(p);
        if (n % 4 == 0)
        {
            Parcel twin = p;
            twin.nParticle *= 0.6;
            parcels.push_back(twin);
        }
        if (n % 5 == 0)
        {
            Parcel twin = p;
            twin.diameter *= 1.3;
            parcels.push_back(twin);
        }
    }
    return parcels;
}

// Demand at clusters of 3 nodes per active direction (a fiber's samples' corners), some
// above the supply (f_n = 1), read from the grid that holds the step.
void addDemand(const GridSpec& spec, const DensityGrid& whole, unsigned seed, CaptureLimit& limit)
{
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int c = 0; c < 8; ++c)
    {
        std::array<int, 3> centre{};
        for (int d = 0; d < 3; ++d)
        {
            centre[d] = static_cast<int>(unit(rng) * spec.nodes[d]);
        }
        IndexBox cluster;
        for (int d = 0; d < 3; ++d)
        {
            cluster.lo[d] = std::max(centre[d] - 1, 0);
            cluster.hi[d] = std::min(centre[d] + 1, spec.nodes[d] - 1);
        }
        forEachRow(cluster, spec.nodes,
                   [&](const IndexRow& row)
                   {
                       for (std::size_t i = 0; i < row.length; ++i)
                       {
                           const std::size_t node = row.first + i;
                           limit.addDemand(node, 2.0 * unit(rng) * whole.lastStepValue(node, quantityMass));
                       }
                   });
    }
}

// A grid that keeps the tables near `region` and one that keeps none (whole grid or block).
struct GridPair
{
    std::unique_ptr<DensityGrid> keeping;
    std::unique_ptr<DensityGrid> rebuilding;
};

GridPair depositedPair(const GridSpec& spec, const GridBlock& block, const std::vector<Parcel>& parcels,
                       const IndexBox& region)
{
    const KernelSettings settings;
    GridPair pair{std::make_unique<DensityGrid>(spec, settings, 1, block),
                  std::make_unique<DensityGrid>(spec, settings, 1, block)};
    pair.keeping->keepTablesNear(region);
    for (const Parcel& parcel : parcels)
    {
        pair.keeping->deposit(parcel, dt);
        pair.rebuilding->deposit(parcel, dt);
    }
    pair.keeping->commitStep();
    pair.rebuilding->commitStep();
    return pair;
}

struct Compared
{
    std::size_t kept = 0;  // tables kept, over the grids
    std::size_t found = 0; // c_p evaluations that read kept tables
    int taken = 0;         // parcels with c_p > 0 on the whole grid
};

// The parcels' c_p on the keeping grids against the rebuilding ones, the whole grid and
// the blocks of a partition into `processors` (each block stores the whole step, owns its
// part), the same limit on both.
Compared compareRemoval(const GridSpec& spec, int processors, const std::vector<Parcel>& parcels,
                        const IndexBox& region, unsigned seed)
{
    std::vector<GridPair> grids;
    grids.push_back(depositedPair(spec, GridBlock{spec.fullBox(), spec.fullBox()}, parcels, region));
    const GridPartition partition = GridPartition::bisection(spec, processors);
    for (int b = 0; b < processors; ++b)
    {
        grids.push_back(depositedPair(spec, GridBlock{partition.owned(b), spec.fullBox()}, parcels, region));
    }
    Compared compared;
    for (std::size_t g = 0; g < grids.size(); ++g)
    {
        CaptureLimit limit;
        addDemand(spec, *grids[0].rebuilding, seed, limit);
        limit.takeForeignDemand(*grids[g].rebuilding);
        limit.limit(*grids[g].rebuilding);
        for (const Parcel& parcel : parcels)
        {
            ParcelReaches rebuilding, keeping;
            limit.reach(*grids[g].rebuilding, parcel, dt, rebuilding);
            limit.reach(*grids[g].keeping, parcel, dt, keeping);
            const ParcelReach& rebuilt = rebuilding.parcels.front();
            EXPECT_TRUE(sameBits(keeping.parcels.front().depth, rebuilt.depth));
            EXPECT_TRUE(sameBits(keeping.parcels.front().saturated, rebuilt.saturated));
            EXPECT_EQ(keeping.weights.size(), rebuilding.weights.size());
            for (std::size_t k = 0; k < std::min(keeping.weights.size(), rebuilding.weights.size()); ++k)
            {
                EXPECT_TRUE(sameBits(keeping.weights[k].weight, rebuilding.weights[k].weight));
            }
            compared.taken += g == 0 && rebuilt.count > 0 ? 1 : 0;
        }
        compared.kept += grids[g].keeping->keptTables().parcels();
        compared.found += grids[g].keeping->keptTables().found();
        EXPECT_EQ(grids[g].rebuilding->keptTables().parcels(), 0u);
    }
    return compared;
}

// Two nodes per active direction a quarter into the grid (a short fiber's cells).
IndexBox smallRegion(const GridSpec& spec)
{
    IndexBox region;
    for (int d = 0; d < 3; ++d)
    {
        region.lo[d] = spec.nodes[d] / 4;
        region.hi[d] = spec.flat(d) ? 0 : region.lo[d] + 1;
    }
    return region;
}

void checkGrid(const GridSpec& spec, int processors, unsigned seed)
{
    for (const double speed : {0.0, 30.0})
    {
        const std::vector<Parcel> parcels = wideParcels(spec, speed, 60, seed);
        const Compared all = compareRemoval(spec, processors, parcels, spec.fullBox(), seed);
        EXPECT_GT(all.taken, 20) << "speed " << speed;
        EXPECT_GT(all.found, 20u) << "speed " << speed;
        const Compared small = compareRemoval(spec, processors, parcels, smallRegion(spec), seed);
        EXPECT_GT(small.found, 5u) << "speed " << speed;
        EXPECT_LT(small.kept, all.kept) << "speed " << speed;
    }
}

} // namespace

TEST(KeptTables, RemovalEqualsTheRebuiltOne3D)
{
    checkGrid(test::grid3D(), 4, 11);
}

TEST(KeptTables, RemovalEqualsTheRebuiltOne2D)
{
    checkGrid(test::grid2D(), 3, 12);
}

TEST(KeptTables, KeepsTheStepsParcelsNearTheRegionUntilTheNextDeposit)
{
    const GridSpec spec = test::grid3D();
    const std::vector<Parcel> parcels = wideParcels(spec, 30.0, 40, 13);
    DensityGrid grid(spec, KernelSettings{}, 1);
    grid.deposit(parcels[0], dt);
    grid.commitStep();
    EXPECT_EQ(grid.keptTables().parcels(), 0u); // no region: nothing kept
    const IndexBox region = smallRegion(spec);
    grid.keepTablesNear(region);
    std::size_t near = 0;
    for (const Parcel& parcel : parcels)
    {
        const std::int64_t separable = grid.stepStatistics().parcelsSeparable;
        grid.deposit(parcel, dt);
        // A separable parcel's weighted box is inside its deposit box
        const bool meets = !grid.depositBox(parcel, dt).intersected(region).empty();
        near += grid.stepStatistics().parcelsSeparable > separable && meets ? 1 : 0;
    }
    grid.commitStep();
    const std::size_t kept = grid.keptTables().parcels();
    EXPECT_GT(kept, 10u);
    EXPECT_LE(kept, near);
    EXPECT_GT(grid.keptTables().bytes(), kept * 8 * 4); // Q (1 + nx + ny + nz) doubles each
    // The next step's first deposit forgets them
    Parcel outside = parcels[0];
    outside.position = Eigen::Vector3d(-1.0, -1.0, -1.0);
    outside.velocity.setZero();
    grid.deposit(outside, dt);
    EXPECT_EQ(grid.keptTables().parcels(), 0u);
}
