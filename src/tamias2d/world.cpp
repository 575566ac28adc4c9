#include "tamias2d/world.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>

#include "tamias2d/dynamics/body_store.hpp"
#include "tamias2d/dynamics/contact_manager.hpp"
#include "tamias2d/dynamics/distance_joint.hpp"
#include "tamias2d/dynamics/island_sleep.hpp"
#include "tamias2d/dynamics/joint_store.hpp"
#include "tamias2d/dynamics/model_bridge.hpp"
#include "tamias2d/dynamics/motor_joint.hpp"
#include "tamias2d/dynamics/prismatic_joint.hpp"
#include "tamias2d/dynamics/revolute_joint.hpp"
#include "tamias2d/dynamics/sensor_overlaps.hpp"
#include "tamias2d/dynamics/shape_store.hpp"
#include "tamias2d/dynamics/state_hasher.hpp"
#include "tamias2d/dynamics/step_solver.hpp"
#include "tamias2d/dynamics/target_joint.hpp"
#include "tamias2d/dynamics/weld_joint.hpp"
#include "tamias2d/dynamics/wheel_joint.hpp"
#include "tamias2d/errors.hpp"
#include "tamias2d/geometry/shape_queries.hpp"
#include "tamias2d/model/dd13_torque.hpp"
#include "tamias2d/model/dd15_kinetic_energy.hpp"
#include "tamias2d/model/dd16_potential_energy.hpp"
#include "tamias2d/model/gd1_conservation_of_momentum.hpp"
#include "tamias2d/parallel/step_tasks.hpp"
#include "tamias2d/units/angle.hpp"
#include "tamias2d/validation.hpp"

namespace tamias2d {

namespace u = tamias2d::units;

namespace {

/// A body a joint definition names, for its checks and their messages.
JointBody joint_body(const BodyStore& bodies, BodyId id, const Body& b) {
    return {id, bodies.label(id.index), b.type};
}

/// A joint reading or setter called on a joint of a kind it does not apply to.
[[noreturn]] void wrong_joint(const char* call, JointId id, const Joint& j, const char* rule) {
    throw WrongKind(call, "joint[" + std::to_string(id.index) + "]", joint_kind_name(j.type), rule);
}

/// Forces, torques and impulses move dynamic bodies only: one given to a static or kinematic
/// body would be lost without a trace, so it is refused as the mistake it is.
void require_dynamic(const BodyStore& bodies, BodyId id, const Body& b, const char* call) {
    if (b.type != BodyType::dynamic)
        throw WrongKind(call, bodies.label(id.index), std::string(type_name(b.type)) + " body",
                        "must be a dynamic body (a static or kinematic body does not move under "
                        "forces, torques or impulses)");
}

} // namespace

/// The engine's state and the step's pipeline over its stages (dynamics/): the bodies, the
/// shapes with the broad phase, the contacts, the joints, the solver, sleeping.
struct World::Impl {
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
    StepTasks tasks;         ///< the step's parallel loops (WorldDef::workers, task_system)
    std::vector<Load> loads; ///< this step's load-function values (empty when none has one)

    explicit Impl(const WorldDef& d) : def(d) {}

    /// The solve diverged (StepSolver::diverged): the joints and sleep states as they were, no
    /// event of this step, and the step refused naming the body (SolverDivergence). Nothing was
    /// finalized, so the bodies are as they were; the contacts hold the manifolds of those same
    /// poses.
    [[noreturn]] void refuse_diverged() {
        contacts.begin_events.clear();
        contacts.end_events.clear();
        joints.refuse_step(solver.diverged(), bodies, def.enable_sleep);
    }

    /// The time-varying loads at the step's start: a user function returning NaN is rejected
    /// before anything has changed. Most worlds have none: then no setting is read and `loads`
    /// stays empty.
    void evaluate_loads() {
        loads.clear();
        if (bodies.loaded_bodies > 0)
            loads.assign(bodies.size(), Load{});
        for (std::uint32_t i = 0; i < loads.size(); ++i) {
            const Body& b = bodies.bodies[i];
            const LoadFunction& load = bodies.settings[i].load;
            if (!b.alive || !load || b.type != BodyType::dynamic)
                continue;
            const Load l = load(time);
            require_within("load(t).force", l.force, supported::input_max, "N");
            require_within("load(t).torque", l.torque, supported::input_max, "N m");
            loads[i] = l;
        }
    }

