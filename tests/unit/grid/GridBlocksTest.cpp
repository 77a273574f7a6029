// Grid blocks: a grid split into blocks that each store their owned nodes, every parcel
// given to each block its deposit reaches (DensityGrid::depositBox), deposits what the
// whole grid deposits: one parcel bit for bit (each node gets the same product), many
// parcels to round-off (the sums at a node add in another order). The partition tiles the
// grid from subdomain bounds, or by bisection when they do not.
#include "grid/DensityGrid.hpp"
#include "grid/GridPartition.hpp"
#include "grid/MultilinearWeights.hpp"

#include "TestGrids.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>

using namespace dropletFiber;
using test::grid2D;
using test::grid3D;
using test::randomParcels;

namespace
{

struct Blocks
{
    GridPartition partition;
    std::vector<std::unique_ptr<DensityGrid>> grids;
};

Blocks makeBlocks(const GridPartition& partition, const GridSpec& spec, int window)
{
    Blocks blocks{partition, {}};
    for (int p = 0; p < partition.processors(); ++p)
    {
        const GridBlock block{partition.owned(p), partition.owned(p)};
        blocks.grids.push_back(std::make_unique<DensityGrid>(spec, KernelSettings{}, window, block));
    }
    return blocks;
}

// What the function object does over MPI: the block holding the parcel deposits it, and
// gives a copy to every other block its deposit reaches.
void depositOnBlocks(Blocks& blocks, int holder, const Parcel& parcel, double dt)
{
    DensityGrid& held = *blocks.grids[static_cast<std::size_t>(holder)];
    held.deposit(parcel, dt);
    std::vector<int> others;
    blocks.partition.holdersOf(held.depositBox(parcel, dt), holder, others);
    for (const int p : others)
    {
        blocks.grids[static_cast<std::size_t>(p)]->depositCopy(parcel, dt);
    }
}

void commit(Blocks& blocks)
{
    for (auto& grid : blocks.grids)
    {
        grid->commitStep();
    }
}

// The owner's window total of every node, as one grid-sized array.
std::vector<double> assembledTotals(const GridSpec& spec, const Blocks& blocks)
{
    std::vector<double> totals(spec.nodeCount() * nQuantities, 0.0);
    for (std::size_t node = 0; node < spec.nodeCount(); ++node)
    {
        for (const auto& grid : blocks.grids)
        {
            if (grid->owns(node))
            {
                grid->windowTotal(node, totals.data() + node * nQuantities);
            }
        }
    }
    return totals;
}

template <class Expected>
void expectNear(const std::vector<double>& actual, const Expected& expected, double relative)
{
    ASSERT_EQ(actual.size(), expected.size());
    double largest = 0.0;
    for (const double v : expected)
    {
        largest = std::max(largest, std::abs(v));
    }
    for (std::size_t k = 0; k < expected.size(); ++k)
    {
        ASSERT_NEAR(actual[k], expected[k], relative * largest) << "value " << k;
    }
}

} // namespace

TEST(GridPartition, SubdomainBoundsOfASimpleDecompositionTileTheGrid)
{
    const GridSpec spec = grid3D();
    // 2 x 2 x 1 subdomains, cut at x = 0.0095 (between nodes) and y = 0.0075 (on node 8 in y)
    const std::vector<SubdomainBounds> bounds{{{0.0, 0.0, 0.0, 0.0095, 0.0075, 0.01}},
                                              {{0.0095, 0.0, 0.0, 0.02, 0.0075, 0.01}},
                                              {{0.0, 0.0075, 0.0, 0.0095, 0.015, 0.01}},
                                              {{0.0095, 0.0075, 0.0, 0.02, 0.015, 0.01}}};
    const GridPartition partition = GridPartition::fromSubdomainBounds(spec, bounds);
    EXPECT_TRUE(partition.tiles(spec));
    EXPECT_EQ(partition.owned(0).hi[0], 9);
    EXPECT_EQ(partition.owned(1).lo[0], 10);
    EXPECT_EQ(partition.owner(20, 15, 10), 3);
    // The node on the shared plane y = 0.0075 belongs to the upper subdomain only
    EXPECT_EQ(partition.owner(0, 7, 0), 0);
    EXPECT_EQ(partition.owner(0, 8, 0), 2);
    for (int p = 0; p < 4; ++p)
    {
        EXPECT_EQ(partition.owned(p).lo[2], 0);
        EXPECT_EQ(partition.owned(p).hi[2], 10);
    }
}

