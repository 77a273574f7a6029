// NodeValueArray: the per-node arrays of a grid's step values and averaging window
// (nQuantities doubles per node), zero when allocated without the array being written:
// the memory comes from calloc, whose large blocks are fresh pages of the operating
// system, zero already and given a physical page only when first touched. A window slot
// or step array laid out over a block's live box (LiveBox.hpp) then costs the pages its
// deposits touch, not the whole box: the window's fill follows the spray.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdlib>
#include <new>
#include <vector>

namespace dropletFiber
{

// calloc'd storage; elements constructed without arguments are left as they are (zero).
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
        void* memory = std::calloc(n, sizeof(T));
        if (memory == nullptr && n != 0)
        {
            throw std::bad_alloc();
        }
        return static_cast<T*>(memory);
    }
    void deallocate(T* p, std::size_t) noexcept { std::free(p); }
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
