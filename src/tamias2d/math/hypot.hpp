// The length of a vector, sqrt(x^2 + y^2), without overflow or underflow of the squares, from
// + - * / and sqrt alone (IEEE 754 rounds them exactly, unlike libm's hypot, whose last bit
// differs between C libraries): the same bits on every platform.
#pragma once

#include <cmath>
#include <limits>

#include "tamias2d/math/error_free.hpp"

namespace tamias2d::math {

/// sqrt(x^2 + y^2) within 1 ulp on every argument tested (tests/model/test_hypot.cpp), C's hypot
/// for infinities and NaNs. The method of Borges ("An improved algorithm for hypot(a, b)",
/// arXiv:1904.09481, 2019): the squares summed exactly as double-doubles, then the rounded root
/// corrected by one Newton step on its exact residual, with Dekker's product where Borges uses a
/// fused multiply-add. The larger component is first brought near 1 by a power of two (exact) when
/// its square could leave the normal range.
inline double hypot(double x, double y) {
    double a = std::fabs(x);
    double b = std::fabs(y);
    constexpr double inf = std::numeric_limits<double>::infinity();
    if (!(a < inf) || !(b < inf))                  // infinite or NaN:
        return a == inf || b == inf ? inf : a + b; // inf if either is (C's rule), else NaN
    if (a < b) {
        const double t = a;
        a = b;
        b = t;
    }
    if (a == 0.0)
        return 0.0;
    double scale = 1.0;
    if (a > 0x1p+300)
        scale = 0x1p-600;
    else if (a < 0x1p-300)
        scale = 0x1p+600;
    a *= scale;
    b *= scale;
    const DoubleDouble aa = two_product(a, a);
    const DoubleDouble bb = two_product(b, b);
    const DoubleDouble s = two_sum(aa.hi, bb.hi);
    const double sum_lo = s.lo + (aa.lo + bb.lo);
    const double r = std::sqrt(s.hi + sum_lo);
    const DoubleDouble rr = two_product(r, r);
    const double residual = ((s.hi - rr.hi) - rr.lo) + sum_lo; // s - r^2, the leading terms exact
    return (r + residual / (2.0 * r)) / scale;
}

} // namespace tamias2d::math
