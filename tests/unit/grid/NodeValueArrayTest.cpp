// NodeValueArray: zero without being written; an array of a megabyte or more has no
// resident page until touched, unless the pages are asked populated (balanced grid
// blocks), when every page is resident at once. Residency read back from the kernel
// (mincore), a second source independent of the allocator.
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
    populateNodeValuePages(false);
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

TEST(NodeValueArray, PopulatedPagesAreResidentAndZeroAtOnce)
{
    populateNodeValuePages(true);
    const NodeValueArray values = zeroedNodeValues(doubles);
    populateNodeValuePages(false);
    EXPECT_EQ(residentShare(values), 1.0);
    for (const double v : values)
    {
        ASSERT_EQ(v, 0.0);
    }
}
