// Storage for the world's large per-step arrays (bodies, shapes, contacts, tree nodes, solver
// packs). From 1 MiB up, a block is 2 MiB-aligned and asked to be backed by transparent huge
// pages: at 16k bodies a step touches about 18 MB of such arrays, more than the TLB maps in
// 4 KiB pages, and huge pages made rain_16k 5-12 % faster (docs/performance.md, session 6).
// Smaller blocks are ordinary. Allocation goes through operator new either way, so allocation
// counters (the steady-state test) still see every block.
#pragma once

#include <cstddef>
#include <new>
#include <vector>

namespace tamias2d {

namespace detail {
void* allocate_large_array(std::size_t bytes, std::size_t align);
void deallocate_large_array(void* p, std::size_t bytes, std::size_t align) noexcept;
} // namespace detail

template <class T> struct LargeArrayAllocator {
    using value_type = T;
    LargeArrayAllocator() = default;
    template <class U> constexpr LargeArrayAllocator(const LargeArrayAllocator<U>&) noexcept {}
    T* allocate(std::size_t n) {
        if (n > std::size_t(-1) / sizeof(T))
            throw std::bad_array_new_length();
        return static_cast<T*>(detail::allocate_large_array(n * sizeof(T), alignof(T)));
    }
    void deallocate(T* p, std::size_t n) noexcept {
        detail::deallocate_large_array(p, n * sizeof(T), alignof(T));
    }
    template <class U>
    friend constexpr bool operator==(LargeArrayAllocator, LargeArrayAllocator<U>) {
        return true;
    }
};

/// A std::vector whose large blocks sit on huge pages.
template <class T> using LargeArray = std::vector<T, LargeArrayAllocator<T>>;

} // namespace tamias2d
