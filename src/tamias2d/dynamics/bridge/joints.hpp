// The joints' solves: IM6's soft form, its impulse bounds and limits (DD21-DD23, IM7), and each
// constraint's errors and impulses (DD19-DD26, DD35), on one pair of solver bodies or, for the
// pin, on a pack of pairs (joints/pin_packs.hpp: Body is WideBody, V Wide).
#pragma once

#include <limits>
#include <utility>

#include "tamias2d/dynamics/bridge/point_impulse.hpp"
#include "tamias2d/dynamics/softness.hpp"
#include "tamias2d/dynamics/solver_body.hpp"
#include "tamias2d/model/dd19_point_constraint.hpp"
#include "tamias2d/model/dd20_distance_constraint.hpp"
#include "tamias2d/model/dd21_target_constraint.hpp"
#include "tamias2d/model/dd22_angular_constraint.hpp"
#include "tamias2d/model/dd23_line_constraint.hpp"
#include "tamias2d/model/dd24_weld_constraint.hpp"
#include "tamias2d/model/dd25_wheel_constraint.hpp"
#include "tamias2d/model/dd26_motor_constraint.hpp"
#include "tamias2d/model/dd35_distance_joint_motor.hpp"
#include "tamias2d/model/im6_motion_with_joints.hpp"
#include "tamias2d/model/im7_soft_contact.hpp"

