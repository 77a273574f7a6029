// Balanced grid blocks: the tile field the deposit work is summed on (TileWork) spreads a
// box's work evenly over the tiles' nodes, and the averaging window moved to new blocks
// (AveragingWindow::savePart, joinedWindowState or restoreParts) keeps its slots and total
// bit for bit.
// The partition itself: DepositBisectionTest.
#include "grid/AveragingWindow.hpp"
#include "grid/TileWork.hpp"
#include "grid/WindowTransfer.hpp"

#include <gtest/gtest.h>

#include <random>

using namespace dropletFiber;

TEST(BalancedPartition, TileWorkOfABoxSpreadsEvenlyOverTiles)
{
    // 10 nodes in tiles of 4, 4, 2: a box of nodes 3..6 adds 1 to tile 0, 3 to tile 1
    TileWork work({{10, 1, 1}}, 3);
    EXPECT_EQ(work.tileNodes()[0], 4);
    work.addBox(IndexBox{{{3, 0, 0}}, {{6, 0, 0}}}, 1.0);
    EXPECT_EQ(work.work(), (std::vector<double>{1.0, 3.0, 0.0}));
    // Nodes 2..5: half of tile 0 (0.5) and half of tile 1 (1.5)
    EXPECT_DOUBLE_EQ(work.workIn(IndexBox{{{2, 0, 0}}, {{5, 0, 0}}}), 2.0);
    // Clipped to the grid
    work.addBox(IndexBox{{{8, -2, 0}}, {{12, 3, 0}}}, 2.0);
    EXPECT_DOUBLE_EQ(work.work()[2], 4.0);
}

TEST(WindowTransfer, WindowMovedToNewBlocksKeepsSlotsAndTotalBitForBit)
{
    // Two old blocks (cut at i = 5) re-partitioned into three (cuts at j = 3, i = 7): each
    // new block's window joined from the old blocks' parts equals the part of a window of
    // the whole grid that took the same steps
    const std::array<int, 3> nodes{{12, 8, 1}};
    const int q = 2;
    const int length = 3;
    const IndexBox whole{{{0, 0, 0}}, {{11, 7, 0}}};
    const std::vector<IndexBox> oldBlocks{IndexBox{{{0, 0, 0}}, {{4, 7, 0}}},
                                          IndexBox{{{5, 0, 0}}, {{11, 7, 0}}}};
    const std::vector<IndexBox> newBlocks{IndexBox{{{0, 0, 0}}, {{11, 2, 0}}},
                                          IndexBox{{{0, 3, 0}}, {{6, 7, 0}}},
                                          IndexBox{{{7, 3, 0}}, {{11, 7, 0}}}};
    AveragingWindow wholeWindow(nodes, q, length);
    std::vector<AveragingWindow> old;
    for (const IndexBox& b : oldBlocks)
    {
        old.emplace_back(nodes, b, q, length);
    }
    std::mt19937 random(3);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const std::vector<IndexBox> stepBoxes{
        IndexBox{{{2, 1, 0}}, {{9, 5, 0}}}, IndexBox{{{0, 0, 0}}, {{3, 7, 0}}},
        IndexBox{{{6, 4, 0}}, {{11, 7, 0}}}, IndexBox{{{4, 2, 0}}, {{6, 3, 0}}}};
    for (const IndexBox& box : stepBoxes)
    {
        std::vector<double> step(whole.nodeCount() * q, 0.0);
        for (int j = box.lo[1]; j <= box.hi[1]; ++j)
        {
            for (int i = box.lo[0]; i <= box.hi[0]; ++i)
            {
                for (int c = 0; c < q; ++c)
                {
                    step[flatNodeIndex(nodes, i, j, 0) * q + static_cast<std::size_t>(c)] = u(random);
                }
            }
        }
        wholeWindow.push(step, box);
        for (std::size_t b = 0; b < old.size(); ++b)
        {
            old[b].push(step.data(), whole, box.intersected(oldBlocks[b]));
        }
    }
    for (const IndexBox& block : newBlocks)
    {
        std::vector<WindowState> parts;
        for (std::size_t b = 0; b < old.size(); ++b)
        {
            const IndexBox part = block.intersected(oldBlocks[b]);
            if (!part.empty())
            {
                parts.push_back(old[b].savePart(part));
            }
        }
        AveragingWindow moved(nodes, block, q, length);
        moved.restore(joinedWindowState(parts, block));
        // The same without the joined state (restoreParts: each part freed once copied)
        AveragingWindow movedFromParts(nodes, block, q, length);
        movedFromParts.restoreParts(parts);
        for (const WindowState& part : parts)
        {
            EXPECT_TRUE(part.values.empty());
        }
        AveragingWindow reference(nodes, block, q, length);
        reference.restore(wholeWindow.save());
        EXPECT_EQ(moved.total(), reference.total());
        EXPECT_EQ(movedFromParts.total(), reference.total());
        EXPECT_EQ(movedFromParts.save().counters, reference.save().counters);
        EXPECT_EQ(moved.committedSteps(), 4);
        EXPECT_EQ(moved.filled(), length);
        // Each slot: the totals again after each further (empty) step evicts the oldest
        const std::vector<double> none(block.nodeCount() * q, 0.0);
        for (int age = 0; age < length; ++age)
        {
            moved.push(none.data(), block, IndexBox{});
            movedFromParts.push(none.data(), block, IndexBox{});
            reference.push(none.data(), block, IndexBox{});
            EXPECT_EQ(moved.total(), reference.total()) << age;
            EXPECT_EQ(movedFromParts.total(), reference.total()) << age;
        }
    }
}

TEST(WindowTransfer, PartsThatDoNotTileTheBlockAreRefused)
{
    const std::array<int, 3> nodes{{6, 4, 1}};
    AveragingWindow window(nodes, 1, 2);
    std::vector<double> step(24, 1.0);
    window.push(step, IndexBox{{{0, 0, 0}}, {{5, 3, 0}}});
    const IndexBox block{{{0, 0, 0}}, {{5, 3, 0}}};
    const WindowState left = window.savePart(IndexBox{{{0, 0, 0}}, {{2, 3, 0}}});
    EXPECT_THROW(joinedWindowState({left}, block), std::invalid_argument);
    EXPECT_THROW(joinedWindowState({left, left}, block), std::invalid_argument);
    std::vector<WindowState> half{left};
    AveragingWindow fromParts(nodes, 1, 2);
    EXPECT_THROW(fromParts.restoreParts(half), std::invalid_argument);
    const WindowState right = window.savePart(IndexBox{{{3, 0, 0}}, {{5, 3, 0}}});
    const WindowState joined = joinedWindowState({right, left}, block);
    AveragingWindow restored(nodes, 1, 2);
    restored.restore(joined);
    EXPECT_EQ(restored.total(), window.total());
    EXPECT_THROW(window.savePart(IndexBox{{{3, 0, 0}}, {{6, 3, 0}}}), std::invalid_argument);
}
