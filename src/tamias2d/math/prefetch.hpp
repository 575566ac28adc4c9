// Cache hints. GCC and Clang have __builtin_prefetch; other compilers (MSVC) get no-ops, which
// change no result: a prefetch only asks for a cache line early.
#pragma once

namespace tamias2d {

/// Asks for the cache line holding p, to be read soon (__builtin_prefetch(p)).
inline void prefetch(const void* p) noexcept {
#if defined(__GNUC__)
    __builtin_prefetch(p);
#else
    (void)p;
#endif
}

/// Asks for the cache line holding p, to be written soon (__builtin_prefetch(p, 1)).
inline void prefetch_for_write(const void* p) noexcept {
#if defined(__GNUC__)
    __builtin_prefetch(p, 1);
#else
    (void)p;
#endif
}

} // namespace tamias2d
