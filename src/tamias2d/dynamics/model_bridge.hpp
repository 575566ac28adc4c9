// The engine's calls into the unit-typed model layer. The engine stores plain doubles (SI);
// these inline adapters wrap them in Boost.Units quantities, call the labelled model function
// and unwrap the result. Everything inlines, so the hot loops pay nothing for the typing
// (verification/bench measures it); the formulas themselves live only in model/.
#pragma once

#include <limits>
#include <type_traits>
#include <utility>

#include "tamias2d/dynamics/solver_body.hpp"
#include "tamias2d/dynamics/solver_settings.hpp"
#include "tamias2d/model/dd03_linear_velocity.hpp"
#include "tamias2d/model/dd04_linear_acceleration.hpp"
#include "tamias2d/model/dd06_angular_velocity.hpp"
#include "tamias2d/model/dd07_angular_acceleration.hpp"
#include "tamias2d/model/dd08_collision_impulse.hpp"
#include "tamias2d/model/dd12_coefficient_of_restitution.hpp"
#include "tamias2d/model/dd19_point_constraint.hpp"
#include "tamias2d/model/dd20_distance_constraint.hpp"
#include "tamias2d/model/dd21_target_constraint.hpp"
#include "tamias2d/model/dd22_angular_constraint.hpp"
#include "tamias2d/model/dd23_line_constraint.hpp"
#include "tamias2d/model/dd24_weld_constraint.hpp"
#include "tamias2d/model/dd25_wheel_constraint.hpp"
#include "tamias2d/model/dd26_motor_constraint.hpp"
#include "tamias2d/model/dd29_time_of_impact.hpp"
#include "tamias2d/model/dd35_distance_joint_motor.hpp"
#include "tamias2d/model/dd36_joint_break.hpp"
#include "tamias2d/model/dd39_motion_locks.hpp"
#include "tamias2d/model/dd40_maximum_linear_speed.hpp"
#include "tamias2d/model/dd41_mass_change.hpp"
#include "tamias2d/model/dd46_rolling_resistance.hpp"
#include "tamias2d/model/dd47_tangent_speed.hpp"
#include "tamias2d/model/im1_translational_motion.hpp"
#include "tamias2d/model/im2_rotational_motion.hpp"
#include "tamias2d/model/im3_collision_response.hpp"
#include "tamias2d/model/im5_motion_with_damping.hpp"
#include "tamias2d/model/im6_motion_with_joints.hpp"
#include "tamias2d/model/im7_soft_contact.hpp"

