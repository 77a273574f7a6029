// The removal's sums X_p = F_p sum_n w_pn x_n and A_p = F_p sum_n w_pn over the saturated
// nodes (docs/model.md sec. 7, P14) as CaptureLimit::reach evaluates them (the parcel's
// weights at the nodes with x_n > 0 only: DensityGrid::depositedShare with SparseNodeValues,
// the weights kept) against the
// straightforward evaluation: the parcel deposited alone on a fresh grid, the mass deposit()
// put on every node divided by the parcel's mass, times f_n, summed over every node. Random
// clouds of wide (separable), narrow (exact), unresolved (cloud-in-cell) parcels, moving and
// still, inside and across the faces (folded kernels), on 2D and 3D grids; the whole grid
// and blocks. Also: the sparse sum equals the dense region sum (every node of the taken
// box, row by row) to the bit, and SparseNodeValues' lookups against a map.
#include "depletion/CaptureLimit.hpp"

#include "grid/GridPartition.hpp"

#include "../grid/TestGrids.hpp"

#include "DepositedBlocks.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <memory>
#include <random>

using namespace dropletFiber;

namespace
{

constexpr double dt = 1e-4;

// Parcels of the spray: mostly wide kernels (hundreds to thousands of droplets: separable
// weights), some near or beyond the faces, some narrow (the exact code, cloud-in-cell).
std::vector<Parcel> sprayParcels(const GridSpec& spec, int count, unsigned seed)
{
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<Parcel> parcels = test::randomParcels(spec, count / 4, seed + 1);
    for (int n = static_cast<int>(parcels.size()); n < count; ++n)
    {
        Parcel p;
        test::placeRandomly(spec, n % 4 == 0 ? 0.0 : 30.0, rng, p);
        p.diameter = 2e-5 + 6e-5 * unit(rng);
        p.nParticle = 300.0 + 3000.0 * unit(rng);
        p.rhoDroplet = 1000.0;
        parcels.push_back(p);
    }
    return parcels;
}

// Demand at random nodes and at clusters of nodes (a fiber's samples), edges included,
// some above the supply (f_n = 1), on the grid that holds every parcel's step.
void addDemand(const GridSpec& spec, const DensityGrid& whole, unsigned seed, CaptureLimit& limit)
{
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::uniform_int_distribution<std::size_t> anyNode(0, spec.nodeCount() - 1);
    std::vector<std::size_t> nodes;
    for (int n = 0; n < 60; ++n)
    {
        nodes.push_back(anyNode(rng));
    }
    for (int c = 0; c < 6; ++c)
    {
        // A cluster: a box of 3 nodes per active direction at a random node, clipped
        std::array<int, 3> centre{};
        for (int d = 0; d < 3; ++d)
        {
            centre[d] = static_cast<int>(unit(rng) * spec.nodes[d]);
        }
        for (int k = -1; k <= 1; ++k)
        {
            for (int j = -1; j <= 1; ++j)
            {
                for (int i = -1; i <= 1; ++i)
                {
                    const std::array<int, 3> at{{centre[0] + i, centre[1] + j, centre[2] + k}};
                    if (at[0] >= 0 && at[0] < spec.nodes[0] && at[1] >= 0 && at[1] < spec.nodes[1]
                        && at[2] >= 0 && at[2] < spec.nodes[2])
                    {
                        nodes.push_back(spec.flatIndex(at[0], at[1], at[2]));
                    }
                }
            }
        }
    }
    for (const std::size_t node : nodes)
    {
        limit.addDemand(node, 2.0 * unit(rng) * (whole.lastStepValue(node, quantityMass) + 1e-13));
    }
}

// x_n where finite (0 where saturated), and 1 on the saturated nodes
double depthAt(const CaptureLimit& limit, std::size_t node)
{
    const double x = limit.opticalDepth(node);
    return std::isinf(x) ? 0.0 : x;
}
double saturatedAt(const CaptureLimit& limit, std::size_t node)
{
    return std::isinf(limit.opticalDepth(node)) ? 1.0 : 0.0;
}

ParcelReach reachOf(const CaptureLimit& limit, DensityGrid& grid, const Parcel& parcel)
{
    ParcelReaches reaches;
    limit.reach(grid, parcel, dt, reaches);
    return reaches.parcels.front();
}

// sum over every node of (the mass deposit() puts there / the parcel's mass) value(n).
template <class Value>
double sumOverEveryNode(const GridSpec& spec, const KernelSettings& settings, const Parcel& parcel,
                        const Value& value)
{
    DensityGrid alone(spec, settings, 1);
    alone.deposit(parcel, dt);
    alone.commitStep();
    double sum = 0.0;
    for (std::size_t node = 0; node < spec.nodeCount(); ++node)
    {
        sum += alone.lastStepValue(node, quantityMass) * value(node);
    }
    return sum / parcelMass(parcel);
}

// The removal on the whole grid and on the blocks of a partition, against the sum over every
// node (round-off: the deposit adds weight x the parcel's mass, divided back here) and the
// dense region sum (to the bit).
struct Taken
{
    int separable = 0; // parcels reaching a node with x_n > 0 and separable weights
    int exact = 0;     // reaching one and the exact code's kernel weights
};
Taken checkRemoval(const GridSpec& spec, int processors, unsigned seed)
{
    const KernelSettings settings;
    const std::vector<Parcel> parcels = sprayParcels(spec, 160, seed);
    DensityGrid whole(spec, settings, 1);
    const GridPartition partition = GridPartition::bisection(spec, processors);
    std::vector<std::unique_ptr<DensityGrid>> blocks
        = test::depositedBlocks(spec, partition, parcels, dt, whole, settings);
    CaptureLimit wholeLimit;
    addDemand(spec, whole, seed, wholeLimit);
    std::vector<CaptureLimit> blockLimits(blocks.size());
    for (std::size_t b = 0; b < blocks.size(); ++b)
    {
        // Each block's owned part of the demand
        addDemand(spec, whole, seed, blockLimits[b]);
        blockLimits[b].takeForeignDemand(*blocks[b]);
        blockLimits[b].limit(*blocks[b]);
    }
    wholeLimit.limit(whole);
    const DensityGrid::NodeBoxTest askAll = [](const IndexBox&) { return true; };
    Taken taken;
    for (const Parcel& parcel : parcels)
    {
        const auto depth = [&](std::size_t node) { return depthAt(wholeLimit, node); };
        const auto saturated = [&](std::size_t node) { return saturatedAt(wholeLimit, node); };
        const double expected = sumOverEveryNode(spec, settings, parcel, depth);
        const double expectedSaturated = sumOverEveryNode(spec, settings, parcel, saturated);
        const ParcelReach reach = reachOf(wholeLimit, whole, parcel);
        EXPECT_NEAR(reach.depth, expected, 1e-13 * (1.0 + expected));
        EXPECT_NEAR(reach.saturated, expectedSaturated, 1e-13);
        // The dense region sum: every node of the taken box, weights row by row (in
        // doubles; the reach's is exact: equal to round-off)
        const DensityGrid::NodeFraction depthOfNode = depth;
        const double dense = whole.depositedShare(parcel, dt, askAll, depthOfNode, wholeLimit.takenBox());
        EXPECT_NEAR(reach.depth, dense, 1e-14 * dense + 1e-30); // + the exact sum's quanta
        double parts = 0.0, saturatedParts = 0.0;
        FixedPointSum exactParts, exactSaturatedParts;
        for (std::size_t b = 0; b < blocks.size(); ++b)
        {
            const ParcelReach part = reachOf(blockLimits[b], *blocks[b], parcel);
            parts += part.depth;
            saturatedParts += part.saturated;
            exactParts.add(part.depthSum);
            exactSaturatedParts.add(part.saturatedSum);
        }
        EXPECT_NEAR(parts, expected, 1e-13 * (1.0 + expected));
        EXPECT_NEAR(saturatedParts, expectedSaturated, 1e-13);
        // The blocks' exact parts give the whole grid's sums to the bit
        EXPECT_EQ(exactParts.value(), reach.depth);
        EXPECT_EQ(exactSaturatedParts.value(), reach.saturated);
        const bool reached = expected > 0.0 || expectedSaturated > 0.0;
        DensityGrid one(spec, settings, 1);
        one.deposit(parcel, dt);
        const StepStatistics& statistics = one.stepStatistics();
        const bool kernel = statistics.parcelsCloudInCell == 0 && statistics.parcelsFallback == 0;
        taken.separable += reached && statistics.parcelsSeparable > 0 ? 1 : 0;
        taken.exact += reached && kernel && statistics.parcelsSeparable == 0 ? 1 : 0;
    }
    return taken;
}

} // namespace