    /// \srs{DCX_range} A step starts only from a state within supported::state_max, the headroom a
    /// simulation of in-range inputs may grow into; from there no product of one step
    /// overflows (docs/design.md, "Supported ranges"). One pass over the bodies, before
    /// anything changes.
    void check_state() const {
        constexpr double m = supported::state_max;
        for (std::uint32_t i = 0; i < bodies.size(); ++i) {
            const Body& b = bodies.bodies[i];
            if (!b.alive || b.type == BodyType::static_body)
                continue;
            if (std::abs(b.center.x) <= m && std::abs(b.center.y) <= m && std::abs(b.v.x) <= m &&
                std::abs(b.v.y) <= m && std::abs(b.w) <= m && std::abs(b.angle) <= m)
                continue;
            const std::string at = bodies.label(i) + ".";
            require_within(at + "position", b.center, m, "m");
            require_within(at + "velocity", b.v, m, "m s^-1");
            require_within(at + "angular_velocity", b.w, m, "rad s^-1");
            require_within(at + "angle", b.angle, m, "rad");
        }
        joints.check_levers(bodies); // (the joints are few: one pass)
    }
};

World::World(const WorldDef& def) {
    validate(def);
    impl_ = std::make_unique<Impl>(def);
    impl_->tasks = StepTasks(def.workers, def.task_system);
}
World::~World() = default;
World::World(World&&) noexcept = default;
World& World::operator=(World&&) noexcept = default;

BodyId World::create_body(const BodyDef& def) {
    validate(def);
    Impl& w = *impl_;
    const std::uint32_t i = w.bodies.create(def, w.def.enable_sleep);
    w.bodies.update_mass(i, w.shapes);
    return w.bodies.id(i);
}

void World::destroy_body(BodyId id) {
    Impl& w = *impl_;
    const Body& b = w.bodies.get(id);
    while (!w.joints.of_body(id.index).empty())
        destroy_joint(w.joints.id(w.joints.of_body(id.index).back()));
    for (std::uint32_t s = b.first_shape; s != null_index;) {
        const std::uint32_t next = w.shapes.shapes[s].next;
        w.contacts.destroy_of_shape(s, w.bodies, w.shapes);
        w.sensors.remove_shape(s, w.bodies, w.shapes);
        w.shapes.release(s);
        s = next;
    }
    w.bodies.destroy(id.index);
}

ShapeId World::create_shape(BodyId body_id, const ShapeDef& def) {
    Impl& w = *impl_;
    Body& b = w.bodies.get(body_id); // handle check before validation: both leave it unchanged
    validate(def);
    const std::uint32_t i = w.shapes.create(body_id.index, b, def);
    w.bodies.update_mass(body_id.index, w.shapes); // also copies the body's pose into its shapes
    if (def.is_sensor)
        w.sensors.add(i);
    return w.shapes.id(i);
}

std::vector<ShapeId> World::create_chain(BodyId body_id, std::span<const ShapeDef> segments) {
    Impl& w = *impl_;
    Body& b = w.bodies.get(body_id);
    for (std::size_t k = 0; k < segments.size(); ++k) {
        if (segments[k].geometry.type != ShapeType::chain_segment)
            throw ValidationError("chain[" + std::to_string(k) + "].type",
                                  double(segments[k].geometry.type), "must be a chain segment",
                                  "DCX_shape");
        validate(segments[k]);
    }
    std::vector<ShapeId> out;
    out.reserve(segments.size());
    std::uint32_t last = null_index; // each segment follows the one before: a linear build
    for (const ShapeDef& def : segments) {
        last = w.shapes.create(body_id.index, b, def, last);
        if (def.is_sensor)
            w.sensors.add(last);
        out.push_back(w.shapes.id(last));
    }
    w.bodies.update_mass(body_id.index, w.shapes);
    return out;
}

void World::set_filter(ShapeId id, const Filter& filter) {
    Impl& w = *impl_;
    const Shape& sh = w.shapes.get(id);
    const Filter old = std::exchange(w.shapes.defs[id.index].filter, filter);
    try {
        w.contacts.refilter(id.index, w.bodies, w.shapes, w.joints);
    } catch (...) { // the user's filter threw (refilter changed nothing): as before the call
        w.shapes.defs[id.index].filter = old;
        throw;
    }
    w.shapes.broad_phase.touch_proxy(sh.proxy); // the pairs it now admits, at the next step
}

Filter World::filter(ShapeId id) const {
    impl_->shapes.get(id);
    return impl_->shapes.defs[id.index].filter;
}

void World::set_custom_filter(std::function<bool(ShapeId, ShapeId)> filter) {
    impl_->contacts.custom_filter = std::move(filter);
}

void World::destroy_shape(ShapeId id) {
    Impl& w = *impl_;
    const std::uint32_t body = w.shapes.get(id).body;
    w.contacts.destroy_of_shape(id.index, w.bodies, w.shapes);
    w.sensors.remove_shape(id.index, w.bodies, w.shapes);
    w.shapes.destroy(id.index, w.bodies.bodies[body]);
    w.bodies.update_mass(body, w.shapes);
}

bool World::is_valid(BodyId id) const {
    return impl_->bodies.is_valid(id);
}
bool World::is_valid(ShapeId id) const {
    return impl_->shapes.is_valid(id);
}

std::vector<BodyId> World::bodies() const {
    std::vector<BodyId> out;
    for (std::uint32_t i = 0; i < impl_->bodies.size(); ++i) {
        if (impl_->bodies.bodies[i].alive)
            out.push_back(impl_->bodies.id(i));
    }
    return out;
}

std::vector<ShapeId> World::shapes(BodyId id) const {
    std::vector<ShapeId> out;
    for (std::uint32_t s = impl_->bodies.get(id).first_shape; s != null_index;
         s = impl_->shapes.shapes[s].next)
        out.push_back(impl_->shapes.id(s));
    return out;
}

namespace {

/// Stores a joint made from a validated definition, removes the contacts it filters, wakes its
/// bodies.
JointId add_joint(World::Impl& w, const Joint& j) {
    validate_levers(w.bodies, j, "joint.");
    const std::uint32_t i = w.joints.create(j);
    if (!j.collide_connected)
        w.contacts.destroy_between(j.body_a, j.body_b, w.bodies, w.shapes);
    w.bodies.wake(j.body_a);
    w.bodies.wake(j.body_b);
    return w.joints.id(i);
}

/// A two-body joint: the handles checked, the definition validated, the joint its kind makes
/// (make_joint, beside the kind's solve) stored.
template <class Def> JointId join(World::Impl& w, const Def& def) {
    const Body& a = w.bodies.get(def.body_a);
    const Body& b = w.bodies.get(def.body_b);
    validate(def, joint_body(w.bodies, def.body_a, a), joint_body(w.bodies, def.body_b, b));
    return add_joint(w, make_joint(def, a, b));
}

} // namespace

JointId World::create_joint(const RevoluteJointDef& def) {
    return join(*impl_, def);
}
JointId World::create_joint(const DistanceJointDef& def) {
    return join(*impl_, def);
}
JointId World::create_joint(const PrismaticJointDef& def) {
    return join(*impl_, def);
}
JointId World::create_joint(const WeldJointDef& def) {
    return join(*impl_, def);
}
JointId World::create_joint(const WheelJointDef& def) {
    return join(*impl_, def);
}
JointId World::create_joint(const MotorJointDef& def) {
    return join(*impl_, def);
}
JointId World::create_joint(const TargetJointDef& def) {
    Impl& w = *impl_;
    const Body& b = w.bodies.get(def.body);
    validate(def, joint_body(w.bodies, def.body, b));
    return add_joint(w, make_joint(def, b));
}

void World::set_joint_target(JointId id, Vec2d target) {
    Joint& j = impl_->joints.get(id);
    if (j.type != JointType::target)
        wrong_joint("set_joint_target", id, j, "must be a target joint");
    require_within("joint.target", target, supported::input_max, "m");
    j.target = target;
    impl_->bodies.wake(j.body_b);
}

void World::destroy_joint(JointId id) {
    Impl& w = *impl_;
    w.joints.get(id); // throws for a stale handle, before anything changes
    w.joints.unjoin(id.index, w.bodies, w.shapes);
}

bool World::is_valid(JointId id) const {
    return impl_->joints.is_valid(id);
}

Vec2d World::joint_reaction_force(JointId id) const {
    return bridge::reaction_force(reaction_impulse(impl_->joints.get(id)), impl_->joints.inv_h);
}

double World::joint_reaction_torque(JointId id) const {
    return bridge::reaction_torque(reaction_angular_impulse(impl_->joints.get(id)),
                                   impl_->joints.inv_h);
}

double World::joint_angle(JointId id) const {
    const Joint& j = impl_->joints.get(id);
    if (j.type == JointType::distance || j.type == JointType::target || j.type == JointType::motor)
        wrong_joint("joint_angle", id, j,
                    "must be a revolute, prismatic, weld or wheel joint (the kinds that hold an "
                    "angle)");
    return bridge::joint_angle(impl_->bodies.bodies[j.body_a].angle,
                               impl_->bodies.bodies[j.body_b].angle, j.reference_angle);
}

double World::joint_translation(JointId id) const {
    const Joint& j = impl_->joints.get(id);
    if (j.type != JointType::prismatic && j.type != JointType::wheel)
        wrong_joint("joint_translation", id, j,
                    "must be a prismatic or wheel joint (the kinds with an axis)");
    const Body& a = impl_->bodies.bodies[j.body_a];
    const Body& b = impl_->bodies.bodies[j.body_b];
    const Vec2d r_a = rotate(a.xf.q, j.local_anchor_a - a.local_center);
    const Vec2d r_b = rotate(b.xf.q, j.local_anchor_b - b.local_center);
    return bridge::line((b.center + r_b) - (a.center + r_a), r_a, r_b, rotate(a.xf.q, j.local_axis))
        .translation;
}

void World::set_joint_motor_speed(JointId id, double speed) {
    Joint& j = impl_->joints.get(id);
    if (j.type != JointType::revolute && j.type != JointType::prismatic &&
        j.type != JointType::wheel)
        wrong_joint("set_joint_motor_speed", id, j,
                    "must be a revolute, prismatic or wheel joint (the kinds with a motor)");
    require_within("joint.motor_speed", speed, supported::input_max,
                   j.type == JointType::prismatic ? "m s^-1" : "rad s^-1");
    j.motor_speed = speed;
    impl_->bodies.wake(j.body_a);
    impl_->bodies.wake(j.body_b);
}

void World::set_motor_joint_offsets(JointId id, Vec2d linear_offset, double angular_offset) {
    Joint& j = impl_->joints.get(id);
    if (j.type != JointType::motor)
        wrong_joint("set_motor_joint_offsets", id, j, "must be a motor joint");
    require_within("joint.linear_offset", linear_offset, supported::input_max, "m");
    require_within("joint.angular_offset", angular_offset, supported::input_max, "rad");
    j.local_anchor_a = linear_offset;
    j.reference_angle = angular_offset;
    impl_->bodies.wake(j.body_a);
    impl_->bodies.wake(j.body_b);
}

std::span<const JointId> World::broken_joints() const {
    return impl_->joints.broken;
}

std::size_t World::joint_count() const {
    return impl_->joints.live();
}

std::size_t World::body_count() const {
    return impl_->bodies.count();
}

void World::step(double dt) {
    validate_time_step(dt);
    Impl& w = *impl_;
    w.check_state();
    w.evaluate_loads();
    w.contacts.forget_filter_error(); // (one a step cut short by bad_alloc left)
    w.joints.broken.clear();
    w.contacts.begin_events.clear();
    w.contacts.end_events.clear();
    w.sensors.begin_events.clear();
    w.sensors.end_events.clear();
    const bool guarded = w.joints.live() > 0;
    if (guarded)
        w.joints.guard_step(w.bodies, w.def.enable_sleep);
    w.contacts.find_new(w.bodies, w.shapes, w.joints);
    const double h = dt / w.def.substeps;
    w.joints.inv_h = w.def.substeps / dt;
    if (w.def.enable_sleep && !w.bodies.any_awake()) {
        // Every body asleep: every contact is kept as it is (a new one, of a static body moved
        // onto sleeping ones, too) and nothing is solved; the step does only this.
        w.contacts.keep_all();
    } else if (w.def.enable_sleep) {
        // The islands need this step's touching contacts, and the solver bodies the islands.
        w.contacts.update(w.bodies, w.shapes, true, w.def.speculative_distance,
                          w.def.manifold_reuse_distance, w.tasks);
        w.sleep.wake_islands(w.bodies, w.contacts, w.joints);
        w.solver.prepare_bodies(w.bodies, w.loads, w.def, h, w.tasks);
        w.solver.prepare_joints(w.joints, w.bodies);
        w.solver.solve(w.contacts, w.joints, w.def, dt, w.tasks);
        if (guarded && w.solver.diverged() != null_index)
            w.refuse_diverged();
        w.solver.finalize(w.bodies, w.shapes, w.contacts, w.joints, w.def, w.tasks);
        w.joints.break_joints(w.bodies, w.shapes);
        w.sleep.update_sleep(w.bodies, w.def, dt);
    } else {
        w.solver.prepare_bodies(w.bodies, w.loads, w.def, h, w.tasks);
        w.solver.prepare_joints(w.joints, w.bodies);
        w.contacts.update(w.bodies, w.shapes, false, w.def.speculative_distance,
                          w.def.manifold_reuse_distance, w.tasks);
        w.solver.solve(w.contacts, w.joints, w.def, dt, w.tasks);
        if (guarded && w.solver.diverged() != null_index)
            w.refuse_diverged();
        w.solver.finalize(w.bodies, w.shapes, w.contacts, w.joints, w.def, w.tasks);
        w.joints.break_joints(w.bodies, w.shapes);
    }
    // DD28: the sensors see the poses this step made.
    if (!w.sensors.empty())
        w.sensors.update(w.bodies, w.shapes, w.contacts);
    // Compensated sum, so that a load switching at t = n dt is seen at step n, not n + 1.
    const double y = dt - w.time_error;
    const double t = w.time + y;
    w.time_error = (t - w.time) - y;
    w.time = t;
    w.contacts.report_stale();
    // The user's filter threw: the step is whole, with the pairs it threw on refused.
    w.contacts.rethrow_filter_error();
}

double World::time() const {
    return impl_->time;
}
void World::set_gravity(Vec2d g) {
    require_within("gravity", g, supported::input_max, "m s^-2");
    impl_->def.gravity = g;
    for (std::uint32_t i = 0; i < impl_->bodies.size(); ++i)
        impl_->bodies.wake(
            i); // a sleeping pile must feel the new gravity (wake skips the immovable)
}
Vec2d World::gravity() const {
    return impl_->def.gravity;
}
const WorldDef& World::settings() const {
    return impl_->def;
}

BodyState World::state(BodyId id) const {
    const Body& b = impl_->bodies.get(id);
    return {b.center, b.v, u::wrap_orientation(b.angle), b.w};
}
Vec2d World::position(BodyId id) const {
    return impl_->bodies.get(id).center;
}
Vec2d World::origin(BodyId id) const {
    return impl_->bodies.get(id).xf.p;
}
double World::orientation(BodyId id) const {
    return u::wrap_orientation(impl_->bodies.get(id).angle);
}
Vec2d World::velocity(BodyId id) const {
    return impl_->bodies.get(id).v;
}
double World::angular_velocity(BodyId id) const {
    return impl_->bodies.get(id).w;
}
double World::mass(BodyId id) const {
    return impl_->bodies.get(id).mass;
}
double World::inertia(BodyId id) const {
    return impl_->bodies.get(id).inertia;
}
Vec2d World::local_center(BodyId id) const {
    return impl_->bodies.get(id).local_center;
}
BodyType World::type(BodyId id) const {
    return impl_->bodies.get(id).type;
}
const std::string& World::name(BodyId id) const {
    impl_->bodies.get(id); // handle check
    return impl_->bodies.settings[id.index].name;
}

void World::set_transform(BodyId id, Vec2d origin, double angle) {
    Body& b = impl_->bodies.get(id);
    require_within("origin", origin, supported::input_max, "m");
    require_within("angle", angle, supported::input_max, "rad");
    b.angle = angle;
    b.xf = {origin, Rot::from_angle(angle)};
    b.center = transform_point(b.xf, b.local_center);
    for (std::uint32_t s = b.first_shape; s != null_index; s = impl_->shapes.shapes[s].next)
        impl_->shapes.follow_body(impl_->shapes.shapes[s], b);
    impl_->shapes.apply_moves();
    impl_->bodies.wake(id.index);
    if (impl_->def.enable_sleep && b.type == BodyType::static_body)
        impl_->contacts.wake_touching(id.index, impl_->bodies);
}
void World::set_damping(BodyId id, double linear, double angular) {
    Body& b = impl_->bodies.get(id);
    validate_damping("linear_damping", linear);
    validate_damping("angular_damping", angular);
    BodySettings& set = impl_->bodies.settings[id.index];
    set.linear_damping = linear;
    set.angular_damping = angular;
    b.damped = b.type == BodyType::dynamic && (linear != 0.0 || angular != 0.0);
}
double World::linear_damping(BodyId id) const {
    impl_->bodies.get(id); // handle check
    return impl_->bodies.settings[id.index].linear_damping;
}
double World::angular_damping(BodyId id) const {
    impl_->bodies.get(id); // handle check
    return impl_->bodies.settings[id.index].angular_damping;
}

void World::set_velocity(BodyId id, Vec2d v) {
    Body& b = impl_->bodies.get(id);
    require_within("velocity", v, supported::input_max, "m s^-1");
    if (b.type != BodyType::static_body)
        b.v = v;
    impl_->bodies.wake(id.index);
}
void World::set_angular_velocity(BodyId id, double omega) {
    Body& b = impl_->bodies.get(id);
    require_within("angular_velocity", omega, supported::input_max, "rad s^-1");
    if (b.type != BodyType::static_body)
        b.w = omega;
    impl_->bodies.wake(id.index);
}
void World::set_force(BodyId id, Vec2d force) {
    Body& b = impl_->bodies.get(id);
    require_within("force", force, supported::input_max, "N");
    b.force = force;
    b.loaded = true;
    impl_->bodies.wake(id.index);
}
void World::set_torque(BodyId id, double torque) {
    Body& b = impl_->bodies.get(id);
    require_within("torque", torque, supported::input_max, "N m");
    b.torque = torque;
    b.loaded = true;
    impl_->bodies.wake(id.index);
}
void World::apply_force(BodyId id, Vec2d force, Vec2d world_point) {
    Body& b = impl_->bodies.get(id);
    require_dynamic(impl_->bodies, id, b, "apply_force");
    require_within("force", force, supported::input_max, "N");
    require_within("world_point", world_point, supported::input_max, "m");
    // The one-step loads add up until the next step: their sums stay within the state's range.
    const Vec2d force_once = b.force_once + force;
    const double torque_once =
        b.torque_once + model::dd13::torque(bridge::typed<u::Length>(world_point - b.center),
                                            bridge::typed<u::Force>(force))
                            .value();
    require_within("force (summed one-step forces)", force_once, supported::state_max, "N");
    require_within("torque (summed one-step torques)", torque_once, supported::state_max, "N m");
    b.force_once = force_once;
    b.loaded = true;
    b.torque_once = torque_once;
    impl_->bodies.wake(id.index);
}
void World::apply_torque(BodyId id, double torque) {
    Body& b = impl_->bodies.get(id);
    require_dynamic(impl_->bodies, id, b, "apply_torque");
    require_within("torque", torque, supported::input_max, "N m");
    require_within("torque (summed one-step torques)", b.torque_once + torque, supported::state_max,
                   "N m");
    b.torque_once += torque;
    b.loaded = true;
    impl_->bodies.wake(id.index);
}
void World::apply_impulse(BodyId id, Vec2d impulse, Vec2d world_point) {
    Body& b = impl_->bodies.get(id);
    require_dynamic(impl_->bodies, id, b, "apply_impulse");
    require_within("impulse", impulse, supported::input_max, "N s");
    require_within("world_point", world_point, supported::input_max, "m");
    const double magnitude = length(impulse);
    if (magnitude == 0.0) {
        impl_->bodies.wake(id.index);
        return;
    }
    // IM3's impulse application (DD10 for v, r x J / I for omega), against an immovable body.
    SolverBody ground{};
    SolverBody self{b.v, b.w, b.inv_mass, b.inv_inertia, {}, 0.0};
    const Vec2d n = impulse / magnitude;
    bridge::apply_impulse(ground, self, 0.0, bridge::moment_arm(world_point - b.center, n), n,
                          magnitude);
    // A light body struck hard: refused, as the next step would refuse its state.
    require_within("impulse: the velocity", self.v, supported::state_max, "m s^-1");
    require_within("impulse: the angular velocity", self.w, supported::state_max, "rad s^-1");
    impl_->bodies.wake(id.index);
    b.v = self.v;
    b.w = self.w;
}
void World::set_load(BodyId id, LoadFunction load) {
    impl_->bodies.get(id); // handle check
    LoadFunction& old = impl_->bodies.settings[id.index].load;
    impl_->bodies.loaded_bodies += (load ? 1 : 0) - (old ? 1 : 0);
    old = std::move(load);
    impl_->bodies.wake(id.index);
}

bool World::is_awake(BodyId id) const {
    impl_->bodies.get(id); // handle check
    return impl_->bodies.sleep_states[id.index].awake;
}
void World::set_awake(BodyId id, bool awake) {
    Body& b = impl_->bodies.get(id);
    if (awake) {
        impl_->bodies.wake(id.index);
        return;
    }
    if (!impl_->def.enable_sleep || b.type == BodyType::static_body)
        return; // with sleeping off every body stays awake
    impl_->bodies.sleep_states[id.index].awake = false;
    impl_->bodies.sleep_states[id.index].sleep_time = 0.0;
    b.v = {};
    b.w = 0.0;
    b.force_once = {};
    b.torque_once = 0.0;
}

double World::kinetic_energy() const {
    double e = 0.0;
    for (const Body& b : impl_->bodies.bodies) {
        if (!b.alive || b.type != BodyType::dynamic)
            continue;
        const double inertia = b.inv_inertia > 0.0 ? b.inertia : 0.0;
        e += model::dd15::kinetic_energy(
                 u::from_value<u::Mass>(b.mass), bridge::typed<u::Velocity>(b.v),
                 u::from_value<u::MomentOfInertia>(inertia), u::from_value<u::AngularVelocity>(b.w))
                 .value();
    }
    return e;
}
double World::potential_energy() const {
    double e = 0.0;
    for (const Body& b : impl_->bodies.bodies) {
        if (!b.alive || b.type != BodyType::dynamic)
            continue;
        e += model::dd16::potential_energy(
                 u::from_value<u::Mass>(b.mass),
                 bridge::typed<u::Acceleration>(b.gravity_scale * impl_->def.gravity),
                 bridge::typed<u::Length>(b.center))
                 .value();
    }
    return e;
}
Vec2d World::linear_momentum() const {
    std::vector<model::gd1::MassVelocity> mv;
    for (const Body& b : impl_->bodies.bodies) {
        if (!b.alive || b.type != BodyType::dynamic)
            continue;
        mv.push_back({u::from_value<u::Mass>(b.mass), bridge::typed<u::Velocity>(b.v)});
    }
    return bridge::plain(model::gd1::total_momentum(mv));
}

std::span<const ContactInfo> World::contacts() const {
    return impl_->contacts.report(impl_->bodies, impl_->shapes);
}
std::span<const ContactEvent> World::contact_begin_events() const {
    return impl_->contacts.begin_events;
}
std::span<const ContactEvent> World::contact_end_events() const {
    return impl_->contacts.end_events;
}
std::span<const SensorEvent> World::sensor_begin_events() const {
    return impl_->sensors.begin_events;
}
std::span<const SensorEvent> World::sensor_end_events() const {
    return impl_->sensors.end_events;
}

std::vector<ShapeId> World::query_aabb(const Aabb& box) const {
    // A box upside down on an axis (min > max) or with a NaN side contains nothing: answering
    // it with no shapes would hide the caller's mistake (corners swapped, a size for a corner).
    require_finite("box.min_x", box.min_x);
    require_finite("box.min_y", box.min_y);
    require_finite("box.max_x", box.max_x);
    require_finite("box.max_y", box.max_y);
    // The query's own rule, not an SRS data constraint: "query" names it.
    if (!(box.min_x <= box.max_x))
        throw ValidationError("box.max_x", box.max_x,
                              "must be >= box.min_x (" + detail::format_value(box.min_x) + " m)",
                              "query");
    if (!(box.min_y <= box.max_y))
        throw ValidationError("box.max_y", box.max_y,
                              "must be >= box.min_y (" + detail::format_value(box.min_y) + " m)",
                              "query");
    std::vector<ShapeId> out;
    impl_->shapes.broad_phase.query(box, [&](int proxy) {
        const std::uint32_t s = impl_->shapes.broad_phase.user_data(proxy);
        const Shape& sh = impl_->shapes.shapes[s];
        if (overlaps(impl_->shapes.box(sh, impl_->bodies.bodies[sh.body]), box))
            out.push_back(impl_->shapes.id(s));
        return true;
    });
    std::sort(out.begin(), out.end(), [](ShapeId a, ShapeId b) { return a.index < b.index; });
    return out;
}

std::vector<ShapeId> World::query_point(Vec2d p) const {
    require_finite("point", p); // a NaN point is in no shape: refused, not answered empty
    std::vector<ShapeId> out;
    const Aabb box{p.x, p.y, p.x, p.y};
    impl_->shapes.broad_phase.query(box, [&](int proxy) {
        const std::uint32_t s = impl_->shapes.broad_phase.user_data(proxy);
        const Shape& sh = impl_->shapes.shapes[s];
        if (test_point(impl_->shapes.defs[s].geometry, impl_->bodies.bodies[sh.body].xf, p))
            out.push_back(impl_->shapes.id(s));
        return true;
    });
    std::sort(out.begin(), out.end(), [](ShapeId a, ShapeId b) { return a.index < b.index; });
    return out;
}

std::optional<RayCastHit> World::ray_cast(Vec2d origin, Vec2d translation) const {
    // Within the supported range, |translation|^2 and the hit fraction cannot overflow.
    require_within("origin", origin, supported::input_max, "m");
    require_within("translation", translation, supported::input_max, "m");
    const Vec2d end = origin + translation;
    const Aabb box{std::min(origin.x, end.x), std::min(origin.y, end.y), std::max(origin.x, end.x),
                   std::max(origin.y, end.y)};
    std::optional<RayCastHit> best;
    impl_->shapes.broad_phase.query(inflated(box, 1e-9), [&](int proxy) {
        const std::uint32_t s = impl_->shapes.broad_phase.user_data(proxy);
        if (impl_->shapes.defs[s].is_sensor)
            return true; // a sensor is not there for rays (DD28)
        const Shape& sh = impl_->shapes.shapes[s];
        const auto hit = tamias2d::ray_cast(impl_->shapes.defs[s].geometry,
                                            impl_->bodies.bodies[sh.body].xf, origin, translation);
        if (hit && (!best || hit->fraction < best->fraction ||
                    (hit->fraction == best->fraction && s < best->shape.index))) {
            best = RayCastHit{impl_->shapes.id(s), impl_->bodies.id(sh.body), hit->point,
                              hit->normal, hit->fraction};
        }
        return true;
    });
    return best;
}

std::uint64_t World::state_hash() const {
    const Impl& w = *impl_;
    StateHasher hs;
    hs(w.time);
    hs(w.time_error);
    hs(w.def.gravity);
    w.bodies.hash(hs, w.shapes, w.def.enable_sleep);
    w.shapes.hash(hs);
    w.joints.hash(hs);
    w.contacts.hash(hs, w.def.manifold_reuse_distance > 0.0);
    return hs.h;
}

} // namespace tamias2d
