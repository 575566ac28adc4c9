// The 2x2 linear complementarity problem of a two-point manifold (LC1, edge-edge contact):
// find x >= 0 with w = K x + b >= 0 and x_i w_i = 0. Solving both points together, exactly,
// is what makes two equal boxes meeting face to face swap velocities without spin; solving
// them one after the other (Box2D v3) leaves spin and loses energy.
#pragma once

namespace tamias2d {

struct TwoPointSolution {
    double x1 = 0.0, x2 = 0.0;
};

/// Enumerates the four cases (both active, only 1, only 2, none) in that order, as Box2D 2.4's
/// block solver does; K must be positive definite (checked by the caller's condition test).
inline TwoPointSolution solve_two_point_lcp(double k11, double k12, double k22, double inv11,
                                            double inv12, double inv22, double b1, double b2) {
    // Both active: x = -K^-1 b.
    double x1 = -(inv11 * b1 + inv12 * b2);
    double x2 = -(inv12 * b1 + inv22 * b2);
    if (x1 >= 0.0 && x2 >= 0.0)
        return {x1, x2};
    // Only point 1 active: w1 = 0, x2 = 0, need w2 >= 0.
    x1 = -b1 / k11;
    if (x1 >= 0.0 && k12 * x1 + b2 >= 0.0)
        return {x1, 0.0};
    // Only point 2 active.
    x2 = -b2 / k22;
    if (x2 >= 0.0 && k12 * x2 + b1 >= 0.0)
        return {0.0, x2};
    // Neither: both separating on their own.
    if (b1 >= 0.0 && b2 >= 0.0)
        return {0.0, 0.0};
    // Unreachable for a positive definite K; be safe rather than push bodies apart.
    return {0.0, 0.0};
}

} // namespace tamias2d
