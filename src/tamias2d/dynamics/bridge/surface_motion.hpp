// A contact's surface motion: rolling resistance (DD46) and tangent speed (DD47).
#pragma once

#include "tamias2d/dynamics/bridge/point_impulse.hpp"
#include "tamias2d/model/dd46_rolling_resistance.hpp"
#include "tamias2d/model/dd47_tangent_speed.hpp"

namespace tamias2d::bridge {

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

} // namespace tamias2d::bridge
