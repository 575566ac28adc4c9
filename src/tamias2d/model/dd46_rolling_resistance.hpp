#pragma once
#include <algorithm>
#include <limits>

#include "tamias2d/math/wide.hpp"
#include "tamias2d/model/dd08_collision_impulse.hpp"
#include "tamias2d/model/dd22_angular_constraint.hpp"
#include "tamias2d/model/im3_collision_response.hpp"
#include "tamias2d/model/t2_newtons_third_law.hpp"
#include "tamias2d/units/angle.hpp"
#include "tamias2d/units/quantities.hpp"

namespace tamias2d::model::dd46 {
using namespace tamias2d::units;
using dd08::InverseInertiaOver;

/// An angular impulse (N m s rad^-1) over V: double, or a pack of lanes.
template <class V> using AngularImpulseOver = Over<dd22::AngularImpulse, V>;

/// \srs{DD46} A contact's rolling resistance coefficient: the larger of its two shapes', so that
/// a resisting ball rolls slowly on any floor.
inline Dimensionless mixed_coefficient(Dimensionless c_a, Dimensionless c_b) {
    return std::max(c_a, c_b);
}

/// \srs{DD46} The lever of the resistance: the larger rolling radius of the two shapes (a circle's
/// or a capsule's radius; 0 for a shape that does not roll, so a box is not resisted).
inline Length lever(Length r_a, Length r_b) {
    return std::max(r_a, r_b);
}

/// \srs{DD46} The coefficient times the lever, c l (m): what the solver keeps per contact.
inline Length resistance_length(Dimensionless c, Length l) {
    return c * l;
}

/// \srs{DD46} A rolling resistance coefficient is valid when finite and >= 0.
inline bool valid_coefficient(double c) {
    return c >= 0.0 && c <= std::numeric_limits<double>::max();
}

/// \srs{DD46} The bound c l (lambda_1 + lambda_2) on the angular impulse of the resistance in a
/// substep, from the manifold's normal impulses: the largest torque c l N over the substep.
template <class V>
AngularImpulseOver<V> impulse_bound(Over<Length, V> resistance_length,
                                    Over<Impulse, V> normal_impulse_sum) {
    return per_radian(resistance_length * normal_impulse_sum);
}

/// \srs{DD46} The accumulated angular impulse after one iteration: the impulse that stops the
/// relative turning omega_b - omega_a, over 1/I_a + 1/I_b, added to `accumulated` and clamped to
/// [-bound, bound]. Where neither body turns (1/I_a + 1/I_b = 0) it stays as it is.
template <class V>
AngularImpulseOver<V>
impulse_update(InverseInertiaOver<V> A, InverseInertiaOver<V> B, Over<AngularVelocity, V> omega_a,
               Over<AngularVelocity, V> omega_b, AngularImpulseOver<V> accumulated,
               AngularImpulseOver<V> bound) {
    const auto k = A.inv_I + B.inv_I;
    const V zero = broadcast<V>(0.0);
    const V turns = k.value();
    const V step = select(turns > zero, ((omega_b - omega_a) / k).value(), zero);
    const V updated = min(max(accumulated.value() - step, -bound.value()), bound.value());
    return AngularImpulseOver<V>::from_value(updated);
}

/// \srs{DD46} The angular impulse delta on the two bodies: -delta on a, +delta on b (T2), each
/// turning by delta / I (IM3's angular jump).
template <class V>
void apply(Over<AngularVelocity, V>& omega_a, Over<AngularVelocity, V>& omega_b,
           InverseInertiaOver<V> A, InverseInertiaOver<V> B, AngularImpulseOver<V> delta) {
    omega_a += t2::reaction(im3::angular_velocity_change(A.inv_I, delta));
    omega_b += im3::angular_velocity_change(B.inv_I, delta);
}

} // namespace tamias2d::model::dd46
