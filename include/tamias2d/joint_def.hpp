/// \file
/// Joints (SRS LC3, relaxing A7): constraints between two bodies. Every field is in SI units,
/// stated beside it.
#pragma once

#include <limits>
#include <optional>

#include "tamias2d/handles.hpp"
#include "tamias2d/joint_kind.hpp"
#include "tamias2d/user_data.hpp"
#include "tamias2d/vec2.hpp"

namespace tamias2d {

/// \srs{DD19} A revolute joint (a pin): one point of body B is held on one point of body A,
/// about which the two turn freely. A pendulum is a revolute joint to a static body; a chain,
/// a door or a ragdoll's limbs are revolute joints between dynamic ones.
struct RevoluteJointDef {
    BodyId body_a{}; ///< the first body (often the static or heavier one)
    BodyId body_b{}; ///< the second body; not body_a
    Vec2d anchor{};  ///< m, world frame: the pin, taken as fixed on both bodies at creation
    /// Whether the two bodies' shapes still collide with each other (default: they do not,
    /// as the parts of one mechanism usually overlap at the pin).
    bool collide_connected = false;
    /// N, > 0: the joint breaks (is destroyed, and listed by World::broken_joints) after a
    /// step in which the force it carried, |reaction force|, exceeded this. Infinite: never.
    double break_force = std::numeric_limits<double>::infinity();
    /// \srs{DD36} N m, > 0: the joint breaks after a step in which the magnitude of the torque
    /// it carried (its reaction torque, World::joint_reaction_torque()) exceeded this (a hinge
    /// that snaps when over-twisted). Infinite: never.
    double break_torque = std::numeric_limits<double>::infinity();
    /// \srs{DD22} Limits of the joint angle (B's turn against A since creation, rad, CCW
    /// positive), lower <= upper: a door's hinge, an elbow.
    bool enable_limit = false;
    double lower_angle = 0.0; ///< rad
    double upper_angle = 0.0; ///< rad
    /// \srs{DD22} A motor driving the joint speed to motor_speed (rad s^-1) with at most
    /// max_motor_torque (N m, >= 0): a wheel, a fan; with speed 0, joint friction.
    bool enable_motor = false;
    double motor_speed = 0.0;      ///< rad s^-1
    double max_motor_torque = 0.0; ///< N m, >= 0
    /// \srs{DD22} A torsional spring pulling the joint angle back to 0 (the pose at creation):
    /// a ragdoll's joints that return to rest, a springy flap. Natural frequency `hertz` (> 0
    /// when enabled) for the relative turn's effective inertia, damping ratio >= 0.
    bool enable_spring = false;
    double hertz = 0.0;         ///< Hz
    double damping_ratio = 0.0; ///< 1: critically damped
    /// \srs{DD22} rad: the value the spring pulls the joint angle to
    /// (World::set_joint_spring_target); 0, the default, is the pose at creation.
    double spring_target = 0.0;
    /// \srs{IM6} This joint's own soft bias in place of the world's (WorldDef::joint_hertz and
    /// joint_damping_ratio; World::set_constraint_tuning): hertz > 0, damping ratio > 0. Unset:
    /// the world's.
    std::optional<ConstraintTuning> constraint_tuning{};
    /// N, >= 0: after a step in which the joint's reaction force exceeded this, the joint is
    /// reported (World::joint_events, threshold_exceeded) and kept. Infinite: never.
    double force_threshold = std::numeric_limits<double>::infinity();
    /// N m, >= 0: the same for its reaction torque. Infinite: never.
    double torque_threshold = std::numeric_limits<double>::infinity();
    UserData user_data = 0; ///< the game's own value (user_data.hpp), not simulation state
    /// Field by field (a scene's joints compare so after a round trip through JSON).
    friend bool operator==(const RevoluteJointDef&, const RevoluteJointDef&) = default;
};

/// \srs{DD20} A distance joint: two anchor points, one on each body, kept at a set distance
/// by a rigid rod (the default) or by a spring-damper (a rope bridge's planks, a car's
/// suspension seen along one axis, a soft link).
struct DistanceJointDef {
    BodyId body_a{};  ///< the first body
    BodyId body_b{};  ///< the second body; not body_a
    Vec2d anchor_a{}; ///< m, world frame: the anchor on body_a, fixed in it at creation
    Vec2d anchor_b{}; ///< m, world frame: the anchor on body_b, fixed in it at creation
    /// m, > 0: the rest length. Unset: the anchors' distance at creation (which must be > 0).
    std::optional<double> length{};
    /// Hz, >= 0: 0 (the default) makes the rod rigid (IM6's soft bias only); above 0 the
    /// distance is held by a spring of this natural frequency for the joint's effective mass.
    double hertz = 0.0;
    double damping_ratio = 0.0; ///< >= 0: the spring's damping ratio (1: critically damped)
    /// With a spring (hertz > 0) or the motor: hard bounds on the anchors' distance, 0 <=
    /// min_length <= max_length (m), so that a soft or driven link cannot stretch or shrink
    /// without end. A rigid rod keeps its length and needs none.
    bool enable_limit = false;
    double min_length = 0.0;                                     ///< m
    double max_length = std::numeric_limits<double>::infinity(); ///< m
    /// \srs{DD35} A motor driving the rate of change of the anchors' distance to motor_speed
    /// (m s^-1, positive: apart) with at most max_motor_force (N, >= 0): a winch, a telescopic
    /// arm. With the motor enabled a rigid rod (hertz 0) gives way to it: the length is the
    /// motor's, bounded by the limits if enabled; with a spring (hertz > 0) both act.
    bool enable_motor = false;
    double motor_speed = 0.0;       ///< m s^-1
    double max_motor_force = 0.0;   ///< N, >= 0
    bool collide_connected = false; ///< as RevoluteJointDef::collide_connected
    double break_force = std::numeric_limits<double>::infinity(); ///< N, > 0, as for revolute
    /// \srs{IM6} This joint's own soft bias in place of the world's (WorldDef::joint_hertz and
    /// joint_damping_ratio; World::set_constraint_tuning): hertz > 0, damping ratio > 0. Unset:
    /// the world's.
    std::optional<ConstraintTuning> constraint_tuning{};
    /// N, >= 0: after a step in which the joint's reaction force exceeded this, the joint is
    /// reported (World::joint_events, threshold_exceeded) and kept. Infinite: never.
    double force_threshold = std::numeric_limits<double>::infinity();
    /// N m, >= 0: the same for its reaction torque. Infinite: never.
    double torque_threshold = std::numeric_limits<double>::infinity();
    UserData user_data = 0; ///< the game's own value (user_data.hpp), not simulation state
    /// Field by field (a scene's joints compare so after a round trip through JSON).
    friend bool operator==(const DistanceJointDef&, const DistanceJointDef&) = default;
};

/// \srs{DD21} A target joint (a mouse joint): pulls the point of `body` under `target` (as
/// it is at creation) towards the target as a spring-damper, with at most `max_force`. Move
/// the target with World::set_joint_target to drag the body.
struct TargetJointDef {
    BodyId body{};              ///< the dragged body (dynamic)
    Vec2d target{};             ///< m, world frame: the target, and the grabbed point of body
    double hertz = 5.0;         ///< Hz, > 0: the spring's natural frequency
    double damping_ratio = 0.7; ///< >= 0: the spring's damping ratio
    /// N, > 0: the largest force the joint applies (infinite: unbounded). A few times the
    /// body's weight drags it firmly without flinging it through walls.
    double max_force = std::numeric_limits<double>::infinity();
    /// N, >= 0: after a step in which the joint's reaction force exceeded this, the joint is
    /// reported (World::joint_events, threshold_exceeded) and kept. Infinite: never.
    double force_threshold = std::numeric_limits<double>::infinity();
    /// N m, >= 0: the same for its reaction torque. Infinite: never.
    double torque_threshold = std::numeric_limits<double>::infinity();
    UserData user_data = 0; ///< the game's own value (user_data.hpp), not simulation state
    /// Field by field (a scene's joints compare so after a round trip through JSON).
    friend bool operator==(const TargetJointDef&, const TargetJointDef&) = default;
};

/// \srs{DD23} A prismatic joint (a slider): body B slides along an axis fixed in body A and
/// does not turn against it: a piston, an elevator, a drawer. Its translation is the anchors'
/// separation along the axis, 0 at creation.
struct PrismaticJointDef {
    BodyId body_a{};      ///< the body the axis is fixed in
    BodyId body_b{};      ///< the sliding body; not body_a
    Vec2d anchor{};       ///< m, world frame: a point taken as fixed on both bodies at creation
    Vec2d axis{1.0, 0.0}; ///< world frame at creation, any non-zero length (it is normalised)
    bool collide_connected = false; ///< as RevoluteJointDef::collide_connected
    double break_force = std::numeric_limits<double>::infinity();  ///< N, > 0, as for revolute
    double break_torque = std::numeric_limits<double>::infinity(); ///< N m, > 0, as for revolute
    /// Limits of the translation (m), lower <= upper: the piston's stroke.
    bool enable_limit = false;
    double lower_translation = 0.0; ///< m
    double upper_translation = 0.0; ///< m
    /// A motor driving the sliding speed to motor_speed (m s^-1) with at most max_motor_force
    /// (N, >= 0): an elevator; with speed 0, sliding friction.
    bool enable_motor = false;
    double motor_speed = 0.0;     ///< m s^-1
    double max_motor_force = 0.0; ///< N, >= 0
    /// A spring pulling the translation back to 0: natural frequency hertz (> 0 when enabled)
    /// for the sliding direction's effective mass, damping ratio >= 0.
    bool enable_spring = false;
    double hertz = 0.0;         ///< Hz
    double damping_ratio = 0.0; ///< 1: critically damped
    /// \srs{DD22} m: the value the spring pulls the translation to
    /// (World::set_joint_spring_target); 0, the default, is the pose at creation.
    double spring_target = 0.0;
    /// \srs{IM6} This joint's own soft bias in place of the world's (WorldDef::joint_hertz and
    /// joint_damping_ratio; World::set_constraint_tuning): hertz > 0, damping ratio > 0. Unset:
    /// the world's.
    std::optional<ConstraintTuning> constraint_tuning{};
    /// N, >= 0: after a step in which the joint's reaction force exceeded this, the joint is
    /// reported (World::joint_events, threshold_exceeded) and kept. Infinite: never.
    double force_threshold = std::numeric_limits<double>::infinity();
    /// N m, >= 0: the same for its reaction torque. Infinite: never.
    double torque_threshold = std::numeric_limits<double>::infinity();
    UserData user_data = 0; ///< the game's own value (user_data.hpp), not simulation state
    /// Field by field (a scene's joints compare so after a round trip through JSON).
    friend bool operator==(const PrismaticJointDef&, const PrismaticJointDef&) = default;
};

/// \srs{DD24} A weld joint: body B held to body A at the anchor with its relative angle kept,
/// as if glued, rigidly (hertz 0, the default) or as a spring in position and in angle: a
/// breakable structure, a soft body made of welded pieces.
struct WeldJointDef {
    BodyId body_a{}; ///< the first body
    BodyId body_b{}; ///< the second body; not body_a
    Vec2d anchor{};  ///< m, world frame: the point held together, fixed on both at creation
    /// Hz, >= 0: 0 holds the anchor rigidly, above 0 with a spring of this frequency.
    double linear_hertz = 0.0;
    double linear_damping_ratio = 0.0; ///< >= 0
    /// Hz, >= 0: 0 holds the angle rigidly, above 0 with a torsional spring.
    double angular_hertz = 0.0;
    double angular_damping_ratio = 0.0; ///< >= 0
    bool collide_connected = false;     ///< as RevoluteJointDef::collide_connected
    double break_force = std::numeric_limits<double>::infinity();  ///< N, > 0, as for revolute
    double break_torque = std::numeric_limits<double>::infinity(); ///< N m, > 0, as for revolute
    /// \srs{IM6} This joint's own soft bias in place of the world's (WorldDef::joint_hertz and
    /// joint_damping_ratio; World::set_constraint_tuning): hertz > 0, damping ratio > 0. Unset:
    /// the world's.
    std::optional<ConstraintTuning> constraint_tuning{};
    /// N, >= 0: after a step in which the joint's reaction force exceeded this, the joint is
    /// reported (World::joint_events, threshold_exceeded) and kept. Infinite: never.
    double force_threshold = std::numeric_limits<double>::infinity();
    /// N m, >= 0: the same for its reaction torque. Infinite: never.
    double torque_threshold = std::numeric_limits<double>::infinity();
    UserData user_data = 0; ///< the game's own value (user_data.hpp), not simulation state
    /// Field by field (a scene's joints compare so after a round trip through JSON).
    friend bool operator==(const WeldJointDef&, const WeldJointDef&) = default;
};

/// \srs{DD25} A wheel joint: body B (the wheel) kept on a line through the anchor along an
/// axis fixed in body A (the chassis), sprung along it (the suspension) and free to turn,
/// optionally driven by a motor: a car's wheel.
struct WheelJointDef {
    BodyId body_a{};                ///< the chassis
    BodyId body_b{};                ///< the wheel; not body_a
    Vec2d anchor{};                 ///< m, world frame: usually the wheel's centre
    Vec2d axis{0.0, 1.0};           ///< world frame at creation: the suspension's travel, non-zero
    bool collide_connected = false; ///< as RevoluteJointDef::collide_connected
    double break_force = std::numeric_limits<double>::infinity();  ///< N, > 0, as for revolute
    double break_torque = std::numeric_limits<double>::infinity(); ///< N m, > 0, as for revolute
    /// The suspension spring (translation pulled back to 0): natural frequency hertz (> 0 when
    /// enabled) for the axis's effective mass, damping ratio >= 0.
    bool enable_spring = true;
    double hertz = 1.0;         ///< Hz
    double damping_ratio = 0.7; ///< 1: critically damped
    /// \srs{DD22} m: the value the spring pulls the suspension's translation to
    /// (World::set_joint_spring_target); 0, the default, is the pose at creation.
    double spring_target = 0.0;
    /// \srs{IM6} This joint's own soft bias in place of the world's (WorldDef::joint_hertz and
    /// joint_damping_ratio; World::set_constraint_tuning): hertz > 0, damping ratio > 0. Unset:
    /// the world's.
    std::optional<ConstraintTuning> constraint_tuning{};
    /// Limits of the suspension's travel (m), lower <= upper.
    bool enable_limit = false;
    double lower_translation = 0.0; ///< m
    double upper_translation = 0.0; ///< m
    /// A motor on the wheel's turn against the chassis, as RevoluteJointDef's.
    bool enable_motor = false;
    double motor_speed = 0.0;      ///< rad s^-1
    double max_motor_torque = 0.0; ///< N m, >= 0
    /// N, >= 0: after a step in which the joint's reaction force exceeded this, the joint is
    /// reported (World::joint_events, threshold_exceeded) and kept. Infinite: never.
    double force_threshold = std::numeric_limits<double>::infinity();
    /// N m, >= 0: the same for its reaction torque. Infinite: never.
    double torque_threshold = std::numeric_limits<double>::infinity();
    UserData user_data = 0; ///< the game's own value (user_data.hpp), not simulation state
    /// Field by field (a scene's joints compare so after a round trip through JSON).
    friend bool operator==(const WheelJointDef&, const WheelJointDef&) = default;
};

/// \srs{DD26} A motor joint: drives body B's pose relative to body A (its origin to
/// linear_offset in A's frame, its angle to A's plus angular_offset) with at most max_force
/// and max_torque: a character pushed along a path, a platform that follows another body.
struct MotorJointDef {
    BodyId body_a{};             ///< the reference body
    BodyId body_b{};             ///< the driven body; not body_a
    Vec2d linear_offset{};       ///< m, body_a's frame: the target of body_b's origin
    double angular_offset = 0.0; ///< rad: the target of phi_B - phi_A
    double max_force = 1.0;      ///< N, >= 0
    double max_torque = 1.0;     ///< N m, >= 0
    /// In [0, 1]: the share of the pose error the joint asks to remove per substep.
    double correction_factor = 0.3;
    bool collide_connected = false; ///< as RevoluteJointDef::collide_connected
    double break_force = std::numeric_limits<double>::infinity();  ///< N, > 0, as for revolute
    double break_torque = std::numeric_limits<double>::infinity(); ///< N m, > 0, as for revolute
    /// N, >= 0: after a step in which the joint's reaction force exceeded this, the joint is
    /// reported (World::joint_events, threshold_exceeded) and kept. Infinite: never.
    double force_threshold = std::numeric_limits<double>::infinity();
    /// N m, >= 0: the same for its reaction torque. Infinite: never.
    double torque_threshold = std::numeric_limits<double>::infinity();
    UserData user_data = 0; ///< the game's own value (user_data.hpp), not simulation state
    /// Field by field (a scene's joints compare so after a round trip through JSON).
    friend bool operator==(const MotorJointDef&, const MotorJointDef&) = default;
};

/// A filter joint: no constraint, only "these two bodies' shapes do not collide" (DD27's
/// joint-filtered pair, as Box2D v3's b2FilterJointDef): a ragdoll's limbs that overlap without
/// being pinned, a bullet that passes its gun. It applies no force and never breaks; destroying
/// it lets the two collide again.
struct FilterJointDef {
    BodyId body_a{};        ///< the first body
    BodyId body_b{};        ///< the second body; not body_a
    UserData user_data = 0; ///< the game's own value (user_data.hpp), not simulation state
    /// Field by field (a scene's joints compare so after a round trip through JSON).
    friend bool operator==(const FilterJointDef&, const FilterJointDef&) = default;
};

} // namespace tamias2d
