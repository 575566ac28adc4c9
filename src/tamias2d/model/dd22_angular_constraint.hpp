#pragma once
#include <algorithm>

#include "tamias2d/model/dd08_collision_impulse.hpp"
#include "tamias2d/model/im3_collision_response.hpp"
#include "tamias2d/model/im6_motion_with_joints.hpp"
#include "tamias2d/model/t2_newtons_third_law.hpp"
#include "tamias2d/units/angle.hpp"

namespace tamias2d::model::dd22 {
using namespace tamias2d::units;
using dd08::InverseInertia;
using im3::Velocities;

/// An angular impulse (N m s): a torque over a time.
using AngularImpulse = decltype(Torque{} * Time{});

/// \srs{DD22} The joint angle theta = (phi_B - phi_A) - theta_0.
inline Angle joint_angle(Angle phi_A, Angle phi_B, Angle reference) {
    return (phi_B - phi_A) - reference;
}

/// \srs{DD22} The joint speed theta' = omega_B - omega_A.
inline AngularVelocity joint_speed(const Velocities& A, const Velocities& B) {
    return B.omega - A.omega;
}

/// \srs{DD22} The angular impulse that changes the joint speed by -(rhs): -rhs / k, with
/// k = 1/I_A + 1/I_B (IM6's soft form with mass_scale and impulse_scale as for DD19). With
/// k = 0 neither body turns under an impulse (fixed rotation, kinematic or static), so no
/// impulse changes the joint speed: the row holds nothing and its impulse is 0, not -rhs / 0.
inline AngularImpulse impulse(InverseInertia A, InverseInertia B, AngularVelocity rhs,
                              Dimensionless mass_scale, Dimensionless impulse_scale,
                              AngularImpulse accumulated) {
    const auto k = A.inv_I + B.inv_I;
    if (!(k > decltype(k){}))
        return AngularImpulse{};
    return im6::soft_impulse(mass_scale, AngularImpulse(-(rhs / k)), impulse_scale, accumulated);
}

/// \srs{DD22} The bound tau_max h on the motor's angular impulse accumulated in a substep h: the
/// angular impulse of the largest torque over h.
inline AngularImpulse impulse_bound(Torque max_torque, Time h) {
    return max_torque * h;
}

/// \srs{DD22} The motor's accumulation bounded by tau_max h: [-max, max].
inline AngularImpulse clamp(AngularImpulse accumulated, AngularImpulse max) {
    return std::clamp(accumulated, -max, max);
}

/// An angular impulse of values of type V (double, or a pack of lanes: dd19_point_constraint.hpp).
template <class V> using AngularImpulseOver = Over<AngularImpulse, V>;

/// \srs{DD22} +Lambda on B, -Lambda on A (T2 for torques): omega changes by Lambda / I (T4),
/// IM3's angular jump.
template <class V>
void apply(im3::VelocitiesOver<V>& A, im3::VelocitiesOver<V>& B, dd08::InverseInertiaOver<V> a,
           dd08::InverseInertiaOver<V> b, AngularImpulseOver<V> lambda) {
    A.omega += t2::reaction(im3::angular_velocity_change(a.inv_I, lambda));
    B.omega += im3::angular_velocity_change(b.inv_I, lambda);
}

/// \srs{DD22} The error a revolute joint's spring pulls to zero: the joint angle theta against
/// the spring's target theta_t (0, the pose at creation, unless set), theta - theta_t.
inline Angle spring_error(Angle joint_angle, Angle target) {
    return joint_angle - target;
}

} // namespace tamias2d::model::dd22