TEST(GridPartition, SubdomainsSharingTheCutsCellLayerAreCutThere)
{
    // A decomposition by cell count: the cells at y = 0.0065..0.0085 (around node 7) are
    // shared out; unsnapped both boxes would hold nodes 7 and 8
    const GridSpec spec = grid3D();
    const std::vector<SubdomainBounds> bounds{{{0.0, 0.0, 0.0, 0.02, 0.0085, 0.01}},
                                              {{0.0, 0.0065, 0.0, 0.02, 0.015, 0.01}}};
    const GridPartition partition = GridPartition::fromSubdomainBounds(spec, bounds);
    EXPECT_TRUE(partition.tiles(spec));
    EXPECT_EQ(partition.owned(0).hi[1], 6);
    EXPECT_EQ(partition.owned(1).lo[1], 7);
}

TEST(GridPartition, FlatDirectionBelongsToEveryBoxCoveringTheSlab)
{
    const GridSpec spec = grid2D();
    const std::vector<SubdomainBounds> bounds{{{0.0, 0.0, 0.0, 0.03, 0.01, 0.001}},
                                              {{0.0, 0.01, 0.0, 0.03, 0.02, 0.001}}};
    const GridPartition partition = GridPartition::fromSubdomainBounds(spec, bounds);
    EXPECT_TRUE(partition.tiles(spec));
    EXPECT_EQ(partition.owned(0).hi[1], 9);
    EXPECT_EQ(partition.owned(1).lo[1], 10);
}

TEST(GridPartition, IrregularBoundsDoNotTileAndBisectionDoes)
{
    const GridSpec spec = grid3D();
    // A subdomain inside another (not boxes), and a grid larger than the mesh
    const std::vector<SubdomainBounds> nested{{{0.0, 0.0, 0.0, 0.02, 0.015, 0.01}},
                                              {{0.008, 0.004, 0.0, 0.012, 0.01, 0.01}}};
    EXPECT_FALSE(GridPartition::fromSubdomainBounds(spec, nested).tiles(spec));
    const std::vector<SubdomainBounds> small{{{0.0, 0.0, 0.0, 0.01, 0.015, 0.01}},
                                             {{0.01, 0.0, 0.0, 0.018, 0.015, 0.01}}};
    EXPECT_FALSE(GridPartition::fromSubdomainBounds(spec, small).tiles(spec));
    for (int parts = 1; parts <= 9; ++parts)
    {
        const GridPartition partition = GridPartition::bisection(spec, parts);
        EXPECT_TRUE(partition.tiles(spec)) << parts << " parts";
        std::size_t largest = 0, smallest = spec.nodeCount();
        for (const IndexBox& box : partition.boxes())
        {
            largest = std::max(largest, box.nodeCount());
            smallest = std::min(smallest, box.nodeCount());
        }
        EXPECT_LE(largest, 2 * smallest + spec.nodeCount() / 10) << parts << " parts";
    }
}

TEST(GridBlocks, EachBlocksNodesEqualTheWholeGridBitForBit)
{
    // A parcel deposited on every block: each block's nodes hold the whole grid's values
    // there, each the same product, to the bit; and no node the whole grid's deposit
    // touches lies outside depositBox().
    for (const GridSpec& spec : {grid3D(), grid2D()})
    {
        const GridPartition partition = GridPartition::bisection(spec, 3);
        for (const Parcel& parcel : randomParcels(spec, 40, 11))
        {
            DensityGrid whole(spec);
            whole.deposit(parcel, 1e-3);
            const IndexBox reached = whole.depositBox(parcel, 1e-3);
            std::vector<double> assembled(spec.nodeCount() * nQuantities, 0.0);
            for (int p = 0; p < partition.processors(); ++p)
            {
                const IndexBox owned = partition.owned(p);
                DensityGrid block(spec, KernelSettings{}, 1, GridBlock{owned, owned});
                block.depositCopy(parcel, 1e-3);
                forEachRow(
                    owned, spec.nodes,
                    [&](const IndexRow& row)
                    {
                        std::copy(
                            block.stepValues().begin()
                                + static_cast<std::ptrdiff_t>(row.offsetInBox * nQuantities),
                            block.stepValues().begin()
                                + static_cast<std::ptrdiff_t>((row.offsetInBox + row.length) * nQuantities),
                            assembled.begin() + static_cast<std::ptrdiff_t>(row.first * nQuantities));
                    });
            }
            ASSERT_TRUE(assembled == whole.stepValues());
            forEachRow(spec.fullBox(), spec.nodes,
                       [&](const IndexRow& row)
                       {
                           for (std::size_t i = 0; i < row.length; ++i)
                           {
                               const std::size_t node = row.first + i;
                               const int x = static_cast<int>(node % static_cast<std::size_t>(spec.nodes[0]));
                               const int y = static_cast<int>((node / static_cast<std::size_t>(spec.nodes[0]))
                                                              % static_cast<std::size_t>(spec.nodes[1]));
                               const int z = static_cast<int>(node
                                                              / (static_cast<std::size_t>(spec.nodes[0])
                                                                 * static_cast<std::size_t>(spec.nodes[1])));
                               if (whole.stepValues()[node * nQuantities] != 0.0)
                               {
                                   ASSERT_TRUE(reached.holds(x, y, z)) << "node " << node << " not reached";
                               }
                           }
                       });
        }
    }
}