TEST(SparseRemoval, EqualsTheSumOverEveryNode3D)
{
    // Separable parcels that take from the nodes, inside and folded at the faces
    for (const Taken& taken : {checkRemoval(test::grid3D(), 1, 5), checkRemoval(test::grid3D(), 4, 6)})
    {
        EXPECT_GT(taken.separable, 40);
        EXPECT_GE(taken.exact, 5);
    }
}

TEST(SparseRemoval, EqualsTheSumOverEveryNode2D)
{
    for (const Taken& taken : {checkRemoval(test::grid2D(), 1, 7), checkRemoval(test::grid2D(), 3, 8)})
    {
        EXPECT_GT(taken.separable, 40);
        EXPECT_GE(taken.exact, 5);
    }
}

TEST(SparseNodeValues, LooksUpAndVisitsTheNodesOfABoxInNodeOrder)
{
    const GridSpec spec = test::grid3D();
    std::mt19937_64 rng(4);
    std::uniform_int_distribution<std::size_t> anyNode(0, spec.nodeCount() - 1);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::map<std::size_t, double> reference; // the last value given per node
    std::vector<NodeValue> given;
    for (int n = 0; n < 300; ++n)
    {
        const std::size_t node = anyNode(rng);
        const double value = unit(rng) + 0.1;
        reference[node] = value;
        given.push_back(NodeValue{node, {}, value});
    }
    SparseNodeValues values;
    values.assign(given, spec.nodes);
    ASSERT_EQ(values.nodes().size(), reference.size());
    for (std::size_t node = 0; node < spec.nodeCount(); ++node)
    {
        const auto entry = reference.find(node);
        ASSERT_EQ(values.at(node), entry == reference.end() ? 0.0 : entry->second);
    }
    IndexBox box;
    box.lo = {{3, 2, 4}};
    box.hi = {{15, 9, 8}};
    std::vector<std::size_t> visited;
    values.forEachIn(box, spec.nodes,
                     [&](const NodeValue& node)
                     {
                         EXPECT_EQ(spec.flatIndex(node.index[0], node.index[1], node.index[2]), node.node);
                         visited.push_back(node.node);
                     });
    std::vector<std::size_t> expected;
    for (const auto& [node, value] : reference)
    {
        const std::size_t nx = 21, ny = 16;
        if (box.holds(static_cast<int>(node % nx), static_cast<int>((node / nx) % ny),
                      static_cast<int>(node / (nx * ny))))
        {
            expected.push_back(node);
        }
    }
    EXPECT_GT(expected.size(), 10U);
    EXPECT_EQ(visited, expected);
}
