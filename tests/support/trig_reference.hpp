// Reference sin and cos for the accuracy of the project's sincos (math/sincos.hpp), independent
// of it:
// * long_double_sincos: the C library's sinl and cosl of the argument reduced in long double
//   (x86-64's 80-bit format, 64-bit significand) with pi/2 split into 32 + 32 + 32 + 64 bits
//   and the reduction's roundings carried by TwoSum in long double; valid for |x| < 2^32,
//   accurate to about 2^-10 ulp of a double;
// * multiprecision_sincos: Boost.Multiprecision's sin and cos at 1400 bits (its own pi and
//   reduction), for any finite x (a 2^1023 argument keeps about 370 bits after its reduction).
// The constants are printed by verification/trig/trig_constants.py from pi to 1400 bits.
#pragma once

#include <cfloat>
#include <cmath>
#include <cstdint>

#include <boost/multiprecision/cpp_bin_float.hpp>

namespace tamias2d::test {

static_assert(LDBL_MANT_DIG >= 64,
              "the long double reference needs x86's 80-bit long double or wider");

struct LongSinCos {
    long double sin;
    long double cos;
};

namespace detail {
inline void two_sum(long double a, long double b, long double& s, long double& e) {
    s = a + b;
    const long double bb = s - a;
    e = (a - (s - bb)) + (b - bb);
}
} // namespace detail

/// sin x and cos x in long double, for |x| < 2^32.
inline LongSinCos long_double_sincos(double x) {
    constexpr long double p1 = 0xc.90fdaa2p-3L;
    constexpr long double p2 = 0x8.5a308d3p-37L;
    constexpr long double p3 = 0x9.8cc517p-72L;
    constexpr long double p4 = 0xd.c1cd129024e088ap-107L;
    constexpr long double two_over_pi = 0xa.2f9836e4e44152ap-4L;
    const long double ax = std::fabs(static_cast<long double>(x));
    const long double n = std::nearbyint(ax * two_over_pi); // n < 2^31: n pk exact for k <= 3
    long double h = ax - n * p1;                            // exact (Sterbenz)
    long double l1 = 0, l2 = 0;
    detail::two_sum(h, -(n * p2), h, l1);
    detail::two_sum(h, -(n * p3), h, l2);
    const long double l = (l1 + l2) - n * p4;
    // sin(h + l) = sin h + cos(h) l (l^2 is below 2^-120 of the result)
    const long double s = std::sin(h) + std::cos(h) * l;
    const long double c = std::cos(h) - std::sin(h) * l;
    long double rs = s, rc = c;
    switch (static_cast<std::int64_t>(n) & 3) {
    case 1:
        rs = c, rc = -s;
        break;
    case 2:
        rs = -s, rc = -c;
        break;
    case 3:
        rs = -c, rc = s;
        break;
    default:
        break;
    }
    return {std::signbit(x) ? -rs : rs, rc};
}

using Multiprecision = boost::multiprecision::number<
    boost::multiprecision::cpp_bin_float<1400, boost::multiprecision::digit_base_2>,
    boost::multiprecision::et_off>;

/// sin x and cos x at 1400 bits, rounded to long double, for any finite x.
inline LongSinCos multiprecision_sincos(double x) {
    const Multiprecision m(x);
    return {static_cast<long double>(sin(m)), static_cast<long double>(cos(m))};
}

/// |got - ref| in units in the last place of the double nearest ref (ulp: 2^(e - 52) for ref in
/// [2^e, 2^(e+1)); the subnormal spacing below DBL_MIN).
inline double ulp_error(double got, long double ref) {
    const long double a = std::fabs(ref);
    int e = 0;
    std::frexp(a, &e); // a in [2^(e-1), 2^e)
    const long double ulp = a < DBL_MIN ? std::ldexp(1.0L, -1074) : std::ldexp(1.0L, e - 53);
    return static_cast<double>(std::fabs(static_cast<long double>(got) - ref) / ulp);
}

} // namespace tamias2d::test