TEST(GridBlocks, ExchangedBlocksEqualTheWholeGridToRoundOff)
{
    for (const GridSpec& spec : {grid3D(), grid2D()})
    {
        for (const int parts : {2, 4, 7})
        {
            DensityGrid whole(spec, KernelSettings{}, 3);
            Blocks blocks = makeBlocks(GridPartition::bisection(spec, parts), spec, 3);
            for (int step = 0; step < 4; ++step)
            {
                const std::vector<Parcel> parcels
                    = randomParcels(spec, 150, 100u + static_cast<unsigned>(step));
                for (std::size_t n = 0; n < parcels.size(); ++n)
                {
                    whole.deposit(parcels[n], 1e-3);
                    depositOnBlocks(blocks, static_cast<int>(n % blocks.grids.size()), parcels[n], 1e-3);
                }
                // Each parcel's mass counted once, by the block holding it
                double massDeposited = 0.0;
                for (const auto& grid : blocks.grids)
                {
                    massDeposited += grid->stepStatistics().massDeposited;
                }
                EXPECT_NEAR(massDeposited, whole.stepStatistics().massDeposited,
                            1e-14 * whole.stepStatistics().massDeposited);
                whole.commitStep();
                commit(blocks);
            }
            SCOPED_TRACE(std::to_string(parts) + " blocks, nodes " + std::to_string(spec.nodeCount()));
            expectNear(assembledTotals(spec, blocks), whole.windowTotals(), 1e-14);
            // A sample from the shares of the corners' owners equals the whole grid's
            std::mt19937_64 rng(3);
            std::uniform_real_distribution<double> unit(0.0, 1.0);
            int sharedSamples = 0; // samples whose corners several blocks own
            for (int s = 0; s < 400; ++s)
            {
                const Eigen::Vector3d point = spec.lower
                    + (spec.upper - spec.lower)
                          .cwiseProduct(Eigen::Vector3d(unit(rng), unit(rng), unit(rng)));
                const CornerWeights corners = multilinearWeights(spec, point);
                std::array<double, nQuantities> sums{};
                int owners = 0;
                for (const auto& grid : blocks.grids)
                {
                    const std::array<double, nQuantities> before = sums;
                    grid->addOwnedCornerSums(corners, sums);
                    owners += sums != before ? 1 : 0;
                }
                sharedSamples += owners > 1 ? 1 : 0;
                const DropletFieldValue expected = whole.sample(point);
                const DropletFieldValue actual = blocks.grids[0]->fieldFromCornerSums(sums);
                EXPECT_NEAR(actual.rho, expected.rho, 1e-13 * std::abs(expected.rho));
                EXPECT_NEAR(actual.rMeanMass, expected.rMeanMass, 1e-13 * std::abs(expected.rMeanMass));
                EXPECT_NEAR(actual.velocity.x(), expected.velocity.x(),
                            1e-12 * (expected.velocity.norm() + 1e-30));
            }
            EXPECT_GT(sharedSamples, 0);
        }
    }
}

