// RecyclingAllocator, as CaptureLimit's per-node maps use it: a map cleared and refilled step
// by step keeps its nodes in its pool (none go back to the heap, none are taken from it
// while the step holds no more nodes than an earlier one), and iterates in the same order,
// with the same values, as a std::unordered_map with the standard allocator filled alike
// (limit()'s sums are taken in that order). Copies share the pool.
#include "depletion/RecyclingAllocator.hpp"

#include <gtest/gtest.h>

#include <random>
#include <unordered_map>
#include <utility>
#include <vector>

using namespace dropletFiber;

namespace
{

using Recycling = std::unordered_map<std::size_t, double, std::hash<std::size_t>, std::equal_to<std::size_t>,
                                     RecyclingAllocator<std::pair<const std::size_t, double>>>;
using Standard = std::unordered_map<std::size_t, double>;

// One step's nodes: a few clusters of neighbouring flat indices (a fiber's corners), with
// repeats (demand added twice at a node).
std::vector<std::pair<std::size_t, double>> stepNodes(std::mt19937_64& rng, int clusters)
{
    std::uniform_int_distribution<std::size_t> anyNode(0, 200000);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<std::pair<std::size_t, double>> nodes;
    for (int c = 0; c < clusters; ++c)
    {
        const std::size_t first = anyNode(rng);
        for (std::size_t n = 0; n < 24; ++n)
        {
            nodes.emplace_back(first + (n * 7) % 31, unit(rng));
        }
    }
    return nodes;
}

template <class Map>
std::vector<std::pair<std::size_t, double>> inOrder(const Map& map)
{
    return std::vector<std::pair<std::size_t, double>>(map.begin(), map.end());
}

} // namespace

TEST(RecyclingAllocator, IteratesAsTheStandardMapStepByStep)
{
    std::mt19937_64 rng(21);
    Recycling recycling;
    Standard standard;
    for (int step = 0; step < 40; ++step)
    {
        recycling.clear();
        standard.clear();
        for (const auto& [node, value] : stepNodes(rng, 1 + step % 9))
        {
            recycling[node] += value;
            standard[node] += value;
        }
        if (step % 3 == 0)
        {
            // Some nodes moved out (CaptureLimit::takeForeignDemand)
            recycling.erase(recycling.begin());
            standard.erase(standard.begin());
        }
        ASSERT_EQ(recycling.bucket_count(), standard.bucket_count()) << "step " << step;
        ASSERT_EQ(inOrder(recycling), inOrder(standard)) << "step " << step;
    }
}

TEST(RecyclingAllocator, RefillsFromItsPoolAfterAClear)
{
    std::mt19937_64 rng(22);
    Recycling map;
    const std::vector<std::pair<std::size_t, double>> largest = stepNodes(rng, 8);
    for (const auto& [node, value] : largest)
    {
        map[node] = value;
    }
    const std::size_t held = map.size();
    const NodePool& pool = *map.get_allocator().pool();
    EXPECT_EQ(pool.freeChunks(), 0u);
    map.clear();
    EXPECT_EQ(pool.freeChunks(), held); // every node kept for the next step
    for (int step = 0; step < 5; ++step)
    {
        for (const auto& [node, value] : stepNodes(rng, 1 + step))
        {
            map[node] += value;
        }
        EXPECT_EQ(pool.freeChunks() + map.size(), held) << "step " << step; // none from the heap
        map.clear();
    }
    // A copy shares the pool: its nodes return there too
    map[1] = 1.0;
    {
        Recycling copy = map;
        EXPECT_EQ(copy.get_allocator(), map.get_allocator());
        EXPECT_EQ(pool.freeChunks(), held - 2);
    }
    EXPECT_EQ(pool.freeChunks(), held - 1);
}
