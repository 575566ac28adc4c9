// A joint as the world stores it (internal). Public access goes through World and JointId.
#pragma once

#include <cstdint>
#include <limits>

#include "tamias2d/math/vec2d.hpp"

namespace tamias2d {

enum class JointType : std::uint8_t { revolute, distance, target };

struct Joint {
    JointType type = JointType::revolute;
    bool alive = false;
    bool collide_connected = false;
    std::uint32_t generation = 0;
    std::uint32_t body_a = 0, body_b = 0;     ///< world body indices
    Vec2d local_anchor_a{}, local_anchor_b{}; ///< m, the pin in each body's frame (from origin)
    double break_force = std::numeric_limits<double>::infinity(); ///< N
    /// N s: the impulse accumulated over the last substep's iterations, the warm start of the
    /// next; over the substep length it is the reaction force (IM6).
    Vec2d linear_impulse{};
    // Distance joints (DD20): rest length, spring (hertz 0: rigid), the impulse along the axis
    // (N s, as linear_impulse) and the axis of the last solve (for the reaction force).
    double length = 0.0, hertz = 0.0, damping_ratio = 0.0;
    double axial_impulse = 0.0;
    Vec2d axis{1.0, 0.0};
    // Revolute motor and limits (DD22): the reference angle phi_B - phi_A at creation, and
    // the angular impulses (N m s) accumulated in the last substep.
    double reference_angle = 0.0;
    bool enable_limit = false, enable_motor = false;
    double lower_angle = 0.0, upper_angle = 0.0, motor_speed = 0.0, max_motor_torque = 0.0;
    double motor_impulse = 0.0, lower_impulse = 0.0, upper_impulse = 0.0;
    // Target joints (DD21): one body (body_a = body_b), the target, the spring, the force limit.
    Vec2d target{};
    double max_force = std::numeric_limits<double>::infinity();

    // Set by the step's preparation (revolute_joint.hpp).
    std::uint32_t solver_a = 0, solver_b = 0; ///< solver bodies (0: immovable this step)
    Vec2d frame_a{}, frame_b{};               ///< m, the pin from each centre, body frame
    double angle_a = 0.0, angle_b = 0.0;      ///< rad, the bodies' angles at the step's start
    Vec2d center_offset{};                    ///< m, p_B - p_A at the step's start
    Vec2d center_b{};                         ///< m, p_B at the step's start
};

/// The angular impulse (N m s) the joint's motor and limits applied to body B in the last
/// substep: over the substep's length, its reaction torque.
inline double reaction_angular_impulse(const Joint& j) {
    return j.motor_impulse + j.lower_impulse - j.upper_impulse;
}

/// The impulse (N s) the joint applied to body B in the last substep: over the substep's
/// length, its reaction force.
inline Vec2d reaction_impulse(const Joint& j) {
    return j.type == JointType::distance ? j.axial_impulse * j.axis : j.linear_impulse;
}

} // namespace tamias2d
