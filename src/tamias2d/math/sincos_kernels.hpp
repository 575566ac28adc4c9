// sin and cos on |r| <= pi/4 (and a rounding): the minimax polynomials of the project's sincos
// (math/sincos.cpp says how they were made: verification/trig/trig_constants.py), inline so that a
// small angle, the most common argument of a step (a substep's turn, a body near its resting
// angle), costs no call and no argument reduction. Only + - * on doubles (see error_free.hpp): the
// same bits everywhere.
#pragma once

#include "tamias2d/math/error_free.hpp"

namespace tamias2d::math::kernels {

// sin r = r + r^3 S(z): relative error of the rounded coefficients below 2^-56.3 on [0, pi/4].
inline constexpr double s1 = -0x1.5555555555548p-3;
inline constexpr double s2 = 0x1.111111110f7d0p-7;
inline constexpr double s3 = -0x1.a01a019bfdf01p-13;
inline constexpr double s4 = 0x1.71de3567d4709p-19;
inline constexpr double s5 = -0x1.ae5e5a927d541p-26;
inline constexpr double s6 = 0x1.5d8fd1f6f1c47p-33;
// cos r = 1 - z/2 + z^2 C(z): relative error below 2^-59.6.
inline constexpr double k1 = 0x1.555555555554bp-5;
inline constexpr double k2 = -0x1.6c16c16c14f91p-10;
inline constexpr double k3 = 0x1.a01a019c844f4p-16;
inline constexpr double k4 = -0x1.27e4f7eac4aa5p-22;
inline constexpr double k5 = 0x1.1ee9d7b4d75b3p-29;
inline constexpr double k6 = -0x1.8fa49a01b68b1p-37;

inline constexpr double pi_over_4 = 0x1.921fb54442d18p-1;

/// sin(x + y) for |x| <= pi/4 (and a rounding), |y| <= ulp(x): the small terms are summed
/// first and x added last, so that only the last addition's rounding reaches the result's ulp;
/// y enters as cos(x) y, with cos x = 1 - x^2/2 to the accuracy its size needs.
inline double sin_kernel(double x, double y) {
    const double z = x * x;
    const double v = z * x;
    const double p = s2 + z * (s3 + z * (s4 + z * (s5 + z * s6)));
    return x + (v * (s1 + z * p) + y * (1.0 - 0.5 * z));
}

/// cos(x + y), same ranges: 1 - z/2 with its rounding error carried (1 - w is exact, and so is
/// its difference from z/2, Sterbenz's lemma), z = x^2 exactly as a double-double, so that the
/// result has only the last addition's rounding of the order of its ulp.
inline double cos_kernel(double x, double y) {
    const DoubleDouble z = two_product(x, x);
    const double hz = 0.5 * z.hi;
    const double w = 1.0 - hz;
    const double q = k1 + z.hi * (k2 + z.hi * (k3 + z.hi * (k4 + z.hi * (k5 + z.hi * k6))));
    return w + (((1.0 - w) - hz) + ((z.hi * z.hi) * q - (0.5 * z.lo + x * y)));
}

} // namespace tamias2d::math::kernels