TEST(GridBlocks, WholeGridBlockIsTheWholeGridBitForBit)
{
    // The corner sums of the whole grid as a block are sample()'s own arithmetic
    const GridSpec spec = grid3D();
    DensityGrid whole(spec, KernelSettings{}, 2);
    DensityGrid block(spec, KernelSettings{}, 2, GridBlock{spec.fullBox(), spec.fullBox()});
    for (const Parcel& parcel : randomParcels(spec, 200, 7))
    {
        whole.deposit(parcel, 1e-3);
        block.deposit(parcel, 1e-3);
    }
    whole.commitStep();
    block.commitStep();
    EXPECT_TRUE(whole.windowTotals() == block.windowTotals());
    const Eigen::Vector3d point(0.0071, 0.0033, 0.0052);
    std::array<double, nQuantities> sums{};
    block.addOwnedCornerSums(multilinearWeights(spec, point), sums);
    EXPECT_EQ(block.fieldFromCornerSums(sums).rho, whole.sample(point).rho);
    EXPECT_EQ(block.fieldFromCornerSums(sums).rMeanNumber, whole.sample(point).rMeanNumber);
}

TEST(GridBlocks, NodesOfOtherBlocksAreLeftToThem)
{
    const GridSpec spec = grid3D();
    const GridPartition partition = GridPartition::bisection(spec, 2);
    DensityGrid block(spec, KernelSettings{}, 1, GridBlock{partition.owned(0), partition.owned(0)});
    DensityGrid whole(spec);
    for (const Parcel& parcel : randomParcels(spec, 50, 1))
    {
        block.deposit(parcel, 1e-3);
        whole.deposit(parcel, 1e-3);
    }
    // The block's step mass is the whole grid's on its nodes only (some of the parcels'
    // kernels reach the other block)
    double blockMass = 0.0, wholeMassOnBlock = 0.0, wholeMass = 0.0;
    forEachRow(partition.owned(0), spec.nodes,
               [&](const IndexRow& row)
               {
                   for (std::size_t i = 0; i < row.length; ++i)
                   {
                       blockMass += block.stepValues()[(row.offsetInBox + i) * nQuantities];
                       wholeMassOnBlock += whole.stepValues()[(row.first + i) * nQuantities];
                   }
               });
    for (std::size_t n = 0; n < spec.nodeCount(); ++n)
    {
        wholeMass += whole.stepValues()[n * nQuantities];
    }
    EXPECT_NEAR(blockMass, wholeMassOnBlock, 1e-14 * wholeMass);
    EXPECT_LT(blockMass, 0.99 * wholeMass);
    EXPECT_NO_THROW(block.commitStep());
    const IndexBox other = partition.owned(1);
    const std::size_t foreign = spec.flatIndex(other.hi[0], other.hi[1], other.hi[2]);
    EXPECT_FALSE(block.owns(foreign));
    double sums[nQuantities];
    EXPECT_THROW(block.windowTotal(foreign, sums), std::out_of_range);
}

// A parcel held by a block its deposit does not reach (balanced blocks: the spray's nodes
// owned by other processors): the holder counts it and logs it but evaluates no weight;
// the block it reaches evaluates it as the whole grid does.
TEST(GridBlocks, HolderOutsideTheParcelsReachEvaluatesNoWeight)
{
    const GridSpec spec = grid3D();
    const GridPartition partition = GridPartition::bisection(spec, 2);
    Blocks blocks = makeBlocks(partition, spec, 1);
    DensityGrid whole(spec);
    Parcel parcel;
    parcel.diameter = 2e-5;
    parcel.nParticle = 200.0;
    parcel.rhoDroplet = 1000.0;
    // In the corner of the grid farthest from the cut
    const IndexBox far = partition.owned(1);
    const int holder = far.lo[0] > 0 || far.lo[1] > 0 || far.lo[2] > 0 ? 0 : 1;
    const IndexBox reached = partition.owned(1 - holder);
    parcel.position = spec.lower + (spec.upper - spec.lower).cwiseProduct(Eigen::Vector3d(0.95, 0.95, 0.95));
    if (reached.lo[0] == 0 && reached.lo[1] == 0 && reached.lo[2] == 0)
    {
        parcel.position
            = spec.lower + (spec.upper - spec.lower).cwiseProduct(Eigen::Vector3d(0.05, 0.05, 0.05));
    }
    const double dt = 1e-3;
    const IndexBox box = whole.depositBox(parcel, dt);
    ASSERT_FALSE(box.empty());
    ASSERT_TRUE(box.intersected(partition.owned(holder)).empty()) << "the test parcel reaches its holder";
    ASSERT_EQ(box.intersected(reached), box);

    depositOnBlocks(blocks, holder, parcel, dt);
    whole.deposit(parcel, dt);
    const DensityGrid& held = *blocks.grids[static_cast<std::size_t>(holder)];
    const DensityGrid& other = *blocks.grids[static_cast<std::size_t>(1 - holder)];
    // Counted once, by its holder, with its whole mass on the grid...
    EXPECT_EQ(held.stepStatistics().parcels, 1);
    EXPECT_EQ(held.stepStatistics().massIn, parcelMass(parcel));
    EXPECT_EQ(held.stepStatistics().massDeposited, parcelMass(parcel));
    // ...and weighed by the block it reaches only, as the whole grid weighs it
    EXPECT_GT(whole.stepStatistics().nodesVisited, 0);
    EXPECT_EQ(held.stepStatistics().nodesVisited, 0);
    EXPECT_EQ(other.copyStatistics().nodesVisited, whole.stepStatistics().nodesVisited);
    EXPECT_TRUE(held.stepBox().empty());
    commit(blocks);
    whole.commitStep();
    EXPECT_EQ(assembledTotals(spec, blocks), whole.windowTotals());
}

