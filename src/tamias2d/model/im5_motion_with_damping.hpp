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

/// \srs{IM5} The factor 1 / (1 + h c) by which one integration step of length h scales a
/// velocity damped at rate c: damping integrated implicitly (backward Euler), so that the
/// velocity decays monotonically for every h c and a constant acceleration a leads to the
/// ODE's terminal velocity a / c exactly. Exactly 1 when c = 0 (A6's regime).
inline Dimensionless decay_factor(Rate c, Time h) {
    return 1.0 / (1.0 + c * h);
}

/// \srs{IM5} One velocity step: v' = (v + a h) / (1 + h c_v), with the factor of decay_factor
/// (computed once per step for every substep). With the factor 1 it is IM1's step (DD4).
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
