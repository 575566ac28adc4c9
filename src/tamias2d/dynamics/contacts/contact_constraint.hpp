// One contact manifold prepared for the solver: anchors, effective masses (DD8) and the
// pre-solve normal velocity that restitution (DD12) refers to.
#pragma once

#include <cstdint>

#include "tamias2d/math/vec2d.hpp"

namespace tamias2d {

struct ContactConstraintPoint {
    Vec2d r_a{}, r_b{}; ///< m, anchors relative to the centres of mass
    /// m, moment arms r x n and r x t of the normal and the tangent (DD8), set by preparation:
    /// the solver needs the anchors only through them.
    double normal_arm_a = 0.0, normal_arm_b = 0.0;
    double tangent_arm_a = 0.0, tangent_arm_b = 0.0;
    double base_separation = 0.0;      ///< m, separation minus dot(r_b - r_a, n) at preparation
    double normal_mass = 0.0;          ///< kg, 1 / K (DD8's denominator)
    double tangent_mass = 0.0;         ///< kg
    double normal_impulse = 0.0;       ///< N s, accumulated in the current substep (warm start)
    double tangent_impulse = 0.0;      ///< N s
    double max_normal_impulse = 0.0;   ///< N s, largest seen in the step: did it push at all?
    double total_normal_impulse = 0.0; ///< N s, everything applied over the step
    double total_tangent_impulse = 0.0;
    double relative_velocity = 0.0; ///< m s^-1, normal relative velocity before the step
};

/// A manifold's surface motion (V: double, or a pack of lanes): what DD47's tangent speeds and
/// DD46's rolling resistance add to its solve. Kept apart from the constraint, and solved only
/// in steps where some shape has surface motion, so that a world without any pays nothing.
template <class V> struct SurfaceMotionOver {
    V tangent_speed{};      ///< m s^-1, DD47: the relative tangential velocity friction targets
    V rolling_resistance{}; ///< m, DD46: c l, the bound's factor on the normal impulse
    V rolling_impulse{};    ///< N m s, DD46: accumulated in the current substep (warm start)
};
using SurfaceMotion = SurfaceMotionOver<double>;

struct ContactConstraint {
    std::uint32_t body_a = 0, body_b = 0; ///< solver body indices
    std::uint32_t contact = 0;            ///< index of the persistent contact
    Vec2d normal{};                       ///< unit, from A into B
    double friction = 0.0;
    double restitution = 0.0;
    int count = 0;
    ContactConstraintPoint points[2]{};
    /// The 2x2 matrix K of the two points (DD8 generalised) and its inverse, when well
    /// conditioned: then both points are solved together, exactly.
    double k11 = 0.0, k12 = 0.0, k22 = 0.0;
    double inv_k11 = 0.0, inv_k12 = 0.0, inv_k22 = 0.0;
    bool use_block = false;  ///< the iterations solve the two points as a block
    bool invertible = false; ///< the restitution pass may (a looser condition bound)
    /// DD46, DD47, for the tests' sequential pass (the engine keeps it in the wide solver).
    SurfaceMotion surface{};
};

} // namespace tamias2d
