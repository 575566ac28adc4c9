#include "tamias2d/memory/large_array.hpp"

#include "tamias2d/memory/allocator.hpp"
#include "tamias2d/memory/retained_blocks.hpp"

#include <algorithm>
#include <atomic>
#include <cstdint>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace tamias2d {

namespace {
constexpr std::size_t huge_page = std::size_t(2) << 20;
constexpr std::size_t large_from = std::size_t(1) << 20; ///< the rounding wastes under 2 MiB

std::atomic<std::size_t> maps{0}, unmaps{0}, remaps{0}, mapped_bytes{0};

bool is_large(std::size_t bytes) {
    return bytes >= large_from;
}
/// A large block's mapping: whole huge pages (a growth within them needs nothing).
std::size_t rounded(std::size_t bytes) {
    return (bytes + huge_page - 1) / huge_page * huge_page;
}

// The platform's part: fresh aligned blocks of whole huge pages, given back, and grown without
// a copy where the platform can.
#if defined(__linux__)
/// `size` bytes of fresh zero pages on a huge-page boundary, advised to be backed by huge pages
/// (only advice: without transparent huge pages this fails harmlessly).
void* map_fresh(std::size_t size) {
    void* raw =
        mmap(nullptr, size + huge_page, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (raw == MAP_FAILED)
        throw std::bad_alloc();
    // Over-map by a huge page, then return the unaligned head and the tail.
    const auto start = reinterpret_cast<std::uintptr_t>(raw);
    const std::uintptr_t aligned = (start + huge_page - 1) / huge_page * huge_page;
    if (aligned != start)
        munmap(raw, aligned - start);
    const std::uintptr_t tail = aligned + size, end = start + size + huge_page;
    if (end != tail)
        munmap(reinterpret_cast<void*>(tail), end - tail);
    void* p = reinterpret_cast<void*>(aligned);
#if defined(MADV_HUGEPAGE)
    madvise(p, size, MADV_HUGEPAGE);
#endif
    return p;
}
void unmap_fresh(void* p, std::size_t size) noexcept {
    munmap(p, size);
}
/// Block p grown from old_size to new_size bytes without copying: in place when the address
/// space after it is free, else its pages moved to the head of a fresh aligned mapping, so that
/// huge pages stay whole.
void* grow_fresh(void* p, std::size_t /*used: the pages move whole*/, std::size_t old_size,
                 std::size_t new_size) {
    if (mremap(p, old_size, new_size, 0) != MAP_FAILED) {
#if defined(MADV_HUGEPAGE)
        madvise(p, new_size, MADV_HUGEPAGE);
#endif
        return p;
    }
    void* q = map_fresh(new_size);
    if (mremap(p, old_size, old_size, MREMAP_MAYMOVE | MREMAP_FIXED, q) == MAP_FAILED) {
        munmap(q, new_size);
        throw std::bad_alloc();
    }
    return q;
}
#else
// Elsewhere: aligned operator new, and growth by copying.
void* map_fresh(std::size_t size) {
    return ::operator new(size, std::align_val_t(huge_page));
}
void unmap_fresh(void* p, std::size_t /*size*/) noexcept {
    ::operator delete(p, std::align_val_t(huge_page)); // unsized, as in release_block
}
void* grow_fresh(void* p, std::size_t used, std::size_t old_size, std::size_t new_size) {
    void* q = map_fresh(new_size);
    std::memcpy(q, p, used);
    unmap_fresh(p, old_size);
    return q;
}
#endif

/// A retained block if one holds the size, else a fresh one.
void* map_large(std::size_t bytes) {
    void* p = detail::retained_blocks().take(rounded(bytes));
    if (p == nullptr)
        p = map_fresh(rounded(bytes));
    maps.fetch_add(1, std::memory_order_relaxed);
    mapped_bytes.fetch_add(rounded(bytes), std::memory_order_relaxed);
    return p;
}
/// Retained for the next blocks if it fits under the limit, else given back.
void unmap_large(void* p, std::size_t bytes) noexcept {
    if (!detail::retained_blocks().keep(p, rounded(bytes)))
        unmap_fresh(p, rounded(bytes));
    unmaps.fetch_add(1, std::memory_order_relaxed);
    mapped_bytes.fetch_sub(rounded(bytes), std::memory_order_relaxed);
}
/// A large block grown to new_bytes, its first `used` bytes kept: copied into a retained block
/// if one holds it (the old block is retained in turn: no page is faulted or given up), else
/// grown by the platform.
void* remap_large(void* p, std::size_t used, std::size_t old_bytes, std::size_t new_bytes) {
    const std::size_t old_size = rounded(old_bytes), new_size = rounded(new_bytes);
    if (new_size == old_size)
        return p;
    if (void* kept = detail::retained_blocks().take(new_size)) {
        std::memcpy(kept, p, used);
        if (!detail::retained_blocks().keep(p, old_size))
            unmap_fresh(p, old_size);
        p = kept;
    } else {
        p = grow_fresh(p, used, old_size, new_size);
    }
    remaps.fetch_add(1, std::memory_order_relaxed);
    mapped_bytes.fetch_add(new_size - old_size, std::memory_order_relaxed);
    return p;
}
} // namespace

LargeArrayStats large_array_stats() noexcept {
    return {maps.load(std::memory_order_relaxed), unmaps.load(std::memory_order_relaxed),
            remaps.load(std::memory_order_relaxed), mapped_bytes.load(std::memory_order_relaxed),
            detail::retained_blocks().bytes()};
}

void release_retained_memory() noexcept {
    detail::retained_blocks().release_all(unmap_fresh);
}

namespace detail {

// With an allocator hook set (allocator.hpp) every block, large or small, comes from it, and a
// large one grows by copying into a new block; without one the small blocks come from operator
// new and the large ones are mapped. The hook cannot change while a block is held, so a block
// is always released to the allocator it came from.
void* allocate_block(std::size_t bytes, std::size_t align) {
    if (is_large(bytes) && !memory::hooked()) {
        void* p = map_large(bytes);
        memory::count_held(1, rounded(bytes));
        return p;
    }
    return memory::allocate(bytes, align);
}

void* grow_block(void* p, std::size_t used, std::size_t old_bytes, std::size_t new_bytes,
                 std::size_t align) {
    if (is_large(old_bytes) && !memory::hooked()) {
        void* q = remap_large(p, used, old_bytes, new_bytes);
        memory::count_held(0, rounded(new_bytes) - rounded(old_bytes));
        return q;
    }
    void* q = allocate_block(new_bytes, align);
    if (used != 0)
        std::memcpy(q, p, used);
    release_block(p, old_bytes, align);
    return q;
}

void release_block(void* p, std::size_t bytes, std::size_t align) noexcept {
    if (is_large(bytes) && !memory::hooked()) {
        unmap_large(p, bytes);
        memory::count_held(-1, -rounded(bytes));
    } else {
        memory::deallocate(p, bytes, align);
    }
}

} // namespace detail
} // namespace tamias2d
