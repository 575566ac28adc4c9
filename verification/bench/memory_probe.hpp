// The machine's memory hierarchy as a step sees it: the latency of a dependent load at random
// within working sets of growing size. It explains the scaling series: a rain of 1k boxes has
// 2.4 MiB of heap, one of 16k 52 MiB, and where the caches this process gets end (on a shared
// virtual machine, often well below the processor's nominal last-level cache) is what sets the
// cost per box at 16k against 1k (docs/performance.md).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace tamias_bench {

struct LoadLatency {
    double mib = 0.0; ///< working set
    double ns = 0.0;  ///< per dependent load, best of the repetitions
};

/// The successor of each of n >= 2 lines in one random cycle through all of them (splitmix64
/// from `seed`): a chase from any line visits every line before it returns, in an order no
/// prefetcher can guess.
std::vector<std::uint32_t> random_cycle(std::size_t n, std::uint64_t seed);

/// A pointer chase through one random cycle over the 64-byte lines of each working set, held in
/// the engine's own large-array storage (huge pages from 1 MiB, as the world's arrays).
std::vector<LoadLatency> measure_load_latency(std::span<const double> sizes_mib);

} // namespace tamias_bench
