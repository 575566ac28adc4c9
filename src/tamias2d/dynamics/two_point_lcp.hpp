// The 2x2 linear complementarity problem of a two-point manifold (LC1, edge-edge contact):
// find x >= 0 with w = K x + b >= 0 and x_i w_i = 0. Solving both points together, exactly,
// is what makes two equal boxes meeting face to face swap velocities without spin; solving
// them one after the other (Box2D v3) leaves spin and loses energy.
#pragma once

#include "tamias2d/math/wide.hpp"

namespace tamias2d {

template <class V> struct TwoPointSolution { V x1{}, x2{}; };

/// Tries the four cases (both active, only 1, only 2, none) in that order, as Box2D 2.4's
/// block solver does, and keeps the first that holds; K must be positive definite (checked by
/// the caller's condition test), inv11..inv22 are K^-1 and m1 = 1 / K11, m2 = 1 / K22 the
/// points' own effective masses. V is double or a pack of lanes: every case is computed and the
/// first valid one selected lane by lane (for a lane whose K is not used, the values are
/// discarded by the caller).
template <class V>
TwoPointSolution<V> solve_two_point_lcp(V k12, V inv11, V inv12, V inv22, V m1, V m2, V b1, V b2) {
    const V zero = broadcast<V>(0.0);
    // Both active: x = -K^-1 b.
    const V both1 = -(inv11 * b1 + inv12 * b2);
    const V both2 = -(inv12 * b1 + inv22 * b2);
    const auto both_active = both(both1 >= zero, both2 >= zero);
    // Only point 1 active: w1 = 0, x2 = 0, need w2 >= 0.
    const V only1 = -b1 * m1;
    const auto first_active = both(only1 >= zero, k12 * only1 + b2 >= zero);
    // Only point 2 active.
    const V only2 = -b2 * m2;
    const auto second_active = both(only2 >= zero, k12 * only2 + b1 >= zero);
    // Neither (both separating on their own; for a positive definite K the last case left):
    // no impulse rather than one that pushes the bodies apart.
    return {
        select(both_active, both1, select(first_active, only1, zero)),
        select(both_active, both2, select(first_active, zero, select(second_active, only2, zero)))};
}

} // namespace tamias2d
