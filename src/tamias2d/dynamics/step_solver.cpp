#include "tamias2d/dynamics/step_solver.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

#include "tamias2d/dynamics/body_store.hpp"
#include "tamias2d/dynamics/bridge/continuous_motion.hpp"
#include "tamias2d/dynamics/bridge/motion.hpp"
#include "tamias2d/dynamics/bridge/surface_motion.hpp"
#include "tamias2d/dynamics/bridge/velocity_control.hpp"
#include "tamias2d/dynamics/contacts/contact_manager.hpp"
#include "tamias2d/dynamics/contacts/restitution.hpp"
#include "tamias2d/dynamics/joints/joint_solver.hpp"
#include "tamias2d/dynamics/joints/joint_store.hpp"
#include "tamias2d/dynamics/shape_store.hpp"
#include "tamias2d/math/prefetch.hpp"
#include "tamias2d/memory/allocator.hpp"
#include "tamias2d/parallel/step_tasks.hpp"

namespace tamias2d {

namespace {

// Blocks of the parallel loops, in solver bodies: ~2 us of work for the integration.
constexpr std::size_t body_block = 512;
// A loop over fewer bodies runs on the calling thread: waking the others costs more.
constexpr std::size_t parallel_bodies = 2 * body_block;

/// Whether body i is immovable this step: static, destroyed, asleep (sleeping on) or disabled
/// (World::set_enabled: a disabled body is never awake; with sleeping off every other movable
/// body is).
bool immovable(const BodyStore& store, std::uint32_t i, const WorldDef& def) {
    const Body& b = store.bodies[i];
    return ((def.enable_sleep || store.disabled_bodies > 0) && !store.sleep_states[i].awake) ||
           !store.alive(i) || b.type == BodyType::static_body;
}

/// A body's place along the regions' cut axis (`across`: across gravity, unit).
double cut_place(const Body& b, Vec2d across) {
    return b.center.x * across.x + b.center.y * across.y;
}

/// IM5's factors of a body for substeps of h, linear and angular: 1 for an undamped body.
struct Decay {
    double linear, angular;
};

Decay decay_of(const Body& b, const BodySettings& set, double h) {
    if (!b.damped)
        return {1.0, 1.0};
    return {bridge::linear_decay_factor(set.linear_damping, h),
            bridge::angular_decay_factor(set.angular_damping, h)};
}

/// A moving body's accelerations from gravity and its loads (IM1, IM2).
struct Accelerations {
    Vec2d a{};
    double alpha = 0.0;
};

Accelerations accelerations_of(const Body& b, std::uint32_t i, const memory::vector<Load>& loads,
                               const WorldDef& def) {
    if (b.type != BodyType::dynamic)
        return {};
    // Unloaded, F = 0 and tau = 0 give g and 0 bit for bit whatever m and I (0 / m is exactly
    // 0), so the body's third line, loads and masses, is not read.
    Vec2d f{};
    double tau = 0.0, mass = 1.0, inertia = 1.0;
    if (b.loaded || !loads.empty()) {
        const Load l = loads.empty() ? Load{} : loads[i];
        f = b.force + b.force_once + l.force;
        tau = b.torque + b.torque_once + l.torque;
        mass = b.mass;
        inertia = b.inertia;
    }
    return {bridge::acceleration(b.gravity_scale * def.gravity, f, mass),
            b.inv_inertia > 0.0 ? bridge::angular_acceleration(tau, inertia) : 0.0};
}

} // namespace

// Built before the narrow phase, not after it: a pass over every body between the narrow
// phase's sweep of the contacts and the lane filling's gather of them pushed them out of the
// cache (rain_16k).
void StepSolver::prepare_bodies(const BodyStore& store, const StepContext& step) {
    const memory::vector<Load>& loads = step.loads;
    const WorldDef& def = step.def;
    const double h = step.h;
    const StepTasks& tasks = step.tasks;
    const auto& bodies = store.bodies;
    solver_index_.resize(bodies.size());
    // The contact regions (WorldDef::contact_regions) are slabs along gravity, cut across it:
    // each holds whole columns of a stack, whose load runs down them, and only the rows that
    // cross a cut give manifolds between regions (without gravity, the cuts are across x).
    const bool regions = def.contact_regions > 1;
    const double g = length(def.gravity);
    const Vec2d across = g > 0.0 ? Vec2d{-def.gravity.y / g, def.gravity.x / g} : Vec2d{1.0, 0.0};
    // DD39: the moving dynamic bodies with a linear lock (none in most worlds: no pass).
    const auto list_locked = [&] {
        locked_.clear();
        for (std::uint32_t i = 0; store.locked_bodies > 0 && i < bodies.size(); ++i) {
            if (solver_index_[i] != 0 && bodies[i].type == BodyType::dynamic &&
                store.linearly_locked(i))
                locked_.push_back({solver_index_[i], store.settings[i].lock_linear_x,
                                   store.settings[i].lock_linear_y});
        }
    };
    if (tasks.parallel() && bodies.size() >= parallel_bodies) {
        prepare_bodies_in_blocks(store, loads, def, h, across, tasks);
        list_locked();
        return;
    }
    // Solver body 0 is the shared immovable body standing in for every static body.
    solver_bodies_.assign(1, SolverBody{});
    accelerations_.assign(1, Vec2d{});
    angular_accelerations_.assign(1, 0.0);
    any_damped_ = false;
    linear_decay_.assign(1, 1.0);
    angular_decay_.assign(1, 1.0);
    cut_.assign(1, 0.0);
    for (std::uint32_t i = 0; i < bodies.size(); ++i) {
        if (immovable(store, i, def)) {
            solver_index_[i] = 0;
            continue;
        }
        const Body& b = bodies[i];
        solver_index_[i] = std::uint32_t(solver_bodies_.size());
        solver_bodies_.push_back({b.v, b.w, b.inv_mass, b.inv_inertia, {}, 0.0});
        if (regions)
            cut_.push_back(cut_place(b, across));
        const Accelerations acc = accelerations_of(b, i, loads, def);
        accelerations_.push_back(acc.a);
        angular_accelerations_.push_back(acc.alpha);
        if (b.damped && !any_damped_) { // the first damped body: undamped ones get 1
            any_damped_ = true;
            linear_decay_.resize(solver_bodies_.size() - 1, 1.0);
            angular_decay_.resize(solver_bodies_.size() - 1, 1.0);
        }
        if (any_damped_) {
            const Decay d = decay_of(b, store.settings[i], h);
            linear_decay_.push_back(d.linear);
            angular_decay_.push_back(d.angular);
        }
    }
    list_locked();
}

// Two passes over the same blocks of bodies: each block numbers its moving bodies and notes
// whether one is damped; after the blocks' counts are summed in block order, each block writes
// its solver bodies from its first number on. The numbering and the values are the serial
// loop's.
void StepSolver::prepare_bodies_in_blocks(const BodyStore& store, const memory::vector<Load>& loads,
                                          const WorldDef& def, double h, Vec2d across,
                                          const StepTasks& tasks) {
    const auto& bodies = store.bodies;
    const auto n = std::uint32_t(bodies.size());
    const int blocks = blocks_of(n, body_block);
    constexpr auto block = std::uint32_t(body_block);
    block_first_.resize(std::size_t(blocks) + 1);
    block_damped_.resize(std::size_t(blocks));
    auto number = [&](int first, int last) {
        for (int k = first; k < last; ++k) {
            std::uint32_t moving = 0;
            bool damped = false;
            const std::uint32_t end = std::min(n, std::uint32_t(k + 1) * block);
            for (std::uint32_t i = std::uint32_t(k) * block; i < end; ++i) {
                const bool still = immovable(store, i, def);
                solver_index_[i] = still ? 0 : ++moving; // within the block, from 1
                damped = damped || (!still && bodies[i].damped);
            }
            block_first_[std::size_t(k) + 1] = moving;
            block_damped_[std::size_t(k)] = damped;
        }
    };
    tasks.for_each_block(blocks, number);
    block_first_[0] = 1; // solver body 0 is the shared immovable body
    any_damped_ = false;
    for (std::size_t k = 0; k < std::size_t(blocks); ++k) {
        block_first_[k + 1] += block_first_[k];
        any_damped_ = any_damped_ || block_damped_[k] != 0;
    }
    const std::size_t count = block_first_[std::size_t(blocks)];
    const bool regions = def.contact_regions > 1;
    solver_bodies_.resize(count);
    accelerations_.resize(count);
    angular_accelerations_.resize(count);
    linear_decay_.resize(any_damped_ ? count : 1);
    angular_decay_.resize(any_damped_ ? count : 1);
    cut_.resize(regions ? count : 1);
    solver_bodies_[0] = SolverBody{};
    accelerations_[0] = Vec2d{};
    angular_accelerations_[0] = 0.0;
    linear_decay_[0] = angular_decay_[0] = 1.0;
    cut_[0] = 0.0;
    auto fill = [&](int first, int last) {
        for (int k = first; k < last; ++k) {
            const std::uint32_t offset = block_first_[std::size_t(k)] - 1;
            const std::uint32_t end = std::min(n, std::uint32_t(k + 1) * block);
            for (std::uint32_t i = std::uint32_t(k) * block; i < end; ++i) {
                if (solver_index_[i] == 0)
                    continue;
                const std::uint32_t s = solver_index_[i] += offset;
                const Body& b = bodies[i];
                solver_bodies_[s] = {b.v, b.w, b.inv_mass, b.inv_inertia, {}, 0.0};
                if (regions)
                    cut_[s] = cut_place(b, across);
                const Accelerations acc = accelerations_of(b, i, loads, def);
                accelerations_[s] = acc.a;
                angular_accelerations_[s] = acc.alpha;
                if (any_damped_) {
                    const Decay d = decay_of(b, store.settings[i], h);
                    linear_decay_[s] = d.linear;
                    angular_decay_[s] = d.angular;
                }
            }
        }
    };
    tasks.for_each_block(blocks, fill);
}

namespace {

/// Runs range(begin, end) over solver bodies [1, count), in parallel blocks when worth it.
template <class Range>
void over_solver_bodies(std::size_t count, const StepTasks& tasks, Range&& range) {
    if (!tasks.parallel() || count < parallel_bodies) {
        range(std::size_t{1}, count);
        return;
    }
    auto run = [&](int first, int last) {
        range(1 + std::size_t(first) * body_block,
              std::min(count, 1 + std::size_t(last) * body_block));
    };
    tasks.for_each_block(blocks_of(count - 1, body_block), run);
}

} // namespace

void StepSolver::integrate_velocities(double h, const StepTasks& tasks) {
    over_solver_bodies(solver_bodies_.size(), tasks, [&](std::size_t begin, std::size_t end) {
        integrate_velocities(h, begin, end);
    });
}

// IM5's factor 1 gives IM1/IM2's bits, so the undamped loop is only the cheaper form of the
// same step (no factors to stream).
void StepSolver::integrate_velocities(double h, std::size_t begin, std::size_t end) {
    if (any_damped_) {
        for (std::size_t k = begin; k < end; ++k) {
            SolverBody& sb = solver_bodies_[k];
            sb.v = bridge::velocity_step(sb.v, accelerations_[k], h, linear_decay_[k]);
            sb.w = bridge::angular_velocity_step(sb.w, angular_accelerations_[k], h,
                                                 angular_decay_[k]);
        }
        return;
    }
    for (std::size_t k = begin; k < end; ++k) {
        SolverBody& sb = solver_bodies_[k];
        sb.v = bridge::velocity_half(sb.v, accelerations_[k], h);
        sb.w = bridge::angular_velocity_half(sb.w, angular_accelerations_[k], h);
    }
}

void StepSolver::integrate_positions(double h, const StepTasks& tasks) {
    over_solver_bodies(solver_bodies_.size(), tasks, [&](std::size_t begin, std::size_t end) {
        integrate_positions(h, begin, end);
    });
}

void StepSolver::integrate_positions(double h, std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) {
        SolverBody& sb = solver_bodies_[k];
        sb.dp = bridge::position_half(sb.dp, sb.v, h);
        sb.dq = bridge::angle_half(sb.dq, sb.w, h);
    }
}

