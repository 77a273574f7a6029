// NodeValueArray: zero without being written; an array of a megabyte or more has no
// resident page until touched; makeBoxResident faults in exactly the pages of a box's
// rows (a moved balanced block's spray), its values kept. Residency read back from the
// kernel (mincore), a second source independent of the allocator.
#include "grid/NodeValueArray.hpp"

#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <unistd.h>
#include <vector>

using namespace dropletFiber;

namespace
{

// The fraction of the array's whole pages the kernel says are resident.
double residentShare(const NodeValueArray& values)
{
    const std::size_t page = static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));
    const auto begin = reinterpret_cast<std::uintptr_t>(values.data());
    const std::uintptr_t first = (begin + page - 1) / page * page;
    const std::uintptr_t last = (begin + values.size() * sizeof(double)) / page * page;
    const std::size_t pages = (last - first) / page;
    std::vector<unsigned char> resident(pages);
    EXPECT_EQ(::mincore(reinterpret_cast<void*>(first), last - first, resident.data()), 0);
    std::size_t count = 0;
    for (const unsigned char r : resident)
    {
        count += r & 1U;
    }
    return static_cast<double>(count) / static_cast<double>(pages);
}

// 8 MB: far above the size from which arrays are pages of their own
constexpr std::size_t doubles = std::size_t(1) << 20;

} // namespace

TEST(NodeValueArray, LargeArrayIsZeroAndNotResidentUntilTouched)
{
    NodeValueArray values = zeroedNodeValues(doubles);
    EXPECT_EQ(residentShare(values), 0.0);
    values[doubles / 2] = 1.0; // one page (a 2 MB huge page where the kernel gives those)
    EXPECT_GT(residentShare(values), 0.0);
    EXPECT_LE(residentShare(values), 0.25);
    double sum = 0.0;
    for (const double v : values)
    {
        sum += v;
    }
    EXPECT_EQ(sum, 1.0);
}

TEST(NodeValueArray, BoxResidentPagesAreThoseOfTheBoxRows)
{
    // An array over a block of 64 x 32 x 16 nodes at lo (10, 20, 30), 7 values a node (1.8
    // MB; a row: 3584 bytes, under a page); the box: i 40..80, j 25..34, k 31..32, beyond
    // the block in i (clipped to it)
    const IndexBox layout{{{10, 20, 30}}, {{73, 51, 45}}};
    const IndexBox box{{{40, 25, 31}}, {{80, 34, 32}}};
    const std::size_t q = 7;
    NodeValueArray values = zeroedNodeValues(layout.nodeCount() * q);
    const std::size_t kept = flatIndexInBox(layout, 50, 30, 32) * q + 3;
    values[kept] = 2.5;
    const std::size_t page = static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));
    const auto begin = reinterpret_cast<std::uintptr_t>(values.data());
    ASSERT_EQ(begin % page, 0U); // mapped pages of its own
    // Expected: the page of every value of every node of the box inside the block
    std::vector<unsigned char> expected((values.size() * sizeof(double) + page - 1) / page, 0);
    for (int k = 31; k <= 32; ++k)
    {
        for (int j = 25; j <= 34; ++j)
        {
            for (int i = 40; i <= 73; ++i)
            {
                for (std::size_t c = 0; c < q; ++c)
                {
                    expected[(flatIndexInBox(layout, i, j, k) * q + c) * sizeof(double) / page] = 1;
                }
            }
        }
    }
    expected[kept * sizeof(double) / page] = 1;
    makeBoxResident(values, layout, box, q);
    std::vector<unsigned char> resident(expected.size());
    ASSERT_EQ(::mincore(values.data(), expected.size() * page, resident.data()), 0);
    std::size_t pages = 0;
    for (std::size_t p = 0; p < expected.size(); ++p)
    {
        EXPECT_EQ(resident[p] & 1U, expected[p]) << "page " << p;
        pages += expected[p];
    }
    EXPECT_GT(pages, 10U);
    EXPECT_EQ(values[kept], 2.5);
    std::size_t nonZero = 0;
    for (const double v : values)
    {
        nonZero += v != 0.0;
    }
    EXPECT_EQ(nonZero, 1U);
}

TEST(NodeValueArray, ReleasedBoxGivesBackItsWholePagesOnly)
{
    // A written array over 64 x 32 x 16 nodes, 7 values a node: the rows j 0..31 of
    // planes k 4..7 (one run of 4 x 32 rows, 458 752 bytes) given back; every page wholly
    // inside that run reads zero and is not resident, every value outside it is kept
    const IndexBox layout{{{0, 0, 0}}, {{63, 31, 15}}};
    const IndexBox box{{{0, 0, 4}}, {{63, 31, 7}}};
    const std::size_t q = 7;
    NodeValueArray values = zeroedNodeValues(layout.nodeCount() * q);
    for (std::size_t v = 0; v < values.size(); ++v)
    {
        values[v] = static_cast<double>(v + 1);
    }
    releaseBoxPages(values, layout, box, q);
    const std::size_t page = static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));
    const std::size_t first = flatIndexInBox(layout, 0, 0, 4) * q * sizeof(double);
    const std::size_t end = (flatIndexInBox(layout, 63, 31, 7) + 1) * q * sizeof(double);
    const std::size_t firstPage = (first + page - 1) / page;
    const std::size_t endPage = end / page;
    ASSERT_GT(endPage, firstPage + 100);
    std::vector<unsigned char> resident((values.size() * sizeof(double) + page - 1) / page);
    ASSERT_EQ(::mincore(values.data(), resident.size() * page, resident.data()), 0);
    for (std::size_t p = 0; p < resident.size(); ++p)
    {
        EXPECT_EQ(resident[p] & 1U, p >= firstPage && p < endPage ? 0U : 1U) << "page " << p;
    }
    for (std::size_t v = 0; v < values.size(); ++v)
    {
        const std::size_t byte = v * sizeof(double);
        const bool released = byte >= firstPage * page && byte < endPage * page;
        ASSERT_EQ(values[v], released ? 0.0 : static_cast<double>(v + 1)) << v;
    }
}
