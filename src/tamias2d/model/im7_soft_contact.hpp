#pragma once
#include <algorithm>
#include <numbers>

#include "tamias2d/math/wide.hpp"
#include "tamias2d/units/quantities.hpp"

namespace tamias2d::model::im7 {
using namespace tamias2d::units;

/// The soft constraint's three coefficients for one substep (IM7; IM6's joint springs use the
/// same ones).
struct Softness {
    Rate bias_rate;              ///< velocity bias per metre of overlap (s^-1)
    Dimensionless mass_scale;    ///< fraction of the rigid impulse applied
    Dimensionless impulse_scale; ///< fraction of the accumulated impulse relaxed away
};

/// \srs{IM7} The contact spring's frequency: the requested one, capped at a quarter of the
/// substep rate n / dt, above which the implicit step no longer resolves the spring.
inline Rate frequency(Rate requested, int substeps, Time dt) {
    return std::min(requested, 0.25 * substeps / dt);
}

/// \srs{IM7} Backward Euler over a substep h of the damped spring x'' = -omega^2 x -
/// 2 zeta omega x' (omega = 2 pi f) acting on the constraint's effective mass, written as a
/// correction of the rigid impulse: with a = h omega (2 zeta + h omega), the bias rate is
/// omega / (2 zeta + h omega), the mass scale a / (1 + a) and the impulse scale 1 / (1 + a).
/// f = 0 is the rigid constraint (mass scale 1, nothing relaxed).
inline Softness softness(Rate f, Dimensionless zeta, Time h) {
    if (f == Rate{})
        return {Rate{}, Dimensionless{1.0}, Dimensionless{}};
    const Rate omega = 2.0 * std::numbers::pi * f;
    const Dimensionless a1 = 2.0 * zeta + h * omega;
    const Dimensionless a2 = h * omega * a1;
    const Dimensionless a3 = 1.0 / (1.0 + a2);
    return {omega / a1, a2 * a3, a3};
}

/// \srs{IM7} The soft impulse of one iteration: the rigid impulse (DD8's impulse_to_reach
/// towards the point's target) scaled by the mass scale, minus the relaxed share of the
/// impulse accumulated so far. Q: an impulse (N s), a vector of them or an angular impulse (a
/// joint's, IM6), of doubles or of packs of lanes; S: the scales, dimensionless (plain values
/// of the packs' type, or quantities).
template <class S, class Q> Q soft_impulse(S mass_scale, Q rigid, S impulse_scale, Q accumulated) {
    return rigid * mass_scale - accumulated * impulse_scale;
}

/// \srs{IM7} The speculative target: a point still `gap` > 0 apart may close the gap within the
/// substep h, no faster, v* = -gap / h. From 1/h (the contacts' form: one product per lane,
/// 1/h computed once per step) or from h (the joints' limits, IM6: one division); the two
/// differ in the last bit, so each caller keeps its own. The gap may be a length or an angle.
template <class G, class V> auto closing_velocity(G gap, Over<Rate, V> inv_h) {
    return -(gap * inv_h);
}
template <class G> auto closing_velocity(G gap, Time h) {
    return -(gap / h);
}

/// A point's target for one iteration (IM7's v*) and the scales its impulse takes.
template <class Q, class V> struct Target {
    Q velocity;
    V mass_scale;
    V impulse_scale;
};

/// \srs{IM7} v*_j for separation s (negative: overlap): a speculative gap (s > 0) closes within
/// the substep (closing_velocity, rigid); otherwise the soft iteration pushes an overlap beyond
/// the slop out at the bias rate times its depth, at most v_push, with the softness' mass and
/// impulse scales, and the rigid relax (soft = false) stops the approach (v* = 0, rigid). V: a
/// double, or a pack of lanes, each taking its own case (lane selects); the separation may be
/// a length (contacts, a joint's travel) or an angle (a joint's limits), the velocities of its
/// rate. Joint limits have no slop and no cap (slop 0, v_push infinite).
template <bool soft, class G, class Step, class Vel, class V = typename G::value_type>
Target<Vel, V> target_velocity(G s, Step step, Over<Rate, V> bias_rate, V mass_scale,
                               V impulse_scale, G slop, Vel push_max) {
    const V zero = broadcast<V>(0.0);
    const V one = broadcast<V>(1.0);
    const auto speculative = s.value() > zero;
    const V closing = Vel(closing_velocity(s, step)).value();
    if constexpr (!soft) {
        return {Vel::from_value(select(speculative, closing, zero)), one, zero};
    } else {
        const V push = (bias_rate * G::from_value(min((s + slop).value(), zero))).value();
        const V bias = max(push, -push_max.value());
        return {Vel::from_value(select(speculative, closing, -bias)),
                select(speculative, one, mass_scale), select(speculative, zero, impulse_scale)};
    }
}

/// The 2x2 matrix K of two points of one manifold (DD8 generalised, kg^-1) and its inverse
/// (kg; zeros where K is not inverted).
template <class V> struct PairMass {
    Over<InverseMass, V> k11, k12, k22;
    Over<Mass, V> inv11, inv12, inv22;
};
template <class V> struct PairImpulses { Over<Impulse, V> x1, x2; };

/// \srs{IM7} Two points of one manifold solved together (LC1): the impulses x >= 0 with
/// w = K x + b >= 0 and x_i w_i = 0, where b is each point's velocity without the accumulated
/// impulses x_acc, minus its target (b = v - t - K x_acc). The four cases are tried in order
/// (both active: x = -K^-1 b; only point 1: x1 = -b1 m1 with w2 >= 0; only point 2; neither),
/// as Box2D 2.4's block solver does, and the first that holds is kept; K must be positive
/// definite (the caller's condition test), m1 = 1 / K11 and m2 = 1 / K22 the points' own
/// effective masses. Solving both points at once is what lets two equal boxes meeting face to
/// face swap velocities without spin. V: a double or a pack of lanes (every case computed, the
/// first valid one selected lane by lane).
template <class V>
PairImpulses<V> two_point_impulses(const PairMass<V>& K, Over<Mass, V> m1, Over<Mass, V> m2,
                                   Over<Velocity, V> v1, Over<Velocity, V> v2, Over<Velocity, V> t1,
                                   Over<Velocity, V> t2, Over<Impulse, V> acc1,
                                   Over<Impulse, V> acc2) {
    using I = Over<Impulse, V>;
    const V zero = broadcast<V>(0.0);
    const Over<Velocity, V> b1 = v1 - t1 - (K.k11 * acc1 + K.k12 * acc2);
    const Over<Velocity, V> b2 = v2 - t2 - (K.k12 * acc1 + K.k22 * acc2);
    // Both active: x = -K^-1 b.
    const V both1 = (-(K.inv11 * b1 + K.inv12 * b2)).value();
    const V both2 = (-(K.inv12 * b1 + K.inv22 * b2)).value();
    const auto both_active = both(both1 >= zero, both2 >= zero);
    // Only point 1 active: w1 = 0, x2 = 0, need w2 >= 0.
    const V only1 = (-b1 * m1).value();
    const auto first_active =
        both(only1 >= zero, (K.k12 * I::from_value(only1) + b2).value() >= zero);
    // Only point 2 active.
    const V only2 = (-b2 * m2).value();
    const auto second_active =
        both(only2 >= zero, (K.k12 * I::from_value(only2) + b1).value() >= zero);
    // Neither (both separating on their own; for a positive definite K the last case left):
    // no impulse rather than one that pushes the bodies apart.
    return {I::from_value(select(both_active, both1, select(first_active, only1, zero))),
            I::from_value(select(both_active, both2,
                                 select(first_active, zero, select(second_active, only2, zero))))};
}

} // namespace tamias2d::model::im7
