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

using kernels::cos_kernel;
using kernels::pi_over_4;
using kernels::sin_kernel;

SinCos sincos_reduced(double x) {
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
