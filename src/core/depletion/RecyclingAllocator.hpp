// RecyclingAllocator: an allocator for node-based containers (CaptureLimit's per-node maps)
// whose single small objects, the nodes, go back to a free list of the container's own pool
// when freed and are handed out again, instead of returning to the heap: a map cleared and
// refilled every time step (demand, granted ratios, taken fractions) allocates from the
// heap only while it grows past its largest size. Everything else (the bucket arrays)
// comes from operator new as usual. The container's algorithm is the standard one, so its
// iteration order, and every sum taken in it, is the same as with std::allocator.
//
// Memory: the pool keeps the largest number of nodes ever held at once (32 bytes each),
// in the chunks themselves.
// Copies of an allocator share its pool (shared ownership: a container and its copies may
// free each other's nodes); each default-constructed one has its own. Not thread-safe, like
// the containers using it.
#pragma once

#include <cstddef>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>

namespace dropletFiber
{

// Blocks of chunkBytes bytes (operator new's alignment), recycled: a freed block holds the
// link to the next free one (no memory of its own, nothing allocated when freeing).
class NodePool
{
public:
    static constexpr std::size_t chunkBytes = 32;

    NodePool() = default;
    NodePool(const NodePool&) = delete;
    NodePool& operator=(const NodePool&) = delete;
    ~NodePool()
    {
        while (free_ != nullptr)
        {
            ::operator delete(std::exchange(free_, free_->next));
        }
    }
    void* allocate()
    {
        if (free_ == nullptr)
        {
            return ::operator new(chunkBytes);
        }
        return std::exchange(free_, free_->next);
    }
    void deallocate(void* chunk) noexcept { free_ = ::new (chunk) FreeChunk{free_}; }
    // Blocks held for reuse.
    std::size_t freeChunks() const
    {
        std::size_t count = 0;
        for (const FreeChunk* c = free_; c != nullptr; c = c->next)
        {
            ++count;
        }
        return count;
    }

private:
    struct FreeChunk
    {
        FreeChunk* next;
    };
    FreeChunk* free_ = nullptr;
};

template <class T>
class RecyclingAllocator
{
public:
    using value_type = T;
    using propagate_on_container_copy_assignment = std::true_type;
    using propagate_on_container_move_assignment = std::true_type;
    using propagate_on_container_swap = std::true_type;
    template <class U>
    struct rebind
    {
        using other = RecyclingAllocator<U>;
    };

    RecyclingAllocator() : pool_(std::make_shared<NodePool>()) {}
    template <class U>
    RecyclingAllocator(const RecyclingAllocator<U>& other) noexcept : pool_(other.pool())
    {
    }

    T* allocate(std::size_t n)
    {
        if (fromPool(n))
        {
            return static_cast<T*>(pool_->allocate());
        }
        return static_cast<T*>(::operator new(n * sizeof(T)));
    }
    void deallocate(T* p, std::size_t n) noexcept
    {
        if (fromPool(n))
        {
            pool_->deallocate(p);
            return;
        }
        ::operator delete(p);
    }

    const std::shared_ptr<NodePool>& pool() const { return pool_; }

    template <class U>
    bool operator==(const RecyclingAllocator<U>& other) const
    {
        return pool_ == other.pool();
    }
    template <class U>
    bool operator!=(const RecyclingAllocator<U>& other) const
    {
        return pool_ != other.pool();
    }

private:
    // One object that fits a chunk (a node); alignment beyond operator new's is not asked
    // for by such nodes.
    static bool fromPool(std::size_t n)
    {
        return n == 1 && sizeof(T) <= NodePool::chunkBytes && alignof(T) <= __STDCPP_DEFAULT_NEW_ALIGNMENT__;
    }

    std::shared_ptr<NodePool> pool_;
};

} // namespace dropletFiber
