// A contact's impulses: DD8's impulse and its two-point coupling, DD12's separating velocity,
// IM7's soft target and impulse, gathered in the Model type the contact iteration is
// instantiated with (contact_iteration.hpp).
#pragma once

#include "tamias2d/dynamics/bridge/point_impulse.hpp"
#include "tamias2d/dynamics/bridge/surface_motion.hpp"
#include "tamias2d/dynamics/solver_settings.hpp"
#include "tamias2d/math/wide.hpp"
#include "tamias2d/model/dd12_coefficient_of_restitution.hpp"
#include "tamias2d/model/im7_soft_contact.hpp"

namespace tamias2d::bridge {

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

} // namespace tamias2d::bridge
