/// \file
/// World settings. Defaults suit games in metres, kilograms and seconds.
#pragma once

#include <limits>

#include "tamias2d/task_system.hpp"
#include "tamias2d/user_data.hpp"
#include "tamias2d/vec2.hpp"

namespace tamias2d {

/// The SRS's value of the magnitude of g (m s^-2, GD2 and erratum E30). Stated here, where the
/// default gravity needs it without the model layer's units; model::gd2::g_srs is this value.
inline constexpr double srs_gravity = 9.81;

/// How many of each the world is expected to hold at once (WorldDef::capacity): 0, none. Each
/// in [0, max_capacity_hint].
struct CapacityHints {
    int bodies = 0;   ///< bodies alive at once
    int shapes = 0;   ///< shapes alive at once (each chain segment is one)
    int joints = 0;   ///< joints alive at once
    int contacts = 0; ///< contacts at once: pairs of shapes whose fattened boxes overlap
};

/// The largest capacity hint: 2^22 of each (a world's stores sized for more would take
/// gigabytes before anything is made in them).
inline constexpr int max_capacity_hint = 1 << 22;

/// The settings of a World: gravity, the soft step's substeps and contact softness, and
/// sleeping. Checked when the World is made (SRS R4).
struct WorldDef {
    Vec2d gravity{0.0, -srs_gravity}; ///< m s^-2 (GD2; the SRS's g, srs_gravity)
    /// Substeps per step (soft step). IM1/IM2 are integrated with h = dt / substeps.
    int substeps = 4;
    /// Contact softness: stiffness (Hz) and damping ratio of the soft contact constraint that
    /// removes overlap, and the fastest speed (m s^-1) it may push bodies apart with. The
    /// stiffness is capped at a quarter of the substep rate (60 Hz at 4 substeps of 1/60 s) for
    /// stability; a stiffer contact sinks less under load (overlap ~ load / (m (2 pi hertz)^2)).
    double contact_hertz = 45.0;
    double contact_damping_ratio = 10.0;    ///< of the soft contact, > 0 (10: overdamped)
    double contact_push_max_velocity = 3.0; ///< m s^-1, >= 0
    /// Joint softness (IM6): stiffness (Hz) and damping ratio of the soft bias that pulls a
    /// joint's position error back, capped like the contact's at a quarter of the substep rate.
    /// A stiffer joint stretches less under load (error ~ load / (m (2 pi hertz)^2)).
    double joint_hertz = 60.0;
    double joint_damping_ratio = 2.0; ///< of the joints' soft bias, > 0
    /// Overlap (m) tolerated before the soft contact pushes back. Default 0: soft contacts do
    /// not jitter at rest, and any slop lets every layer of a stack sink by that much. Within
    /// the slop a contact has no positional stiffness: a stack resting there keeps its pose by
    /// friction alone (a frictionless one drifts sideways and tips).
    double linear_slop = 0.0;
    /// Contacts are created this far (m) before the shapes touch (speculative contacts).
    double speculative_distance = 0.02;
    /// Manifold reuse: a touching contact whose two bodies have moved less than this (m)
    /// against each other since its manifold was computed keeps that manifold's points, each
    /// point's separation recomputed exactly from the bodies' poses, instead of running the
    /// separating axis test and clipping again (a resting pile's contacts mostly qualify). Its
    /// points then lie within this distance of where a fresh manifold would put them, and its
    /// normal and moment arms within this distance's turn (docs/collision.md). 0: every touching
    /// manifold is computed afresh each step. >= 0.
    double manifold_reuse_distance = 0.005;
    /// The solve's regions, in [1, 8]. 1, the default: each contact pass is the sequential
    /// Gauss-Seidel pass over the touching manifolds in creation order, and each joint pass over
    /// the joints in creation order. n > 1: the bodies are cut, across gravity, into n slabs
    /// holding about equal numbers of manifolds (drawn again when the touching manifolds or the
    /// awake bodies change; until then each keeps its slab); each contact pass solves the
    /// manifolds within slab 0, then within slab 1, ..., each in creation order, then those
    /// between slabs, by greedy colour (each takes the lowest colour no earlier one on its bodies
    /// took; creation order within a colour). With at least 256 joints solved, the joints are
    /// split too, by the bodies' creation order: the moving bodies form n runs of about equal
    /// length, and each joint pass solves the joints within run 0, ..., within run n - 1, then
    /// the rest (between runs, or on an immovable body), each in creation order. The slabs, and
    /// the runs, share no moving body, so with workers > 1 they are solved on several threads at
    /// once. The order, and with it the result, depends on this setting and on the scene, never
    /// on workers: a world gives the same bits on any number of threads. Set it to the number of
    /// workers a game steps on; on one thread it costs a few packs that the manifolds between
    /// slabs fill only part way (docs/performance.md, "Threads").
    int contact_regions = 1;
    /// Continuous collision (DD29): after each step, a dynamic body that moved farther than
    /// the speculative distance is swept from its start pose to its end pose against the
    /// static shapes; if the core of one of its shapes (a disc about its centroid) would reach
    /// one, the body is put back just short of the impact (pose and velocity interpolated; the
    /// next step's contact stops it), so that it cannot pass through a thin static shape
    /// between two steps. Not guarded: pairs of moving bodies (dynamic or kinematic), and a
    /// body whose core already overlaps a static shape at the step's start. Off: bodies move as
    /// the solver leaves them, and a fast one can tunnel.
    bool enable_continuous = true;
    /// Warm starting (IM7): each contact and joint starts a substep's solve by applying the
    /// impulses it accumulated in the last one, the last step's for the first substep (Box2D
    /// v3's enableWarmStarting). Off, as Box2D v3 does it: each step starts from zero impulses
    /// and no substep applies the last one's first, so a contact must build its impulse again
    /// within each substep's single iteration: a stack sinks deeper into its supports and takes
    /// longer to come to rest. For comparing solvers and finding a warm start's faults, not for
    /// games. Changed at run time by World::set_warm_starting.
    bool enable_warm_starting = true;
    /// Restitution (DD12) applies when the bodies approach faster than this (m s^-1).
    double restitution_threshold = 0.0;
    /// A touching pair is reported as a hit (World::contact_hit_events) when its bodies
    /// approach faster than this (m s^-1, >= 0) and one of its shapes has
    /// ShapeDef::enable_hit_events. Changed at run time by World::set_hit_event_threshold.
    double hit_event_threshold = 1.0;
    /// \srs{DD40} m s^-1, > 0: no body's centre moves faster; a faster one is slowed to it
    /// along its direction at each substep (a guard against a game's runaway body, not
    /// physics: it breaks IM1 while it acts). Infinite, the default: no limit, and IM1 as
    /// the SRS states it; a game in metres might choose 100 to 400.
    double maximum_linear_speed = std::numeric_limits<double>::infinity();
    /// Sleeping (dynamics/sleep.hpp): a group of touching bodies that has stayed slower than
    /// both tolerances for time_to_sleep (s) is held still, and its bodies and contacts take no
    /// solver or narrow-phase work, until something wakes it (an awake body touches one of
    /// them, or the API changes one). Off by default: a sleeping body is not integrated by
    /// IM1/IM2 (at rest, gravity and its supports' impulses cancel, within the tolerances), and
    /// the SRS's results and the benchmark (sleeping off in every engine) are for bodies that
    /// never sleep.
    bool enable_sleep = false;
    double time_to_sleep = 0.5;             ///< s
    double linear_sleep_tolerance = 0.05;   ///< m s^-1
    double angular_sleep_tolerance = 0.035; ///< rad s^-1 (2 degrees per second)
    /// Threads that share a step's parallel parts (the narrow phase, the bodies' integration and
    /// write-back, the contacts' and the joints' preparation, and with contact_regions > 1 the
    /// contact passes and the joint passes),
    /// in [1, 256]. The results are bitwise identical for every count (task_system.hpp). 1, the
    /// default: the step runs on the calling thread alone, as without this setting. Above 1,
    /// without task_system's callbacks, the World starts a pool of workers - 1 threads of its
    /// own, kept until it is destroyed.
    int workers = 1;
    /// A game's job system to run those parts on instead of the World's pool (task_system.hpp):
    /// both callbacks or neither; used only when workers > 1, which must then be the number of
    /// worker numbers it hands out.
    TaskSystem task_system{};
    UserData user_data = 0; ///< the game's own value (user_data.hpp), not simulation state
    /// Capacity hints: the stores of bodies, shapes, joints and contacts (with the broad
    /// phase's tree, the step's per-body and per-contact arrays and the events' lists) are sized
    /// for these counts when the World is made, so that creating up to that many and the first
    /// steps that touch them do not grow them (each growth is an allocation and a copy). Never
    /// a limit: more grow the stores as without hints. Not simulation state: no effect on any
    /// result, not in snapshots, recordings or scene files (World::restore keeps the world's
    /// own; a world made by World::from_snapshot has none). Checked (ValidationError naming
    /// "world.capacity.bodies", ...).
    CapacityHints capacity{};
};

} // namespace tamias2d
