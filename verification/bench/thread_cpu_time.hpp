// The benchmark's clock: the calling thread's CPU time.
#pragma once

#include <sys/resource.h>
#include <time.h>

namespace tamias_bench {

/// Thread CPU time (ms). The engines are single-threaded, so this is the work a step takes,
/// without the time the thread waits for a core on a shared machine; wall time is recorded
/// beside it (raw data) and equals it on an idle machine.
inline double cpu_ms() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

/// The part of the thread's CPU time spent in the kernel (ms): page faults, mostly. Recorded
/// beside the steps' time because on a virtual machine whose kernel hands freed memory back to
/// the host, faulting fresh pages in costs far more than their zeroing (docs/performance.md,
/// "Why the engine is built this way": retained blocks).
inline double system_ms() {
    rusage u{};
    getrusage(RUSAGE_THREAD, &u);
    return double(u.ru_stime.tv_sec) * 1e3 + double(u.ru_stime.tv_usec) * 1e-3;
}

} // namespace tamias_bench
