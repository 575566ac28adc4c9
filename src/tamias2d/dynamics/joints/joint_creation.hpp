// A joint made from its definition (internal): what every kind's creation shares. Each kind's
// file (revolute_joint.cpp, ...) makes its Joint from its definition (tamias2d/joint_def.hpp)
// beside its solve; the World validates the definition first and stores the result.
#pragma once

#include "tamias2d/dynamics/body.hpp"
#include "tamias2d/dynamics/joints/joint.hpp"

namespace tamias2d {

/// A two-body joint's common fields: the bodies (world indices), one anchor (world frame)
/// fixed on both, the reference angle phi_B - phi_A, the collision choice and the break force.
Joint two_body_joint(JointType type, std::uint32_t index_a, const Body& a, std::uint32_t index_b,
                     const Body& b, Vec2d anchor, bool collide_connected, double break_force);

/// The joint's axis (world frame, validated non-zero) in body A's frame, normalised.
Vec2d local_axis(const Body& a, Vec2d axis);

} // namespace tamias2d
