// A body's motion over a substep: IM1 and IM2 (with T1, T4, DD3, DD4, DD6, DD7) and IM5's
// damped velocity step.
#pragma once

#include "tamias2d/dynamics/bridge/typing.hpp"
#include "tamias2d/model/dd03_linear_velocity.hpp"
#include "tamias2d/model/dd04_linear_acceleration.hpp"
#include "tamias2d/model/dd06_angular_velocity.hpp"
#include "tamias2d/model/dd07_angular_acceleration.hpp"
#include "tamias2d/model/im1_translational_motion.hpp"
#include "tamias2d/model/im2_rotational_motion.hpp"
#include "tamias2d/model/im5_motion_with_damping.hpp"

namespace tamias2d::bridge {

/// IM1's acceleration g + F / m (m s^-2).
inline Vec2d acceleration(Vec2d g, Vec2d force, double mass) {
    return plain(m::im1::acceleration(typed<u::Acceleration>(g), typed<u::Force>(force),
                                      u::from_value<u::Mass>(mass)));
}
/// IM2's angular acceleration tau / I (rad s^-2).
inline double angular_acceleration(double torque, double inertia) {
    return m::im2::angular_acceleration(u::from_value<u::Torque>(torque),
                                        u::from_value<u::MomentOfInertia>(inertia))
        .value();
}
/// IM1's velocity half over a substep: v + a h (DD4).
inline Vec2d velocity_half(Vec2d v, Vec2d a, double h) {
    return plain(m::im1::velocity_half(typed<u::Velocity>(v), typed<u::Acceleration>(a),
                                       u::from_value<u::Time>(h)));
}
/// IM2's velocity half over a substep: omega + alpha h (DD7).
inline double angular_velocity_half(double w, double alpha, double h) {
    return m::im2::velocity_half(u::from_value<u::AngularVelocity>(w),
                                 u::from_value<u::AngularAcceleration>(alpha),
                                 u::from_value<u::Time>(h))
        .value();
}
/// IM1's position half over a substep: p + v h with the new velocity (DD3).
inline Vec2d position_half(Vec2d p, Vec2d v, double h) {
    return plain(m::im1::position_half(typed<u::Length>(p), typed<u::Velocity>(v),
                                       u::from_value<u::Time>(h)));
}
/// IM2's position half over a substep: phi + omega h with the new angular velocity (DD6).
inline double angle_half(double phi, double w, double h) {
    return m::im2::position_half(u::from_value<u::Angle>(phi), u::from_value<u::AngularVelocity>(w),
                                 u::from_value<u::Time>(h))
        .value();
}
/// DD4 over a substep: dv = a h.
inline Vec2d velocity_change(Vec2d a, double h) {
    return plain(
        m::dd04::velocity_change_over(typed<u::Acceleration>(a), u::from_value<u::Time>(h)));
}
/// DD7 over a substep: d omega = alpha h.
inline double angular_velocity_change(double alpha, double h) {
    return m::dd07::angular_velocity_change_over(u::from_value<u::AngularAcceleration>(alpha),
                                                 u::from_value<u::Time>(h))
        .value();
}
/// IM5's decay factor 1 / (1 + h c) over a substep h of a velocity damped at rate c (s^-1) by
/// DD17's law, backward Euler of DD17's acceleration.
inline double linear_decay_factor(double rate, double h) {
    return m::im5::linear_decay_factor(u::from_value<u::Rate>(rate), u::from_value<u::Time>(h))
        .value();
}
/// The same for an angular velocity damped by DD18's law.
inline double angular_decay_factor(double rate, double h) {
    return m::im5::angular_decay_factor(u::from_value<u::Rate>(rate), u::from_value<u::Time>(h))
        .value();
}
/// IM5 over a substep: v' = (v + a h) f, with f from linear_decay_factor (1: IM1's DD4 step).
inline Vec2d velocity_step(Vec2d v, Vec2d a, double h, double decay) {
    return plain(m::im5::velocity_step(typed<u::Velocity>(v), typed<u::Acceleration>(a),
                                       u::from_value<u::Time>(h),
                                       u::from_value<u::Dimensionless>(decay)));
}
/// IM5 over a substep: omega' = (omega + alpha h) f (1: IM2's DD7 step).
inline double angular_velocity_step(double w, double alpha, double h, double decay) {
    return m::im5::angular_velocity_step(
               u::from_value<u::AngularVelocity>(w), u::from_value<u::AngularAcceleration>(alpha),
               u::from_value<u::Time>(h), u::from_value<u::Dimensionless>(decay))
        .value();
}
/// DD3 over a substep: dp = v h.
inline Vec2d displacement(Vec2d v, double h) {
    return plain(m::dd03::displacement_over(typed<u::Velocity>(v), u::from_value<u::Time>(h)));
}
/// DD6 over a substep: d phi = omega h.
inline double rotation(double w, double h) {
    return m::dd06::angle_over(u::from_value<u::AngularVelocity>(w), u::from_value<u::Time>(h))
        .value();
}

} // namespace tamias2d::bridge
