// An impulse at a point of two bodies: DD8's moment arm and effective mass, IM3's relative
// velocity and impulse (with T2's reaction). Contacts, joints and the world's one-off impulses
// all apply theirs through these.
#pragma once

#include "tamias2d/dynamics/bridge/typing.hpp"
#include "tamias2d/model/dd08_collision_impulse.hpp"
#include "tamias2d/model/im3_collision_response.hpp"

namespace tamias2d::bridge {

template <class Body>
inline m::dd08::InverseInertiaOver<value_of<Body>> inverse_inertia(const Body& b) {
    return {typed_value<u::InverseMass>(b.inv_m), typed_value<u::InverseMomentOfInertia>(b.inv_I)};
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

} // namespace tamias2d::bridge
