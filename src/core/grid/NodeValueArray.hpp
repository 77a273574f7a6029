// NodeValueArray: the per-node arrays of a grid's step values and averaging window
// (nQuantities doubles per node), zero when allocated without the array being written:
// arrays of a megabyte or more are fresh anonymous pages of the operating system (mmap),
// zero already and given a physical page only when first touched; smaller ones come from
// calloc. (calloc alone would not do: glibc serves blocks below its mmap threshold, which
// grows to 32 MB as such blocks are freed, from the heap, and zeroes all of them.) A
// window slot or step array laid out over a block's live box (LiveBox.hpp) then costs
// the pages its deposits touch, not the whole box: the window's fill follows the spray.
// populateNodeValuePages(true) maps the pages populated instead (resident and zero at
// once, as a zero-filled vector): balanced grid blocks, whose windows move at each
// re-partition, otherwise pay the first touch of their pages in the steps that follow,
// on the blocks at the spray's edge (docs/scaleOut.md: 4 ranks, steady deposit max /
// mean 1.59 lazy against 1.22 populated). Process-wide: every array allocated after.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdlib>
#include <new>
#include <utility>

#include <sys/mman.h>
#include <vector>

namespace dropletFiber
{

// Whether arrays of pagesFrom bytes or more are mapped populated (see above); false.
inline std::atomic<bool>& nodeValuePagesPopulated()
{
    static std::atomic<bool> populated{false};
    return populated;
}
inline void populateNodeValuePages(bool populated)
{
    nodeValuePagesPopulated() = populated;
}

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
            memory
                = ::mmap(nullptr, bytes, PROT_READ | PROT_WRITE,
                         MAP_PRIVATE | MAP_ANONYMOUS | (nodeValuePagesPopulated() ? MAP_POPULATE : 0), -1, 0);
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

} // namespace dropletFiber
