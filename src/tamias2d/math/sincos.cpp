// The method: reduce x to r = x - n pi/2, |r| <= pi/4, as a double-double
// (quadrant_reduction.cpp: Cody and Waite below 1.6e6, Payne and Hanek above), evaluate sin and
// cos of r by minimax polynomials, and pick and sign them by n mod 4 (as in Cody and Waite,
// Software Manual for the Elementary Functions, 1980, ch. 8 and 9). The polynomials' coefficients
// are our own, computed by Remez's exchange algorithm for the relative error on [0, (pi/4)^2] in
// z = r^2 (verification/trig/trig_constants.py, which prints them and their error bounds).
// Only + - * on doubles, in round to nearest without excess precision or contraction: the same
// bits everywhere.
#include "tamias2d/math/sincos.hpp"

#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "tamias2d/math/error_free.hpp"
#include "tamias2d/math/quadrant_reduction.hpp"

#if defined(__FAST_MATH__)
#error "sincos.cpp relies on IEEE 754 arithmetic: do not compile it with -ffast-math"
#endif
static_assert(FLT_EVAL_METHOD == 0,
              "sincos needs each double operation rounded to double (no x87 excess precision)");

namespace tamias2d::math {
namespace {

// sin r = r + r^3 S(z): relative error of the rounded coefficients below 2^-56.3 on [0, pi/4].
constexpr double s1 = -0x1.5555555555548p-3;
constexpr double s2 = 0x1.111111110f7d0p-7;
constexpr double s3 = -0x1.a01a019bfdf01p-13;
constexpr double s4 = 0x1.71de3567d4709p-19;
constexpr double s5 = -0x1.ae5e5a927d541p-26;
constexpr double s6 = 0x1.5d8fd1f6f1c47p-33;
// cos r = 1 - z/2 + z^2 C(z): relative error below 2^-59.6.
constexpr double k1 = 0x1.555555555554bp-5;
constexpr double k2 = -0x1.6c16c16c14f91p-10;
constexpr double k3 = 0x1.a01a019c844f4p-16;
constexpr double k4 = -0x1.27e4f7eac4aa5p-22;
constexpr double k5 = 0x1.1ee9d7b4d75b3p-29;
constexpr double k6 = -0x1.8fa49a01b68b1p-37;

constexpr double pi_over_4 = 0x1.921fb54442d18p-1;

/// sin(x + y) for |x| <= pi/4 (and a rounding), |y| <= ulp(x): the small terms are summed
/// first and x added last, so that only the last addition's rounding reaches the result's ulp;
/// y enters as cos(x) y, with cos x = 1 - x^2/2 to the accuracy its size needs.
double sin_kernel(double x, double y) {
    const double z = x * x;
    const double v = z * x;
    const double p = s2 + z * (s3 + z * (s4 + z * (s5 + z * s6)));
    return x + (v * (s1 + z * p) + y * (1.0 - 0.5 * z));
}

/// cos(x + y), same ranges: 1 - z/2 with its rounding error carried (1 - w is exact, and so is
/// its difference from z/2, Sterbenz's lemma), z = x^2 exactly as a double-double, so that the
/// result has only the last addition's rounding of the order of its ulp.
double cos_kernel(double x, double y) {
    const DoubleDouble z = two_product(x, x);
    const double hz = 0.5 * z.hi;
    const double w = 1.0 - hz;
    const double q = k1 + z.hi * (k2 + z.hi * (k3 + z.hi * (k4 + z.hi * (k5 + z.hi * k6))));
    return w + (((1.0 - w) - hz) + ((z.hi * z.hi) * q - (0.5 * z.lo + x * y)));
}

} // namespace

SinCos sincos(double x) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &x, sizeof bits); // (no std::bit_cast in the WebAssembly build's libc++)
    const bool negative = (bits >> 63) != 0;
    const double ax = std::fabs(x);
    if (!(ax <= DBL_MAX)) { // infinite or NaN
        const double nan = x - x;
        return {nan, nan};
    }
    double s = 0.0;
    double c = 1.0;
    if (ax <= pi_over_4) {
        s = sin_kernel(ax, 0.0);
        c = cos_kernel(ax, 0.0);
    } else {
        const QuadrantReduction red = reduce_quadrant(ax);
        const double sr = sin_kernel(red.r.hi, red.r.lo);
        const double cr = cos_kernel(red.r.hi, red.r.lo);
        switch (red.quadrant) {
        case 0:
            s = sr, c = cr;
            break;
        case 1:
            s = cr, c = -sr;
            break;
        case 2:
            s = -sr, c = -cr;
            break;
        default:
            s = -cr, c = sr;
            break;
        }
    }
    return {negative ? -s : s, c}; // sin is odd, cos even
}

} // namespace tamias2d::math