template <class Range> void StepSolver::each_pack(const StepTasks& tasks, Range& range) {
    constexpr std::size_t block = 64;
    const std::size_t n = pin_packs_.pack_count();
    if (!tasks.parallel() || n < 2 * block) {
        range(0, n);
        return;
    }
    auto run = [&](int first, int last) {
        range(std::size_t(first) * block, std::min(n, std::size_t(last) * block));
    };
    tasks.for_each_block(blocks_of(n, block), run);
}

template <class Each> void StepSolver::each_sim(const StepTasks& tasks, Each& each) {
    constexpr std::size_t block = 128;
    if (!tasks.parallel() || sims_.size() < JointStreams::min_joints) {
        for (JointSim& s : sims_)
            each(s);
        return;
    }
    auto run = [&](int first, int last) {
        const std::size_t end = std::min(sims_.size(), std::size_t(last) * block);
        for (std::size_t k = std::size_t(first) * block; k < end; ++k)
            each(sims_[k]);
    };
    tasks.for_each_block(blocks_of(sims_.size(), block), run);
}

template <class Single, class Packs>
void StepSolver::joint_pass(const StepTasks& tasks, Single& single, Packs& packs) {
    auto run_stream = [&](std::uint32_t stream) {
        for (const PinRun& r : pin_packs_.runs(stream)) {
            if (r.packed)
                packs(r.pack, r.count / wide_lanes);
            else
                for (std::uint32_t k = r.first; k < r.first + r.count; ++k)
                    single(sims_[k]);
        }
    };
    const std::uint32_t R = joint_streams_.regions();
    if (R < 2 || !tasks.parallel()) { // the streams in order on this thread
        for (std::uint32_t stream = 0; stream < pin_packs_.streams(); ++stream)
            run_stream(stream);
        return;
    }
    auto run = [&](int first, int last) {
        for (int stream = first; stream < last; ++stream)
            run_stream(std::uint32_t(stream));
    };
    tasks.for_each_block(int(R), run);
    run_stream(R); // the rest
}

