// The replaceable global allocation functions ([new.delete]) on malloc and aligned_alloc,
// counted and failing on demand (replaced_new.hpp).
#include "support/replaced_new.hpp"

#include <atomic>
#include <cstddef>
#include <cstdlib>
#include <new>

// Built on malloc/free; once inlined GCC cannot see that they pair up.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
#endif

namespace {

std::atomic<long> left{-1}; ///< allocations before the failure; -1: never fail
std::atomic<bool> failed{false}, fail_once{false};
std::atomic<long> count{0}, released{0};

void* allocate(std::size_t n, std::size_t align) noexcept {
    count.fetch_add(1, std::memory_order_relaxed);
    if (left.load(std::memory_order_relaxed) >= 0 && left.fetch_sub(1) <= 0) {
        left.store(fail_once.load() ? -1 : 0);
        failed.store(true);
        return nullptr;
    }
    if (n == 0)
        n = 1;
    if (align <= alignof(std::max_align_t))
        return std::malloc(n);
    return std::aligned_alloc(align, (n + align - 1) / align * align);
}

void* allocate_or_throw(std::size_t n, std::size_t align) {
    if (void* p = allocate(n, align))
        return p;
    throw std::bad_alloc();
}

void release(void* p) noexcept {
    if (p)
        released.fetch_add(1, std::memory_order_relaxed);
    std::free(p);
}

} // namespace

namespace tamias2d::test {
void fail_allocation_after(long n, bool once) {
    failed.store(false);
    fail_once.store(once);
    left.store(n);
}
void stop_failing() {
    left.store(-1);
}
bool allocation_failed() {
    return failed.load();
}
long allocation_count() {
    return count.load();
}
long deallocation_count() {
    return released.load();
}
} // namespace tamias2d::test

void* operator new(std::size_t n) {
    return allocate_or_throw(n, 0);
}
void* operator new[](std::size_t n) {
    return allocate_or_throw(n, 0);
}
void* operator new(std::size_t n, std::align_val_t a) {
    return allocate_or_throw(n, static_cast<std::size_t>(a));
}
void* operator new[](std::size_t n, std::align_val_t a) {
    return allocate_or_throw(n, static_cast<std::size_t>(a));
}
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
    return allocate(n, 0);
}
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept {
    return allocate(n, 0);
}
void* operator new(std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept {
    return allocate(n, static_cast<std::size_t>(a));
}
void* operator new[](std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept {
    return allocate(n, static_cast<std::size_t>(a));
}
void operator delete(void* p) noexcept {
    release(p);
}
void operator delete[](void* p) noexcept {
    release(p);
}
void operator delete(void* p, std::size_t) noexcept {
    release(p);
}
void operator delete[](void* p, std::size_t) noexcept {
    release(p);
}
void operator delete(void* p, std::align_val_t) noexcept {
    release(p);
}
void operator delete[](void* p, std::align_val_t) noexcept {
    release(p);
}
void operator delete(void* p, std::size_t, std::align_val_t) noexcept {
    release(p);
}
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept {
    release(p);
}
void operator delete(void* p, const std::nothrow_t&) noexcept {
    release(p);
}
void operator delete[](void* p, const std::nothrow_t&) noexcept {
    release(p);
}
void operator delete(void* p, std::align_val_t, const std::nothrow_t&) noexcept {
    release(p);
}
void operator delete[](void* p, std::align_val_t, const std::nothrow_t&) noexcept {
    release(p);
}
