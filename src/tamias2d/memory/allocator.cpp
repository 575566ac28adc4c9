#include "tamias2d/memory/allocator.hpp"

#include <algorithm>
#include <atomic>
#include <mutex>
#include <stdexcept>
#include <string>

#include "tamias2d/errors.hpp"
#include "tamias2d/memory.hpp"

namespace tamias2d {

namespace {

// Changed only while nothing is held (set_allocator), so a block's allocate and free always
// meet the same hook; `hooked_flag` publishes the hook to the threads that read it after.
Allocator hook{};
std::atomic<bool> hooked_flag{false};
std::atomic<std::size_t> held_blocks{0}, held_bytes{0};
std::mutex setting; ///< one set_allocator at a time

std::size_t aligned(std::size_t alignment) {
    return std::max(alignment, alignof(std::max_align_t));
}

void replace(const Allocator& next) {
    const std::lock_guard lock(setting);
    const std::size_t blocks = held_blocks.load(), bytes = held_bytes.load();
    if (blocks != 0)
        throw AllocatorInUse(blocks, bytes);
    // The retained large blocks are mappings of the default allocator, not in use: returned,
    // so that no block outlives the allocator it came from.
    release_retained_memory();
    hook = next;
    hooked_flag.store(next.allocate != nullptr, std::memory_order_release);
}

} // namespace

void set_allocator(const Allocator& next) {
    // Not physics: "allocator" names the rule, as "capacity" does for the capacity hints.
    if (next.allocate == nullptr)
        throw ValidationError(ValidationError::NotANumber{}, "allocator.allocate",
                              "must not be null", "allocator");
    if (next.free == nullptr)
        throw ValidationError(ValidationError::NotANumber{}, "allocator.free", "must not be null",
                              "allocator");
    replace(next);
}

void reset_allocator() {
    replace(Allocator{});
}

Allocator current_allocator() noexcept {
    return hooked_flag.load(std::memory_order_acquire) ? hook : Allocator{};
}

AllocatorUse allocator_use() noexcept {
    return {held_blocks.load(std::memory_order_relaxed),
            held_bytes.load(std::memory_order_relaxed)};
}

namespace memory {

void count_held(std::ptrdiff_t blocks, std::size_t bytes) noexcept {
    held_blocks.fetch_add(std::size_t(blocks), std::memory_order_relaxed);
    held_bytes.fetch_add(bytes, std::memory_order_relaxed);
}

bool hooked() noexcept {
    return hooked_flag.load(std::memory_order_acquire);
}

void* allocate(std::size_t size, std::size_t alignment) {
    const std::size_t a = aligned(alignment);
    void* p = nullptr;
    if (hooked()) {
        p = hook.allocate(size, a, hook.user);
        if (p == nullptr)
            throw std::bad_alloc();
    } else {
        p = ::operator new(size, std::align_val_t(a));
    }
    held_blocks.fetch_add(1, std::memory_order_relaxed);
    held_bytes.fetch_add(size, std::memory_order_relaxed);
    return p;
}

void deallocate(void* p, std::size_t size, std::size_t alignment) noexcept {
    if (p == nullptr)
        return;
    held_blocks.fetch_sub(1, std::memory_order_relaxed);
    held_bytes.fetch_sub(size, std::memory_order_relaxed);
    if (hooked())
        hook.free(p, size, aligned(alignment), hook.user);
    else // unsized: the sized form needs -fsized-deallocation, off by default in Clang 14
        ::operator delete(p, std::align_val_t(aligned(alignment)));
}

} // namespace memory
} // namespace tamias2d
