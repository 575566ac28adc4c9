// The calls a recording holds (internal): the one list of them, with their encoding.
//
// TAMIAS2D_RECORDED_CALLS lists every World call a Recorder records, each as
// X(name, member) with the World member it calls; its position in the list is the call's code in
// a recording (a u8), so a call is only ever appended. Each call's arguments are written in the
// order of the member's parameters, each by the one codec of its type below (argument_io): an
// argument type added to World's calls is added there once. tests/recording/
// check_recorded_calls.py checks this list against World's mutating calls in world.hpp.
//
// Not recorded (nothing of the simulation can be written for them): set_custom_filter,
// set_load, set_pre_solve, set_friction_mixing and set_restitution_mixing (functions: a world
// with one is refused), set_profiling (changes no bit of the simulation).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <vector>

#include "tamias2d/dynamics/snapshot_io.hpp"
#include "tamias2d/errors.hpp"
#include "tamias2d/memory/allocator.hpp"
#include "tamias2d/world.hpp"

namespace tamias2d::recording {

/// A World member function of signature Sig (for the overloaded names).
template <class Sig> using Member = Sig World::*;

// clang-format off
#define TAMIAS2D_RECORDED_CALLS(X)                                                                \
    X(create_body, Member<BodyId(const BodyDef&)>(&World::create_body))                           \
    X(destroy_body, &World::destroy_body)                                                          \
    X(create_shape, &World::create_shape)                                                          \
    X(create_chain, &World::create_chain)                                                          \
    X(destroy_shape, &World::destroy_shape)                                                        \
    X(set_filter, &World::set_filter)                                                              \
    X(set_friction, &World::set_friction)                                                          \
    X(set_restitution, &World::set_restitution)                                                    \
    X(set_density, &World::set_density)                                                            \
    X(set_circle, &World::set_circle)                                                              \
    X(set_capsule, &World::set_capsule)                                                            \
    X(set_polygon, &World::set_polygon)                                                            \
    X(set_segment, &World::set_segment)                                                            \
    X(set_sensor, &World::set_sensor)                                                              \
    X(step, &World::step)                                                                          \
    X(set_gravity, &World::set_gravity)                                                            \
    X(set_transform, &World::set_transform)                                                        \
    X(set_velocity, &World::set_velocity)                                                          \
    X(set_angular_velocity, &World::set_angular_velocity)                                          \
    X(set_damping, &World::set_damping)                                                            \
    X(set_force, &World::set_force)                                                                \
    X(set_torque, &World::set_torque)                                                              \
    X(apply_force, &World::apply_force)                                                            \
    X(apply_torque, &World::apply_torque)                                                          \
    X(apply_impulse, &World::apply_impulse)                                                        \
    X(create_revolute_joint, Member<JointId(const RevoluteJointDef&)>(&World::create_joint))       \
    X(create_distance_joint, Member<JointId(const DistanceJointDef&)>(&World::create_joint))       \
    X(create_target_joint, Member<JointId(const TargetJointDef&)>(&World::create_joint))           \
    X(create_prismatic_joint, Member<JointId(const PrismaticJointDef&)>(&World::create_joint))     \
    X(create_weld_joint, Member<JointId(const WeldJointDef&)>(&World::create_joint))               \
    X(create_wheel_joint, Member<JointId(const WheelJointDef&)>(&World::create_joint))             \
    X(create_motor_joint, Member<JointId(const MotorJointDef&)>(&World::create_joint))             \
    X(create_filter_joint, Member<JointId(const FilterJointDef&)>(&World::create_joint))           \
    X(set_motor_joint_offsets, &World::set_motor_joint_offsets)                                    \
    X(set_joint_target, &World::set_joint_target)                                                  \
    X(destroy_joint, &World::destroy_joint)                                                        \
    X(set_joint_motor_speed, &World::set_joint_motor_speed)                                        \
    X(enable_joint_limit, &World::enable_joint_limit)                                              \
    X(set_joint_limits, &World::set_joint_limits)                                                  \
    X(enable_joint_motor, &World::enable_joint_motor)                                              \
    X(set_joint_max_motor_torque, &World::set_joint_max_motor_torque)                              \
    X(set_joint_max_motor_force, &World::set_joint_max_motor_force)                                \
    X(enable_joint_spring, &World::enable_joint_spring)                                            \
    X(set_joint_spring, &World::set_joint_spring)                                                  \
    X(set_joint_spring_target, &World::set_joint_spring_target)                                    \
    X(set_distance_joint_length, &World::set_distance_joint_length)                                \
    X(set_constraint_tuning, &World::set_constraint_tuning)                                        \
    X(set_joint_collide_connected, &World::set_joint_collide_connected)                            \
    X(set_joint_break_force, &World::set_joint_break_force)                                        \
    X(set_joint_break_torque, &World::set_joint_break_torque)                                      \
    X(set_awake, &World::set_awake)                                                                \
    X(restore, &World::restore)                                                                    \
    X(set_hit_event_threshold, &World::set_hit_event_threshold)                                    \
    X(set_hit_events_enabled, &World::set_hit_events_enabled)                                      \
    X(set_contact_events_enabled, &World::set_contact_events_enabled)                              \
    X(set_sensor_events_enabled, &World::set_sensor_events_enabled)                                \
    X(set_move_events_enabled, &World::set_move_events_enabled)                                    \
    X(set_joint_event_thresholds, &World::set_joint_event_thresholds)                              \
    X(explode, &World::explode)                                                                    \
    X(set_world_user_data, Member<void(UserData)>(&World::set_user_data))                          \
    X(set_body_user_data, Member<void(BodyId, UserData)>(&World::set_user_data))                   \
    X(set_shape_user_data, Member<void(ShapeId, UserData)>(&World::set_user_data))                 \
    X(set_joint_user_data, Member<void(JointId, UserData)>(&World::set_user_data))                 \
    X(set_body_type, &World::set_body_type)                                                        \
    X(set_enabled, &World::set_enabled)                                                            \
    X(set_gravity_scale, &World::set_gravity_scale)                                                \
    X(set_bullet, &World::set_bullet)                                                              \
    X(set_motion_locks, &World::set_motion_locks)                                                  \
    X(set_fixed_rotation, &World::set_fixed_rotation)                                              \
    X(set_mass_data, &World::set_mass_data)                                                        \
    X(reset_mass_data, &World::reset_mass_data)                                                    \
    X(set_sleep_threshold, &World::set_sleep_threshold)                                            \
    X(wake_touching, &World::wake_touching)                                                        \
    X(set_continuous, &World::set_continuous)                                                      \
    X(set_sleeping, &World::set_sleeping)                                                          \
    X(set_contact_tuning, &World::set_contact_tuning)                                              \
    X(set_joint_tuning, &World::set_joint_tuning)                                                  \
    X(set_restitution_threshold, &World::set_restitution_threshold)                                \
    X(set_maximum_linear_speed, &World::set_maximum_linear_speed)                                  \
    X(set_workers, &World::set_workers)                                                            \
    X(set_warm_starting, &World::set_warm_starting)                                                \
    X(set_user_material, &World::set_user_material)                                                \
    X(set_target_transform, &World::set_target_transform)                                          \
    X(apply_wind, &World::apply_wind)                                                              \
    X(set_rolling_resistance, &World::set_rolling_resistance)                                      \
    X(set_tangent_speed, &World::set_tangent_speed)
// clang-format on

/// A call's code in a recording: its place in TAMIAS2D_RECORDED_CALLS.
enum class Call : std::uint8_t {
#define TAMIAS2D_CALL_ENUM(name, member) name,
    TAMIAS2D_RECORDED_CALLS(TAMIAS2D_CALL_ENUM)
#undef TAMIAS2D_CALL_ENUM
        count
};

/// The calls' names, by code (reports, Replayer's listing).
inline constexpr std::array<std::string_view, std::size_t(Call::count)> call_names{
#define TAMIAS2D_CALL_NAME(name, member) #name,
    TAMIAS2D_RECORDED_CALLS(TAMIAS2D_CALL_NAME)
#undef TAMIAS2D_CALL_NAME
};

/// The member a call code names: member_of<Call::x>().
template <Call C> constexpr auto member_of() {
#define TAMIAS2D_CALL_MEMBER(name, member)                                                         \
    if constexpr (C == Call::name)                                                                 \
        return member;                                                                             \
    else
    TAMIAS2D_RECORDED_CALLS(TAMIAS2D_CALL_MEMBER)
#undef TAMIAS2D_CALL_MEMBER
    return nullptr;
}

/// A member function's parameter types.
template <class M> struct MemberTraits;
template <class R, class... A> struct MemberTraits<R (World::*)(A...)> {
    using Result = R;
    using Args = std::tuple<A...>;
};

/// Where a decoded argument of parameter type P is held: the value itself (a span's elements
/// in a vector).
template <class P> struct Held { using type = std::remove_cvref_t<P>; };
template <class T> struct Held<std::span<const T>> { using type = memory::vector<T>; };
template <class Tuple> struct HeldTuple;
template <class... A> struct HeldTuple<std::tuple<A...>> {
    using type = std::tuple<typename Held<A>::type...>;
};

// --- the codec of every argument type: io(name, value) over SnapshotWriter (const values) and
// SnapshotReader (values to fill) alike ---

template <class IO, class T> void argument_io(IO& io, const char* f, T& v);

template <class IO, class G> void geometry_io(IO& io, G& g) {
    io.enumeration("geometry.type", g.type, ShapeType::chain_segment);
    switch (g.type) { // only the member the type names means anything
    case ShapeType::circle:
        argument_io(io, "geometry.circle", g.circle);
        break;
    case ShapeType::polygon:
        argument_io(io, "geometry.polygon", g.polygon);
        break;
    case ShapeType::capsule:
        argument_io(io, "geometry.capsule", g.capsule);
        break;
    case ShapeType::segment:
        argument_io(io, "geometry.segment", g.segment);
        break;
    case ShapeType::chain_segment:
        argument_io(io, "geometry.chain_segment.ghost1", g.chain_segment.ghost1);
        argument_io(io, "geometry.chain_segment.point1", g.chain_segment.point1);
        argument_io(io, "geometry.chain_segment.point2", g.chain_segment.point2);
        argument_io(io, "geometry.chain_segment.ghost2", g.chain_segment.ghost2);
        break;
    }
}

/// The fields every joint definition but the target joint's starts with.
template <class IO, class D> void two_bodies_io(IO& io, D& d) {
    io.handle("joint.body_a", d.body_a);
    io.handle("joint.body_b", d.body_b);
}
/// The fields every joint definition ends with.
template <class IO, class D> void joint_tail_io(IO& io, D& d) {
    if constexpr (requires { d.collide_connected; })
        io("joint.collide_connected", d.collide_connected);
    if constexpr (requires { d.break_force; })
        io("joint.break_force", d.break_force);
    if constexpr (requires { d.break_torque; })
        io("joint.break_torque", d.break_torque);
    if constexpr (requires { d.force_threshold; }) {
        io("joint.force_threshold", d.force_threshold);
        io("joint.torque_threshold", d.torque_threshold);
    }
    if constexpr (requires { d.spring_target; })
        io("joint.spring_target", d.spring_target);
    if constexpr (requires { d.constraint_tuning; }) {
        // (an optional ConstraintTuning as a flag and its two values, 0 when unset)
        bool has = d.constraint_tuning.has_value();
        double hertz = has ? d.constraint_tuning->hertz : 0.0;
        double ratio = has ? d.constraint_tuning->damping_ratio : 0.0;
        io("joint.constraint_tuning", has);
        io("joint.constraint_tuning.hertz", hertz);
        io("joint.constraint_tuning.damping_ratio", ratio);
        if constexpr (!std::is_const_v<D>) {
            if (has)
                d.constraint_tuning = ConstraintTuning{hertz, ratio};
            else
                d.constraint_tuning.reset();
        }
    }
    io.user_data("joint.user_data", d.user_data);
}

// The definitions' sizes where they are known (64-bit libstdc++): a field added to one of them
// almost always changes its size (not a bool that fits in padding) and fails here until the
// codec below has a line for it and the size is updated, so that a new field is not silently
// left to its default on replay.
#if defined(__GLIBCXX__) && UINTPTR_MAX == UINT64_MAX
static_assert(sizeof(BodyDef) == 240, "BodyDef changed: update definition_io");
static_assert(sizeof(ShapeDef) == 528, "ShapeDef changed: update definition_io");
#endif

/// A shape's or a body's definition, field by field. A field added to ShapeDef or BodyDef
/// needs its line here (the size check below fails until it has one).
template <class IO, class T> void definition_io(IO& io, T& v) {
    using V = std::remove_const_t<T>;
    if constexpr (std::is_same_v<V, ShapeDef>) {
        geometry_io(io, v.geometry);
        io("shape.material.density", v.material.density);
        io("shape.material.restitution", v.material.restitution);
        io("shape.material.friction", v.material.friction);
        io("shape.material.user_material_id", v.material.user_material_id);
        io("shape.material.rolling_resistance", v.material.rolling_resistance);
        io("shape.material.tangent_speed", v.material.tangent_speed);
        argument_io(io, "shape.filter", v.filter);
        io("shape.is_sensor", v.is_sensor);
        io("shape.enable_contact_events", v.enable_contact_events);
        io("shape.enable_sensor_events", v.enable_sensor_events);
        io("shape.enable_hit_events", v.enable_hit_events);
        io("shape.enable_pre_solve", v.enable_pre_solve);
        io.user_data("shape.user_data", v.user_data);
    } else if constexpr (std::is_same_v<V, BodyDef>) {
        if constexpr (std::is_const_v<T>) {
            if (v.load)
                throw ValidationError(ValidationError::NotANumber{}, "body.load",
                                      "must be empty while the world is recorded (a function "
                                      "cannot be recorded: docs/user-guide.md, \"Recordings\")",
                                      "recording");
        }
        io.enumeration("body.type", v.type, BodyType::dynamic);
        io("body.position", v.position);
        io("body.angle", v.angle);
        io("body.linear_velocity", v.linear_velocity);
        io("body.angular_velocity", v.angular_velocity);
        io("body.force", v.force);
        io("body.torque", v.torque);
        io("body.mass", v.mass);
        io("body.inertia", v.inertia);
        io("body.gravity_scale", v.gravity_scale);
        io("body.linear_damping", v.linear_damping);
        io("body.angular_damping", v.angular_damping);
        io("body.fixed_rotation", v.fixed_rotation);
        argument_io(io, "body.motion_locks", v.motion_locks);
        io("body.bullet", v.bullet);
        io("body.enable_sleep", v.enable_sleep);
        io("body.awake", v.awake);
        io("body.sleep_threshold", v.sleep_threshold);
        io("body.enabled", v.enabled);
        io("body.enable_move_events", v.enable_move_events);
        io("body.name", v.name);
        io.user_data("body.user_data", v.user_data);
    }
}

template <class V>
inline constexpr bool is_joint_definition_v =
    std::is_same_v<V, RevoluteJointDef> || std::is_same_v<V, DistanceJointDef> ||
    std::is_same_v<V, TargetJointDef> || std::is_same_v<V, PrismaticJointDef> ||
    std::is_same_v<V, WeldJointDef> || std::is_same_v<V, WheelJointDef> ||
    std::is_same_v<V, MotorJointDef> || std::is_same_v<V, FilterJointDef>;

/// A joint's definition, field by field (the shared tail: joint_tail_io).
template <class IO, class T> void joint_definition_io(IO& io, T& v) {
    using V = std::remove_const_t<T>;
    if constexpr (std::is_same_v<V, RevoluteJointDef>) {
        two_bodies_io(io, v);
        io("joint.anchor", v.anchor);
        io("joint.enable_limit", v.enable_limit);
        io("joint.lower_angle", v.lower_angle);
        io("joint.upper_angle", v.upper_angle);
        io("joint.enable_motor", v.enable_motor);
        io("joint.motor_speed", v.motor_speed);
        io("joint.max_motor_torque", v.max_motor_torque);
        io("joint.enable_spring", v.enable_spring);
        io("joint.hertz", v.hertz);
        io("joint.damping_ratio", v.damping_ratio);
        joint_tail_io(io, v);
    } else if constexpr (std::is_same_v<V, DistanceJointDef>) {
        two_bodies_io(io, v);
        io("joint.anchor_a", v.anchor_a);
        io("joint.anchor_b", v.anchor_b);
        io("joint.length", v.length);
        io("joint.hertz", v.hertz);
        io("joint.damping_ratio", v.damping_ratio);
        io("joint.enable_limit", v.enable_limit);
        io("joint.min_length", v.min_length);
        io("joint.max_length", v.max_length);
        io("joint.enable_motor", v.enable_motor);
        io("joint.motor_speed", v.motor_speed);
        io("joint.max_motor_force", v.max_motor_force);
        joint_tail_io(io, v);
    } else if constexpr (std::is_same_v<V, TargetJointDef>) {
        io.handle("joint.body", v.body);
        io("joint.target", v.target);
        io("joint.hertz", v.hertz);
        io("joint.damping_ratio", v.damping_ratio);
        io("joint.max_force", v.max_force);
        joint_tail_io(io, v);
    } else if constexpr (std::is_same_v<V, PrismaticJointDef>) {
        two_bodies_io(io, v);
        io("joint.anchor", v.anchor);
        io("joint.axis", v.axis);
        io("joint.enable_limit", v.enable_limit);
        io("joint.lower_translation", v.lower_translation);
        io("joint.upper_translation", v.upper_translation);
        io("joint.enable_motor", v.enable_motor);
        io("joint.motor_speed", v.motor_speed);
        io("joint.max_motor_force", v.max_motor_force);
        io("joint.enable_spring", v.enable_spring);
        io("joint.hertz", v.hertz);
        io("joint.damping_ratio", v.damping_ratio);
        joint_tail_io(io, v);
    } else if constexpr (std::is_same_v<V, WeldJointDef>) {
        two_bodies_io(io, v);
        io("joint.anchor", v.anchor);
        io("joint.linear_hertz", v.linear_hertz);
        io("joint.linear_damping_ratio", v.linear_damping_ratio);
        io("joint.angular_hertz", v.angular_hertz);
        io("joint.angular_damping_ratio", v.angular_damping_ratio);
        joint_tail_io(io, v);
    } else if constexpr (std::is_same_v<V, WheelJointDef>) {
        two_bodies_io(io, v);
        io("joint.anchor", v.anchor);
        io("joint.axis", v.axis);
        io("joint.enable_spring", v.enable_spring);
        io("joint.hertz", v.hertz);
        io("joint.damping_ratio", v.damping_ratio);
        io("joint.enable_limit", v.enable_limit);
        io("joint.lower_translation", v.lower_translation);
        io("joint.upper_translation", v.upper_translation);
        io("joint.enable_motor", v.enable_motor);
        io("joint.motor_speed", v.motor_speed);
        io("joint.max_motor_torque", v.max_motor_torque);
        joint_tail_io(io, v);
    } else if constexpr (std::is_same_v<V, MotorJointDef>) {
        two_bodies_io(io, v);
        io("joint.linear_offset", v.linear_offset);
        io("joint.angular_offset", v.angular_offset);
        io("joint.max_force", v.max_force);
        io("joint.max_torque", v.max_torque);
        io("joint.correction_factor", v.correction_factor);
        joint_tail_io(io, v);
    } else if constexpr (std::is_same_v<V, FilterJointDef>) {
        two_bodies_io(io, v);
        joint_tail_io(io, v);
    }
}

template <class IO, class T> void argument_io(IO& io, const char* f, T& v) {
    using V = std::remove_const_t<T>;
    if constexpr (std::is_same_v<V, BodyId> || std::is_same_v<V, ShapeId> ||
                  std::is_same_v<V, JointId>) {
        io.handle(f, v);
    } else if constexpr (std::is_same_v<V, UserData>) {
        io.user_data(f, v);
    } else if constexpr (std::is_same_v<V, BodyType>) {
        io.enumeration(f, v, BodyType::dynamic);
    } else if constexpr (std::is_same_v<V, int>) {
        // (int is 32 bits on every platform the library is built for)
        io(f, reinterpret_cast<
                  std::conditional_t<std::is_const_v<T>, const std::int32_t&, std::int32_t&>>(v));
    } else if constexpr (std::is_arithmetic_v<V> || std::is_same_v<V, Vec2d>) {
        io(f, v);
    } else if constexpr (std::is_same_v<V, Filter>) {
        io("filter.category_bits", v.category_bits);
        io("filter.mask_bits", v.mask_bits);
        io("filter.group_index", v.group_index);
    } else if constexpr (std::is_same_v<V, Circle>) {
        io("circle.center", v.center);
        io("circle.radius", v.radius);
    } else if constexpr (std::is_same_v<V, Capsule>) {
        io("capsule.center1", v.center1);
        io("capsule.center2", v.center2);
        io("capsule.radius", v.radius);
    } else if constexpr (std::is_same_v<V, Segment>) {
        io("segment.point1", v.point1);
        io("segment.point2", v.point2);
    } else if constexpr (std::is_same_v<V, Polygon>) {
        for (auto& p : v.vertices)
            io("polygon.vertices", p);
        for (auto& n : v.normals)
            io("polygon.normals", n);
        io("polygon.centroid", v.centroid);
        argument_io(io, "polygon.count", v.count);
    } else if constexpr (std::is_same_v<V, Geometry>) {
        geometry_io(io, v);
    } else if constexpr (std::is_same_v<V, ShapeDef> || std::is_same_v<V, BodyDef>) {
        definition_io(io, v);
    } else if constexpr (is_joint_definition_v<V>) {
        joint_definition_io(io, v);
    } else if constexpr (std::is_same_v<V, memory::vector<ShapeDef>> ||
                         std::is_same_v<V, std::span<const ShapeDef>>) {
        if constexpr (std::is_same_v<V, memory::vector<ShapeDef>> && !std::is_const_v<T>) {
            v.resize(io.count(f, 8)); // (a reader: each definition is 8 bytes or more)
        } else {
            io.count(f, v.size());
        }
        for (auto& d : v)
            argument_io(io, f, d);
    } else if constexpr (std::is_same_v<V, memory::vector<std::byte>> ||
                         std::is_same_v<V, std::span<const std::byte>>) {
        if constexpr (std::is_same_v<V, memory::vector<std::byte>> && !std::is_const_v<T>) {
            v.resize(io.count(f, 1));
            for (auto& b : v)
                b = std::byte(io.u8(f));
        } else {
            io.count(f, v.size());
            for (const std::byte b : v)
                io.u8(std::uint8_t(b));
        }
    } else if constexpr (std::is_same_v<V, ExplosionDef>) {
        io("explosion.position", v.position);
        io("explosion.radius", v.radius);
        io("explosion.falloff", v.falloff);
        io("explosion.impulse_per_length", v.impulse_per_length);
        io("explosion.impulse_per_body", v.impulse_per_body);
        io("explosion.mask_bits", v.mask_bits);
    } else if constexpr (std::is_same_v<V, MotionLocks>) {
        io("locks.linear_x", v.linear_x);
        io("locks.linear_y", v.linear_y);
        io("locks.angular", v.angular);
    } else if constexpr (std::is_same_v<V, BodyMassData>) {
        io("mass_data.mass", v.mass);
        io("mass_data.center", v.center);
        io("mass_data.inertia", v.inertia);
    } else {
        static_assert(sizeof(V) == 0, "a World call's argument type without a codec: add it here");
    }
}

/// Writes a call's arguments, in the order of its member's parameters.
template <class... A> void write_arguments(SnapshotWriter& w, const A&... args) {
    (argument_io(w, "argument", args), ...);
}

} // namespace tamias2d::recording
