#include "tamias2d/world.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>

#include "tamias2d/dynamics/body_store.hpp"
#include "tamias2d/dynamics/bridge/joint_reactions.hpp"
#include "tamias2d/dynamics/bridge/point_impulse.hpp"
#include "tamias2d/dynamics/bridge/typing.hpp"
#include "tamias2d/dynamics/contacts/contact_manager.hpp"
#include "tamias2d/dynamics/contacts/sensor_overlaps.hpp"
#include "tamias2d/dynamics/island_sleep.hpp"
#include "tamias2d/dynamics/joints/distance_joint.hpp"
#include "tamias2d/dynamics/joints/filter_joint.hpp"
#include "tamias2d/dynamics/joints/joint_store.hpp"
#include "tamias2d/dynamics/joints/motor_joint.hpp"
#include "tamias2d/dynamics/joints/prismatic_joint.hpp"
#include "tamias2d/dynamics/joints/revolute_joint.hpp"
#include "tamias2d/dynamics/joints/target_joint.hpp"
#include "tamias2d/dynamics/joints/weld_joint.hpp"
#include "tamias2d/dynamics/joints/wheel_joint.hpp"
#include "tamias2d/dynamics/shape_store.hpp"
#include "tamias2d/dynamics/state_hasher.hpp"
#include "tamias2d/dynamics/step_context.hpp"
#include "tamias2d/dynamics/step_solver.hpp"
#include "tamias2d/errors.hpp"
#include "tamias2d/model/dd13_torque.hpp"
#include "tamias2d/parallel/step_tasks.hpp"
#include "tamias2d/units/angle.hpp"
#include "tamias2d/validation.hpp"
#include "tamias2d/world_impl.hpp"

