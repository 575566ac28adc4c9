#pragma once
#include "tamias2d/math/wide.hpp"
#include "tamias2d/model/dd08_collision_impulse.hpp"
#include "tamias2d/model/dd09_chasles_theorem.hpp"
#include "tamias2d/model/dd10_impulse.hpp"
#include "tamias2d/model/im3_collision_response.hpp"
#include "tamias2d/model/im6_motion_with_joints.hpp"
#include "tamias2d/model/t2_newtons_third_law.hpp"
#include "tamias2d/units/angle.hpp"
#include "tamias2d/units/vec2.hpp"

// Each function is a template over V, the values' type: double for one joint, a pack of lanes
// (math/wide.hpp) for four plain pins at once (dynamics/joints/pin_packs.hpp), with the same
// operations in the same order, so each lane's bits are one joint's.
namespace tamias2d::model::dd19 {
using namespace tamias2d::units;
using dd08::InverseInertia;
using dd08::InverseInertiaOver;
using im3::Velocities;
using im3::VelocitiesOver;

/// \srs{DD19} The pin's effective inverse mass K, symmetric: its entries k11, k12 = k21, k22.
template <class V> struct PinMassOver { Over<InverseMass, V> k11, k12, k22; };
using PinMass = PinMassOver<double>;

/// \srs{DD19} Position error C = (p_B - p_A) + (r_B - r_A): the pin on B minus the pin on A,
/// from the centres' offset and the pin's offsets from each centre.
template <class V>
Vec2<Over<Length, V>> position_error(Vec2<Over<Length, V>> center_offset, Vec2<Over<Length, V>> r_A,
                                     Vec2<Over<Length, V>> r_B) {
    return center_offset + (r_B - r_A);
}

/// \srs{DD19} Velocity error Cdot = v_B + omega_B x r_B - (v_A + omega_A x r_A), each term
/// Chasles' theorem (DD9) at the pin.
template <class V>
Vec2<Over<Velocity, V>> velocity_error(const VelocitiesOver<V>& A, Vec2<Over<Length, V>> r_A,
                                       const VelocitiesOver<V>& B, Vec2<Over<Length, V>> r_B) {
    return dd09::point_velocity(B.v, B.omega, r_B) - dd09::point_velocity(A.v, A.omega, r_A);
}

/// \srs{DD19} K = (1/m_A + 1/m_B) 1 + [r_A]x^T [r_A]x / I_A + [r_B]x^T [r_B]x / I_B, with
/// [r]x = (-r_y, r_x) (omega x r = omega [r]x).
template <class V>
PinMassOver<V> effective_mass_inverse(InverseInertiaOver<V> A, InverseInertiaOver<V> B,
                                      Vec2<Over<Length, V>> r_A, Vec2<Over<Length, V>> r_B) {
    const auto ax = per_radian(r_A.x), ay = per_radian(r_A.y);
    const auto bx = per_radian(r_B.x), by = per_radian(r_B.y);
    const Over<InverseMass, V> m = A.inv_m + B.inv_m;
    return {m + A.inv_I * ay * ay + B.inv_I * by * by, -(A.inv_I * ay * ax) - B.inv_I * by * bx,
            m + A.inv_I * ax * ax + B.inv_I * bx * bx};
}

/// \srs{DD19} The impulse P = -K^-1 (Cdot + b) that stops the pin's velocity error (b: IM6's
/// bias), in IM6's soft form: P = -mass_scale K^-1 (Cdot + b) - impulse_scale P_acc, where
/// P_acc is the impulse accumulated so far (rigid: mass_scale 1, impulse_scale 0). K^-1 by
/// Cramer's rule (K is 2 x 2 and positive definite, DCX_joint).
template <class V, class S>
Vec2<Over<Impulse, V>> impulse(PinMassOver<V> K, Vec2<Over<Velocity, V>> rhs, S mass_scale,
                               S impulse_scale, Vec2<Over<Impulse, V>> accumulated) {
    // One division: the determinant's inverse scales both components (two divisions in a row
    // were the joint solve's longest latency).
    const auto inv_det = broadcast<V>(1.0) / (K.k11 * K.k22 - K.k12 * K.k12);
    const Vec2<Over<Impulse, V>> solved{(K.k22 * rhs.x - K.k12 * rhs.y) * inv_det,
                                        (K.k11 * rhs.y - K.k12 * rhs.x) * inv_det};
    return im6::soft_impulse(mass_scale, -solved, impulse_scale, accumulated);
}

/// \srs{DD19} P at the pin: +P on B, -P on A (T2); each velocity changes by P / m (DD10), each
/// angular velocity by r x P / I (IM3's angular jump of the moment r x P).
template <class V>
void apply(VelocitiesOver<V>& A, VelocitiesOver<V>& B, InverseInertiaOver<V> a,
           InverseInertiaOver<V> b, Vec2<Over<Length, V>> r_A, Vec2<Over<Length, V>> r_B,
           Vec2<Over<Impulse, V>> P) {
    B.v += dd10::velocity_change(P, b.inv_m);
    A.v += t2::reaction(dd10::velocity_change(P, a.inv_m));
    B.omega += im3::angular_velocity_change_of_moment(b.inv_I, cross(r_B, P));
    A.omega += t2::reaction(im3::angular_velocity_change_of_moment(a.inv_I, cross(r_A, P)));
}

} // namespace tamias2d::model::dd19