namespace tamias2d::bridge {

// IM6, the joints' soft form, and their bounds (DD10, DD22).

/// IM6's biased velocity error Cdot + beta C of a point (m s^-1, m).
template <class V>
inline Vec2<V> biased_error(Vec2<V> velocity_error, V bias_rate, Vec2<V> position_error) {
    return plain_vec(m::im6::biased_velocity_error(typed_vec<u::Velocity>(velocity_error),
                                                   typed_value<u::Rate>(bias_rate),
                                                   typed_vec<u::Length>(position_error)));
}
/// The same along one direction (m s^-1, m).
inline double biased_error(double velocity_error, double bias_rate, double position_error) {
    return m::im6::biased_velocity_error(u::from_value<u::Velocity>(velocity_error),
                                         u::from_value<u::Rate>(bias_rate),
                                         u::from_value<u::Length>(position_error))
        .value();
}
/// The same for an angle (rad s^-1, rad).
inline double biased_angular_error(double speed, double bias_rate, double angle_error) {
    return m::im6::biased_velocity_error(u::from_value<u::AngularVelocity>(speed),
                                         u::from_value<u::Rate>(bias_rate),
                                         u::from_value<u::Angle>(angle_error))
        .value();
}

/// DD21's bound F_max h on a joint's impulse accumulated in a substep h (N s), and DD23's (the
/// same).
inline double force_impulse_bound(double max_force, double h) {
    return m::dd21::impulse_bound(u::from_value<u::Force>(max_force), u::from_value<u::Time>(h))
        .value();
}
inline double axial_force_impulse_bound(double max_force, double h) {
    return m::dd23::impulse_bound(u::from_value<u::Force>(max_force), u::from_value<u::Time>(h))
        .value();
}
/// DD22's bound tau_max h on a motor's angular impulse accumulated in a substep h (N m s).
inline double torque_impulse_bound(double max_torque, double h) {
    return m::dd22::impulse_bound(u::from_value<u::Torque>(max_torque), u::from_value<u::Time>(h))
        .value();
}

/// IM7's target, as a joint's one-sided limit takes it: the limit `c` (>= 0 inside) ahead of
/// the bound closes within the substep h (speculative), a bound passed is pulled back at the
/// softness' bias rate (soft) or held (the relax, soft false); no slop, no cap. c and the
/// target are a length and a velocity (m, m s^-1) or an angle and an angular velocity.
struct LimitTarget {
    double velocity = 0.0, mass_scale = 1.0, impulse_scale = 0.0;
};
template <class Gap>
inline LimitTarget limit_target(double c, const Softness& softness, double h, bool soft) {
    using Vel = decltype(Gap{} / u::Time{});
    const Gap gap = Gap::from_value(c), none{};
    const Vel uncapped = Vel::from_value(std::numeric_limits<double>::infinity());
    const u::Time step = u::from_value<u::Time>(h);
    const u::Rate rate = u::from_value<u::Rate>(softness.bias_rate);
    const auto t = soft ? m::im7::target_velocity<true>(gap, step, rate, softness.mass_scale,
                                                        softness.impulse_scale, none, uncapped)
                        : m::im7::target_velocity<false>(gap, step, rate, softness.mass_scale,
                                                         softness.impulse_scale, none, uncapped);
    return {t.velocity.value(), t.mass_scale, t.impulse_scale};
}

// DD19, the revolute joint's pin, on one pair of solver bodies, or on four pairs at once (a
// pack of plain pins, joints/pin_packs.hpp: Body is WideBody, V Wide).

/// DD19's position error C (m): centres' offset plus the pin's offsets r_b - r_a.
template <class V>
inline Vec2<V> pin_position_error(Vec2<V> center_offset, Vec2<V> r_a, Vec2<V> r_b) {
    return plain_vec(m::dd19::position_error(typed_vec<u::Length>(center_offset),
                                             typed_vec<u::Length>(r_a), typed_vec<u::Length>(r_b)));
}
/// DD19's velocity error Cdot (m s^-1).
template <class Body, class V = value_of<Body>>
inline Vec2<V> pin_velocity_error(const Body& a, Vec2<V> r_a, const Body& b, Vec2<V> r_b) {
    return plain_vec(m::dd19::velocity_error(velocities(a), typed_vec<u::Length>(r_a),
                                             velocities(b), typed_vec<u::Length>(r_b)));
}
/// DD19's impulse (N s) in IM6's soft form, K from the bodies and the pin's offsets.
template <class Body, class V = value_of<Body>>
inline Vec2<V> pin_impulse(const Body& a, Vec2<V> r_a, const Body& b, Vec2<V> r_b, Vec2<V> rhs,
                           V mass_scale, V impulse_scale, Vec2<V> accumulated) {
    const m::dd19::PinMassOver<V> K =
        m::dd19::effective_mass_inverse(inverse_inertia(a), inverse_inertia(b),
                                        typed_vec<u::Length>(r_a), typed_vec<u::Length>(r_b));
    return plain_vec(m::dd19::impulse(
        K, typed_vec<u::Velocity>(rhs), typed_value<u::Dimensionless>(mass_scale),
        typed_value<u::Dimensionless>(impulse_scale), typed_vec<u::Impulse>(accumulated)));
}
/// DD19: P on b at the pin, -P on a.
template <class Body, class V = value_of<Body>>
inline void apply_pin_impulse(Body& a, Vec2<V> r_a, Body& b, Vec2<V> r_b, Vec2<V> P) {
    m::im3::VelocitiesOver<V> va = velocities(a);
    m::im3::VelocitiesOver<V> vb = velocities(b);
    m::dd19::apply(va, vb, inverse_inertia(a), inverse_inertia(b), typed_vec<u::Length>(r_a),
                   typed_vec<u::Length>(r_b), typed_vec<u::Impulse>(P));
    a.v = plain_vec(va.v);
    a.w = va.omega.value();
    b.v = plain_vec(vb.v);
    b.w = vb.omega.value();
}

// DD20, the distance joint's axis, on one pair of solver bodies.

/// DD20's axis of the anchors' separation d (m): its length and unit direction.
inline void distance_axis(Vec2d d, double& length, Vec2d& n) {
    const m::dd20::Axis a = m::dd20::axis(typed<u::Length>(d));
    length = a.length.value();
    n = {a.n.x, a.n.y};
}
/// DD20's position error |d| - L (m).
inline double distance_position_error(double length, double rest_length) {
    return m::dd20::position_error({u::from_value<u::Length>(length), {1.0, 0.0}},
                                   u::from_value<u::Length>(rest_length))
        .value();
}
/// DD20's velocity error along n (m s^-1), from the anchors' moment arms r x n.
inline double axial_velocity_error(const SolverBody& a, double arm_a, const SolverBody& b,
                                   double arm_b, Vec2d n) {
    return m::dd20::velocity_error(velocities(a), u::from_value<u::Length>(arm_a), velocities(b),
                                   u::from_value<u::Length>(arm_b), {n.x, n.y})
        .value();
}
/// DD20's impulse along n (N s) in IM6's soft form.
inline double axial_impulse(const SolverBody& a, double arm_a, const SolverBody& b, double arm_b,
                            double rhs, double mass_scale, double impulse_scale,
                            double accumulated) {
    return m::dd20::impulse(inverse_inertia(a), inverse_inertia(b), u::from_value<u::Length>(arm_a),
                            u::from_value<u::Length>(arm_b), u::from_value<u::Velocity>(rhs),
                            u::from_value<u::Dimensionless>(mass_scale),
                            u::from_value<u::Dimensionless>(impulse_scale),
                            u::from_value<u::Impulse>(accumulated))
        .value();
}
/// DD20: lambda n on b at its anchor, -lambda n on a.
inline void apply_axial_impulse(SolverBody& a, double arm_a, SolverBody& b, double arm_b, Vec2d n,
                                double lambda) {
    m::im3::Velocities va = velocities(a);
    m::im3::Velocities vb = velocities(b);
    m::dd20::apply(va, vb, inverse_inertia(a), inverse_inertia(b), u::from_value<u::Length>(arm_a),
                   u::from_value<u::Length>(arm_b), {n.x, n.y}, u::from_value<u::Impulse>(lambda));
    a.v = plain(va.v);
    a.w = va.omega.value();
    b.v = plain(vb.v);
    b.w = vb.omega.value();
}

// DD21, the target joint.

/// DD21's position error (m): the grabbed point (centre plus offset) minus the target.
inline Vec2d target_position_error(Vec2d center, Vec2d r, Vec2d target) {
    return plain(m::dd21::position_error(typed<u::Length>(center), typed<u::Length>(r),
                                         typed<u::Length>(target)));
}
/// DD21's clamp of the accumulated impulse (N s) to max_impulse.
inline Vec2d clamp_impulse(Vec2d accumulated, double max_impulse) {
    return plain(
        m::dd21::clamp(typed<u::Impulse>(accumulated), u::from_value<u::Impulse>(max_impulse)));
}

// DD22, a revolute joint's motor and limits.

/// DD22's joint angle (rad).
inline double joint_angle(double phi_a, double phi_b, double reference) {
    return m::dd22::joint_angle(u::from_value<u::Angle>(phi_a), u::from_value<u::Angle>(phi_b),
                                u::from_value<u::Angle>(reference))
        .value();
}
/// DD22's joint speed (rad s^-1).
inline double joint_speed(const SolverBody& a, const SolverBody& b) {
    return m::dd22::joint_speed(velocities(a), velocities(b)).value();
}
/// DD22's angular impulse (N m s) in IM6's soft form.
inline double angular_impulse(const SolverBody& a, const SolverBody& b, double rhs,
                              double mass_scale, double impulse_scale, double accumulated) {
    return m::dd22::impulse(inverse_inertia(a), inverse_inertia(b),
                            u::from_value<u::AngularVelocity>(rhs),
                            u::from_value<u::Dimensionless>(mass_scale),
                            u::from_value<u::Dimensionless>(impulse_scale),
                            m::dd22::AngularImpulse::from_value(accumulated))
        .value();
}
/// DD22's motor clamp to [-max, max] (N m s).
inline double clamp_angular_impulse(double accumulated, double max) {
    return m::dd22::clamp(m::dd22::AngularImpulse::from_value(accumulated),
                          m::dd22::AngularImpulse::from_value(max))
        .value();
}
/// DD22: +lambda on b, -lambda on a (N m s).
template <class Body, class V = value_of<Body>>
inline void apply_angular_impulse(Body& a, Body& b, V lambda) {
    m::im3::VelocitiesOver<V> va = velocities(a);
    m::im3::VelocitiesOver<V> vb = velocities(b);
    m::dd22::apply(va, vb, inverse_inertia(a), inverse_inertia(b),
                   m::dd22::AngularImpulseOver<V>::from_value(lambda));
    a.w = va.omega.value();
    b.w = vb.omega.value();
}

// DD23, the line of a prismatic or wheel joint.

/// DD23's translation, line error and moment arms (m) of the anchors' separation d along the
/// unit axis a (and its perpendicular), from the anchors' offsets r_a, r_b.
struct Line {
    double translation, perpendicular, arm_a, arm_b, perp_arm_a, perp_arm_b;
};
inline Line line(Vec2d d, Vec2d r_a, Vec2d r_b, Vec2d axis) {
    const m::dd23::Line l = m::dd23::line(typed<u::Length>(d), typed<u::Length>(r_a),
                                          typed<u::Length>(r_b), {axis.x, axis.y});
    return {l.translation.value(), l.perpendicular.value(), l.arm_A.value(),
            l.arm_B.value(),       l.perp_arm_A.value(),    l.perp_arm_B.value()};
}
/// DD23's line-and-angle impulses (N s, N m s) in IM6's soft form; accumulated and result as
/// (linear, angular).
inline std::pair<double, double> block_impulse(const SolverBody& a, const SolverBody& b,
                                               double perp_arm_a, double perp_arm_b,
                                               double rhs_perp, double rhs_angle, double mass_scale,
                                               double impulse_scale, double acc_linear,
                                               double acc_angular) {
    const m::dd23::BlockImpulse P = m::dd23::block_impulse(
        inverse_inertia(a), inverse_inertia(b), u::from_value<u::Length>(perp_arm_a),
        u::from_value<u::Length>(perp_arm_b), u::from_value<u::Velocity>(rhs_perp),
        u::from_value<u::AngularVelocity>(rhs_angle), u::from_value<u::Dimensionless>(mass_scale),
        u::from_value<u::Dimensionless>(impulse_scale),
        {u::from_value<u::Impulse>(acc_linear), m::dd22::AngularImpulse::from_value(acc_angular)});
    return {P.linear.value(), P.angular.value()};
}
/// DD23's motor clamp to [-max, max] (N s).
inline double clamp_axial_impulse(double accumulated, double max) {
    return m::dd23::clamp(u::from_value<u::Impulse>(accumulated), u::from_value<u::Impulse>(max))
        .value();
}

/// DD22's spring error of a revolute joint: its angle (rad) against the spring's target.
inline double angular_spring_error(double joint_angle, double target) {
    return m::dd22::spring_error(u::from_value<u::Angle>(joint_angle),
                                 u::from_value<u::Angle>(target))
        .value();
}
/// DD23's spring error of a prismatic or wheel joint: its translation (m) against the target.
inline double axial_spring_error(double translation, double target) {
    return m::dd23::spring_error(u::from_value<u::Length>(translation),
                                 u::from_value<u::Length>(target))
        .value();
}

// DD35: a distance joint's motor.

/// DD35's accumulated motor impulse (N s) after one iteration of a distance joint's motor:
/// the anchors' distance rate `length_rate` (m s^-1) driven to `motor_speed` with at most
/// max_force (N) over the substep h.
inline double distance_motor_update(const SolverBody& a, double arm_a, const SolverBody& b,
                                    double arm_b, double length_rate, double motor_speed,
                                    double max_force, double h, double accumulated) {
    return m::dd35::motor_update(
               inverse_inertia(a), inverse_inertia(b), u::from_value<u::Length>(arm_a),
               u::from_value<u::Length>(arm_b), u::from_value<u::Velocity>(length_rate),
               u::from_value<u::Velocity>(motor_speed), u::from_value<u::Force>(max_force),
               u::from_value<u::Time>(h), u::from_value<u::Impulse>(accumulated))
        .value();
}

// DD24-DD26: the weld's angle, the wheel's line, the motor joint's rows.

/// DD24's angular impulse (N m s) of a weld from the joint speed and the angle error, in IM6's
/// soft form with softness s (the relax: rigid on the speed alone).
inline double weld_angular_impulse(const SolverBody& a, const SolverBody& b, double speed,
                                   double angle_error, const Softness& s, bool use_bias,
                                   double accumulated) {
    return m::dd24::angular_impulse(
               inverse_inertia(a), inverse_inertia(b), u::from_value<u::AngularVelocity>(speed),
               u::from_value<u::Angle>(angle_error),
               {u::from_value<u::Rate>(s.bias_rate), s.mass_scale, s.impulse_scale}, use_bias,
               m::dd22::AngularImpulse::from_value(accumulated))
        .value();
}
/// DD25's impulse (N s) across a wheel's axis from the line's rate and error and the moment
/// arms of a_perp, in IM6's soft form with softness s (the relax: rigid on the rate alone).
inline double wheel_line_impulse(const SolverBody& a, const SolverBody& b, double perp_arm_a,
                                 double perp_arm_b, double rate, double line_error,
                                 const Softness& s, bool use_bias, double accumulated) {
    return m::dd25::line_impulse(
               inverse_inertia(a), inverse_inertia(b), u::from_value<u::Length>(perp_arm_a),
               u::from_value<u::Length>(perp_arm_b), u::from_value<u::Velocity>(rate),
               u::from_value<u::Length>(line_error),
               {u::from_value<u::Rate>(s.bias_rate), s.mass_scale, s.impulse_scale}, use_bias,
               u::from_value<u::Impulse>(accumulated))
        .value();
}
/// DD26's correction rate c / h (s^-1).
inline double correction_rate(double correction, double h) {
    return m::dd26::correction_rate(correction, u::from_value<u::Time>(h)).value();
}
/// DD26's angular row: the accumulated angular impulse after one iteration (N m s).
inline double motor_angular_update(const SolverBody& a, const SolverBody& b, double speed,
                                   double angle_error, double rate, double max_torque, double h,
                                   double accumulated) {
    return m::dd26::angular_update(
               inverse_inertia(a), inverse_inertia(b), u::from_value<u::AngularVelocity>(speed),
               u::from_value<u::Angle>(angle_error), u::from_value<u::Rate>(rate),
               u::from_value<u::Torque>(max_torque), u::from_value<u::Time>(h),
               m::dd22::AngularImpulse::from_value(accumulated))
        .value();
}
/// DD26's linear row: the accumulated impulse after one iteration (N s).
inline Vec2d motor_linear_update(const SolverBody& a, Vec2d r_a, const SolverBody& b, Vec2d r_b,
                                 Vec2d velocity_error, Vec2d position_error, double rate,
                                 double max_force, double h, Vec2d accumulated) {
    return plain(m::dd26::linear_update(
        inverse_inertia(a), inverse_inertia(b), typed<u::Length>(r_a), typed<u::Length>(r_b),
        typed<u::Velocity>(velocity_error), typed<u::Length>(position_error),
        u::from_value<u::Rate>(rate), u::from_value<u::Force>(max_force), u::from_value<u::Time>(h),
        typed<u::Impulse>(accumulated)));
}

} // namespace tamias2d::bridge
