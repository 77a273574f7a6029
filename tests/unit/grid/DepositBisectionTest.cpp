// Grid blocks sized by the steady deposit's work: GridPartition::depositBisection on a
// DepositWork. Each part's work is computed here by an explicit loop over the parcels (a
// parcel in full to every part its deposit box meets) and the nodes
// (touched work per node), not from the groups or the tiles; the cuts are compared with a
// brute force over every cut of the box.
#include "grid/DepositWork.hpp"
#include "grid/GridPartition.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

using namespace dropletFiber;

namespace
{

struct Spray
{
    std::vector<IndexBox> boxes; // the parcels' deposit boxes (nodes)
    std::vector<double> work;    // each parcel's work
    double touchedPerNode = 0.0; // over each parcel's box, once per parcel
};

GridSpec gridOf(const std::array<int, 3>& nodes)
{
    GridSpec spec;
    spec.lower = Eigen::Vector3d(0, 0, 0);
    spec.upper = Eigen::Vector3d(1, 1, 1);
    spec.nodes = nodes;
    return spec;
}

// Parcels with boxes of `side` nodes a side, the lower corner uniform in [from, to] per
// direction.
Spray sprayIn(int parcels, int side, int from, int to, double touchedPerNode, unsigned seed)
{
    std::mt19937 random(seed);
    std::uniform_int_distribution<int> corner(from, to);
    std::uniform_real_distribution<double> scale(0.5, 1.5);
    Spray spray;
    spray.touchedPerNode = touchedPerNode;
    for (int p = 0; p < parcels; ++p)
    {
        IndexBox box;
        for (int d = 0; d < 3; ++d)
        {
            box.lo[d] = corner(random);
            box.hi[d] = box.lo[d] + side - 1;
        }
        spray.boxes.push_back(box);
        spray.work.push_back(scale(random) * static_cast<double>(box.nodeCount()));
    }
    return spray;
}

DepositWork workOf(const Spray& spray, const std::array<int, 3>& nodes, int maxTiles)
{
    DepositWork work(nodes, maxTiles);
    for (std::size_t p = 0; p < spray.boxes.size(); ++p)
    {
        work.addParcel(spray.boxes[p], spray.work[p]);
        work.addTouched(spray.boxes[p], spray.touchedPerNode);
    }
    return work;
}

// The work on a part, parcel by parcel and node by node.
double partWork(const Spray& spray, const IndexBox& part)
{
    double work = 0.0;
    for (std::size_t p = 0; p < spray.boxes.size(); ++p)
    {
        const IndexBox common = spray.boxes[p].intersected(part);
        if (!common.empty())
        {
            work += spray.work[p];
        }
        work += spray.touchedPerNode * static_cast<double>(common.nodeCount());
    }
    return work;
}

// The smallest max(lower / lowerParts, upper / upperParts) over every cut of a box of tiles
// given to `parts` processors (the lower part's first), each side keeping a tile per
// processor, the sides' work by partWork.
double bruteForceBestCut(const Spray& spray, const DepositWork& work, const IndexBox& tileBox, int parts)
{
    const int lowerParts = parts / 2;
    double best = 1e300;
    for (int d = 0; d < 3; ++d)
    {
        for (int c = tileBox.lo[d] + 1; c <= tileBox.hi[d]; ++c)
        {
            IndexBox lower = tileBox;
            IndexBox upper = tileBox;
            lower.hi[d] = c - 1;
            upper.lo[d] = c;
            if (lower.nodeCount() < static_cast<std::size_t>(lowerParts)
                || upper.nodeCount() < static_cast<std::size_t>(parts - lowerParts))
            {
                continue;
            }
            const double l = partWork(spray, work.touched().nodesOf(lower)) / lowerParts;
            const double u = partWork(spray, work.touched().nodesOf(upper)) / (parts - lowerParts);
            best = std::min(best, std::max(l, u));
        }
    }
    return best;
}

IndexBox tilesOf(const DepositWork& work)
{
    const std::array<int, 3>& t = work.tiles();
    return IndexBox{{{0, 0, 0}}, {{t[0] - 1, t[1] - 1, t[2] - 1}}};
}

// The tile box of a part of whole tiles.
IndexBox tileBoxOf(const DepositWork& work, const IndexBox& nodes)
{
    IndexBox tiles;
    for (int d = 0; d < 3; ++d)
    {
        tiles.lo[d] = nodes.lo[d] / work.touched().tileNodes()[d];
        tiles.hi[d] = nodes.hi[d] / work.touched().tileNodes()[d];
    }
    return tiles;
}

} // namespace

