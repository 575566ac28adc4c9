/// \file
/// Joints (SRS LC3, relaxing A7): constraints between two bodies. Every field is in SI units,
/// stated beside it.
#pragma once

#include <limits>
#include <optional>

#include "tamias2d/handles.hpp"
#include "tamias2d/vec2.hpp"

namespace tamias2d {

/// \srs{DD19} A revolute joint (a pin): one point of body B is held on one point of body A,
/// about which the two turn freely. A pendulum is a revolute joint to a static body; a chain,
/// a door or a ragdoll's limbs are revolute joints between dynamic ones.
struct RevoluteJointDef {
    BodyId body_a;  ///< the first body (often the static or heavier one)
    BodyId body_b;  ///< the second body; not body_a
    Vec2d anchor{}; ///< m, world frame: the pin, taken as fixed on both bodies at creation
    /// Whether the two bodies' shapes still collide with each other (default: they do not,
    /// as the parts of one mechanism usually overlap at the pin).
    bool collide_connected = false;
    /// N, > 0: the joint breaks (is destroyed, and listed by World::broken_joints) after a
    /// step in which the force it carried, |reaction force|, exceeded this. Infinite: never.
    double break_force = std::numeric_limits<double>::infinity();
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
};

/// \srs{DD20} A distance joint: two anchor points, one on each body, kept at a set distance
/// by a rigid rod (the default) or by a spring-damper (a rope bridge's planks, a car's
/// suspension seen along one axis, a soft link).
struct DistanceJointDef {
    BodyId body_a;    ///< the first body
    BodyId body_b;    ///< the second body; not body_a
    Vec2d anchor_a{}; ///< m, world frame: the anchor on body_a, fixed in it at creation
    Vec2d anchor_b{}; ///< m, world frame: the anchor on body_b, fixed in it at creation
    /// m, > 0: the rest length. Unset: the anchors' distance at creation (which must be > 0).
    std::optional<double> length{};
    /// Hz, >= 0: 0 (the default) makes the rod rigid (IM6's soft bias only); above 0 the
    /// distance is held by a spring of this natural frequency for the joint's effective mass.
    double hertz = 0.0;
    double damping_ratio = 0.0;     ///< >= 0: the spring's damping ratio (1: critically damped)
    bool collide_connected = false; ///< as RevoluteJointDef::collide_connected
    double break_force = std::numeric_limits<double>::infinity(); ///< N, > 0, as for revolute
};

/// \srs{DD21} A target joint (a mouse joint): pulls the point of `body` under `target` (as
/// it is at creation) towards the target as a spring-damper, with at most `max_force`. Move
/// the target with World::set_joint_target to drag the body.
struct TargetJointDef {
    BodyId body;                ///< the dragged body (dynamic)
    Vec2d target{};             ///< m, world frame: the target, and the grabbed point of body
    double hertz = 5.0;         ///< Hz, > 0: the spring's natural frequency
    double damping_ratio = 0.7; ///< >= 0: the spring's damping ratio
    /// N, > 0: the largest force the joint applies (infinite: unbounded). A few times the
    /// body's weight drags it firmly without flinging it through walls.
    double max_force = std::numeric_limits<double>::infinity();
};

} // namespace tamias2d
