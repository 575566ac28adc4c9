/// \file
/// The kind of a joint (World::joint_kind), one per definition of joint_def.hpp.
#pragma once

#include <cstdint>
#include <string_view>

namespace tamias2d {

/// Which definition a joint was made from: RevoluteJointDef gives `revolute`, and so on.
enum class JointKind : std::uint8_t {
    revolute,  ///< RevoluteJointDef (DD19, DD22)
    distance,  ///< DistanceJointDef (DD20)
    target,    ///< TargetJointDef (DD21)
    prismatic, ///< PrismaticJointDef (DD23)
    weld,      ///< WeldJointDef (DD24)
    wheel,     ///< WheelJointDef (DD25)
    motor,     ///< MotorJointDef (DD26)
    filter     ///< FilterJointDef (DD27)
};

/// A joint kind's name as messages spell it ("revolute", ...); "" outside the enumeration.
constexpr std::string_view to_string(JointKind kind) noexcept {
    switch (kind) {
    case JointKind::revolute:
        return "revolute";
    case JointKind::distance:
        return "distance";
    case JointKind::target:
        return "target";
    case JointKind::prismatic:
        return "prismatic";
    case JointKind::weld:
        return "weld";
    case JointKind::wheel:
        return "wheel";
    case JointKind::motor:
        return "motor";
    case JointKind::filter:
        return "filter";
    }
    return "";
}

/// A joint's limits (World::joint_limits): rad for a revolute joint's angle, m for a prismatic
/// or wheel joint's translation and a distance joint's length.
struct JointLimits {
    double lower = 0.0; ///< rad or m
    double upper = 0.0; ///< rad or m, >= lower
    /// Field by field.
    friend bool operator==(const JointLimits&, const JointLimits&) = default;
};

/// A soft constraint's stiffness and damping (World::set_constraint_tuning): the spring-damper
/// that pulls a joint's position error back (IM6).
struct ConstraintTuning {
    double hertz = 0.0;         ///< Hz, > 0
    double damping_ratio = 0.0; ///< > 0 (1: critically damped)
    /// Field by field.
    friend bool operator==(const ConstraintTuning&, const ConstraintTuning&) = default;
};

} // namespace tamias2d
