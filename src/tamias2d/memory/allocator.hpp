// The library's allocation functions (internal) behind the allocator hook (allocator.hpp), and
// a stateless std-compatible allocator over them with the container aliases the sources use:
// every container a World keeps, and every scratch container of its calls, is one of these, so
// that with a hook set its blocks come from the hook. Without one they come from the global
// operator new (so the tests that count operator new still see them).
#pragma once

#include <cstddef>
#include <new>
#include <string>
#include <vector>

#include "tamias2d/allocator.hpp"

namespace tamias2d::memory {

/// A block of `size` (> 0) bytes aligned to max(alignment, alignof(std::max_align_t)), from the
/// hook if one is set, else from operator new; std::bad_alloc when there is none.
void* allocate(std::size_t size, std::size_t alignment);
/// Takes back a block of allocate(size, alignment).
void deallocate(void* p, std::size_t size, std::size_t alignment) noexcept;
/// Counts `blocks` more (or fewer) blocks and `bytes` more (or fewer, modulo 2^N) as held, for
/// the blocks the library takes from elsewhere (the default's mapped large blocks).
void count_held(std::ptrdiff_t blocks, std::size_t bytes) noexcept;
/// Whether a hook is set (the large arrays then take their blocks from it, not from mappings).
bool hooked() noexcept;

/// The std-compatible allocator over allocate/deallocate: stateless, all instances equal.
template <class T> struct HookAllocator {
    using value_type = T;
    HookAllocator() noexcept = default;
    template <class U> HookAllocator(const HookAllocator<U>&) noexcept {} // NOLINT: rebinding
    T* allocate(std::size_t n) {
        if (n > std::size_t(-1) / sizeof(T))
            throw std::bad_array_new_length();
        return static_cast<T*>(memory::allocate(n * sizeof(T), alignof(T)));
    }
    void deallocate(T* p, std::size_t n) noexcept {
        memory::deallocate(p, n * sizeof(T), alignof(T));
    }
    template <class U> bool operator==(const HookAllocator<U>&) const noexcept { return true; }
};

template <class T> using vector = std::vector<T, HookAllocator<T>>;

/// Scratch of n value-initialised Ts: in the object itself up to N, else from the allocator
/// (a call's scratch that is usually small, such as a body's shapes, then allocates nothing).
template <class T, std::size_t N> class Scratch {
  public:
    explicit Scratch(std::size_t n) : size_(n) {
        if (n > N)
            more_.resize(n);
    }
    T* data() { return size_ > N ? more_.data() : inline_; }
    std::size_t size() const { return size_; }
    T& operator[](std::size_t i) { return data()[i]; }

  private:
    std::size_t size_;
    T inline_[N]{};
    vector<T> more_;
};
using string = std::basic_string<char, std::char_traits<char>, HookAllocator<char>>;

/// An object of class T whose storage comes from the hook: T derives from it, and `new T` and
/// `delete` (std::unique_ptr<T>'s) go through allocate/deallocate.
template <class T> struct HookAllocated {
    static void* operator new(std::size_t size) { return memory::allocate(size, alignof(T)); }
    static void operator delete(void* p, std::size_t size) noexcept {
        memory::deallocate(p, size, alignof(T));
    }
};

} // namespace tamias2d::memory
