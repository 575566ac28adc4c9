// Storage for the world's large per-step arrays (bodies, shapes, contacts, tree nodes, solver
// packs): a vector of trivially copyable elements whose large blocks grow in place.
//
// From 1 MiB up, a block is mapped from the kernel, 2 MiB-aligned and asked to be backed by
// transparent huge pages: at 16k bodies a step touches about 18 MB of such arrays, more than
// the TLB maps in 4 KiB pages, and huge pages make rain_16k 5-12 % faster (docs/performance.md).
// Such a block grows by remapping its pages (mremap), not by copying them into a new block: a
// world whose contacts and packs grow during its first steps needs only the new pages, not a
// second copy of the old ones. New pages are what costs on a virtual machine whose
// kernel hands freed memory back to the host (free page reporting: rain_16k's growth needed
// 42 MiB of them with copying and needs 24 by remapping; docs/performance.md).
// A released large block is kept mapped, up to 64 MiB in all, for the blocks of the next world,
// as malloc keeps freed heap memory for the peers (release_retained_memory() returns it).
// Smaller blocks come from the library's allocator (memory/allocator.hpp: operator new, so the
// steady-state allocation test sees them); the large ones are counted by large_array_stats().
// With an allocator hook set (allocator.hpp) every block, large or small, comes from the hook,
// and a large one grows by copying: the game's allocator decides where memory comes from.
#pragma once

#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <new>
#include <type_traits>
#include <utility>

#include "tamias2d/memory.hpp"

namespace tamias2d {

namespace detail {
/// A block of `bytes` (its capacity), aligned to `align` (and to 2 MiB when large).
void* allocate_block(std::size_t bytes, std::size_t align);
/// Block p of `old_bytes`, whose first `used` bytes matter, as a block of `new_bytes` holding
/// them; p is no longer valid unless returned. On failure (std::bad_alloc) p is unchanged.
void* grow_block(void* p, std::size_t used, std::size_t old_bytes, std::size_t new_bytes,
                 std::size_t align);
void release_block(void* p, std::size_t bytes, std::size_t align) noexcept;
} // namespace detail

/// The subset of std::vector the world uses, for trivially copyable elements (which may be
/// moved by copying their bytes, as remapping does). New elements are value-initialised.
template <class T> class LargeArray {
    static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>,
                  "a LargeArray moves its elements by their bytes");

  public:
    using value_type = T;
    using size_type = std::size_t;
    using iterator = T*;
    using const_iterator = const T*;

    LargeArray() = default;
    explicit LargeArray(std::size_t n) { resize(n); }
    LargeArray(const LargeArray& o) { *this = o; }
    LargeArray(LargeArray&& o) noexcept
        : data_(std::exchange(o.data_, nullptr)), size_(std::exchange(o.size_, 0)),
          capacity_(std::exchange(o.capacity_, 0)) {}
    LargeArray& operator=(const LargeArray& o) {
        if (this != &o) {
            clear();
            reserve(o.size_);
            if (o.size_ != 0)
                std::memcpy(static_cast<void*>(data_), o.data_, o.size_ * sizeof(T));
            size_ = o.size_;
        }
        return *this;
    }
    LargeArray& operator=(LargeArray&& o) noexcept {
        if (this != &o) {
            release();
            data_ = std::exchange(o.data_, nullptr);
            size_ = std::exchange(o.size_, 0);
            capacity_ = std::exchange(o.capacity_, 0);
        }
        return *this;
    }
    ~LargeArray() { release(); }

    std::size_t size() const { return size_; }
    std::size_t capacity() const { return capacity_; }
    bool empty() const { return size_ == 0; }
    T* data() { return data_; }
    const T* data() const { return data_; }
    T* begin() { return data_; }
    T* end() { return data_ + size_; }
    const T* begin() const { return data_; }
    const T* end() const { return data_ + size_; }
    T& operator[](std::size_t i) {
        check_index(i);
        return data_[i];
    }
    const T& operator[](std::size_t i) const {
        check_index(i);
        return data_[i];
    }
    T& front() { return data_[0]; }
    const T& front() const { return data_[0]; }
    T& back() { return data_[size_ - 1]; }
    const T& back() const { return data_[size_ - 1]; }

    void reserve(std::size_t n) {
        if (n <= capacity_)
            return;
        if (n > std::size_t(-1) / sizeof(T))
            throw std::bad_array_new_length();
        data_ = static_cast<T*>(data_ == nullptr ? detail::allocate_block(n * sizeof(T), alignof(T))
                                                 : detail::grow_block(data_, size_ * sizeof(T),
                                                                      capacity_ * sizeof(T),
                                                                      n * sizeof(T), alignof(T)));
        capacity_ = n;
    }
    /// Capacity for `extra` more elements, grown as push_back grows it: the pushes that follow
    /// cannot fail, so that arrays kept parallel grow all or none (bad_alloc).
    void reserve_more(std::size_t extra) {
        if (size_ + extra > capacity_)
            reserve(grown(size_ + extra));
    }
    void resize(std::size_t n) {
        if (n > capacity_)
            reserve(grown(n));
        for (std::size_t i = size_; i < n; ++i)
            ::new (static_cast<void*>(data_ + i)) T();
        size_ = n;
    }
    void assign(std::size_t n, const T& v) {
        const T copy = v; // v may be an element
        clear();
        reserve(n);
        for (std::size_t i = 0; i < n; ++i)
            ::new (static_cast<void*>(data_ + i)) T(copy);
        size_ = n;
    }
    void clear() { size_ = 0; }
    void push_back(const T& v) {
        if (size_ == capacity_) {
            const T copy = v; // v may be an element, which growing moves
            reserve(grown(size_ + 1));
            ::new (static_cast<void*>(data_ + size_)) T(copy);
        } else {
            ::new (static_cast<void*>(data_ + size_)) T(v);
        }
        ++size_;
    }
    template <class... A> T& emplace_back(A&&... args) {
        if (size_ == capacity_) {
            T made(std::forward<A>(args)...); // args may refer to elements
            reserve(grown(size_ + 1));
            ::new (static_cast<void*>(data_ + size_)) T(made);
        } else {
            ::new (static_cast<void*>(data_ + size_)) T(std::forward<A>(args)...);
        }
        return data_[size_++];
    }
    void pop_back() { --size_; }
    /// Down to size(); a large block may become a small one (bytes copied).
    void shrink_to_fit() {
        if (size_ == capacity_)
            return;
        LargeArray fit;
        fit.reserve(size_);
        if (size_ != 0)
            std::memcpy(static_cast<void*>(fit.data_), data_, size_ * sizeof(T));
        fit.size_ = size_;
        *this = std::move(fit);
    }

  private:
    /// With the standard library's checked mode (_GLIBCXX_ASSERTIONS, as std::vector's []
    /// checks there) an index past the end stops the program; otherwise no check, no cost.
    void check_index([[maybe_unused]] std::size_t i) const {
#if defined(_GLIBCXX_ASSERTIONS)
        if (i >= size_)
            std::abort();
#endif
    }

    /// Geometric growth, as std::vector's (libstdc++ doubles).
    std::size_t grown(std::size_t needed) const {
        return needed > 2 * capacity_ ? needed : 2 * capacity_;
    }
    void release() noexcept {
        if (data_ != nullptr)
            detail::release_block(data_, capacity_ * sizeof(T), alignof(T));
        data_ = nullptr;
        size_ = capacity_ = 0;
    }

    T* data_ = nullptr;
    std::size_t size_ = 0, capacity_ = 0;
};

} // namespace tamias2d
