/// \file
/// The kinds of joint (World::joint_kind), one per joint definition of joint_def.hpp.
#pragma once

#include <cstdint>
#include <string_view>

namespace tamias2d {

/// Which definition a joint was made from.
enum class JointKind : std::uint8_t {
    revolute,  ///< RevoluteJointDef
    distance,  ///< DistanceJointDef
    target,    ///< TargetJointDef
    prismatic, ///< PrismaticJointDef
    weld,      ///< WeldJointDef
    wheel,     ///< WheelJointDef
    motor,     ///< MotorJointDef
    filter     ///< FilterJointDef
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

} // namespace tamias2d