void StepSolver::prepare_joints(const JointStore& joints, const BodyStore& bodies,
                                const StepContext& step) {
    // The moving bodies the joints hold, each once, with its angle at the step's start.
    joint_rotations_.begin(solver_bodies_.size());
    solved_.clear();
    if (joints.live() == 0) {
        sims_.clear();
        pin_packs_.order(solved_, {}, 0); // no streams
        return;
    }
    for (std::uint32_t i = 0; i < joints.joints.size(); ++i) {
        const Joint& j = joints.joints[i];
        if (!joints.alive(i) || j.type == JointType::filter) // (no constraint to solve)
            continue;
        // A joint none of whose bodies is dynamic, or one holding a disabled body, is not
        // solved (World::set_body_type, set_enabled): both sides immovable this step. Nor is
        // one between two immovable bodies (both asleep, or asleep and static).
        const std::uint32_t a = solver_index_[j.body_a], b = solver_index_[j.body_b];
        const Body& body_a = bodies.bodies[j.body_a];
        const Body& body_b = bodies.bodies[j.body_b];
        if ((body_a.type != BodyType::dynamic && body_b.type != BodyType::dynamic) ||
            bodies.disabled(j.body_a) || bodies.disabled(j.body_b) || (a == 0 && b == 0))
            continue;
        const std::uint32_t pin =
            plain_pin(j.type, j.enable_spring, j.enable_motor, j.enable_limit) ? 1 : 0;
        // A moving side's rotation is its body's, turned once per body rather than once per
        // joint; an immovable side's is its own (solver body 0 stands for every immovable body).
        const double dq0 = solver_bodies_[0].dq;
        solved_.push_back({i, a, b, pin, joint_rotations_.side(a, body_a.angle, dq0),
                           joint_rotations_.side(b, body_b.angle, dq0)});
    }
    joint_streams_.split(solved_, std::uint32_t(step.def.contact_regions),
                         std::uint32_t(solver_bodies_.size() - 1));
    // Each stream's levels, its plain pins in packs of four (PinPacks).
    const std::uint32_t R = joint_streams_.regions();
    std::array<std::uint32_t, JointStreams::max_regions + 2> bounds{};
    for (std::uint32_t stream = 0; stream <= R; ++stream)
        bounds[stream] = R == 0 ? 0 : joint_streams_.begin(stream);
    bounds[R + 1] = std::uint32_t(solved_.size());
    pin_packs_.order(solved_, std::span<const std::uint32_t>(bounds.data(), R + 2),
                     solver_bodies_.size());
    // The records, each its own (a packed pin's is its pack's lane, and its record stays unmade).
    // Only those beyond the last step's count are initialised first: prepare_joint, the
    // pointers and the softness write every field.
    sims_.resize(solved_.size());
    // IM6: the joints' soft bias, capped like the contacts' at a quarter of the substep rate;
    // DD37: a joint with a tuning of its own uses it in place of the world's.
    const WorldDef& def = step.def;
    const int n = def.substeps;
    const Softness joint_softness = make_joint_softness(
        capped_joint_frequency(def.joint_hertz, n, step.dt), def.joint_damping_ratio, step.h);
    const auto softness_of = [&](const Joint& j) {
        return j.tuned ? make_tuned_joint_softness(j.tuning_hertz, j.tuning_damping_ratio, n,
                                                   step.dt, step.h)
                       : joint_softness;
    };
    const Rot* rotations = joint_rotations_.data();
    auto prepare = [&](JointSim& s) {
        const std::size_t k = std::size_t(&s - sims_.data());
        if (pin_packs_.in_pack(k)) // its pack's lane holds it (fill, below)
            return;
        const SolvedJoint& sj = solved_[k];
        const Joint& j = joints.joints[sj.joint];
        prepare_joint(s, j, sj.joint, bodies, solver_index_);
        s.q_a = rotations + sj.rotation_a;
        s.q_b = rotations + sj.rotation_b;
        s.softness = softness_of(j);
        if (!def.enable_warm_starting) // (the joints forget theirs once the step is accepted)
            forget_impulses(s.step);
    };
    each_sim(step.tasks, prepare);
    // The packed pins straight into their lanes, as their records would hold them: no record is
    // written and read back. The packs take their joints level by level, a sparse sweep of the
    // joints and bodies that the hardware prefetcher does not follow: each joint's three lines
    // are asked for eight packs ahead, its bodies' two (local centre, centre) four ahead, once
    // the joint's first line (which names them) has come.
    const auto joint_of = [&](std::size_t p, int lane) -> const Joint& {
        return joints.joints[solved_[pin_packs_.first_record(p) + std::size_t(lane)].joint];
    };
    auto fill = [&](std::size_t begin, std::size_t end) {
        for (std::size_t p = begin; p < end; ++p) {
            for (int lane = 0; lane < wide_lanes; ++lane) {
                if (p + 8 < end) {
                    const char* line = reinterpret_cast<const char*>(&joint_of(p + 8, lane));
                    for (std::size_t off = 0; off < 192; off += 64)
                        prefetch(line + off);
                }
                if (p + 4 < end) {
                    const Joint& ahead = joint_of(p + 4, lane);
                    for (const std::uint32_t body : {ahead.body_a, ahead.body_b}) {
                        const char* line = reinterpret_cast<const char*>(&bodies.bodies[body]);
                        prefetch(line);
                        prefetch(line + 64);
                    }
                }
                const SolvedJoint& sj = solved_[pin_packs_.first_record(p) + std::size_t(lane)];
                const Joint& j = joints.joints[sj.joint];
                const PinFrames f = pin_frames(j, bodies.bodies[j.body_a], bodies.bodies[j.body_b]);
                JointStepState st = j.step;
                if (!def.enable_warm_starting)
                    forget_impulses(st);
                pin_packs_.fill(
                    p, lane,
                    {sj.solver_a, sj.solver_b, rotations + sj.rotation_a, rotations + sj.rotation_b,
                     f.frame_a, f.frame_b, f.center_offset, st.linear_impulse,
                     reaction_angular_impulse(JointType::revolute, st), softness_of(j)});
            }
        }
    };
    each_pack(step.tasks, fill);
    turn_joints(step.tasks);
}