TEST(DepositBisection, TwoPartsTakeTheBestCutOfABruteForce)
{
    const std::array<int, 3> nodes{{20, 16, 12}};
    const Spray spray = sprayIn(60, 4, 0, 8, 0.3, 11);
    const DepositWork work = workOf(spray, nodes, 8);
    const GridPartition partition = GridPartition::depositBisection(work, 2);
    ASSERT_TRUE(partition.tiles(gridOf(nodes)));
    const double most = std::max(partWork(spray, partition.owned(0)), partWork(spray, partition.owned(1)));
    EXPECT_NEAR(most, bruteForceBestCut(spray, work, tilesOf(work), 2), 1e-9 * most);
    // The groups' sum per block is the parcels' (blocks of whole tiles)
    EXPECT_NEAR(work.workOf(partition.owned(1)), partWork(spray, partition.owned(1)), 1e-9 * most);
}

TEST(DepositBisection, ThreePartsTakeTheBestCutAtEachLevel)
{
    const std::array<int, 3> nodes{{18, 14, 10}};
    const Spray spray = sprayIn(80, 3, 1, 7, 0.2, 5);
    const DepositWork work = workOf(spray, nodes, 7);
    const GridPartition partition = GridPartition::depositBisection(work, 3);
    ASSERT_TRUE(partition.tiles(gridOf(nodes)));
    // First cut: processor 0 below, 1 and 2 above
    const IndexBox upper = partition.owned(1).united(partition.owned(2));
    ASSERT_EQ(upper.nodeCount(), partition.owned(1).nodeCount() + partition.owned(2).nodeCount());
    const double first = std::max(partWork(spray, partition.owned(0)), partWork(spray, upper) / 2.0);
    EXPECT_NEAR(first, bruteForceBestCut(spray, work, tilesOf(work), 3), 1e-9 * first);
    // Second cut, inside the upper box
    const double second = std::max(partWork(spray, partition.owned(1)), partWork(spray, partition.owned(2)));
    EXPECT_NEAR(second, bruteForceBestCut(spray, work, tileBoxOf(work, upper), 2), 1e-9 * second);
}

TEST(DepositBisection, SprayInACornerOverFourPartsWithinTheBound)
{
    // 300 parcels of 5 nodes a side in the corner [2, 22]^3 of a 48^3 grid (7 % of it),
    // tiles of 2 nodes
    const std::array<int, 3> nodes{{48, 48, 48}};
    const Spray spray = sprayIn(300, 5, 2, 18, 0.05, 3);
    const DepositWork work = workOf(spray, nodes, 24);
    // L: the largest work meeting one tile layer of the grid (parcels in full, touched nodes)
    double largestLayer = 0.0;
    for (int d = 0; d < 3; ++d)
    {
        for (int t = 0; t < work.tiles()[d]; ++t)
        {
            IndexBox layer = tilesOf(work);
            layer.lo[d] = t;
            layer.hi[d] = t;
            largestLayer = std::max(largestLayer, partWork(spray, work.touched().nodesOf(layer)));
        }
    }
    const double total = partWork(spray, gridOf(nodes).fullBox());
    EXPECT_NEAR(work.total(), total, 1e-9 * total);
    for (const int parts : {2, 3, 4, 5, 7})
    {
        const GridPartition partition = GridPartition::depositBisection(work, parts);
        ASSERT_TRUE(partition.tiles(gridOf(nodes))) << parts;
        double most = 0.0;
        double sum = 0.0;
        for (int p = 0; p < parts; ++p)
        {
            const double w = partWork(spray, partition.owned(p));
            EXPECT_LE(w, total / parts + 4.5 * largestLayer) << parts << " parts, part " << p;
            most = std::max(most, w);
            sum += w;
        }
        if (parts <= 4)
        {
            EXPECT_LE(most / (sum / parts), 1.25) << parts;
        }
        // By node counts the corner's part does nearly all of it
        const GridPartition even = GridPartition::bisection(gridOf(nodes), parts);
        double evenMost = 0.0;
        for (int p = 0; p < parts; ++p)
        {
            evenMost = std::max(evenMost, partWork(spray, even.owned(p)));
        }
        EXPECT_GT(evenMost / (total / parts), 1.5) << parts;
    }
}

