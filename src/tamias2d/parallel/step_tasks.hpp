// The step's parallel loops (internal): over [0, count) blocks of work fixed by the scene, on
// the game's task system (TaskSystem), on the World's own pool, or on the calling thread alone.
// A block writes only its own data, so which thread runs it, and when, changes no result.
#pragma once

#include <memory>

#include "tamias2d/parallel/thread_pool.hpp"
#include "tamias2d/task_system.hpp"

namespace tamias2d {

class StepTasks {
  public:
    StepTasks() = default;
    /// workers >= 1; the pool is started only for workers > 1 without the game's callbacks.
    StepTasks(int workers, const TaskSystem& system) : workers_(workers), system_(system) {
        if (workers_ > 1 && system_.enqueue == nullptr)
            pool_ = std::make_unique<ThreadPool>(workers_);
    }

    /// Whether loops may run on more than one thread (else the step keeps its serial loops).
    bool parallel() const { return workers_ > 1; }

    /// Runs block(begin, end) over pieces covering [0, count) exactly once, in any order and on
    /// any threads, and returns when all have run.
    template <class Block> void for_each_block(int count, Block& block) const {
        if (count <= 0)
            return;
        if (workers_ <= 1 || count == 1) {
            block(0, count);
            return;
        }
        const TaskCallback task = [](int begin, int end, int, void* context) {
            (*static_cast<Block*>(context))(begin, end);
        };
        if (pool_) {
            pool_->run(task, count, &block);
            return;
        }
        void* handle = system_.enqueue(task, count, &block, system_.user_context);
        system_.finish(handle, system_.user_context);
    }

  private:
    int workers_ = 1;
    TaskSystem system_{};
    std::unique_ptr<ThreadPool> pool_;
};

/// The number of blocks of `size` items that cover `n` items.
inline int blocks_of(std::size_t n, std::size_t size) {
    return int((n + size - 1) / size);
}

} // namespace tamias2d