void StepSolver::turn_joints(const StepTasks& tasks) {
    auto turn = [&](std::size_t begin, std::size_t end) {
        joint_rotations_.turn(solver_bodies_.data(), begin, end);
    };
    constexpr std::size_t block = 512;
    const std::size_t moving = joint_rotations_.moving();
    if (!tasks.parallel() || moving < 2 * block) {
        turn(0, moving);
        return;
    }
    auto run = [&](int first, int last) {
        turn(std::size_t(first) * block, std::min(moving, std::size_t(last) * block));
    };
    tasks.for_each_block(blocks_of(moving, block), run);
}

// The manifolds are prepared straight into their packs, four lanes at once, in solve order (a
// per-step array of prepared constraints cost a pass over ~300 bytes each). Over all the packs
// (on the calling thread) each pack is warm started as soon as it is prepared (`warm_start`); a
// block of a parallel preparation leaves the warm start to a pass after all of them.
namespace {

/// DD46's rolling radius of a shape: a circle's or a capsule's radius, 0 for a shape that does
/// not roll (a polygon, a segment).
double rolling_radius(const Geometry& g) {
    if (g.type == ShapeType::circle)
        return g.circle.radius;
    if (g.type == ShapeType::capsule)
        return g.capsule.radius;
    return 0.0;
}

} // namespace

