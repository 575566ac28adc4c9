/// \file
/// The scene format's field tables: the keys of world settings, bodies and joints, each the
/// name of its definition's field, with how it is checked and written. One table per kind of
/// object, walked by the parser, the key check and the writer alike, so the three cannot
/// disagree on a key, its order or its type.
#pragma once

#include <array>
#include <cstddef>
#include <string_view>
#include <variant>

#include "tamias2d/body_def.hpp"
#include "tamias2d/io/scene.hpp"
#include "tamias2d/validation.hpp"
#include "tamias2d/world_def.hpp"

namespace tamias2d::io::scene_detail {

/// How the parser checks a key's value beyond its type, and when the writer leaves it out.
struct FieldRule {
    /// The library's own check of the value, run on it as read and reported at its key
    /// (validation.hpp); none if null.
    void (*check)(std::string_view field, double value) = nullptr;
    /// Left out of the written form when the member has its default value (BodyDef{}'s: an
    /// empty name, no bullet, enabled), so scenes without it are written as before it existed.
    bool omit_default = false;
};

/// World settings, as "world" holds them: v(key, member). Ranges are the World's to check (in
/// validate_scene), as World's constructor checks them.
template <class W, class V> void world_fields(W& w, V&& v) {
    v("gravity", w.gravity); // DCI_g
    v("substeps", w.substeps);
    v("contact_hertz", w.contact_hertz);
    v("contact_damping_ratio", w.contact_damping_ratio);
    v("contact_push_max_velocity", w.contact_push_max_velocity);
    v("linear_slop", w.linear_slop);
    v("speculative_distance", w.speculative_distance);
    v("manifold_reuse_distance", w.manifold_reuse_distance);
    v("contact_regions", w.contact_regions);
    v("restitution_threshold", w.restitution_threshold);
    v("enable_sleep", w.enable_sleep);
    v("time_to_sleep", w.time_to_sleep);
    v("linear_sleep_tolerance", w.linear_sleep_tolerance);
    v("angular_sleep_tolerance", w.angular_sleep_tolerance);
    v("enable_continuous", w.enable_continuous);
    v("enable_warm_starting", w.enable_warm_starting);
}

/// A body's keys that are BodyDef's fields ("velocity" is its linear_velocity), in the order
/// the key check lists them and the writer writes them: v(key, member, rule). A body's "loads"
/// and "shapes" (SceneBody's) follow them. The whole definition is checked by the library
/// (validate(BodyDef)) once read.
template <class D, class V> void body_fields(D& d, V&& v) {
    v("name", d.name, FieldRule{nullptr, true});
    v("type", d.type, FieldRule{});
    v("position", d.position, FieldRule{});                 // DCI_p
    v("angle", d.angle, FieldRule{});                       // DCI_phi: any real, wrapped on output
    v("velocity", d.linear_velocity, FieldRule{});          // DCI_v
    v("angular_velocity", d.angular_velocity, FieldRule{}); // DCI_omega
    v("mass", d.mass, FieldRule{&validate_mass});           // DCI_m
    v("inertia", d.inertia, FieldRule{&validate_inertia});  // DCI_I
    v("gravity_scale", d.gravity_scale, FieldRule{});
    v("linear_damping", d.linear_damping, FieldRule{&validate_damping}); // DCX_damping
    v("angular_damping", d.angular_damping, FieldRule{&validate_damping});
    v("fixed_rotation", d.fixed_rotation, FieldRule{});
    v("lock_linear_x", d.motion_locks.linear_x, FieldRule{nullptr, true}); // DD39
    v("lock_linear_y", d.motion_locks.linear_y, FieldRule{nullptr, true});
    v("lock_angular", d.motion_locks.angular, FieldRule{nullptr, true});
    v("bullet", d.bullet, FieldRule{nullptr, true}); // DD29
    v("enable_sleep", d.enable_sleep, FieldRule{});
    v("awake", d.awake, FieldRule{});
    v("sleep_threshold", d.sleep_threshold, FieldRule{&validate_sleep_threshold});
    v("enabled", d.enabled, FieldRule{nullptr, true});
    v("force", d.force, FieldRule{});   // DCI_F
    v("torque", d.torque, FieldRule{}); // DCI_tau
}

// A joint's keys are its definition's fields under the same names, one table per kind: a
// visitor is called as v(key, member, required).

template <class V> void joint_fields(RevoluteJointDef& d, V&& v) {
    v("anchor", d.anchor, true);
    v("enable_limit", d.enable_limit, false);
    v("lower_angle", d.lower_angle, false);
    v("upper_angle", d.upper_angle, false);
    v("enable_motor", d.enable_motor, false);
    v("motor_speed", d.motor_speed, false);
    v("max_motor_torque", d.max_motor_torque, false);
    v("enable_spring", d.enable_spring, false);
    v("hertz", d.hertz, false);
    v("damping_ratio", d.damping_ratio, false);
    v("spring_target", d.spring_target, false);
}
template <class V> void joint_fields(DistanceJointDef& d, V&& v) {
    v("anchor_a", d.anchor_a, true);
    v("anchor_b", d.anchor_b, true);
    v("length", d.length, false);
    v("hertz", d.hertz, false);
    v("damping_ratio", d.damping_ratio, false);
    v("enable_limit", d.enable_limit, false);
    v("min_length", d.min_length, false);
    v("max_length", d.max_length, false);
    v("enable_motor", d.enable_motor, false); // DD35
    v("motor_speed", d.motor_speed, false);
    v("max_motor_force", d.max_motor_force, false);
}
template <class V> void joint_fields(PrismaticJointDef& d, V&& v) {
    v("anchor", d.anchor, true);
    v("axis", d.axis, true);
    v("enable_limit", d.enable_limit, false);
    v("lower_translation", d.lower_translation, false);
    v("upper_translation", d.upper_translation, false);
    v("enable_motor", d.enable_motor, false);
    v("motor_speed", d.motor_speed, false);
    v("max_motor_force", d.max_motor_force, false);
    v("enable_spring", d.enable_spring, false);
    v("hertz", d.hertz, false);
    v("damping_ratio", d.damping_ratio, false);
    v("spring_target", d.spring_target, false);
}
template <class V> void joint_fields(WeldJointDef& d, V&& v) {
    v("anchor", d.anchor, true);
    v("linear_hertz", d.linear_hertz, false);
    v("linear_damping_ratio", d.linear_damping_ratio, false);
    v("angular_hertz", d.angular_hertz, false);
    v("angular_damping_ratio", d.angular_damping_ratio, false);
}
template <class V> void joint_fields(WheelJointDef& d, V&& v) {
    v("anchor", d.anchor, true);
    v("axis", d.axis, true);
    v("enable_spring", d.enable_spring, false);
    v("hertz", d.hertz, false);
    v("damping_ratio", d.damping_ratio, false);
    v("spring_target", d.spring_target, false);
    v("enable_limit", d.enable_limit, false);
    v("lower_translation", d.lower_translation, false);
    v("upper_translation", d.upper_translation, false);
    v("enable_motor", d.enable_motor, false);
    v("motor_speed", d.motor_speed, false);
    v("max_motor_torque", d.max_motor_torque, false);
}
template <class V> void joint_fields(MotorJointDef& d, V&& v) {
    v("linear_offset", d.linear_offset, false);
    v("angular_offset", d.angular_offset, false);
    v("max_force", d.max_force, false);
    v("max_torque", d.max_torque, false);
    v("correction_factor", d.correction_factor, false);
}
/// A filter joint has no field beyond its bodies (it never collides them and never breaks).
template <class V> void all_joint_fields(FilterJointDef&, V&&) {}
/// The fields every two-body joint has, and a break torque (DD36) and a constraint tuning where
/// the kind carries one.
template <class Def, class V> void all_joint_fields(Def& d, V&& v) {
    joint_fields(d, v);
    v("collide_connected", d.collide_connected, false);
    v("break_force", d.break_force, false);
    if constexpr (requires { d.break_torque; })
        v("break_torque", d.break_torque, false);
    if constexpr (requires { d.constraint_tuning; }) // IM6: the joint's own soft bias
        v("constraint_tuning", d.constraint_tuning, false);
}

/// The "type" names, in SceneJoint::Definition's order.
inline constexpr std::array<std::string_view, std::variant_size_v<SceneJoint::Definition>>
    joint_types{"revolute", "distance", "prismatic", "weld", "wheel", "motor", "filter"};

/// A default definition of the kind named `type`; false for an unknown name.
template <std::size_t I = 0> bool make_joint_def(std::string_view type, SceneJoint::Definition& d) {
    if constexpr (I < std::variant_size_v<SceneJoint::Definition>) {
        if (type == joint_types[I]) {
            d.emplace<I>();
            return true;
        }
        return make_joint_def<I + 1>(type, d);
    } else {
        return false;
    }
}

} // namespace tamias2d::io::scene_detail
