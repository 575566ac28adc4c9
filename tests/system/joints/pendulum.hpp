// The pendulum rig of the joint tests: a disc pinned by a revolute joint to a static body at
// the origin, and the constants it and the distance joint's rod pendulum share.
#pragma once

#include <cmath>

#include "tamias2d/world.hpp"

namespace tamias2d::system_test::pendulum {

inline constexpr double g = 9.81, l = 1.0, bob_radius = 0.05;

/// A physical pendulum: a small disc pinned at the origin to a static body, released from rest
/// at angle theta0 from the downward vertical. joint_hertz 1e9 asks for the stiffest joint the
/// soft step allows, a quarter of the substep rate, so that the joint's compliance shrinks
/// with the step (IM6) and the comparison measures convergence.
struct Pendulum {
    World world;
    BodyId bob;
    JointId joint;
    double m = 0.0, I_pivot = 0.0;
    explicit Pendulum(double theta0, double joint_hertz = 1e9, double break_force = INFINITY)
        : world(WorldDef{.gravity = {0.0, -g}, .joint_hertz = joint_hertz}) {
        BodyDef ground_def;
        ground_def.type = BodyType::static_body;
        const BodyId ground = world.create_body(ground_def);
        BodyDef bob_def;
        bob_def.position = {l * std::sin(theta0), -l * std::cos(theta0)};
        bob = world.create_body(bob_def);
        world.create_shape(bob, circle_shape(bob_radius));
        joint = world.create_joint(RevoluteJointDef{
            .body_a = ground, .body_b = bob, .anchor = {0.0, 0.0}, .break_force = break_force});
        m = world.mass(bob);
        I_pivot = world.inertia(bob) + m * l * l; // parallel axes (DD14)
    }
    double angle() const {
        const Vec2d p = world.position(bob);
        return std::atan2(p.x, -p.y);
    }
};

} // namespace tamias2d::system_test::pendulum
