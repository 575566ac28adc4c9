// Preparing a contact manifold for the solver, once per step: the moment arms of the normal and
// the tangent (DD8), the points' effective masses, and for two points the 2x2 matrix K with its
// inverse. Written once as a template over the value type V, like the iteration: V = double
// prepares one manifold (prepare_contact, restitution.cpp), V = Wide four, one per lane
// (WideContactSolver::prepare_pack). Neither uses fused multiply-add, so a lane and the scalar
// preparation of the same manifold agree bit for bit.
#pragma once

#include "tamias2d/dynamics/bridge/contacts.hpp"
#include "tamias2d/dynamics/bridge/point_impulse.hpp"
#include "tamias2d/dynamics/contacts/contact_iteration.hpp"
#include "tamias2d/math/wide.hpp"

namespace tamias2d::preparation {

/// Bounds on K's condition for solving two points together: the block needs k11^2 < bound * det
/// (strictly, as Box2D 2.4's test), and otherwise the two rows are nearly the same constraint and
/// the sequential solve is used. The iterations keep Box2D 2.4's 1000
/// (1e6 there changed the rain scene enough for two boxes to splash over its wall, finding O3).
/// The restitution pass must be exact for a two-point bounce to conserve energy (finding E3,
/// docs/verification.md: seed 2000114 has a condition of 1408); in double a condition of 1e6
/// still leaves about ten correct digits.
inline constexpr double max_condition_number = 1.0e3;
inline constexpr double max_restitution_condition_number = 1.0e6;

template <class V> struct PreparedPoint {
    V normal_arm_a{}, normal_arm_b{};   ///< m, r x n at each body's anchor
    V tangent_arm_a{}, tangent_arm_b{}; ///< m, r x t
    V normal_mass{}, tangent_mass{};    ///< kg, 1 / K along n and t (0 where K is 0)
};

/// One point with anchors r_a, r_b (relative to the centres of mass) on a manifold of unit
/// normal n.
template <class Body, class V = bridge::value_of<Body>>
PreparedPoint<V> prepare_point(const Body& a, const Body& b, Vec2<V> r_a, Vec2<V> r_b, Vec2<V> n) {
    const V zero = broadcast<V>(0.0);
    const V one = broadcast<V>(1.0);
    const Vec2<V> t = iteration::tangent_of(n); // the direction the iteration applies
    PreparedPoint<V> p;
    p.normal_arm_a = bridge::moment_arm(r_a, n);
    p.normal_arm_b = bridge::moment_arm(r_b, n);
    p.tangent_arm_a = bridge::moment_arm(r_a, t);
    p.tangent_arm_b = bridge::moment_arm(r_b, t);
    const V k = bridge::inverse_effective_mass(a, b, p.normal_arm_a, p.normal_arm_b);
    const V kt = bridge::inverse_effective_mass(a, b, p.tangent_arm_a, p.tangent_arm_b);
    p.normal_mass = select(k > zero, one / k, zero);
    p.tangent_mass = select(kt > zero, one / kt, zero);
    return p;
}

template <class V> struct PreparedBlock {
    V k11{}, k12{}, k22{};             ///< kg^-1, K of the two points (DD8 generalised)
    V inv_k11{}, inv_k12{}, inv_k22{}; ///< kg, K^-1 where invertible, else 0
    mask_of<V> invertible{};           ///< the restitution pass may solve them as a block
    mask_of<V> use_block{};            ///< the iterations solve them as a block
};

/// K of two points from their normal moment arms, and its inverse where well conditioned.
template <class Body, class V = bridge::value_of<Body>>
PreparedBlock<V> prepare_block(const Body& a, const Body& b, V arm_a1, V arm_b1, V arm_a2,
                               V arm_b2) {
    const V zero = broadcast<V>(0.0);
    PreparedBlock<V> k;
    k.k11 = bridge::inverse_effective_mass(a, b, arm_a1, arm_b1);
    k.k22 = bridge::inverse_effective_mass(a, b, arm_a2, arm_b2);
    k.k12 = bridge::normal_mass_coupling(a, b, arm_a1, arm_b1, arm_a2, arm_b2);
    const V det = k.k11 * k.k22 - k.k12 * k.k12;
    const V k11_squared = k.k11 * k.k11;
    k.invertible = both(both(k.k11 > zero, k.k22 > zero),
                        k11_squared < broadcast<V>(max_restitution_condition_number) * det);
    k.use_block = both(k.invertible, k11_squared < broadcast<V>(max_condition_number) * det);
    const V inv_det = broadcast<V>(1.0) / det; // used only where invertible (det > 0)
    k.inv_k11 = select(k.invertible, k.k22 * inv_det, zero);
    k.inv_k12 = select(k.invertible, -k.k12 * inv_det, zero);
    k.inv_k22 = select(k.invertible, k.k11 * inv_det, zero);
    return k;
}

} // namespace tamias2d::preparation
