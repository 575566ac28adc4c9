// The argument reduction of sincos: x = n pi/2 + r with |r| <= pi/4 (to a rounding), r carried
// as a double-double, so that sin and cos of x follow from those of r and n mod 4.
#pragma once

#include "tamias2d/math/error_free.hpp"

namespace tamias2d::math {

struct QuadrantReduction {
    int quadrant = 0; ///< n mod 4
    DoubleDouble r;   ///< x - n pi/2, to about 2^-100 relative
};

/// Cody and Waite's reduction (Software Manual for the Elementary Functions, 1980, ch. 8), inline
/// so that a loop over many arguments can run it in lanes (sincos_batch.cpp).
namespace cody_waite {

// Computed from pi to 1400 bits by verification/trig/trig_constants.py. pi/2 = c1 + c2 + c3 + c4
// to 2^-160, c1 to c3 of 33 significant bits each, so that n ck is exact for n <= 2^20.
inline constexpr double two_over_pi = 0x1.45f306dc9c883p-1;
inline constexpr double c1 = 0x1.921fb544p+0;
inline constexpr double c2 = 0x1.0b4611a6p-34;
inline constexpr double c3 = 0x1.3198a2ep-69;
inline constexpr double c4 = 0x1.b839a252049c1p-104;
/// Below this, n = round(x 2/pi) <= 1043038 < 2^20.
inline constexpr double limit = 0x1.9p+20;
/// Adding it to a double below 2^51 rounds that to an integer, which its bits then end in.
inline constexpr double round_shift = 0x1.8p52;

struct Reduction {
    double n = 0.0; ///< round(x 2/pi), an integer
    DoubleDouble r; ///< x - n pi/2
};

/// x = n pi/2 + r for 0 <= x < limit.
inline Reduction reduce(double x) {
    // n = round(x 2/pi) by the shift (round to nearest, no excess precision: FLT_EVAL_METHOD
    // == 0, sincos.cpp checks it).
    const double n = (x * two_over_pi + round_shift) - round_shift;
    const double r = x - n * c1; // exact: n c1 is, and x lies within [n c1 / 2, 2 n c1] (Sterbenz)
    const DoubleDouble a = two_sum(r, -(n * c2));
    const DoubleDouble b = two_sum(a.hi, -(n * c3));
    const double lo = (a.lo + b.lo) - n * c4;
    return {n, two_sum(b.hi, lo)};
}

} // namespace cody_waite

/// Reduces a finite x >= 0. Below 1.6e6 (n <= 2^20): Cody and Waite's method with pi/2 split
/// into four parts; above: Payne and Hanek's, with the bits of 2/pi in integers. Both use only
/// exact integer operations and + - * on doubles, so the result is the same on every IEEE 754
/// platform.
QuadrantReduction reduce_quadrant(double x);

} // namespace tamias2d::math
