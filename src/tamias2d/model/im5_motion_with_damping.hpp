#pragma once
#include "tamias2d/model/dd04_linear_acceleration.hpp"
#include "tamias2d/model/dd07_angular_acceleration.hpp"
#include "tamias2d/model/dd17_linear_damping.hpp"
#include "tamias2d/model/dd18_angular_damping.hpp"
#include "tamias2d/units/vec2.hpp"

namespace tamias2d::model::im5 {
using namespace tamias2d::units;

/// \srs{IM5} The ODEs of damped motion: IM1's and IM2's accelerations plus DD17's and DD18's.
inline Vec2<Acceleration> acceleration(Vec2<Acceleration> applied, Rate c_v, Vec2<Velocity> v) {
    return applied + dd17::acceleration(c_v, v);
}
inline AngularAcceleration angular_acceleration(AngularAcceleration applied, Rate c_omega,
                                                AngularVelocity omega) {
    return applied + dd18::angular_acceleration(c_omega, omega);
}

/// \srs{IM5} Backward Euler over a step h of dv/dt = a + s v, whose damping term is linear in
/// v with slope s: v' = (v + a h) / (1 - h s), the factor 1 / (1 - h s). For s <= 0 (damping)
/// the velocity decays monotonically for every h |s|, and a constant acceleration a leads to
/// the ODE's terminal velocity -a / s exactly. Exactly 1 when s = 0 (A6's regime).
inline Dimensionless implicit_factor(Rate slope, Time h) {
    return 1.0 / (1.0 - h * slope);
}

/// \srs{IM5} The slope of DD17's damping acceleration in v, d a_d / d v: a_d is linear in v, so
/// its value at v = 1 m s^-1 (along x) per 1 m s^-1 is the slope, whatever law DD17 states.
inline Rate linear_damping_slope(Rate c_v) {
    const Velocity unit = 1.0 * metre / second;
    return dd17::acceleration(c_v, Vec2<Velocity>{unit, Velocity{}}).x / unit;
}
/// \srs{IM5} The slope of DD18's damping acceleration in omega, d alpha_d / d omega.
inline Rate angular_damping_slope(Rate c_omega) {
    const AngularVelocity unit = 1.0 * radian / second;
    return dd18::angular_acceleration(c_omega, unit) / unit;
}

/// \srs{IM5} The factor of one step of length h for a velocity damped at rate c_v (DD17) and
/// an angular velocity damped at rate c_omega (DD18): 1 / (1 + h c) for the SRS's laws.
inline Dimensionless linear_decay_factor(Rate c_v, Time h) {
    return implicit_factor(linear_damping_slope(c_v), h);
}
inline Dimensionless angular_decay_factor(Rate c_omega, Time h) {
    return implicit_factor(angular_damping_slope(c_omega), h);
}

/// \srs{IM5} One velocity step: v' = (v + a h) / (1 + h c_v), with the factor of
/// linear_decay_factor (computed once per step for every substep). With the factor 1 it is IM1's
/// step (DD4).
inline Vec2<Velocity> velocity_step(Vec2<Velocity> v, Vec2<Acceleration> applied, Time h,
                                    Dimensionless decay) {
    return (v + dd04::velocity_change_over(applied, h)) * decay;
}
/// \srs{IM5} One angular velocity step: omega' = (omega + alpha h) / (1 + h c_omega) (DD7).
inline AngularVelocity angular_velocity_step(AngularVelocity omega, AngularAcceleration applied,
                                             Time h, Dimensionless decay) {
    return (omega + dd07::angular_velocity_change_over(applied, h)) * decay;
}

} // namespace tamias2d::model::im5