void StepSolver::prepare_packs(const ContactManager& contacts, const ShapeStore* surfaces,
                               std::size_t begin, std::size_t end, bool warm_start) {
    const auto order = wide_solver_.order();
    // Reused: every lane is set or cleared each pack (clearing the whole input per pack,
    // 600 bytes, was a tenth of this loop's time).
    WideManifoldInput in;
    // The packs read the contacts level by level, a sparse sweep the hardware prefetcher
    // does not follow once the contacts outgrow the caches: ask for them four packs ahead.
    constexpr std::size_t ahead = 4;
    for (std::size_t p = begin; p < end; ++p) {
        if (p + ahead < end) {
            for (int l = 0; l < wide_lanes; ++l) {
                const std::uint32_t k = order[p + ahead][l];
                if (k == ConstraintGraph::no_constraint)
                    continue;
                const char* c =
                    reinterpret_cast<const char*>(&contacts.contacts()[edge_contact_[k]]);
                for (std::size_t line = 0; line < sizeof(Contact); line += 64)
                    prefetch(c + line);
                prefetch(&contacts.warm_impulses()[edge_contact_[k]]);
            }
        }
        for (int l = 0; l < wide_lanes; ++l) {
            const std::uint32_t k = order[p][l];
            if (k == ConstraintGraph::no_constraint) {
                clear_input_lane(in, l);
                continue;
            }
            const std::uint32_t c = edge_contact_[k];
            set_input_lane(in, l, edges_[k], c, contacts.contacts()[c], contacts.warm_impulses()[c],
                           edge_slot_[k]);
        }
        if (surfaces != nullptr) {
            for (int l = 0; l < wide_lanes; ++l) {
                const std::uint32_t k = order[p][l];
                if (k == ConstraintGraph::no_constraint) {
                    wide_solver_.set_surface_lane(p, l, 0.0, 0.0, 0.0);
                    continue;
                }
                const std::uint32_t ci = edge_contact_[k];
                const Contact& c = contacts.contacts()[ci];
                const ShapeDef& a = surfaces->defs[c.shape_a];
                const ShapeDef& b = surfaces->defs[c.shape_b];
                // \srs{DD46} \srs{DD47} the contact's surface motion from its shapes'
                wide_solver_.set_surface_lane(
                    p, l,
                    bridge::tangent_target(a.material.tangent_speed, b.material.tangent_speed),
                    bridge::rolling_resistance_length(
                        a.material.rolling_resistance, rolling_radius(a.geometry),
                        b.material.rolling_resistance, rolling_radius(b.geometry)),
                    contacts.rolling_impulses()[ci]);
            }
        }
        if (warm_start)
            wide_solver_.prepare_pack_and_warm_start(p, in, solver_bodies_);
        else
            wide_solver_.prepare_pack(p, in, solver_bodies_);
    }
}

namespace {

// Blocks of the edge listing, in contacts (~4 us each).
constexpr std::uint32_t edge_block = 1024;

} // namespace

std::uint32_t StepSolver::list_edges(const ContactManager& contacts, const StepTasks& tasks) {
    const auto& inputs = contacts.edge_inputs();
    const auto n = std::uint32_t(inputs.size());
    // The edge of contact i, or none: not touching, or both bodies asleep or static (only
    // with sleeping on), nothing to solve.
    const auto edge_of = [&](std::uint32_t i, GraphEdge& edge) {
        const ContactManager::EdgeInput& e = inputs[i];
        if (!e.touching)
            return false;
        edge = {solver_index_[e.body_a], solver_index_[e.body_b], e.group};
        return edge.body_a != 0 || edge.body_b != 0;
    };
    if (!tasks.parallel() || n < 2 * edge_block) {
        edges_.clear();
        edge_contact_.clear();
        edge_slot_.clear();
        std::uint32_t bounces = 0;
        GraphEdge edge;
        for (std::uint32_t i = 0; i < n; ++i) {
            if (!edge_of(i, edge))
                continue;
            edges_.push_back(edge);
            edge_contact_.push_back(i);
            edge_slot_.push_back(inputs[i].bounces ? bounces++ : WideContactSolver::no_slot);
        }
        return bounces;
    }
    // In parallel: each block counts its edges and bounces, the counts are summed in block
    // order, and each block writes its edges from there: the serial loop's lists.
    const int blocks = blocks_of(n, edge_block);
    edge_block_first_.resize(std::size_t(blocks) + 1);
    auto count = [&](int first, int last) {
        GraphEdge edge;
        for (int k = first; k < last; ++k) {
            EdgeCount c;
            const std::uint32_t end = std::min(n, std::uint32_t(k + 1) * edge_block);
            for (std::uint32_t i = std::uint32_t(k) * edge_block; i < end; ++i) {
                if (edge_of(i, edge)) {
                    ++c.edges;
                    c.bounces += inputs[i].bounces ? 1 : 0;
                }
            }
            edge_block_first_[std::size_t(k) + 1] = c;
        }
    };
    tasks.for_each_block(blocks, count);
    edge_block_first_[0] = {};
    for (std::size_t k = 0; k < std::size_t(blocks); ++k) {
        edge_block_first_[k + 1].edges += edge_block_first_[k].edges;
        edge_block_first_[k + 1].bounces += edge_block_first_[k].bounces;
    }
    const EdgeCount total = edge_block_first_[std::size_t(blocks)];
    edges_.resize(total.edges);
    edge_contact_.resize(total.edges);
    edge_slot_.resize(total.edges);
    auto fill = [&](int first, int last) {
        GraphEdge edge;
        for (int k = first; k < last; ++k) {
            EdgeCount at = edge_block_first_[std::size_t(k)];
            const std::uint32_t end = std::min(n, std::uint32_t(k + 1) * edge_block);
            for (std::uint32_t i = std::uint32_t(k) * edge_block; i < end; ++i) {
                if (!edge_of(i, edge))
                    continue;
                edges_[at.edges] = edge;
                edge_contact_[at.edges] = i;
                edge_slot_[at.edges] =
                    inputs[i].bounces ? at.bounces++ : WideContactSolver::no_slot;
                ++at.edges;
            }
        }
    };
    tasks.for_each_block(blocks, fill);
    return total.bounces;
}

