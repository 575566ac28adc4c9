#include "memory_probe.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <utility>

#include "bench_scenes.hpp"
#include "tamias2d/memory/large_array.hpp"
#include "thread_cpu_time.hpp"

namespace tamias_bench {

namespace {

struct alignas(64) Line {
    std::uint32_t next = 0;
};
static_assert(sizeof(Line) == 64);

volatile std::uint32_t sink = 0;

} // namespace

std::vector<std::uint32_t> random_cycle(std::size_t n, std::uint64_t seed) {
    // The lines in a random order (Fisher-Yates), each linked to the next and the last to the
    // first: one cycle through all of them.
    std::vector<std::uint32_t> order(n);
    for (std::size_t i = 0; i < n; ++i)
        order[i] = std::uint32_t(i);
    SplitMix64 rng{seed};
    for (std::size_t i = n - 1; i > 0; --i)
        std::swap(order[i], order[std::size_t(rng.next() % (i + 1))]);
    std::vector<std::uint32_t> next(n);
    for (std::size_t i = 0; i < n; ++i)
        next[order[i]] = order[(i + 1) % n];
    return next;
}

std::vector<LoadLatency> measure_load_latency(std::span<const double> sizes_mib) {
    constexpr int loads = 1 << 20, repetitions = 3;
    std::vector<LoadLatency> out;
    for (const double mib : sizes_mib) {
        const auto n = std::max<std::size_t>(2, std::size_t(mib * 1048576.0) / sizeof(Line));
        tamias2d::LargeArray<Line> lines(n);
        const std::vector<std::uint32_t> next = random_cycle(n, 2);
        for (std::size_t i = 0; i < n; ++i)
            lines[i].next = next[i];
        std::uint32_t at = 0;
        for (std::size_t i = 0; i < n; ++i) // one lap untimed: the set is in whatever holds it
            at = lines[at].next;
        double best = 1e300;
        for (int r = 0; r < repetitions; ++r) {
            const double t0 = cpu_ms();
            for (int i = 0; i < loads; ++i)
                at = lines[at].next;
            best = std::min(best, (cpu_ms() - t0) * 1e6 / loads);
        }
        sink = at; // the chase's end is used, so the loop cannot be dropped
        out.push_back({mib, best});
    }
    return out;
}

} // namespace tamias_bench