TEST(GridBlocks, WindowStateRestoresOnTheSameBlockOnly)
{
    const GridSpec spec = grid3D();
    const GridPartition two = GridPartition::bisection(spec, 2);
    const GridPartition three = GridPartition::bisection(spec, 3);
    Blocks blocks = makeBlocks(two, spec, 2);
    for (const Parcel& parcel : randomParcels(spec, 30, 5))
    {
        depositOnBlocks(blocks, 0, parcel, 1e-3);
    }
    commit(blocks);
    // Both formats: the deposit log (a block's: 4) and the node values (a block's: 2)
    for (const WindowState& state : {blocks.grids[1]->saveWindow(DensityGrid::WindowStateFormat::DepositLog),
                                     blocks.grids[1]->saveWindowValues()})
    {
        EXPECT_TRUE(state.counters[0] == 4 || state.counters[0] == 2); // a block's format
        DensityGrid same(spec, KernelSettings{}, 2, GridBlock{two.owned(1), two.owned(1)});
        same.restoreWindow(state);
        EXPECT_TRUE(same.windowTotals() == blocks.grids[1]->windowTotals());
        DensityGrid other(spec, KernelSettings{}, 2, GridBlock{three.owned(1), three.owned(1)});
        EXPECT_THROW(other.restoreWindow(state), std::invalid_argument);
        DensityGrid whole(spec, KernelSettings{}, 2);
        EXPECT_THROW(whole.restoreWindow(state), std::invalid_argument);
        EXPECT_EQ(whole.saveWindow(DensityGrid::WindowStateFormat::DepositLog).counters[0], 3); // a log
        EXPECT_EQ(whole.saveWindowValues().counters[0], 1); // ...and node values, unchanged
    }
}

// A serial run's state decomposed onto processors: each block takes its part of the whole
// grid's window, and its fields are the whole grid's at its nodes, to the bit (the same
// slot values summed in the same order).
TEST(GridBlocks, WholeGridWindowRestoresOntoEachBlock)
{
    const GridSpec spec = grid3D();
    DensityGrid whole(spec, KernelSettings{}, 2);
    for (int step = 0; step < 3; ++step)
    {
        for (const Parcel& parcel : randomParcels(spec, 30, 7 + step))
        {
            whole.deposit(parcel, 1e-3);
        }
        whole.commitStep();
    }
    const GridPartition two = GridPartition::bisection(spec, 2);
    // Both formats: the deposit log, replayed, and the node values, cut out
    for (const WindowState& state :
         {whole.saveWindow(DensityGrid::WindowStateFormat::DepositLog), whole.saveWindowValues()})
        for (int p = 0; p < 2; ++p)
        {
            DensityGrid block(spec, KernelSettings{}, 2, GridBlock{two.owned(p), two.owned(p)});
            block.restoreWindow(state);
            const IndexBox owned = two.owned(p);
            for (int k = owned.lo[2]; k <= owned.hi[2]; ++k)
                for (int j = owned.lo[1]; j <= owned.hi[1]; ++j)
                    for (int i = owned.lo[0]; i <= owned.hi[0]; ++i)
                    {
                        const DropletFieldValue a = whole.nodeValue(i, j, k);
                        const DropletFieldValue b = block.nodeValue(i, j, k);
                        ASSERT_EQ(a.rho, b.rho);
                        ASSERT_EQ(a.rMeanMass, b.rMeanMass);
                        ASSERT_EQ(a.velocity, b.velocity);
                    }
            EXPECT_EQ(block.committedSteps(), whole.committedSteps());
        }
}