void StepSolver::solve(ContactManager& contacts, JointStore& joint_store, const ShapeStore& shapes,
                       const StepContext& step) {
    const WorldDef& def = step.def;
    const StepTasks& tasks = step.tasks;
    const int n = def.substeps;
    const double dt = step.dt;
    const double h = step.h;
    memory::vector<Joint>& joints = joint_store.joints;
    // Warm starting off (Box2D v3's enableWarmStarting): the step starts from zero impulses,
    // and no substep starts from the impulses of the one before.
    const bool warm = def.enable_warm_starting;
    if (!warm)
        contacts.forget_warm_starts();
    // The touching manifolds in creation order, as the colouring sees them; those that can
    // bounce get a slot for the restitution pass's copy, also in creation order.
    const std::uint32_t bounce_count = list_edges(contacts, tasks);
    if (bouncing_.size() < bounce_count)
        bouncing_.resize(bounce_count); // only while the scene grows: never shrunk
    // With WorldDef::contact_regions > 1 the manifolds are solved region by region, on any
    // number of workers; with more than one worker the regions' streams run on several threads.
    wide_solver_.colour(edges_, solver_bodies_.size(), std::uint32_t(def.contact_regions), cut_);
    const std::uint32_t streams = tasks.parallel() ? wide_solver_.graph().streams() : 1;
    // DD46, DD47: only a world where some shape has surface motion fills and solves it.
    wide_solver_.use_surfaces(shapes.surface_motion);
    if (shapes.surface_motion)
        contacts.use_rolling();
    const ShapeStore* surfaces = shapes.surface_motion ? &shapes : nullptr;
    // Those that can bounce get a scalar copy for the restitution pass, prepared from the
    // velocities before the step (DD11's relative velocity before the impact).
    for (std::uint32_t k = 0; k < edges_.size(); ++k) {
        if (edge_slot_[k] == WideContactSolver::no_slot)
            continue;
        ContactConstraint& copy = bouncing_[edge_slot_[k]];
        contacts.unprepared_constraint(copy, edges_[k], edge_contact_[k]);
        prepare_contact(copy, solver_bodies_);
    }
    // The first substep's velocity half comes before the preparation, so that each pack can
    // be warm started as soon as it is prepared (below), as warm_start would after it. The
    // joints come before the contacts in every stage, as the later substeps have them.
    integrate_velocities(h, tasks);
    if (warm)
        warm_start_joints(joints, tasks);
    const std::size_t pack_count = wide_solver_.order().size();
    constexpr std::size_t pack_block = 32; // ~10 us of lane filling and preparation
    if (streams > 1 || (tasks.parallel() && pack_count > pack_block)) {
        // Preparation reads only the bodies' inverse masses, which the warm start leaves alone,
        // so the packs may be prepared in any order, and warm started after them in solve
        // order: the fused loop's bits.
        auto run = [&](int first, int last) {
            prepare_packs(contacts, surfaces, std::size_t(first) * pack_block,
                          std::min(pack_count, std::size_t(last) * pack_block), false);
        };
        tasks.for_each_block(blocks_of(pack_count, pack_block), run);
        if (warm)
            contact_pass(tasks, streams, nullptr, false);
    } else {
        prepare_packs(contacts, surfaces, 0, pack_count, warm);
    }

    ContactSolverSettings st;
    st.inv_h = 1.0 / h;
    // The contact spring is kept below a quarter of the substep rate to stay stable.
    st.softness =
        make_softness(capped_frequency(def.contact_hertz, n, dt), def.contact_damping_ratio, h);
    st.linear_slop = def.linear_slop;
    st.push_max_velocity = def.contact_push_max_velocity;
    st.restitution_threshold = def.restitution_threshold;

    for (int sub = 0; sub < n; ++sub) {
        if (sub > 0) { // the first substep's were done with the preparation
            integrate_velocities(h, tasks);
            if (warm) {
                warm_start_joints(joints, tasks);
                contact_pass(tasks, streams, nullptr, false);
            }
        }
        solve_joints(joints, h, true, tasks);
        contact_pass(tasks, streams, &st, true);
        constrain_velocities(def.maximum_linear_speed, tasks);
        integrate_positions(h, tasks);
        turn_joints(tasks);
        solve_joints(joints, h, false, tasks);
        contact_pass(tasks, streams, &st, false);
    }
    // A joint's solve can diverge where no input rule foresaw it (conflicting joints on light
    // bodies): checked before any impulse is stored, so that the world can refuse the step.
    if (find_divergence())
        return;
    // The step is accepted: the joints take its impulses (without warm starting, the joints
    // it did not solve start the next from none too).
    if (!warm)
        joint_store.forget_warm_starts();
    // (A packed pin's step changes only in its pin's impulse.)
    auto store = [&](std::size_t begin, std::size_t end) {
        for (std::size_t p = begin; p < end; ++p)
            for (int lane = 0; lane < wide_lanes; ++lane)
                joints[solved_[pin_packs_.first_record(p) + std::size_t(lane)].joint]
                    .step.linear_impulse = pin_packs_.impulse(p, lane);
    };
    each_pack(tasks, store);
    auto keep = [&](JointSim& s) {
        if (!pin_packs_.in_pack(std::size_t(&s - sims_.data())))
            joints[s.joint].step = s.step;
    };
    each_sim(tasks, keep);
    store_impulses(contacts, tasks, bounce_count, st);
    // The velocities the step leaves keep the locks and the limit too (DD39, DD40).
    constrain_velocities(def.maximum_linear_speed, tasks);
}

void StepSolver::warm_start_joints(const memory::vector<Joint>& joints, const StepTasks& tasks) {
    auto single = [&](JointSim& s) { warm_start_joint(s, joints[s.joint], solver_bodies_); };
    auto packs = [&](std::uint32_t first, std::uint32_t count) {
        pin_packs_.warm_start(first, count, solver_bodies_.data());
    };
    joint_pass(tasks, single, packs);
}

