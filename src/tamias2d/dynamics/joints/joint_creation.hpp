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

/// The fields a definition shares with the joints' run-time setters, as those set them: the
/// spring's target (World::set_joint_spring_target; revolute, prismatic, wheel) and the joint's
/// own soft bias (World::set_constraint_tuning), where the kind's definition has them.
template <class Def> void take_definition_controls(Joint& j, const Def& def) {
    if constexpr (requires { def.spring_target; })
        j.spring_target = def.spring_target;
    if constexpr (requires { def.constraint_tuning; }) {
        if (def.constraint_tuning) {
            j.tuned = true;
            j.tuning_hertz = def.constraint_tuning->hertz;
            j.tuning_damping_ratio = def.constraint_tuning->damping_ratio;
        }
    }
}

} // namespace tamias2d
