/// \file
/// The process's CPU time, for tests that state a cost as a ratio or a bound: unlike the wall
/// clock, it does not count the time other processes on a shared machine take the cores.
#pragma once

#include <ctime>

namespace tamias2d::test {

/// Seconds of CPU time the process has used (every thread of it).
inline double process_cpu_seconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

/// A sanitizer build runs several times slower by design (shadow memory, checks on every
/// access): a time bound stated for an optimised build is held there to this many times it.
#if defined(__SANITIZE_ADDRESS__)
inline constexpr double sanitizer_slowdown = 4.0;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr double sanitizer_slowdown = 4.0;
#else
inline constexpr double sanitizer_slowdown = 1.0;
#endif
#else
inline constexpr double sanitizer_slowdown = 1.0;
#endif

} // namespace tamias2d::test
