// NodeValueArray: the per-node arrays of a grid's step values and averaging window
// (nQuantities doubles per node), zero when allocated without the array being written:
// arrays of a megabyte or more are fresh anonymous pages of the operating system (mmap),
// zero already and given a physical page only when first touched; smaller ones come from
// calloc. (calloc alone would not do: glibc serves blocks below its mmap threshold, which
// grows to 32 MB as such blocks are freed, from the heap, and zeroes all of them.) A
// block's resident memory then follows the pages its deposits touch, not its size.
// makeBoxResident() faults in a box's pages at once (values kept): balanced grid blocks,
// whose windows move at each re-partition, pre-fault the spray's box there, else the
// blocks at the spray's edge pay the first touch of their pages in the steps that
// follow (docs/scaleOut.md: 4 ranks, steady deposit max / mean 1.59 lazy);
// releaseBoxPages() gives a box's pages back as a moved window's parts are saved.
#pragma once

#include "grid/GridSpec.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <new>
#include <utility>

#include <sys/mman.h>
#include <unistd.h>
#include <vector>

namespace dropletFiber
{

// Zeroed storage; elements constructed without arguments are left as they are (zero).
template <class T>
struct ZeroedAllocator
{
    using value_type = T;
    ZeroedAllocator() = default;
    template <class U>
    ZeroedAllocator(const ZeroedAllocator<U>&) noexcept
    {
    }
    T* allocate(std::size_t n)
    {
        const std::size_t bytes = n * sizeof(T);
        void* memory = nullptr;
        if (bytes >= pagesFrom)
        {
            memory = ::mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
            memory = memory == MAP_FAILED ? nullptr : memory;
        }
        else
        {
            memory = std::calloc(n, sizeof(T));
        }
        if (memory == nullptr && n != 0)
        {
            throw std::bad_alloc();
        }
        return static_cast<T*>(memory);
    }
    void deallocate(T* p, std::size_t n) noexcept
    {
        const std::size_t bytes = n * sizeof(T);
        if (bytes >= pagesFrom)
        {
            ::munmap(p, bytes);
        }
        else
        {
            std::free(p);
        }
    }
    // Arrays from this size on are mapped pages of their own
    static constexpr std::size_t pagesFrom = std::size_t(1) << 20;
    // Value-initialisation without a write: calloc's zero is the value
    template <class U>
    void construct(U* p) noexcept
    {
        ::new (static_cast<void*>(p)) U;
    }
    template <class U, class... Args>
    void construct(U* p, Args&&... args)
    {
        ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
    }
};

template <class T, class U>
bool operator==(const ZeroedAllocator<T>&, const ZeroedAllocator<U>&) noexcept
{
    return true;
}
template <class T, class U>
bool operator!=(const ZeroedAllocator<T>&, const ZeroedAllocator<U>&) noexcept
{
    return false;
}

using NodeValueArray = std::vector<double, ZeroedAllocator<double>>;

// Comparisons with plain vectors of the same values (found by argument-dependent lookup
// through the allocator): the same elements, in order.
inline bool operator==(const NodeValueArray& a, const std::vector<double>& b)
{
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin());
}
inline bool operator==(const std::vector<double>& a, const NodeValueArray& b)
{
    return b == a;
}
inline bool operator!=(const NodeValueArray& a, const std::vector<double>& b)
{
    return !(a == b);
}
inline bool operator!=(const std::vector<double>& a, const NodeValueArray& b)
{
    return !(b == a);
}

// `size` zeros, written by nobody (NodeValueArray(size) value-initialises through the
// allocator's construct: no write).
inline NodeValueArray zeroedNodeValues(std::size_t size)
{
    return NodeValueArray(size);
}

