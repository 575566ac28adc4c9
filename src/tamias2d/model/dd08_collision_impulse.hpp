#pragma once
#include "tamias2d/model/dd12_coefficient_of_restitution.hpp"
#include "tamias2d/units/angle.hpp"
#include "tamias2d/units/vec2.hpp"

namespace tamias2d::model::dd08 {
using namespace tamias2d::units;

/// Unit collision normal: dimensionless (the SRS gives n the unit m, an erratum: with it, j
/// would come out in kg s^-1 instead of N s).
using Normal = Vec2<double>;

/// Inverse mass properties of one body at one contact (or of one body per lane, V a pack of
/// lanes); a static body has zeros.
template <class V> struct InverseInertiaOver {
    Over<InverseMass, V> inv_m;
    Over<InverseMomentOfInertia, V> inv_I;
};
using InverseInertia = InverseInertiaOver<double>;

/// \srs{DD8} The moment arm of the line of action n through P about a body's centre of mass,
/// r x n (m): the quantity DD8's denominator squares. It stays constant while r and n do, so
/// the solver computes it once per step; (omega x r) . n = omega (r x n) (DD9) and
/// r x (j n) = j (r x n) (IM3) are then one product each.
template <class V> Over<Length, V> moment_arm(Vec2<Over<Length, V>> r, Vec2<V> n) {
    return cross(r, n);
}

/// \srs{DD8} The denominator of DD8 generalised to two contact points 1 and 2 of the same pair,
/// from the moment arms a_i = r_Ai x n, b_i = r_Bi x n:
/// K12 = (1/mA + 1/mB) |n|^2 + a1 a2 / I_A + b1 b2 / I_B with |n| = 1.
/// K11 is DD8's own denominator; K12 couples two simultaneous contacts (see the solver).
/// (V: double, or a pack of lanes.)
template <class V>
Over<InverseMass, V> normal_mass_coupling(InverseInertiaOver<V> A, InverseInertiaOver<V> B,
                                          Over<Length, V> arm_A1, Over<Length, V> arm_B1,
                                          Over<Length, V> arm_A2, Over<Length, V> arm_B2) {
    return A.inv_m + B.inv_m + A.inv_I * per_radian(arm_A1) * per_radian(arm_A2) +
           B.inv_I * per_radian(arm_B1) * per_radian(arm_B2);
}

/// \srs{DD8} The same from the anchors r_A1, r_B1, r_A2, r_B2 and the unit normal n.
inline InverseMass normal_mass_coupling(InverseInertia A, InverseInertia B, Vec2<Length> r_A1,
                                        Vec2<Length> r_B1, Vec2<Length> r_A2, Vec2<Length> r_B2,
                                        Normal n) {
    return normal_mass_coupling(A, B, moment_arm(r_A1, n), moment_arm(r_B1, n), moment_arm(r_A2, n),
                                moment_arm(r_B2, n));
}

/// \srs{DD8} DD8's denominator: the inverse effective mass of the pair along n at P, from the
/// moment arms r_AP x n and r_BP x n.
template <class V>
Over<InverseMass, V> effective_mass_inverse(InverseInertiaOver<V> A, InverseInertiaOver<V> B,
                                            Over<Length, V> arm_A, Over<Length, V> arm_B) {
    return normal_mass_coupling(A, B, arm_A, arm_B, arm_A, arm_B);
}

/// \srs{DD8} The same from the anchors r_AP, r_BP and the unit normal n.
inline InverseMass effective_mass_inverse(InverseInertia A, InverseInertia B, Vec2<Length> r_AP,
                                          Vec2<Length> r_BP, Normal n) {
    return effective_mass_inverse(A, B, moment_arm(r_AP, n), moment_arm(r_BP, n));
}

/// \srs{DD8} The impulse along n that takes the normal relative velocity from v_rel_n to
/// v_target: j = -(v_rel_n - v_target) m_eff with m_eff = 1 / K. DD8 is the case
/// v_target = -C_R v_rel_n (DD12); an iterative solver uses the same law with its own targets
/// (0 to stop, DD12's for a bounce) and a precomputed m_eff.
template <class V>
Over<Impulse, V> impulse_to_reach(Over<Velocity, V> v_rel_n, Over<Velocity, V> v_target,
                                  Over<Mass, V> m_eff) {
    return -(v_rel_n - v_target) * m_eff;
}

/// \srs{DD8} Impulse for collision response: j = -(1 + C_R) (v_i^AB . n) / K, where
/// K = effective_mass_inverse(...) and v_i^AB . n is the normal relative velocity before.
inline Impulse collision_impulse(Dimensionless C_R, Velocity v_rel_n, InverseMass K) {
    return impulse_to_reach(v_rel_n, dd12::separating_normal_velocity(C_R, v_rel_n), 1.0 / K);
}

} // namespace tamias2d::model::dd08
