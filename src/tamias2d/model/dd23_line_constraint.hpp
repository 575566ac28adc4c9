#pragma once
#include <algorithm>

#include "tamias2d/model/dd08_collision_impulse.hpp"
#include "tamias2d/model/dd21_target_constraint.hpp"
#include "tamias2d/model/dd22_angular_constraint.hpp"
#include "tamias2d/model/im6_motion_with_joints.hpp"
#include "tamias2d/units/angle.hpp"
#include "tamias2d/units/vec2.hpp"

namespace tamias2d::model::dd23 {
using namespace tamias2d::units;
using dd08::InverseInertia;
using dd22::AngularImpulse;

/// \srs{DD23} The anchors' separation d = (p_B + r_B) - (p_A + r_A) seen along a unit axis a
/// fixed in body A and along its perpendicular a_perp: the translation s = a . d and the
/// line error C_perp = a_perp . d, with each direction's moment arms. A's arm is taken at the
/// anchor on B, (d + r_A) x n, because the axis turns with A: Cdot = n . (v_B + omega_B x r_B
/// - v_A - omega_A x (d + r_A)) for n = a and for n = a_perp.
struct Line {
    Length translation;            ///< s = a . d
    Length perpendicular;          ///< C_perp = a_perp . d
    Length arm_A, arm_B;           ///< (d + r_A) x a, r_B x a
    Length perp_arm_A, perp_arm_B; ///< (d + r_A) x a_perp, r_B x a_perp
};
inline Line line(Vec2<Length> d, Vec2<Length> r_A, Vec2<Length> r_B, Vec2<double> a) {
    const Vec2<double> p{-a.y, a.x};
    const Vec2<Length> lever_A = d + r_A;
    return {dot(d, a),     dot(d, p),         cross(lever_A, a),
            cross(r_B, a), cross(lever_A, p), cross(r_B, p)};
}

/// \srs{DD23} The impulses (lambda along a_perp, Lambda about z) that stop the line and angle
/// velocity errors together: [k11 k12; k12 k22] (lambda, Lambda) = -(rhs_perp, rhs_angle), with
/// k11 DD8's denominator for the perpendicular arms, k12 = a_A / I_A + a_B / I_B and
/// k22 = 1 / I_A + 1 / I_B; in IM6's soft form (mass_scale, impulse_scale as for DD19). Solved
/// by Cramer's rule: K is positive definite when a body moves (DCX_joint) and can turn. When
/// neither can turn (k22 = 0: fixed rotation, kinematic or static) the angle row holds nothing
/// and K is singular: the line row is solved alone, -rhs_perp / k11, with no angular impulse.
struct BlockImpulse {
    Impulse linear;
    AngularImpulse angular;
};
inline BlockImpulse block_impulse(InverseInertia A, InverseInertia B, Length perp_arm_A,
                                  Length perp_arm_B, Velocity rhs_perp, AngularVelocity rhs_angle,
                                  Dimensionless mass_scale, Dimensionless impulse_scale,
                                  BlockImpulse accumulated) {
    const auto k11 = dd08::effective_mass_inverse(A, B, perp_arm_A, perp_arm_B);
    const auto k12 = A.inv_I * per_radian(perp_arm_A) + B.inv_I * per_radian(perp_arm_B);
    const auto k22 = A.inv_I + B.inv_I;
    if (!(k22 > decltype(k22){}))
        return {im6::soft_impulse(mass_scale, Impulse(-(rhs_perp / k11)), impulse_scale,
                                  accumulated.linear),
                AngularImpulse{}};
    const auto det = k11 * k22 - k12 * k12;
    const Impulse linear = (k22 * rhs_perp - k12 * rhs_angle) / det;
    const AngularImpulse angular = (k11 * rhs_angle - k12 * rhs_perp) / det;
    return {im6::soft_impulse(mass_scale, -linear, impulse_scale, accumulated.linear),
            im6::soft_impulse(mass_scale, -angular, impulse_scale, accumulated.angular)};
}

/// \srs{DD23} The bound F_max h on a motor's impulse along the axis accumulated in a substep h,
/// as DD21 bounds its.
inline Impulse impulse_bound(Force max_force, Time h) {
    return dd21::impulse_bound(max_force, h);
}

/// \srs{DD23} A motor's accumulated impulse along the axis bounded by F_max h: [-max, max].
inline Impulse clamp(Impulse accumulated, Impulse max) {
    return std::clamp(accumulated, -max, max);
}

/// \srs{DD23} The error a prismatic (or wheel, DD25) joint's spring pulls to zero: the
/// translation s against the spring's target s_t (0 unless set), s - s_t.
inline Length spring_error(Length translation, Length target) {
    return translation - target;
}

} // namespace tamias2d::model::dd23
