/// \file
/// A game's job system, lent to a World for the parallel parts of its step (WorldDef::workers,
/// WorldDef::task_system).
///
/// The step hands its parallel work over as loops over [0, item_count): each item is a block
/// of work that Tamias2D cuts from the scene alone (a run of contacts, bodies or contact packs,
/// never from the worker count or from timing), and each block writes only its own data. So a
/// task system may split the range as it likes, run the pieces in any order on any threads, and
/// the step's results are bitwise identical to those of one thread.
///
/// The contact passes with WorldDef::contact_regions > 1 are loops whose items share the work
/// of all the regions' streams: a piece runs whatever stream packs are ready, and may spin for
/// a while on a pack another running piece is solving, but never waits for a piece that has not
/// started. So they too finish whether the pieces run at once, one after another, or some
/// never get a thread before the others are done.
#pragma once

namespace tamias2d {

/// Runs items [begin, end) of one parallel loop. `worker` is the calling thread's number in
/// [0, WorldDef::workers): two pieces running at the same time must have different numbers.
/// `task_context` is the one the World passed to enqueue.
using TaskCallback = void (*)(int begin, int end, int worker, void* task_context);

/// Starts `task` over [0, item_count) (item_count >= 1) and returns a handle for finish (any
/// value, null included). The system calls `task` on pieces that cover every item exactly once;
/// it may run them before returning, on the calling thread or on others. `user_context` is
/// TaskSystem::user_context.
using EnqueueTaskCallback = void* (*)(TaskCallback task, int item_count, void* task_context,
                                      void* user_context);

/// Returns once every piece of the loop `handle` names has run (the World then reads their
/// results). Called exactly once per enqueue, from the thread that called enqueue.
using FinishTaskCallback = void (*)(void* handle, void* user_context);

/// A job system: both callbacks, or neither (the World then runs its own pool of
/// WorldDef::workers - 1 threads, or none with one worker). The callbacks must not throw; the
/// step calls them from the thread that called World::step, one loop at a time.
struct TaskSystem {
    EnqueueTaskCallback enqueue = nullptr; ///< starts a loop (EnqueueTaskCallback)
    FinishTaskCallback finish = nullptr;   ///< waits for a loop (FinishTaskCallback)
    void* user_context = nullptr;          ///< handed back to both callbacks
};

} // namespace tamias2d
