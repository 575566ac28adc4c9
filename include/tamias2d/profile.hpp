/// \file
/// Measuring a live world: the time each stage of the last step took (World::profile, with
/// World::set_profiling on) and what the world holds now (World::counters).
#pragma once

#include <cstddef>

namespace tamias2d {

/// Wall-clock seconds the last step spent in each of its stages (steady clock). The stages
/// follow the step's order; `step` is the whole step, the stages' sum plus the little between
/// them. All zero until a step has run with profiling on (World::set_profiling).
struct StepProfile {
    double step = 0.0;         ///< s, the whole of World::step
    double prepare = 0.0;      ///< s, the state checks, loads, and the solver bodies and joints
    double broad_phase = 0.0;  ///< s, the new pairs from the broad phase's moved boxes
    double narrow_phase = 0.0; ///< s, every pair's manifold (R7), its begin and end events
    double solve = 0.0;        ///< s, the substeps of the solver and the restitution pass
    double finalize = 0.0;     ///< s, the new states written back, the boxes refitted and moved
    double continuous = 0.0;   ///< s, the continuous pass (DD29) over the bodies that moved far
    double events = 0.0;       ///< s, the joints broken and the sensors' overlaps (DD28)
    double sleep = 0.0;        ///< s, the islands woken and put to sleep (enable_sleep)
};

/// What the world holds now, counted when asked (World::counters): nothing is counted during
/// a step.
struct WorldCounters {
    std::size_t bodies = 0;       ///< bodies that exist, static ones included
    std::size_t awake_bodies = 0; ///< movable (dynamic or kinematic) bodies awake
    std::size_t shapes = 0;       ///< shapes that exist, sensors included
    std::size_t joints = 0;       ///< joints that exist
    /// Pairs of shapes whose broad-phase (fattened) boxes overlap and that may collide: each
    /// holds a contact whether or not its shapes touch.
    std::size_t pairs = 0;
    std::size_t touching = 0;       ///< pairs whose shapes touch (World::contacts' entries)
    std::size_t contact_points = 0; ///< points of the touching pairs' manifolds
    /// Islands: groups of movable bodies linked by touching contacts and joints (a static body
    /// joins none), each movable body in exactly one.
    std::size_t islands = 0;
    /// Packs of up to four manifolds the last step's contact solver ran, in the colouring that
    /// keeps them free of shared moving bodies (0 before the first step).
    std::size_t solver_packs = 0;
};

} // namespace tamias2d
