// One contact pass (warm start, soft iteration or relax) over a ConstraintGraph's streams on
// several threads at once (internal). Each stream's packs run in order, and a pack runs only
// once the other streams have finished the packs it waits for, so every body sees the updates
// of the sequential pass in its order: the bits do not depend on the threads or their timing.
//
// Any thread may run any stream. A caller takes a stream nobody holds (its own first), runs its
// packs while their waits are met, and lets it go when one is not met (at once if the stream it
// waits for is free, else after a short spin), to take another. So one thread alone runs the
// whole pass, and the pass never waits for a thread that a task system starts late or runs
// after the others: a game's job system may run the loop's pieces in any order.
#pragma once

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>

#include "tamias2d/dynamics/constraint_graph.hpp"

namespace tamias2d {

class PackStreams {
  public:
    /// Runs packs [first, first + count) of the graph's packs(), all of stream `stream`.
    using RunPacks = void (*)(void* context, std::size_t first, std::size_t count,
                              std::uint32_t stream);

    /// Before each pass, on one thread: no stream held, none begun.
    void reset();
    /// Runs the pass; any number of threads may call it at once, with the same arguments but
    /// `preferred` (the stream to try first), and each returns once every pack has run.
    void run(const ConstraintGraph& graph, std::uint32_t preferred, RunPacks run_packs,
             void* context);

  private:
    struct alignas(64) Stream {
        std::atomic<std::uint32_t> done{0}; ///< the stream's packs finished in this pass
        std::atomic<std::uint32_t> held{0}; ///< 1 while a thread runs the stream
    };
    std::array<Stream, ConstraintGraph::max_streams> streams_;
};

} // namespace tamias2d
