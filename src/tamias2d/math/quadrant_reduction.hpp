// The argument reduction of sincos: x = n pi/2 + r with |r| <= pi/4 (to a rounding), r carried
// as a double-double, so that sin and cos of x follow from those of r and n mod 4.
#pragma once

#include "tamias2d/math/error_free.hpp"

namespace tamias2d::math {

struct QuadrantReduction {
    int quadrant = 0; ///< n mod 4
    DoubleDouble r;   ///< x - n pi/2, to about 2^-100 relative
};

/// Reduces a finite x >= 0. Below 1.6e6 (n <= 2^20): Cody and Waite's method with pi/2 split
/// into four parts; above: Payne and Hanek's, with the bits of 2/pi in integers. Both use only
/// exact integer operations and + - * on doubles, so the result is the same on every IEEE 754
/// platform.
QuadrantReduction reduce_quadrant(double x);

} // namespace tamias2d::math
