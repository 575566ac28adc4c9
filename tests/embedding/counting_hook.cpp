// The counting hook and the windowed counting operator new (counting_hook.hpp).
#include "embedding/counting_hook.hpp"

#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <mutex>
#include <new>

// Built on malloc/free; once inlined GCC cannot see that they pair up.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
#endif

/// Called for each of the hook's allocations: a place for a debugger's breakpoint.
extern "C" [[gnu::noinline]] void tamias_embedding_hook_allocate() {
    asm volatile(""); // (kept: not folded into its callers)
}

namespace tamias2d::test {

namespace {

// --- the hook: live blocks in an open-addressing table keyed by address ---
struct Block {
    std::uintptr_t address = 0; ///< 0: empty; 1: a removed entry
    std::size_t size = 0, alignment = 0;
};
constexpr std::size_t table_size = std::size_t(1) << 18;
Block table[table_size];
std::mutex table_mutex;
HookCounts counts;

std::size_t home(std::uintptr_t a) {
    return std::size_t((a >> 4) * 0x9E3779B97F4A7C15ULL >> 46) & (table_size - 1);
}

void* hook_allocate(std::size_t size, std::size_t alignment, void*) {
    tamias_embedding_hook_allocate();
    const bool power_of_two = alignment != 0 && (alignment & (alignment - 1)) == 0;
    const std::size_t a = power_of_two ? alignment : 64;
    void* p = std::aligned_alloc(a, (size + a - 1) / a * a);
    const std::lock_guard lock(table_mutex);
    ++counts.allocations;
    counts.bytes += size;
    if (p == nullptr)
        return nullptr;
    ++counts.live;
    if (!power_of_two || reinterpret_cast<std::uintptr_t>(p) % a != 0)
        ++counts.misaligned;
    const auto address = reinterpret_cast<std::uintptr_t>(p);
    for (std::size_t i = home(address), probes = 0; probes < table_size;
         i = (i + 1) & (table_size - 1), ++probes)
        if (table[i].address <= 1) {
            table[i] = {address, size, alignment};
            return p;
        }
    ++counts.table_full;
    return p;
}

void hook_free(void* p, std::size_t size, std::size_t alignment, void*) {
    {
        const std::lock_guard lock(table_mutex);
        ++counts.frees;
        const auto address = reinterpret_cast<std::uintptr_t>(p);
        bool found = false;
        for (std::size_t i = home(address), probes = 0;
             probes < table_size && table[i].address != 0; i = (i + 1) & (table_size - 1), ++probes)
            if (table[i].address == address) {
                if (table[i].size != size || table[i].alignment != alignment)
                    ++counts.mismatched;
                table[i].address = 1;
                found = true;
                --counts.live;
                break;
            }
        if (!found)
            ++counts.unknown;
    }
    std::free(p);
}

// --- the window of the global operator new ---
std::atomic<bool> window_open{false};
std::atomic<std::size_t> news{0}, new_bytes{0};
const bool trap = [] {
    const char* v = std::getenv("TAMIAS_EMBEDDING_TRAP");
    return v != nullptr && v[0] == '1';
}();

} // namespace

Allocator counting_hook() {
    return {hook_allocate, hook_free, nullptr};
}
HookCounts hook_counts() {
    const std::lock_guard lock(table_mutex);
    return counts;
}
void reset_hook_counts() {
    const std::lock_guard lock(table_mutex);
    const std::size_t live = counts.live;
    counts = HookCounts{};
    counts.live = live;
}

void open_window() {
    news.store(0);
    new_bytes.store(0);
    window_open.store(true);
}
void close_window() {
    window_open.store(false);
}
std::size_t window_news() {
    return news.load();
}
std::size_t window_new_bytes() {
    return new_bytes.load();
}

} // namespace tamias2d::test

/// Called for each operator new inside the window: a place for a debugger's breakpoint.
extern "C" [[gnu::noinline]] void tamias_embedding_window_new() {
    if (tamias2d::test::trap)
        std::abort();
}

namespace {

void* allocate(std::size_t n, std::size_t align) noexcept {
    if (tamias2d::test::window_open.load(std::memory_order_relaxed)) {
        tamias2d::test::news.fetch_add(1);
        tamias2d::test::new_bytes.fetch_add(n);
        tamias_embedding_window_new();
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

} // namespace

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
    std::free(p);
}
void operator delete[](void* p) noexcept {
    std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
    std::free(p);
}
void operator delete[](void* p, std::size_t) noexcept {
    std::free(p);
}
void operator delete(void* p, std::align_val_t) noexcept {
    std::free(p);
}
void operator delete[](void* p, std::align_val_t) noexcept {
    std::free(p);
}
void operator delete(void* p, std::size_t, std::align_val_t) noexcept {
    std::free(p);
}
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept {
    std::free(p);
}
void operator delete(void* p, const std::nothrow_t&) noexcept {
    std::free(p);
}
void operator delete[](void* p, const std::nothrow_t&) noexcept {
    std::free(p);
}
void operator delete(void* p, std::align_val_t, const std::nothrow_t&) noexcept {
    std::free(p);
}
void operator delete[](void* p, std::align_val_t, const std::nothrow_t&) noexcept {
    std::free(p);
}
