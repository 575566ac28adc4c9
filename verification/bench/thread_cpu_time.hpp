// The benchmark's clock: the calling thread's CPU time.
#pragma once

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

} // namespace tamias_bench
