// World::Impl, the engine's state behind the public World: a header of its own so that the
// World's calls can be defined by area (world_*.cpp) while world.cpp keeps creation, stepping and
// the state hash.
#pragma once

#include <vector>

#include "tamias2d/dynamics/body_store.hpp"
#include "tamias2d/dynamics/contacts/contact_manager.hpp"
#include "tamias2d/dynamics/contacts/sensor_overlaps.hpp"
#include "tamias2d/dynamics/island_sleep.hpp"
#include "tamias2d/dynamics/joints/joint_store.hpp"
#include "tamias2d/dynamics/shape_store.hpp"
#include "tamias2d/dynamics/step_context.hpp"
#include "tamias2d/dynamics/step_events.hpp"
#include "tamias2d/dynamics/step_profiler.hpp"
#include "tamias2d/dynamics/step_solver.hpp"
#include "tamias2d/memory/allocator.hpp"
#include "tamias2d/parallel/step_tasks.hpp"
#include "tamias2d/world.hpp"

namespace tamias2d {

/// The engine's state and the step's pipeline over its stages (dynamics/): the bodies, the
/// shapes with the broad phase, the contacts, the joints, the solver, sleeping.
struct World::Impl : memory::HookAllocated<World::Impl> {
    WorldDef def;
    double time = 0.0;
    double time_error = 0.0; ///< Kahan compensation: n steps of dt read back as n dt
    BodyStore bodies;
    ShapeStore shapes;
    ContactManager contacts;
    JointStore joints;
    SensorOverlaps sensors;
    StepSolver solver;
    IslandSleep sleep;
    StepEvents events;          ///< hits, moves and joint events (events.hpp)
    StepTasks tasks;            ///< the step's parallel loops (WorldDef::workers, task_system)
    memory::vector<Load> loads; ///< this step's load-function values (empty when none has one)
    StepProfiler profiler;      ///< the stages' times (World::set_profiling; off: never read)

    /// A world tagged `tag` (World::tag).
    Impl(const WorldDef& d, std::uint32_t tag) : def(d), bodies(tag), shapes(tag), joints(tag) {
        shapes.broad_phase.set_least_margin(d.speculative_distance); // (BroadPhase::fattened)
        reserve(d.capacity);
    }

    /// The stores sized for the hinted counts (WorldDef::capacity; 0: left as they are).
    void reserve(const CapacityHints& c) {
        const auto n = [](int v) { return std::size_t(v); };
        bodies.reserve(n(c.bodies));
        shapes.reserve(n(c.shapes), n(c.bodies));
        joints.reserve(n(c.joints), c.joints > 0 ? n(c.bodies) : 0);
        contacts.reserve(n(c.contacts));
        events.reserve(n(c.bodies));
        solver.reserve(n(c.bodies), n(c.contacts));
    }

    /// The solve diverged (StepSolver::diverged): the joints and sleep states as they were, no
    /// event of this step, and the step refused naming the body (SolverDivergence). Nothing was
    /// finalized, so the bodies are as they were; the contacts hold the manifolds of those same
    /// poses.
    [[noreturn]] void refuse_diverged() {
        contacts.clear_events();
        joints.refuse_step(solver.diverged(), bodies, def.enable_sleep);
    }

    /// The solver bodies and the joints' frames at the step's start.
    void prepare(const StepContext& step) {
        solver.prepare_bodies(bodies, step);
        solver.prepare_joints(joints, bodies, step);
    }

    /// A step with some body awake: its stages in one order. Only where the solver bodies are
    /// prepared depends on sleeping: with sleeping, after the islands (which need this step's
    /// touching contacts) have woken what they wake; without, before the narrow phase. With
    /// joints (`guarded`), a diverged solve is refused before anything is finalized.
    void solve(const StepContext& step, bool guarded) {
        if (!step.sleeping) {
            prepare(step);
            profiler.lap(&StepProfile::prepare);
        }
        contacts.update(bodies, shapes, step);
        profiler.lap(&StepProfile::narrow_phase);
        if (step.sleeping) {
            sleep.wake_islands(bodies, contacts, joints);
            profiler.lap(&StepProfile::sleep);
            prepare(step);
            profiler.lap(&StepProfile::prepare);
        }
        events.before_solve(bodies, shapes, contacts, def.hit_event_threshold);
        solver.solve(contacts, joints, shapes, step);
        if (guarded && solver.diverged() != null_index)
            refuse_diverged();
        profiler.lap(&StepProfile::solve);
        solver.finalize(bodies, shapes, step);
        profiler.lap(&StepProfile::finalize);
        solver.continuous(bodies, shapes, contacts, joints, step);
        profiler.lap(&StepProfile::continuous);
        joints.break_joints(bodies, shapes);
        profiler.lap(&StepProfile::events);
        if (step.sleeping) {
            events.before_sleep(bodies);
            sleep.update_sleep(bodies, step);
            profiler.lap(&StepProfile::sleep);
        }
    }

    /// A step starts only from a state within supported::state_max (BodyStore::check_state),
    /// with its joints' anchors within their levers' limit.
    void check_state() const {
        bodies.check_state();
        joints.check_levers(bodies); // (the joints are few: one pass)
    }
};

/// The world's snapshot (World::snapshot) written by `out`, its header completed in it.
void write_snapshot(const World::Impl& w, SnapshotWriter& out);

} // namespace tamias2d
