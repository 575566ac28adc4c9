// The joints' settings after creation (World's joint_control calls): limits, motors, springs
// and their targets, a distance joint's length, the joint's own soft bias, collide_connected,
// the break thresholds, and what a joint joins. Each call checks the handle, the kind and the
// value (the definition's rule for the field, validation.hpp) before it changes anything.
#include <cstdint>

#include "tamias2d/dynamics/joints/joint_store.hpp"
#include "tamias2d/errors.hpp"
#include "tamias2d/joint_kind.hpp"
#include "tamias2d/validation.hpp"
#include "tamias2d/world.hpp"
#include "tamias2d/world_impl.hpp"

namespace tamias2d {

namespace {

using T = JointType;

// The kinds each group of calls applies to, with the rule WrongKind states.
constexpr const char* limited_rule =
    "must be a revolute, prismatic, wheel or distance joint (the kinds with limits)";
constexpr const char* motor_rule =
    "must be a revolute, prismatic, wheel or distance joint (the kinds with a motor)";
constexpr const char* sprung_rule =
    "must be a revolute, prismatic or wheel joint (a distance joint's spring is on while its "
    "hertz is > 0: set_joint_spring)";
constexpr const char* spring_rule = "must be a revolute, prismatic, wheel, distance or target "
                                    "joint (the kinds with a spring)";
constexpr const char* target_rule =
    "must be a revolute, prismatic or wheel joint (the kinds whose spring has a target)";
constexpr const char* two_body_rule =
    "must be a joint that holds two bodies (not a target joint, which holds one, nor a filter "
    "joint, which holds none)";

constexpr JointType limited[] = {T::revolute, T::prismatic, T::wheel, T::distance};
constexpr JointType motored[] = {T::revolute, T::prismatic, T::wheel, T::distance};
constexpr JointType sprung[] = {T::revolute, T::prismatic, T::wheel};
constexpr JointType switched_spring[] = {T::revolute, T::prismatic, T::wheel, T::distance};
constexpr JointType with_spring[] = {T::revolute, T::prismatic, T::wheel, T::distance, T::target};
constexpr JointType holding[] = {T::revolute, T::distance, T::prismatic,
                                 T::weld,     T::wheel,    T::motor};
constexpr JointType turning_motor[] = {T::revolute, T::wheel};
constexpr JointType pushing_motor[] = {T::prismatic, T::distance};
constexpr JointType distance_only[] = {T::distance};
constexpr JointType biased[] = {T::revolute, T::distance, T::prismatic, T::weld, T::wheel};
constexpr JointType torqued[] = {T::revolute, T::prismatic, T::weld, T::wheel, T::motor};
constexpr const char* turning_rule =
    "must be a revolute or wheel joint (the kinds whose motor turns)";
constexpr const char* pushing_rule =
    "must be a prismatic or distance joint (the kinds whose motor pushes)";
constexpr const char* switched_rule = "must be a revolute, prismatic, wheel or distance joint "
                                      "(the kinds whose spring is switched)";
constexpr const char* torque_rule = "must be a revolute, prismatic, weld, wheel or motor joint "
                                    "(the kinds that carry a torque)";

/// A changed setting acts from the next step: the joint's bodies are woken.
void wake_joint(World::Impl& w, const Joint& j) {
    w.bodies.wake(j.body_a);
    w.bodies.wake(j.body_b);
}

/// The unit of a joint's limits, motor speed or spring target: its angle's or its travel's.
bool angular(const Joint& j) {
    return j.type == T::revolute;
}

/// A zero of either sign stored as +0, so that a value set to -0 changes no bit of a step.
double plain_zero(double v) {
    return v == 0.0 ? 0.0 : v;
}

} // namespace

JointKind World::joint_kind(JointId id) const {
    return impl_->joints.get(id).type;
}

BodyId World::joint_body_a(JointId id) const {
    return impl_->bodies.id(impl_->joints.get(id).body_a);
}

BodyId World::joint_body_b(JointId id) const {
    return impl_->bodies.id(impl_->joints.get(id).body_b);
}

void World::enable_joint_limit(JointId id, bool enable) {
    Joint& j = impl_->joints.get_of(id, limited, "enable_joint_limit", limited_rule);
    if (j.enable_limit == enable)
        return;
    j.enable_limit = enable;
    j.step.lower_impulse = j.step.upper_impulse = 0.0; // a limit starts unloaded
    wake_joint(*impl_, j);
}

bool World::is_joint_limit_enabled(JointId id) const {
    return impl_->joints.get_of(id, limited, "is_joint_limit_enabled", limited_rule).enable_limit;
}

void World::set_joint_limits(JointId id, double lower, double upper) {
    Joint& j = impl_->joints.get_of(id, limited, "set_joint_limits", limited_rule);
    if (j.type == T::distance)
        validate_length_range(lower, upper);
    else if (angular(j))
        validate_joint_limits("joint.lower_angle", lower, "joint.upper_angle", upper, "rad");
    else
        validate_joint_limits("joint.lower_translation", lower, "joint.upper_translation", upper,
                              "m");
    lower = plain_zero(lower);
    upper = plain_zero(upper);
    if (j.lower_limit == lower && j.upper_limit == upper)
        return;
    j.lower_limit = lower;
    j.upper_limit = upper;
    wake_joint(*impl_, j);
}

JointLimits World::joint_limits(JointId id) const {
    const Joint& j = impl_->joints.get_of(id, limited, "joint_limits", limited_rule);
    return {j.lower_limit, j.upper_limit};
}

void World::enable_joint_motor(JointId id, bool enable) {
    Joint& j = impl_->joints.get_of(id, motored, "enable_joint_motor", motor_rule);
    if (j.enable_motor == enable)
        return;
    j.enable_motor = enable;
    j.step.motor_impulse = 0.0; // a motor starts unloaded
    if (j.type == T::distance && j.hertz == 0.0)
        j.step.axial_impulse = 0.0; // the rod gives way to the motor, or takes over from it
    wake_joint(*impl_, j);
}

bool World::is_joint_motor_enabled(JointId id) const {
    return impl_->joints.get_of(id, motored, "is_joint_motor_enabled", motor_rule).enable_motor;
}

double World::joint_motor_speed(JointId id) const {
    return impl_->joints.get_of(id, motored, "joint_motor_speed", motor_rule).motor_speed;
}

void World::set_joint_max_motor_torque(JointId id, double torque) {
    Joint& j = impl_->joints.get_of(id, turning_motor, "set_joint_max_motor_torque", turning_rule);
    validate_joint_max_motor("joint.max_motor_torque", torque);
    if (j.max_motor == torque)
        return;
    j.max_motor = torque;
    wake_joint(*impl_, j);
}

double World::joint_max_motor_torque(JointId id) const {
    return impl_->joints.get_of(id, turning_motor, "joint_max_motor_torque", turning_rule)
        .max_motor;
}

void World::set_joint_max_motor_force(JointId id, double force) {
    Joint& j = impl_->joints.get_of(id, pushing_motor, "set_joint_max_motor_force", pushing_rule);
    validate_joint_max_motor("joint.max_motor_force", force);
    if (j.max_motor == force)
        return;
    j.max_motor = force;
    wake_joint(*impl_, j);
}

double World::joint_max_motor_force(JointId id) const {
    return impl_->joints.get_of(id, pushing_motor, "joint_max_motor_force", pushing_rule).max_motor;
}

void World::enable_joint_spring(JointId id, bool enable) {
    Joint& j = impl_->joints.get_of(id, sprung, "enable_joint_spring", sprung_rule);
    validate_joint_spring(enable, j.hertz, j.damping_ratio);
    if (j.enable_spring == enable)
        return;
    j.enable_spring = enable;
    j.step.spring_impulse = 0.0; // a spring starts unloaded
    wake_joint(*impl_, j);
}

bool World::is_joint_spring_enabled(JointId id) const {
    const Joint& j =
        impl_->joints.get_of(id, switched_spring, "is_joint_spring_enabled", switched_rule);
    return j.type == T::distance ? j.hertz > 0.0 : j.enable_spring;
}

void World::set_joint_spring(JointId id, double hertz, double damping_ratio) {
    Joint& j = impl_->joints.get_of(id, with_spring, "set_joint_spring", spring_rule);
    if (j.type == T::distance)
        validate_distance_spring(hertz, damping_ratio);
    else if (j.type == T::target)
        validate_target_spring(hertz, damping_ratio);
    else
        validate_joint_spring(j.enable_spring, hertz, damping_ratio);
    if (j.hertz == hertz && j.damping_ratio == damping_ratio)
        return;
    if (j.type == T::distance && (j.hertz == 0.0) != (hertz == 0.0))
        j.step.axial_impulse = 0.0; // a rod becomes a spring, or a spring a rod
    j.hertz = hertz;
    j.damping_ratio = damping_ratio;
    wake_joint(*impl_, j);
}

double World::joint_spring_hertz(JointId id) const {
    return impl_->joints.get_of(id, with_spring, "joint_spring_hertz", spring_rule).hertz;
}

double World::joint_spring_damping_ratio(JointId id) const {
    return impl_->joints.get_of(id, with_spring, "joint_spring_damping_ratio", spring_rule)
        .damping_ratio;
}

void World::set_joint_spring_target(JointId id, double target) {
    Joint& j = impl_->joints.get_of(id, sprung, "set_joint_spring_target", target_rule);
    require_within("joint.spring_target", target, supported::input_max, angular(j) ? "rad" : "m");
    target = plain_zero(target);
    if (j.spring_target == target)
        return;
    j.spring_target = target;
    wake_joint(*impl_, j);
}

double World::joint_spring_target(JointId id) const {
    return impl_->joints.get_of(id, sprung, "joint_spring_target", target_rule).spring_target;
}

void World::set_distance_joint_length(JointId id, double length) {
    Joint& j = impl_->joints.get_of(id, distance_only, "set_distance_joint_length",
                                    "must be a distance joint");
    validate_rest_length(length);
    if (j.length == length)
        return;
    j.length = length;
    wake_joint(*impl_, j);
}

double World::distance_joint_length(JointId id) const {
    return impl_->joints
        .get_of(id, distance_only, "distance_joint_length", "must be a distance joint")
        .length;
}

void World::set_constraint_tuning(JointId id, double hertz, double damping_ratio) {
    Joint& j = impl_->joints.get_of(
        id, biased, "set_constraint_tuning",
        "must be a revolute, distance, prismatic, weld or wheel joint (the kinds held by the "
        "soft bias: a target or motor joint is held by its own spring or correction factor, a "
        "filter joint by nothing)");
    validate_constraint_tuning(hertz, damping_ratio);
    if (j.tuned && j.tuning_hertz == hertz && j.tuning_damping_ratio == damping_ratio)
        return;
    j.tuned = true;
    j.tuning_hertz = hertz;
    j.tuning_damping_ratio = damping_ratio;
    wake_joint(*impl_, j);
}

ConstraintTuning World::constraint_tuning(JointId id) const {
    const Joint& j = impl_->joints.get(id);
    if (j.tuned)
        return {j.tuning_hertz, j.tuning_damping_ratio};
    return {impl_->def.joint_hertz, impl_->def.joint_damping_ratio};
}

void World::set_joint_collide_connected(JointId id, bool collide) {
    Impl& w = *impl_;
    Joint& j = w.joints.get_of(id, holding, "set_joint_collide_connected", two_body_rule);
    if (j.collide_connected == collide)
        return;
    j.collide_connected = collide;
    if (collide)
        JointStore::touch_pairs(j, w.bodies, w.shapes); // their pairs, found by the next step
    else if (w.joints.filters(j.body_a, j.body_b))
        w.contacts.destroy_between(j.body_a, j.body_b, w.bodies, w.shapes); // (end events)
    wake_joint(w, j);
}

bool World::joint_collide_connected(JointId id) const {
    return impl_->joints.get_of(id, holding, "joint_collide_connected", two_body_rule)
        .collide_connected;
}

void World::set_joint_break_force(JointId id, double force) {
    Joint& j = impl_->joints.get_of(id, holding, "set_joint_break_force", two_body_rule);
    validate_break_force(force);
    if (j.break_force == force)
        return;
    j.break_force = force;
    impl_->joints.note_breakable(j);
    wake_joint(*impl_, j);
}

double World::joint_break_force(JointId id) const {
    return impl_->joints.get_of(id, holding, "joint_break_force", two_body_rule).break_force;
}

void World::set_joint_break_torque(JointId id, double torque) {
    Joint& j = impl_->joints.get_of(id, torqued, "set_joint_break_torque", torque_rule);
    validate_break_torque(torque);
    if (j.break_torque == torque)
        return;
    j.break_torque = torque;
    impl_->joints.note_breakable(j);
    wake_joint(*impl_, j);
}

double World::joint_break_torque(JointId id) const {
    return impl_->joints.get_of(id, torqued, "joint_break_torque", torque_rule).break_torque;
}

} // namespace tamias2d
