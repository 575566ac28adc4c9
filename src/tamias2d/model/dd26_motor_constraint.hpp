#pragma once
#include "tamias2d/model/dd19_point_constraint.hpp"
#include "tamias2d/model/dd21_target_constraint.hpp"
#include "tamias2d/model/dd22_angular_constraint.hpp"
#include "tamias2d/model/im6_motion_with_joints.hpp"
#include "tamias2d/units/vec2.hpp"

namespace tamias2d::model::dd26 {
using namespace tamias2d::units;
using dd08::InverseInertia;
using dd22::AngularImpulse;

/// \srs{DD26} The velocity asked per unit of error: the share c (the correction factor, in
/// [0, 1]) of the error removed per substep h, c / h. It takes the place of IM6's bias rate.
inline Rate correction_rate(Dimensionless correction, Time h) {
    return correction / h;
}

/// \srs{DD26} The angular row after one iteration: Lambda_acc <- clamp(Lambda_acc - (thetadot +
/// (c/h) C_theta) / k, tau_max h), DD22's rigid impulse on the angle error C_theta against the
/// angular offset, bounded as DD22's motor is.
inline AngularImpulse angular_update(InverseInertia A, InverseInertia B,
                                     AngularVelocity joint_speed, Angle angle_error, Rate rate,
                                     Torque max_torque, Time h, AngularImpulse accumulated) {
    const AngularImpulse lambda =
        dd22::impulse(A, B, im6::biased_velocity_error(joint_speed, rate, angle_error),
                      Dimensionless{1.0}, Dimensionless{}, accumulated);
    return dd22::clamp(accumulated + lambda, dd22::impulse_bound(max_torque, h));
}

/// \srs{DD26} The linear row after one iteration: P_acc <- clamp(P_acc - K^-1 (Cdot + (c/h) C),
/// F_max h), DD19's rigid impulse between A's point at the offset and B's origin (its anchors
/// r_A, r_B, velocity error Cdot and position error C), bounded as DD21 bounds its.
inline Vec2<Impulse> linear_update(InverseInertia A, InverseInertia B, Vec2<Length> r_A,
                                   Vec2<Length> r_B, Vec2<Velocity> velocity_error,
                                   Vec2<Length> position_error, Rate rate, Force max_force, Time h,
                                   Vec2<Impulse> accumulated) {
    const Vec2<Impulse> P =
        dd19::impulse(dd19::effective_mass_inverse(A, B, r_A, r_B),
                      im6::biased_velocity_error(velocity_error, rate, position_error),
                      Dimensionless{1.0}, Dimensionless{}, accumulated);
    return dd21::clamp(accumulated + P, dd21::impulse_bound(max_force, h));
}

} // namespace tamias2d::model::dd26