TEST(DepositBisection, GroupsSumParcelsOfTheSameTilesAndPartitionsAreDeterministic)
{
    const std::array<int, 3> nodes{{10, 10, 10}};
    DepositWork work(nodes, 5);
    // Tiles of 2 nodes: boxes 0..2 and 1..3 both meet tiles 0..1; 4..5 meets tile 2 only
    work.addParcel(IndexBox{{{0, 0, 0}}, {{2, 2, 2}}}, 1.0);
    work.addParcel(IndexBox{{{1, 1, 1}}, {{3, 3, 3}}}, 2.0);
    work.addParcel(IndexBox{{{4, 4, 4}}, {{5, 5, 5}}}, 4.0);
    work.addParcel(IndexBox{{{11, 11, 11}}, {{12, 12, 12}}}, 8.0); // outside: nothing
    ASSERT_EQ(work.groupCount(), 2u);
    const std::vector<DepositWork::ParcelGroup> groups = work.groups();
    EXPECT_EQ(groups[0].tiles, (IndexBox{{{0, 0, 0}}, {{1, 1, 1}}}));
    EXPECT_DOUBLE_EQ(groups[0].work, 3.0);
    EXPECT_EQ(groups[1].tiles, (IndexBox{{{2, 2, 2}}, {{2, 2, 2}}}));
    EXPECT_DOUBLE_EQ(groups[1].work, 4.0);
    // A gathered group adds to the same tiles'
    work.addGroup(IndexBox{{{2, 2, 2}}, {{2, 2, 2}}}, 0.5);
    EXPECT_DOUBLE_EQ(work.groups()[1].work, 4.5);
    // A block of tiles 2-4 (nodes 4-9) meets the second group only; tiles 3-4 none
    EXPECT_DOUBLE_EQ(work.workOf(IndexBox{{{4, 0, 0}}, {{9, 9, 9}}}), 4.5);
    EXPECT_DOUBLE_EQ(work.workOf(IndexBox{{{6, 0, 0}}, {{9, 9, 9}}}), 0.0);
    const DepositWork copy = work;
    for (int parts = 1; parts <= 9; ++parts)
    {
        const GridPartition a = GridPartition::depositBisection(work, parts);
        EXPECT_EQ(a.boxes(), GridPartition::depositBisection(copy, parts).boxes());
        EXPECT_TRUE(a.tiles(gridOf(nodes))) << parts;
        for (const IndexBox& box : a.boxes())
        {
            EXPECT_FALSE(box.empty()) << parts;
        }
    }
    // No work anywhere: the nodes are evened as far as the 5 tile layers allow (2 and 3)
    const DepositWork none(nodes, 5);
    const GridPartition even = GridPartition::depositBisection(none, 2);
    EXPECT_EQ(std::max(even.owned(0).nodeCount(), even.owned(1).nodeCount()), 600u);
    EXPECT_THROW(GridPartition::depositBisection(none, 126), std::invalid_argument);
}

TEST(DepositBisection, NodeCapKeepsEveryPartNearItsShareOfTheGrid)
{
    // The corner spray of above: by work alone the parts outside the corner are large
    const std::array<int, 3> nodes{{48, 48, 48}};
    const Spray spray = sprayIn(300, 5, 2, 18, 0.05, 3);
    const DepositWork work = workOf(spray, nodes, 24);
    const double gridNodes = 48.0 * 48.0 * 48.0;
    for (const int parts : {2, 3, 4})
    {
        const double cap = 1.25 * gridNodes / parts;
        std::size_t uncappedMost = 0;
        for (const IndexBox& box : GridPartition::depositBisection(work, parts).boxes())
        {
            uncappedMost = std::max(uncappedMost, box.nodeCount());
        }
        EXPECT_GT(static_cast<double>(uncappedMost), cap) << parts;
        const GridPartition capped = GridPartition::depositBisection(work, parts, cap);
        ASSERT_TRUE(capped.tiles(gridOf(nodes))) << parts;
        for (const IndexBox& box : capped.boxes())
        {
            EXPECT_LE(static_cast<double>(box.nodeCount()), cap) << parts;
        }
    }
    EXPECT_THROW(GridPartition::depositBisection(work, 2, 0.0), std::invalid_argument);
}