namespace tamias2d::bridge {

namespace u = tamias2d::units;
namespace bu = boost::units;
namespace m = tamias2d::model;

template <class Q> inline u::Vec2<Q> typed(Vec2d v) {
    return u::vec_from_values<Q>(v.x, v.y);
}
template <class Q> inline Vec2d plain(u::Vec2<Q> v) {
    return {v.x.value(), v.y.value()};
}

// The hot-loop adapters below are templates over the value type V: double for one contact,
// Wide (math/wide.hpp) for a pack of contacts, one per lane. Body is SolverBody or WideBody.
template <class Body> using value_of = std::remove_cvref_t<decltype(std::declval<Body>().w)>;

template <class Q, class V> inline u::Over<Q, V> typed_value(V x) {
    return u::Over<Q, V>::from_value(x);
}
template <class Q, class V> inline u::Vec2<u::Over<Q, V>> typed_vec(u::Vec2<V> v) {
    return {typed_value<Q>(v.x), typed_value<Q>(v.y)};
}
template <class Q, class V> inline u::Vec2<V> plain_vec(u::Vec2<bu::quantity<Q, V>> v) {
    return {v.x.value(), v.y.value()};
}

template <class Body>
inline m::dd08::InverseInertiaOver<value_of<Body>> inverse_inertia(const Body& b) {
    return {typed_value<u::InverseMass>(b.inv_m), typed_value<u::InverseMomentOfInertia>(b.inv_I)};
}

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

/// DD29's bound on how far any point of a body moves when its centre moves `translation` (m)
/// and it turns `rotation` (rad, >= 0), its points at most `reach` (m) from the centre.
inline double motion_bound(double translation, double rotation, double reach) {
    return m::dd29::motion_bound(u::from_value<u::Length>(translation),
                                 u::from_value<u::Angle>(rotation), u::from_value<u::Length>(reach))
        .value();
}

/// DD29's linear motion over the step: a centre (m), an angle (rad), a velocity (m s^-1) or an
/// angular velocity (rad s^-1) at the fraction t, from its values at the start and the end.
inline Vec2d center_at(Vec2d start, Vec2d end, double t) {
    return plain(m::dd29::at_fraction(typed<u::Length>(start), typed<u::Length>(end), t));
}
inline double angle_at(double start, double end, double t) {
    return m::dd29::at_fraction(u::from_value<u::Angle>(start), u::from_value<u::Angle>(end), t)
        .value();
}
inline Vec2d velocity_at(Vec2d start, Vec2d end, double t) {
    return plain(m::dd29::at_fraction(typed<u::Velocity>(start), typed<u::Velocity>(end), t));
}
inline double angular_velocity_at(double start, double end, double t) {
    return m::dd29::at_fraction(u::from_value<u::AngularVelocity>(start),
                                u::from_value<u::AngularVelocity>(end), t)
        .value();
}

/// DD8's moment arm r x n of unit direction n at anchor r (m).
template <class V> inline V moment_arm(u::Vec2<V> r, u::Vec2<V> n) {
    return m::dd08::moment_arm(typed_vec<u::Length>(r), n).value();
}
/// DD8's denominator K along a unit direction with moment arms arm_a, arm_b (kg^-1).
template <class Body, class V = value_of<Body>>
inline V inverse_effective_mass(const Body& a, const Body& b, V arm_a, V arm_b) {
    return m::dd08::effective_mass_inverse(inverse_inertia(a), inverse_inertia(b),
                                           typed_value<u::Length>(arm_a),
                                           typed_value<u::Length>(arm_b))
        .value();
}
/// DD8's K generalised to two points of one manifold, from their moment arms (kg^-1).
template <class Body, class V = value_of<Body>>
inline V normal_mass_coupling(const Body& a, const Body& b, V arm_a1, V arm_b1, V arm_a2,
                              V arm_b2) {
    return m::dd08::normal_mass_coupling(
               inverse_inertia(a), inverse_inertia(b), typed_value<u::Length>(arm_a1),
               typed_value<u::Length>(arm_b1), typed_value<u::Length>(arm_a2),
               typed_value<u::Length>(arm_b2))
        .value();
}
/// DD12 solved for the separating normal velocity: -C_R vn (m s^-1).
inline double separating_normal_velocity(double restitution, double vn_before) {
    return m::dd12::separating_normal_velocity(restitution, u::from_value<u::Velocity>(vn_before))
        .value();
}

/// DD8: impulse (N s) taking the relative normal velocity from vn to target, given 1/K (kg).
template <class V> inline V impulse_to_reach(V vn, V target, V effective_mass) {
    return m::dd08::impulse_to_reach(typed_value<u::Velocity>(vn), typed_value<u::Velocity>(target),
                                     typed_value<u::Mass>(effective_mass))
        .value();
}

/// IM7's soft impulse (N s): the rigid impulse scaled, minus the relaxed accumulated share.
template <class V> inline V soft_impulse(V mass_scale, V rigid, V impulse_scale, V accumulated) {
    return m::im7::soft_impulse(mass_scale, typed_value<u::Impulse>(rigid), impulse_scale,
                                typed_value<u::Impulse>(accumulated))
        .value();
}

// The manifold normal points from A into B; IM3's n points from its "B" into its "A" (A is
// pushed along +n). So IM3's A is the manifold's B and vice versa in the two adapters below.

template <class Body> inline m::im3::VelocitiesOver<value_of<Body>> velocities(const Body& b) {
    return {typed_vec<u::Velocity>(b.v), typed_value<u::AngularVelocity>(b.w)};
}

/// IM3 (DD9, DD11): relative velocity of B with respect to A at the contact, along dir, from
/// the moment arms of dir at A's and B's anchors.
template <class Body, class V = value_of<Body>>
inline V relative_velocity(const Body& a, const Body& b, V arm_a, V arm_b, u::Vec2<V> dir) {
    return m::im3::normal_relative_velocity(velocities(b), velocities(a),
                                            typed_value<u::Length>(arm_b),
                                            typed_value<u::Length>(arm_a), dir)
        .value();
}

/// IM3: impulse lambda dir on B and -lambda dir on A (T2), from the moment arms of dir.
template <class Body, class V = value_of<Body>>
inline void apply_impulse(Body& a, Body& b, V arm_a, V arm_b, u::Vec2<V> dir, V lambda) {
    m::im3::VelocitiesOver<V> va = velocities(a);
    m::im3::VelocitiesOver<V> vb = velocities(b);
    m::im3::apply_impulse(vb, va, inverse_inertia(b), inverse_inertia(a),
                          typed_value<u::Length>(arm_b), typed_value<u::Length>(arm_a), dir,
                          typed_value<u::Impulse>(lambda));
    a.v = plain_vec(va.v);
    a.w = va.omega.value();
    b.v = plain_vec(vb.v);
    b.w = vb.omega.value();
}

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
/// IM6's reaction force (N) of a joint's impulse (N s) over the substep of rate inv_h (s^-1).
inline Vec2d reaction_force(Vec2d impulse, double inv_h) {
    return plain(m::im6::reaction(typed<u::Impulse>(impulse), u::from_value<u::Rate>(inv_h)));
}
inline double reaction_force(double impulse, double inv_h) {
    return m::im6::reaction(u::from_value<u::Impulse>(impulse), u::from_value<u::Rate>(inv_h))
        .value();
}
/// IM6's reaction torque (N m) of a joint's angular impulse (N m s).
inline double reaction_torque(double angular_impulse, double inv_h) {
    return m::im6::reaction(m::dd22::AngularImpulse::from_value(angular_impulse),
                            u::from_value<u::Rate>(inv_h))
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

// DD35, DD36: a distance joint's motor, a joint's break thresholds.

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

/// DD36: whether a joint whose last substep's reaction force has the magnitude `force` (N) and
/// whose reaction torque is `torque` (N m) breaks at the thresholds break_force, break_torque.
inline bool joint_breaks(double force, double break_force, double torque, double break_torque) {
    return m::dd36::breaks(u::from_value<u::Force>(force), u::from_value<u::Force>(break_force),
                           u::from_value<u::Torque>(torque),
                           u::from_value<u::Torque>(break_torque));
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

// DD46, DD47: a contact's surface motion.

/// DD46's c l (m) of a contact from its shapes' coefficients and rolling radii (m).
inline double rolling_resistance_length(double c_a, double r_a, double c_b, double r_b) {
    return m::dd46::resistance_length(
               m::dd46::mixed_coefficient(u::from_value<u::Dimensionless>(c_a),
                                          u::from_value<u::Dimensionless>(c_b)),
               m::dd46::lever(u::from_value<u::Length>(r_a), u::from_value<u::Length>(r_b)))
        .value();
}
/// DD47's target of a contact's relative tangential velocity (m s^-1) from its shapes' tangent
/// speeds.
inline double tangent_target(double s_a, double s_b) {
    return m::dd47::friction_target(u::from_value<u::Velocity>(s_a),
                                    u::from_value<u::Velocity>(s_b))
        .value();
}
/// DD46's bound c l (lambda_1 + lambda_2) on the rolling impulse (N m s).
template <class V> inline V rolling_impulse_bound(V resistance_length, V normal_impulse_sum) {
    return m::dd46::impulse_bound(typed_value<u::Length>(resistance_length),
                                  typed_value<u::Impulse>(normal_impulse_sum))
        .value();
}
/// DD46's accumulated rolling impulse (N m s) after one iteration, within [-bound, bound].
template <class Body, class V = value_of<Body>>
inline V rolling_impulse_update(const Body& a, const Body& b, V accumulated, V bound) {
    return m::dd46::impulse_update(inverse_inertia(a), inverse_inertia(b),
                                   typed_value<u::AngularVelocity>(a.w),
                                   typed_value<u::AngularVelocity>(b.w),
                                   m::dd46::AngularImpulseOver<V>::from_value(accumulated),
                                   m::dd46::AngularImpulseOver<V>::from_value(bound))
        .value();
}
/// DD46: -delta on a, +delta on b (N m s).
template <class Body, class V = value_of<Body>>
inline void apply_rolling_impulse(Body& a, Body& b, V delta) {
    auto wa = typed_value<u::AngularVelocity>(a.w);
    auto wb = typed_value<u::AngularVelocity>(b.w);
    m::dd46::apply(wa, wb, inverse_inertia(a), inverse_inertia(b),
                   m::dd46::AngularImpulseOver<V>::from_value(delta));
    a.w = wa.value();
    b.w = wb.value();
}

/// IM7's target of a contact point (V: double or a pack) and the scales its impulse takes.
template <class V> struct Target {
    V target{};
    V mass_scale{};
    V impulse_scale{};
};
/// IM7's two impulses of a two-point manifold (V: double or a pack).
template <class V> struct TwoPointSolution { V x1{}, x2{}; };

/// The adapters the contact iteration calls, as one type it is instantiated with
/// (contact_iteration.hpp's Model parameter).
struct Model {
    template <class V> static V impulse_to_reach(V vn, V target, V effective_mass) {
        return bridge::impulse_to_reach(vn, target, effective_mass);
    }
    template <class V>
    static V soft_impulse(V mass_scale, V rigid, V impulse_scale, V accumulated) {
        return bridge::soft_impulse(mass_scale, rigid, impulse_scale, accumulated);
    }
    template <class Body, class V = value_of<Body>>
    static V relative_velocity(const Body& a, const Body& b, V arm_a, V arm_b, u::Vec2<V> dir) {
        return bridge::relative_velocity(a, b, arm_a, arm_b, dir);
    }
    template <class Body, class V = value_of<Body>>
    static void apply_impulse(Body& a, Body& b, V arm_a, V arm_b, u::Vec2<V> dir, V lambda) {
        bridge::apply_impulse(a, b, arm_a, arm_b, dir, lambda);
    }
    /// DD46's bound, update and application of the rolling impulse.
    template <class V> static V rolling_impulse_bound(V resistance_length, V normal_impulse_sum) {
        return bridge::rolling_impulse_bound(resistance_length, normal_impulse_sum);
    }
    template <class Body, class V = value_of<Body>>
    static V rolling_impulse_update(const Body& a, const Body& b, V accumulated, V bound) {
        return bridge::rolling_impulse_update(a, b, accumulated, bound);
    }
    template <class Body, class V = value_of<Body>>
    static void apply_rolling_impulse(Body& a, Body& b, V delta) {
        bridge::apply_rolling_impulse(a, b, delta);
    }
    /// IM7's target for separation s (m) in the soft iteration (soft) or the relax.
    template <bool soft, class V> static Target<V> target(V s, const ContactSolverSettings& st) {
        const auto t = m::im7::target_velocity<soft>(
            typed_value<u::Length>(s), typed_value<u::Rate>(broadcast<V>(st.inv_h)),
            typed_value<u::Rate>(broadcast<V>(st.softness.bias_rate)),
            broadcast<V>(st.softness.mass_scale), broadcast<V>(st.softness.impulse_scale),
            typed_value<u::Length>(broadcast<V>(st.linear_slop)),
            typed_value<u::Velocity>(broadcast<V>(st.push_max_velocity)));
        return {t.velocity.value(), t.mass_scale, t.impulse_scale};
    }
    /// IM7's two-point impulses from K (k11, k12, k22 in kg^-1, its inverse in kg), the points'
    /// effective masses m1, m2, velocities vn1, vn2, targets t1, t2 and accumulated impulses.
    template <class V>
    static TwoPointSolution<V> two_point_impulses(V k11, V k12, V k22, V inv11, V inv12, V inv22,
                                                  V m1, V m2, V vn1, V vn2, V t1, V t2, V x1,
                                                  V x2) {
        const m::im7::PairMass<V> K{
            typed_value<u::InverseMass>(k11), typed_value<u::InverseMass>(k12),
            typed_value<u::InverseMass>(k22), typed_value<u::Mass>(inv11),
            typed_value<u::Mass>(inv12),      typed_value<u::Mass>(inv22)};
        const m::im7::PairImpulses<V> x = m::im7::two_point_impulses(
            K, typed_value<u::Mass>(m1), typed_value<u::Mass>(m2), typed_value<u::Velocity>(vn1),
            typed_value<u::Velocity>(vn2), typed_value<u::Velocity>(t1),
            typed_value<u::Velocity>(t2), typed_value<u::Impulse>(x1), typed_value<u::Impulse>(x2));
        return {x.x1.value(), x.x2.value()};
    }
};

// Run-time control: motion locks (DD39), the speed limit (DD40), a mass change (DD41).
inline Vec2d locked_velocity(Vec2d v, bool lock_x, bool lock_y) {
    return plain(m::dd39::projected_velocity(typed<u::Velocity>(v), lock_x, lock_y));
}
inline Vec2d limited_velocity(Vec2d v, double v_max) {
    return plain(
        m::dd40::limited_velocity(typed<u::Velocity>(v), u::from_value<u::Velocity>(v_max)));
}
inline Vec2d shifted_center_velocity(Vec2d v, double w, Vec2d shift) {
    return plain(m::dd41::center_velocity(
        typed<u::Velocity>(v), u::from_value<u::AngularVelocity>(w), typed<u::Length>(shift)));
}

} // namespace tamias2d::bridge
