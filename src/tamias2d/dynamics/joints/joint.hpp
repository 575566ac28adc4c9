// A joint as the world stores it (internal). Public access goes through World and JointId.
// One record serves every kind; each kind's file (revolute_joint.cpp, ...) reads the fields
// its definition (tamias2d/joint_def.hpp) sets.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <type_traits>

#include "tamias2d/joint_kind.hpp"
#include "tamias2d/math/vec2d.hpp"
#include "tamias2d/user_data.hpp"

namespace tamias2d {

using JointType = JointKind; // the engine's name for the public kinds (joint_kind.hpp)

/// The part of a joint that a step writes: the impulses (the warm start of the next substep and
/// step, and the reaction force) and the axis of the last solve. A step solves a copy of it in
/// the joint's JointSim and writes the copy back only once the step is accepted, so that a
/// refused step leaves the joint as it was.
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
};

/// The impulses forgotten (warm starting off, or a body's joints cleared): the axis is kept.
inline void forget_impulses(JointStepState& st) {
    st.linear_impulse = {};
    st.axial_impulse = st.motor_impulse = st.lower_impulse = st.upper_impulse = 0.0;
    st.spring_impulse = st.angular_impulse = st.perp_impulse = 0.0;
}

/// Laid out for the step: the first line holds what every step reads of every joint (the
/// kind, the switches, the bodies, the anchors, the break thresholds), the next two the
/// impulses a step starts from and the reference angle (JointSim takes them), the rest the
/// definition a kind reads only for a part that is enabled.
struct alignas(64) Joint {
    JointType type = JointType::revolute;
    bool collide_connected = false;
    bool enable_spring = false, enable_limit = false, enable_motor = false;
    /// The joint's own soft bias (DD37: tuning_hertz, tuning_damping_ratio) in place of the
    /// world's.
    bool tuned = false;
    std::uint32_t body_a = 0, body_b = 0;     ///< world body indices
    Vec2d local_anchor_a{}, local_anchor_b{}; ///< m, the pin in each body's frame (from origin)
    /// N and N m: above these the joint breaks (DD36); infinite: never.
    double break_force = std::numeric_limits<double>::infinity();
    double break_torque = std::numeric_limits<double>::infinity();

    JointStepState step; ///< what an accepted step wrote
    // The reference angle phi_B - phi_A at creation (DD22, DD23, DD24; a motor joint's
    // angular offset).
    double reference_angle = 0.0;

    /// N and N m: above these the joint is reported (World::joint_events); infinite: never.
    double force_threshold = std::numeric_limits<double>::infinity();
    double torque_threshold = std::numeric_limits<double>::infinity();
    // A spring (distance, target, revolute, prismatic, wheel; a weld's linear part): hertz 0
    // is rigid (distance, weld) or no spring. A distance joint's rest length.
    double length = 0.0, hertz = 0.0, damping_ratio = 0.0;
    // Prismatic and wheel joints: the axis in A's frame.
    Vec2d local_axis{1.0, 0.0};
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
    // wheel joint's spring pulls the angle (rad) or translation (m) to, and the tuning.
    double spring_target = 0.0;
    double tuning_hertz = 0.0, tuning_damping_ratio = 0.0;

    UserData user_data = 0; ///< the game's own value: never hashed, never read
};

static_assert(std::is_standard_layout_v<Joint> && std::is_trivially_copyable_v<Joint>);
static_assert(offsetof(Joint, step) == 64 && offsetof(Joint, reference_angle) < 192,
              "the break thresholds in the first line, the impulses in the next two");

/// \srs{DD22} The angular impulse (N m s) the joint's angular parts (motor, limits, spring,
/// held angle) applied to body B in the last substep (`st`: the joint's step state or its copy
/// in a step): over the substep's length, its reaction torque (World::joint_reaction_torque).
/// A distance, target or filter joint has no angular part.
inline double reaction_angular_impulse(JointType type, const JointStepState& st) {
    switch (type) {
    case JointType::revolute:
        return st.motor_impulse + st.lower_impulse - st.upper_impulse + st.spring_impulse;
    case JointType::prismatic:
    case JointType::weld:
    case JointType::motor:
        return st.angular_impulse;
    case JointType::wheel:
        return st.motor_impulse;
    case JointType::distance:
    case JointType::target:
    case JointType::filter:
        return 0.0;
    }
    return 0.0;
}

/// \srs{DD20, DD35} A distance joint's impulse along its axis in the last substep (N s): the
/// rod's or spring's and the limits' (DD20), and the motor's while it is enabled (DD35).
inline double distance_axial_impulse(const Joint& j, const JointStepState& st) {
    const double held = st.axial_impulse + st.lower_impulse - st.upper_impulse;
    return j.enable_motor ? held + st.motor_impulse : held;
}

inline double reaction_angular_impulse(const Joint& j) {
    return reaction_angular_impulse(j.type, j.step);
}
inline double distance_axial_impulse(const Joint& j) {
    return distance_axial_impulse(j, j.step);
}

/// \srs{DD20, DD23, DD25} The impulse (N s) the joint applied to body B in the last substep:
/// over the substep's length, its reaction force. The distance, prismatic and wheel joints'
/// parts along and across their axes are summed here (DD20, DD23, DD25); the other kinds keep
/// theirs as one linear impulse.
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
