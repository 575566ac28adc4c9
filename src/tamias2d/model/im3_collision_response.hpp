#pragma once
#include "tamias2d/model/dd08_collision_impulse.hpp"
#include "tamias2d/model/dd09_chasles_theorem.hpp"
#include "tamias2d/model/dd10_impulse.hpp"
#include "tamias2d/model/dd11_relative_velocity.hpp"
#include "tamias2d/model/t2_newtons_third_law.hpp"

namespace tamias2d::model::im3 {
using namespace tamias2d::units;
using dd08::InverseInertia;
using dd08::InverseInertiaOver;
using dd08::Normal;

/// A body's velocities (V = double), or one body's per lane (V a pack of lanes).
template <class V> struct VelocitiesOver {
    Vec2<Over<Velocity, V>> v;
    Over<AngularVelocity, V> omega;
};
using Velocities = VelocitiesOver<double>;

/// \srs{IM3} The angular velocity jump of a body from an angular impulse L about its centre of
/// mass (N m s rad^-1): L / I, with 1/I = 0 for a body that does not turn (T4 over the impulse).
template <class V, class L>
Over<AngularVelocity, V> angular_velocity_change(Over<InverseMomentOfInertia, V> inv_I, L angular) {
    return inv_I * angular;
}

/// \srs{IM3} The same from the moment r x J of an impulse J applied at r from the centre of mass
/// (N m s): (r x J / rad) / I, IM3's angular jump.
template <class V, class M>
Over<AngularVelocity, V> angular_velocity_change_of_moment(Over<InverseMomentOfInertia, V> inv_I,
                                                           M moment) {
    return angular_velocity_change(inv_I, per_radian(moment));
}

/// \srs{IM3} Applies a normal impulse j n at P to A and -j n to B (T2):
/// v_A' = v_A + j n / m_A, v_B' = v_B - j n / m_B,
/// omega_A' = omega_A + (r_AP x j n) / I_A, omega_B' = omega_B - (r_BP x j n) / I_B,
/// with r x (j n) = j (r x n) from the moment arms arm_A = r_AP x n, arm_B = r_BP x n (DD8);
/// the velocity jumps are DD10's J / m, B's those of T2's reaction to A's impulse (negated
/// last, so that the optimiser folds it into a subtraction: no extra instruction).
template <class V>
void apply_impulse(VelocitiesOver<V>& A, VelocitiesOver<V>& B, InverseInertiaOver<V> a,
                   InverseInertiaOver<V> b, Over<Length, V> arm_A, Over<Length, V> arm_B, Vec2<V> n,
                   Over<Impulse, V> j) {
    const Vec2<Over<Impulse, V>> J = j * n;
    A.v += dd10::velocity_change(J, a.inv_m);
    B.v += t2::reaction(dd10::velocity_change(J, b.inv_m));
    A.omega += angular_velocity_change_of_moment(a.inv_I, j * arm_A);
    B.omega += t2::reaction(angular_velocity_change_of_moment(b.inv_I, j * arm_B));
}

/// \srs{IM3} The same from the anchors r_AP, r_BP.
template <class V>
void apply_impulse(VelocitiesOver<V>& A, VelocitiesOver<V>& B, InverseInertiaOver<V> a,
                   InverseInertiaOver<V> b, Vec2<Over<Length, V>> r_AP, Vec2<Over<Length, V>> r_BP,
                   Vec2<V> n, Over<Impulse, V> j) {
    apply_impulse(A, B, a, b, dd08::moment_arm(r_AP, n), dd08::moment_arm(r_BP, n), n, j);
}

/// \srs{IM3} Normal relative velocity of A with respect to B at P: (v^AP - v^BP) . n (DD9 along
/// n, DD11), from the moment arms arm_A = r_AP x n, arm_B = r_BP x n.
template <class V>
Over<Velocity, V> normal_relative_velocity(const VelocitiesOver<V>& A, const VelocitiesOver<V>& B,
                                           Over<Length, V> arm_A, Over<Length, V> arm_B,
                                           Vec2<V> n) {
    return dd11::relative_velocity(dd09::point_velocity_along(A.v, A.omega, arm_A, n),
                                   dd09::point_velocity_along(B.v, B.omega, arm_B, n));
}

/// \srs{IM3} The same from the anchors r_AP, r_BP.
template <class V>
Over<Velocity, V> normal_relative_velocity(const VelocitiesOver<V>& A, const VelocitiesOver<V>& B,
                                           Vec2<Over<Length, V>> r_AP, Vec2<Over<Length, V>> r_BP,
                                           Vec2<V> n) {
    return normal_relative_velocity(A, B, dd08::moment_arm(r_AP, n), dd08::moment_arm(r_BP, n), n);
}

/// \srs{IM3} Collision response for one vertex-edge contact (A5, no friction A6): the impulse of
/// DD8 applied as above. n points from B into A (A's outward velocity is +n), so approaching
/// bodies have v^AB . n < 0. Returns j (zero when the bodies are already separating).
inline Impulse resolve(Velocities& A, Velocities& B, InverseInertia a, InverseInertia b,
                       Vec2<Length> r_AP, Vec2<Length> r_BP, Normal n, Dimensionless C_R) {
    const Velocity vn = normal_relative_velocity(A, B, r_AP, r_BP, n);
    if (vn >= Velocity{})
        return Impulse{};
    const Impulse j =
        dd08::collision_impulse(C_R, vn, dd08::effective_mass_inverse(a, b, r_AP, r_BP, n));
    apply_impulse(A, B, a, b, r_AP, r_BP, n, j);
    return j;
}

} // namespace tamias2d::model::im3