// The pages holding values[first, first + count) resident and writable, their values
// kept: one madvise(MADV_POPULATE_WRITE) (Linux 5.14 on; MADV_WILLNEED does not fault
// anonymous memory), else each page's first byte written back as read. Each page's
// zeroing then costs here, not in the first deposit that writes it.
inline void makeValuesResident(NodeValueArray& values, std::size_t first, std::size_t count)
{
    if (count == 0 || first >= values.size())
    {
        return;
    }
    count = std::min(count, values.size() - first);
    static const std::uintptr_t page = static_cast<std::uintptr_t>(::sysconf(_SC_PAGESIZE));
    const auto begin = reinterpret_cast<std::uintptr_t>(values.data() + first) / page * page;
    const auto end = reinterpret_cast<std::uintptr_t>(values.data() + first + count);
#ifdef MADV_POPULATE_WRITE
    if (::madvise(reinterpret_cast<void*>(begin), end - begin, MADV_POPULATE_WRITE) == 0)
    {
        return;
    }
#endif
    for (std::uintptr_t at = std::max(begin, reinterpret_cast<std::uintptr_t>(values.data())); at < end;
         at = (at / page + 1) * page)
    {
        volatile unsigned char* byte = reinterpret_cast<unsigned char*>(at);
        *byte = *byte;
    }
}

// Calls onRange(first, count) for each range of the values of `box`'s nodes (nQuantities
// each; grid indices, the part outside `layout` ignored) in an array laid out over
// `layout` (flatIndexInBox): rows that follow each other in memory are one range, so
// that a system call covers as many pages as it can.
template <class OnRange>
void forEachValueRangeIn(const IndexBox& layout, const IndexBox& box, std::size_t nQuantities,
                         OnRange&& onRange)
{
    std::size_t first = 0;
    std::size_t end = 0;
    forEachRowIn(box.intersected(layout), layout,
                 [&](const IndexRow& row)
                 {
                     const std::size_t from = row.first * nQuantities;
                     if (from != end)
                     {
                         onRange(first, end - first);
                         first = from;
                     }
                     end = from + row.length * nQuantities;
                 });
    onRange(first, end - first);
}

// makeValuesResident over the values of `box`'s nodes (nQuantities each; grid indices,
// the part outside `layout` ignored) in an array laid out over `layout`
// (flatIndexInBox): rows that follow each other in memory are one range.
inline void makeBoxResident(NodeValueArray& values, const IndexBox& layout, const IndexBox& box,
                            std::size_t nQuantities)
{
    forEachValueRangeIn(layout, box, nQuantities,
                        [&](std::size_t first, std::size_t count)
                        { makeValuesResident(values, first, count); });
}

// The whole pages inside values[first, first + count) given back to the operating system
// (madvise MADV_DONTNEED): they read as zero after. For arrays about to be freed whose
// values are copied out part by part (a balanced block's window at a move).
inline void releaseValuePages(NodeValueArray& values, std::size_t first, std::size_t count)
{
    if (count == 0 || first >= values.size())
    {
        return;
    }
    count = std::min(count, values.size() - first);
    static const std::uintptr_t page = static_cast<std::uintptr_t>(::sysconf(_SC_PAGESIZE));
    const auto begin = (reinterpret_cast<std::uintptr_t>(values.data() + first) + page - 1) / page * page;
    const auto end = reinterpret_cast<std::uintptr_t>(values.data() + first + count) / page * page;
    if (end > begin && values.size() * sizeof(double) >= ZeroedAllocator<double>::pagesFrom)
    {
        ::madvise(reinterpret_cast<void*>(begin), end - begin, MADV_DONTNEED);
    }
}

// releaseValuePages over the rows of `box` (as makeBoxResident): the pages wholly inside
// runs of the box's rows.
inline void releaseBoxPages(NodeValueArray& values, const IndexBox& layout, const IndexBox& box,
                            std::size_t nQuantities)
{
    forEachValueRangeIn(layout, box, nQuantities,
                        [&](std::size_t first, std::size_t count)
                        { releaseValuePages(values, first, count); });
}

} // namespace dropletFiber
