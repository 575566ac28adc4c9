/// \file
/// Joints (SRS LC3, relaxing A7): constraints between two bodies. Every field is in SI units,
/// stated beside it.
#pragma once

#include <limits>

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
};

} // namespace tamias2d
