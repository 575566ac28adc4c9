// The World's own pool of threads (internal), used when WorldDef::workers > 1 and the game lends
// no task system: workers - 1 threads that sleep between loops, and the calling thread, which
// takes items too. One loop at a time; no allocation after construction.
//
// Why not oneTBB (Debian's libtbb-dev): the step needs one parallel loop over fixed blocks, and
// a game that has a job system lends it (TaskSystem); a dependency for the rest would be carried
// by every game that links Tamias2D (docs/performance.md, "Threads").
#pragma once

#include <atomic>
#include <cstdint>
#include <thread>
#include <vector>

#include "tamias2d/memory/allocator.hpp"
#include "tamias2d/task_system.hpp"

namespace tamias2d {

class ThreadPool : public memory::HookAllocated<ThreadPool> {
  public:
    /// Starts workers - 1 threads (workers >= 2).
    explicit ThreadPool(int workers);
    ~ThreadPool();
    ThreadPool(const ThreadPool&) = delete;
    ThreadPool& operator=(const ThreadPool&) = delete;

    /// Runs task(i, i + 1, worker, context) for every i in [0, item_count), item_count below
    /// 2^22, on the pool's threads and the caller (worker 0); returns when all have run.
    void run(TaskCallback task, int item_count, void* context);

  private:
    /// The pool thread numbered `worker` (1 ...): sleeps until the bell differs from `heard`
    /// (a loop starts, or the pool stops), takes items.
    void serve(int worker, std::uint32_t heard);
    /// Takes and runs the current loop's items until none is left.
    void take_items(int worker);

    memory::vector<std::thread> threads_;
    // The loop's generation, item count and next item, in one word, so that a thread that comes
    // late to a loop (or to the next one) can take an item only of the loop it read: a claim is a
    // compare-and-swap of the whole word.
    std::atomic<std::uint64_t> claim_{0};
    std::atomic<int> remaining_{0};      ///< items of the current loop not yet finished
    std::atomic<std::uint32_t> bell_{0}; ///< bumped to wake the pool (a loop, or the end)
    std::atomic<bool> stopping_{false};
    TaskCallback task_ = nullptr; // set before claim_ publishes a loop
    void* context_ = nullptr;
};

} // namespace tamias2d