void StepSolver::solve_joints(const memory::vector<Joint>& joints, double h, bool use_bias,
                              const StepTasks& tasks) {
    auto single = [&](JointSim& s) {
        solve_joint(s, joints[s.joint], solver_bodies_, h, use_bias);
    };
    auto packs = [&](std::uint32_t first, std::uint32_t count) {
        pin_packs_.solve(first, count, solver_bodies_.data(), use_bias);
    };
    joint_pass(tasks, single, packs);
}

bool StepSolver::find_divergence() {
    // Contacts alone have not been seen to diverge, and worlds without joints skip the pass.
    diverged_ = null_index;
    if (joint_rotations_.moving() == 0)
        return false;
    for (std::size_t k = 1; k < solver_bodies_.size(); ++k) {
        const SolverBody& sb = solver_bodies_[k];
        // (A finite state beyond the supported one is the next step's DCX_range refusal.)
        if (std::isfinite(sb.v.x) && std::isfinite(sb.v.y) && std::isfinite(sb.w) &&
            std::isfinite(sb.dp.x) && std::isfinite(sb.dp.y) && std::isfinite(sb.dq))
            continue;
        const auto at = std::find(solver_index_.begin(), solver_index_.end(), k);
        diverged_ = std::uint32_t(at - solver_index_.begin());
        return true;
    }
    return false;
}

void StepSolver::store_impulses(ContactManager& contacts, const StepTasks& tasks,
                                std::uint32_t bounce_count, const ContactSolverSettings& st) {
    constexpr std::size_t store_block = 128; // ~10 us of stores
    const std::size_t pack_count = wide_solver_.order().size();
    const std::span<ContactConstraint> bouncers(bouncing_.data(), bounce_count);
    const ContactManager::ImpulseRecords records = contacts.impulse_records();
    const std::span<double> rolling = contacts.rolling_records(); // DD46 (empty: none)
    if (tasks.parallel() && pack_count > store_block) {
        auto run = [&](int first, int last) {
            wide_solver_.store(records.warm, records.totals, bouncers,
                               std::size_t(first) * store_block,
                               std::min(pack_count, std::size_t(last) * store_block), rolling);
        };
        tasks.for_each_block(blocks_of(pack_count, store_block), run);
    } else {
        wide_solver_.store(records.warm, records.totals, bouncers, 0, pack_count, rolling);
    }
    // \srs{R8} Post-collision velocities (and, integrated, positions) of colliding bodies.
    apply_restitution(bouncers, solver_bodies_, st);
    // A bouncing manifold's normal totals include the restitution pass's impulses: written
    // here, once (store left them to this pass).
    for (const ContactConstraint& b : bouncers) {
        for (int j = 0; j < b.count; ++j)
            records.totals[b.contact].normal[j] = b.points[j].total_normal_impulse;
    }
}

void StepSolver::constrain_velocities(double max_speed, const StepTasks& tasks) {
    for (const LockedBody& l : locked_) {
        SolverBody& sb = solver_bodies_[l.solver];
        sb.v = bridge::locked_velocity(sb.v, l.x, l.y);
    }
    if (!(max_speed < std::numeric_limits<double>::infinity()))
        return;
    over_solver_bodies(solver_bodies_.size(), tasks, [&](std::size_t begin, std::size_t end) {
        for (std::size_t k = begin; k < end; ++k)
            solver_bodies_[k].v = bridge::limited_velocity(solver_bodies_[k].v, max_speed);
    });
}

void StepSolver::contact_pass(const StepTasks& tasks, std::uint32_t streams,
                              const ContactSolverSettings* settings, bool use_bias) {
    if (streams <= 1) { // the packs in their stored order, on this thread
        if (settings == nullptr)
            wide_solver_.warm_start(solver_bodies_);
        else
            wide_solver_.solve(solver_bodies_, *settings, use_bias);
        return;
    }
    struct Pass {
        StepSolver* solver;
        const ContactSolverSettings* settings;
        bool use_bias;
    } pass{this, settings, use_bias};
    const PackStreams::RunPacks run_packs = [](void* context, std::size_t first, std::size_t count,
                                               std::uint32_t stream) {
        const Pass& p = *static_cast<const Pass*>(context);
        StepSolver& s = *p.solver;
        if (p.settings == nullptr)
            s.wide_solver_.warm_start_run(first, count, stream, s.solver_bodies_);
        else
            s.wide_solver_.solve_run(first, count, stream, s.solver_bodies_, *p.settings,
                                     p.use_bias);
    };
    pack_streams_.reset();
    const ConstraintGraph& graph = wide_solver_.graph();
    // One item per stream, each preferring its own; a piece of several items runs them all.
    auto run = [&](int first, int) {
        pack_streams_.run(graph, std::uint32_t(first), run_packs, &pass);
    };
    tasks.for_each_block(int(graph.streams()), run);
}