namespace tamias2d {

namespace u = tamias2d::units;

namespace {

/// A body a joint definition names, for its checks and their messages.
JointBody joint_body(const BodyStore& bodies, BodyId id, const Body& b) {
    return {id, bodies.label(id.index), b.type};
}

/// Forces, torques and impulses move dynamic bodies only: one given to a static or kinematic
/// body would be lost without a trace, so it is refused as the mistake it is.
void require_dynamic(const BodyStore& bodies, BodyId id, const Body& b, const char* call) {
    if (b.type != BodyType::dynamic)
        throw WrongKind(call, bodies.label(id.index), std::string(type_name(b.type)) + " body",
                        "must be a dynamic body (a static or kinematic body does not move under "
                        "forces, torques or impulses)");
}

/// A tag no World of this process has had (World::tag), never 0.
std::uint32_t new_world_tag() {
    static std::atomic<std::uint32_t> last{0};
    std::uint32_t tag = last.fetch_add(1, std::memory_order_relaxed) + 1;
    while (tag == 0) // after 2^32 worlds the count wraps; 0 stays "no world"
        tag = last.fetch_add(1, std::memory_order_relaxed) + 1;
    return tag;
}

} // namespace

World::World(const WorldDef& def) {
    validate(def);
    impl_ = std::make_unique<Impl>(def, new_world_tag());
    impl_->tasks = StepTasks(def.workers, def.task_system);
}
std::uint32_t World::tag() const {
    return impl_->bodies.slots.world();
}
World::~World() = default;
World::World(World&&) noexcept = default;
World& World::operator=(World&&) noexcept = default;

BodyId World::create_body(const BodyDef& def) {
    validate(def);
    Impl& w = *impl_;
    const std::uint32_t i = w.bodies.create(def, w.def.enable_sleep);
    w.bodies.update_mass(i, w.shapes);
    w.events.body_created(i, def);
    return w.bodies.id(i);
}

void World::destroy_body(BodyId id) {
    Impl& w = *impl_;
    const Body& b = w.bodies.get(id);
    w.events.body_destroying(id.index, w.bodies, w.shapes, w.joints);
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
    // The handle is checked before validation (both leave the world unchanged); the body's mass
    // is left pending (attach_shape), so that N shapes on one body cost O(N).
    Body& b = w.bodies.get_for_attach(body_id);
    validate(def);
    const std::uint32_t i = w.shapes.create(body_id.index, b, def);
    w.events.shape_created(def);
    w.bodies.attach_shape(body_id.index, w.shapes, i);
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
    for (const ShapeDef& def : segments) {
        const std::uint32_t last = w.shapes.create(body_id.index, b, def);
        w.events.shape_created(def);
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
    w.events.shape_destroying(w.shapes.defs[id.index]);
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
    return impl_->bodies.live_ids();
}

std::vector<ShapeId> World::shapes(BodyId id) const {
    return impl_->shapes.ids_of(impl_->bodies.get(id));
}

namespace {

/// Stores a joint made from a validated definition, removes the contacts it filters, wakes its
/// bodies.
JointId add_joint(World::Impl& w, const Joint& j) {
    validate_levers(w.bodies, j, null_index);
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
    Joint j = make_joint(def, a, b);
    j.user_data = def.user_data;
    return add_joint(w, with_event_thresholds(w.events, j, def));
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
JointId World::create_joint(const FilterJointDef& def) {
    return join(*impl_, def);
}
JointId World::create_joint(const TargetJointDef& def) {
    Impl& w = *impl_;
    const Body& b = w.bodies.get(def.body);
    validate(def, joint_body(w.bodies, def.body, b));
    Joint j = make_joint(def, b);
    j.user_data = def.user_data;
    return add_joint(w, with_event_thresholds(w.events, j, def));
}

void World::set_joint_target(JointId id, Vec2d target) {
    Joint& j =
        impl_->joints.get(id, {JointType::target}, "set_joint_target", "must be a target joint");
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
    const Joint& j = impl_->joints.get(
        id, {JointType::revolute, JointType::prismatic, JointType::weld, JointType::wheel},
        "joint_angle",
        "must be a revolute, prismatic, weld or wheel joint (the kinds that hold an "
        "angle)");
    return joint_angle_now(j, impl_->bodies);
}

double World::joint_translation(JointId id) const {
    const Joint& j =
        impl_->joints.get(id, {JointType::prismatic, JointType::wheel}, "joint_translation",
                          "must be a prismatic or wheel joint (the kinds with an axis)");
    impl_->bodies.settle();
    return joint_translation_now(j, impl_->bodies);
}

void World::set_joint_motor_speed(JointId id, double speed) {
    Joint& j = impl_->joints.get(
        id, {JointType::revolute, JointType::prismatic, JointType::wheel, JointType::distance},
        "set_joint_motor_speed",
        "must be a revolute, prismatic, wheel or distance joint (the kinds with a motor)");
    require_within("joint.motor_speed", speed, supported::input_max,
                   j.type == JointType::prismatic || j.type == JointType::distance ? "m s^-1"
                                                                                   : "rad s^-1");
    if (j.motor_speed == speed)
        return; // the same speed: nothing woken (a game may set it every frame)
    j.motor_speed = speed;
    impl_->bodies.wake(j.body_a);
    impl_->bodies.wake(j.body_b);
}

void World::set_motor_joint_offsets(JointId id, Vec2d linear_offset, double angular_offset) {
    Joint& j = impl_->joints.get(id, {JointType::motor}, "set_motor_joint_offsets",
                                 "must be a motor joint");
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
    w.profiler.begin();
    w.bodies.settle(); // the masses attach_shape left pending
    w.check_state();
    w.bodies.evaluate_loads(w.time, w.loads);
    w.contacts.forget_filter_error(); // (one a step cut short by bad_alloc left)
    w.joints.broken.clear();
    w.contacts.clear_events();
    w.sensors.begin_events.clear();
    w.sensors.end_events.clear();
    w.events.clear();
    const bool guarded = w.joints.live() > 0;
    if (guarded)
        w.joints.guard_step(w.bodies, w.def.enable_sleep);
    w.profiler.lap(&StepProfile::prepare);
    w.contacts.find_new(w.bodies, w.shapes, w.joints);
    w.profiler.lap(&StepProfile::broad_phase);
    w.joints.inv_h = w.def.substeps / dt;
    const StepContext step{w.def, dt, dt / w.def.substeps, w.def.enable_sleep, w.loads, w.tasks};
    if (step.sleeping && !w.bodies.any_awake()) {
        // Every body asleep: every contact is kept as it is (a new one, of a static body moved
        // onto sleeping ones, too) and nothing is solved; the step does only this.
        w.contacts.keep_all();
        w.profiler.lap(&StepProfile::narrow_phase);
    } else {
        w.solve(step, guarded);
    }
    // DD28: the sensors see the poses this step made.
    if (!w.sensors.empty())
        w.sensors.update(w.bodies, w.shapes, w.contacts);
    w.profiler.lap(&StepProfile::events);
    // Compensated sum, so that a load switching at t = n dt is seen at step n, not n + 1.
    const double y = dt - w.time_error;
    const double t = w.time + y;
    w.time_error = (t - w.time) - y;
    w.time = t;
    w.events.after_step(w.bodies, w.shapes, w.contacts, w.joints, step.sleeping);
    w.contacts.report_stale();
    w.profiler.end();
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
    impl_->shapes.move_with(b);
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
    // \srs{DD39} Under the angular lock nothing turns a dynamic body, a set velocity included.
    if (b.type != BodyType::static_body && !impl_->bodies.angularly_locked(id.index))
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
    impl_->bodies.put_to_sleep(id.index);
}

double World::kinetic_energy() const {
    impl_->bodies.settle();
    return impl_->bodies.kinetic_energy();
}
double World::potential_energy() const {
    impl_->bodies.settle();
    return impl_->bodies.potential_energy(impl_->def.gravity);
}
Vec2d World::linear_momentum() const {
    impl_->bodies.settle();
    return impl_->bodies.linear_momentum();
}

std::span<const ContactInfo> World::contacts() const {
    return impl_->contacts.report(impl_->bodies, impl_->shapes);
}
std::span<const ContactEvent> World::contact_begin_events() const {
    return impl_->contacts.begin_events();
}
std::span<const ContactEvent> World::contact_end_events() const {
    return impl_->contacts.end_events();
}
std::span<const SensorEvent> World::sensor_begin_events() const {
    return impl_->sensors.begin_events;
}
std::span<const SensorEvent> World::sensor_end_events() const {
    return impl_->sensors.end_events;
}

std::vector<ShapeId> World::query_aabb(const Aabb& box) const {
    validate_query_box(box, "box");
    return impl_->shapes.overlapping(box, impl_->bodies);
}

std::vector<ShapeId> World::query_point(Vec2d p) const {
    require_finite("point", p); // a NaN point is in no shape: refused, not answered empty
    return impl_->shapes.containing(p, impl_->bodies);
}

std::optional<RayCastHit> World::ray_cast(Vec2d origin, Vec2d translation) const {
    // Within the supported range, |translation|^2 and the hit fraction cannot overflow.
    require_within("origin", origin, supported::input_max, "m");
    require_within("translation", translation, supported::input_max, "m");
    return impl_->shapes.ray_cast(origin, translation, impl_->bodies);
}

std::uint64_t World::state_hash() const {
    const Impl& w = *impl_;
    w.bodies.settle();
    StateHasher hs;
    hs(w.time);
    hs(w.time_error);
    hs(w.def.gravity);
    w.bodies.hash(hs, w.shapes, w.def.enable_sleep);
    w.shapes.hash(hs);
    w.joints.hash(hs);
    w.contacts.hash(hs, w.def.manifold_reuse_distance > 0.0);
    w.events.hash(hs, w.shapes, w.joints, w.def.hit_event_threshold);
    return hs.h;
}

} // namespace tamias2d
