// A joint as the world stores it (internal). Public access goes through World and JointId.
// One record serves every kind; each kind's file (revolute_joint.cpp, ...) reads the fields
// its definition (tamias2d/joint_def.hpp) sets.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <type_traits>

#include "tamias2d/dynamics/softness.hpp"
#include "tamias2d/joint_kind.hpp"
#include "tamias2d/math/vec2d.hpp"
#include "tamias2d/user_data.hpp"

namespace tamias2d {

using JointType = JointKind; // the engine's name for the public kinds (joint_kind.hpp)

/// The part of a joint that a step writes: the impulses (the warm start of the next substep and
/// the reaction force) and the step's preparation. The World keeps a copy of this part alone to
/// refuse a diverged step (the rest of a Joint is its definition, which only the World's
/// setters change).
struct JointStepState {
    /// N s: the impulse accumulated over the last substep's iterations, the warm start of the
    /// next; over the substep length it is the reaction force (IM6).
    Vec2d linear_impulse{};
    // The impulse along the axis (N s: a distance joint's rod or spring) and the axis of the
    // last solve (for the reaction force).
    double axial_impulse = 0.0;
    Vec2d axis{1.0, 0.0};
    // The motor's and the limits' impulses in the last substep (N m s, or N s along an axis).
    double motor_impulse = 0.0, lower_impulse = 0.0, upper_impulse = 0.0;
    double spring_impulse = 0.0;  ///< N s or N m s: a spring's along the axis or about z
    double angular_impulse = 0.0; ///< N m s: the angle held (prismatic, weld, motor joint)
    double perp_impulse = 0.0;    ///< N s: the line held (prismatic, wheel)

    // Set by the step's preparation (joint_solver.hpp).
    std::uint32_t solver_a = 0, solver_b = 0; ///< solver bodies (0: immovable this step)
    Vec2d frame_a{}, frame_b{};               ///< m, the pin from each centre, body frame
    double angle_a = 0.0, angle_b = 0.0;      ///< rad, the bodies' angles at the step's start
    Vec2d center_offset{};                    ///< m, p_B - p_A at the step's start
    Vec2d center_b{};                         ///< m, p_B at the step's start
    /// The bodies' rotations now, angle at the step's start plus the turn dq made since, as the
    /// write-back will place them: the step solver updates them after each position half, one
    /// cosine and sine per body rather than per joint and pass.
    Rot q_a{}, q_b{};
    /// The joint's own soft bias for this step (Joint::tuned), set by the step solver.
    Softness tuning{};
};

struct Joint {
    JointType type = JointType::revolute;
    bool collide_connected = false;
    std::uint32_t body_a = 0, body_b = 0;     ///< world body indices
    Vec2d local_anchor_a{}, local_anchor_b{}; ///< m, the pin in each body's frame (from origin)
    double break_force = std::numeric_limits<double>::infinity(); ///< N
    /// N and N m: above these the joint is reported (World::joint_events); infinite: never.
    double force_threshold = std::numeric_limits<double>::infinity();
    double torque_threshold = std::numeric_limits<double>::infinity();
    // A spring (distance, target, revolute, prismatic, wheel; a weld's linear part): hertz 0
    // is rigid (distance, weld) or no spring. A distance joint's rest length.
    double length = 0.0, hertz = 0.0, damping_ratio = 0.0;
    bool enable_spring = false;
    // Prismatic and wheel joints: the axis in A's frame.
    Vec2d local_axis{1.0, 0.0};
    // The reference angle phi_B - phi_A at creation (DD22, DD23, DD24; a motor joint's
    // angular offset).
    double reference_angle = 0.0;
    bool enable_limit = false, enable_motor = false;
    /// Limits: rad (revolute), m (prismatic and wheel translation, distance length).
    double lower_limit = 0.0, upper_limit = 0.0;
    /// Motor: rad s^-1 and N m (revolute, wheel), m s^-1 and N (prismatic).
    double motor_speed = 0.0, max_motor = 0.0;
    // A weld's angular spring (hertz 0: rigid).
    double angular_hertz = 0.0, angular_damping_ratio = 0.0;
    // Target joints (DD21): one body (body_a = body_b), the target, the spring, the force limit.
    // Motor joints (DD26): max_force, max_torque and the correction factor.
    Vec2d target{};
    double max_force = std::numeric_limits<double>::infinity();
    double max_torque = 0.0, correction_factor = 0.0;
    // Set after creation (World's joint_control calls): the value a revolute, prismatic or
    // wheel joint's spring pulls the angle (rad) or translation (m) to; the torque (N m) above
    // which the joint breaks (DD36); the joint's own soft bias (DD37) in place of the world's.
    double spring_target = 0.0;
    double break_torque = std::numeric_limits<double>::infinity();
    bool tuned = false;
    double tuning_hertz = 0.0, tuning_damping_ratio = 0.0;

    UserData user_data = 0; ///< the game's own value: never hashed, never read

    JointStepState step; ///< what a step writes (copied by value to refuse a diverged step)
};

static_assert(std::is_standard_layout_v<Joint> && std::is_trivially_copyable_v<Joint>);

/// The angular impulse (N m s) the joint's angular parts (motor, limits, spring, held angle)
/// applied to body B in the last substep: over the substep's length, its reaction torque.
inline double reaction_angular_impulse(const Joint& j) {
    switch (j.type) {
    case JointType::revolute:
        return j.step.motor_impulse + j.step.lower_impulse - j.step.upper_impulse +
               j.step.spring_impulse;
    case JointType::prismatic:
    case JointType::weld:
    case JointType::motor:
        return j.step.angular_impulse;
    case JointType::wheel:
        return j.step.motor_impulse;
    case JointType::distance:
    case JointType::target:
    case JointType::filter:
        return 0.0;
    }
    return 0.0;
}

/// A distance joint's impulse along its axis in the last substep (N s): the rod's or spring's,
/// the limits', and the motor's while it is enabled (DD35).
inline double distance_axial_impulse(const Joint& j) {
    const double held = j.step.axial_impulse + j.step.lower_impulse - j.step.upper_impulse;
    return j.enable_motor ? held + j.step.motor_impulse : held;
}

/// The impulse (N s) the joint applied to body B in the last substep: over the substep's
/// length, its reaction force.
inline Vec2d reaction_impulse(const Joint& j) {
    switch (j.type) {
    case JointType::distance:
        return distance_axial_impulse(j) * j.step.axis;
    case JointType::prismatic:
        return j.step.perp_impulse * left_perp(j.step.axis) +
               (j.step.spring_impulse + j.step.motor_impulse + j.step.lower_impulse -
                j.step.upper_impulse) *
                   j.step.axis;
    case JointType::wheel:
        return j.step.perp_impulse * left_perp(j.step.axis) +
               (j.step.spring_impulse + j.step.lower_impulse - j.step.upper_impulse) * j.step.axis;
    case JointType::revolute:
    case JointType::target:
    case JointType::weld:
    case JointType::motor:
    case JointType::filter: // (zero: a filter joint is never solved)
        return j.step.linear_impulse;
    }
    return j.step.linear_impulse;
}

} // namespace tamias2d