void StepSolver::finalize(BodyStore& store, ShapeStore& shape_store, const StepContext& step) {
    const WorldDef& def = step.def;
    const StepTasks& tasks = step.tasks;
    const auto body_count = std::uint32_t(store.bodies.size());
    shape_store.reserve_undecided(); // allocates only after shapes were added
    continuous_.clear();
    if (!tasks.parallel() || solver_bodies_.size() < parallel_bodies) {
        write_back<false>(store, shape_store, def, 0, body_count);
    } else {
        if (written_back_.size() < body_count) { // only while the scene grows
            written_back_.resize(body_count);
            starts_.resize(body_count);
        }
        if (undecided_.size() < shape_store.shapes.size())
            undecided_.resize(shape_store.shapes.size());
        constexpr std::uint32_t block = 256;
        auto run = [&](int first, int last) {
            write_back<true>(store, shape_store, def, std::uint32_t(first) * block,
                             std::min(body_count, std::uint32_t(last) * block));
        };
        tasks.for_each_block(blocks_of(body_count, block), run);
        // The lists in body order, as the serial sweep makes them.
        auto& shapes = shape_store.shapes;
        for (std::uint32_t i = 0; i < body_count; ++i) {
            const std::uint8_t done = written_back_[i];
            if (done == 0)
                continue;
            if (done & 1u) {
                const Start& st = starts_[i];
                continuous_.add(i, st.center, st.angle, st.v, st.w);
            }
            if (done & 2u) {
                for (std::uint32_t s = store.bodies[i].first_shape; s != null_index;
                     s = shapes[s].next) {
                    if (undecided_[s])
                        shape_store.mark_undecided(s);
                }
            }
        }
    }
    shape_store.refit_undecided();
}

void StepSolver::continuous(BodyStore& store, ShapeStore& shape_store,
                            const ContactManager& contacts, const JointStore& joints,
                            const StepContext& step) {
    continuous_.run(store, shape_store, contacts, joints, step.def);
}

template <bool deferred>
void StepSolver::write_back(BodyStore& store, ShapeStore& shape_store, const WorldDef& def,
                            std::uint32_t begin, std::uint32_t end) {
    auto& bodies = store.bodies;
    auto& shapes = shape_store.shapes;
    // Bodies and shapes are swept in order, but the sweep reads two lines of each shape
    // at a 384-byte stride beside the bodies', which the hardware prefetcher does not keep
    // ahead of at 16k boxes: ask for the bodies 16 ahead and their first shapes 8 ahead.
    // (The vertex lines are read only by a shape the header's bound cannot decide.)
    constexpr std::uint32_t body_ahead = 16, shape_ahead = 8;
    // A body whose every point moved less than the speculative distance cannot reach a shape
    // it had no contact with at the step's start: only the others are swept (DD29).
    const double seen = def.speculative_distance;
    const bool jointed = joint_rotations_.moving() != 0;
    // Solver body 0 stands for the bodies that did not move: static, asleep or destroyed
    // (their lines are neither asked for nor read).
    for (std::uint32_t i = begin; i < end; ++i) {
        if (i + body_ahead < end && solver_index_[i + body_ahead] != 0) {
            // Its first two lines: the third only if it is loaded (rare).
            const char* p = reinterpret_cast<const char*>(&bodies[i + body_ahead]);
            for (std::size_t line = 0; line < offsetof(Body, force); line += 64)
                prefetch(p + line);
        }
        if (i + shape_ahead < end && solver_index_[i + shape_ahead] != 0) {
            const std::uint32_t s = bodies[i + shape_ahead].first_shape;
            if (s != null_index) {
                const Shape& sh = shapes[s];
                prefetch(&sh.fat_box);
                prefetch(&sh.body_xf);
            }
        }
        if (solver_index_[i] == 0) {
            if constexpr (deferred)
                written_back_[i] = 0;
            continue;
        }
        Body& b = bodies[i];
        const SolverBody& sb = solver_bodies_[solver_index_[i]];
        const Vec2d v0 = b.v;
        const double w0 = b.w;
        b.v = sb.v;
        b.w = sb.w;
        const double dp2 = dot(sb.dp, sb.dp);
        // Most bodies are decided by the translation alone; a turning slow one by its reach.
        bool fast = def.enable_continuous && b.type == BodyType::dynamic && dp2 > seen * seen;
        if (def.enable_continuous && !fast && sb.dq != 0.0 && b.type == BodyType::dynamic) {
            double reach = 0.0; // a bound: the radius plus the centre's offset in 1-norm
            for (std::uint32_t s = b.first_shape; s != null_index; s = shapes[s].next) {
                const Collider& k = shapes[s].collider;
                reach = std::max(reach, k.radius + std::abs(k.center.x - b.local_center.x) +
                                            std::abs(k.center.y - b.local_center.y));
            }
            fast = bridge::motion_bound(std::sqrt(dp2), std::abs(sb.dq), reach) > seen;
        }
        std::uint8_t done = 0;
        if (fast) {
            if constexpr (deferred) {
                starts_[i] = {b.center, b.angle, v0, w0};
                done = 1;
            } else {
                continuous_.add(i, b.center, b.angle, v0, w0);
            }
        }
        b.center += sb.dp;
        b.angle += sb.dq;
        // A jointed body's rotation was turned to this angle, the same sum, after the last
        // position half (turn_joints).
        const std::uint32_t solver = solver_index_[i];
        b.xf.q = jointed && joint_rotations_.jointed(solver) ? joint_rotations_.rotation(solver)
                                                             : Rot::from_angle(b.angle);
        b.xf.p = b.center - rotate(b.xf.q, b.local_center);
        if (b.loaded) {
            b.force_once = {};
            b.torque_once = 0.0;
            b.loaded = !b.unloaded();
        }
        // The shapes' copies, in the same pass.
        for (std::uint32_t s = b.first_shape; s != null_index; s = shapes[s].next) {
            const bool inside = shape_store.follow_pose(shapes[s], b);
            if constexpr (deferred) {
                undecided_[s] = !inside;
                done |= inside ? 0 : 2;
            } else if (!inside) {
                shape_store.mark_undecided(s);
            }
        }
        if constexpr (deferred)
            written_back_[i] = done;
    }
}

} // namespace tamias2d
