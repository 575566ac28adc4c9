// Error-free transformations: a sum or a product of two doubles as the rounded result plus its
// exact rounding error (Knuth's TwoSum, Dekker's Fast2Sum, and Dekker's product with Veltkamp's
// splitting; Muller et al., Handbook of Floating-Point Arithmetic, 2nd ed., ch. 4). Only + - *
// in round-to-nearest, no fused multiply-add (the library compiles with -ffp-contract=off, and
// a contraction would break the identities), so the results are the same on every IEEE 754
// platform. Used where one double is not precise enough: the argument reduction of sincos.
#pragma once

namespace tamias2d::math {

/// A value as an unevaluated sum hi + lo, |lo| <= ulp(hi) / 2.
struct DoubleDouble {
    double hi = 0.0;
    double lo = 0.0;
};

/// a + b = hi + lo exactly, for any a and b (no overflow): Knuth's TwoSum, six operations.
constexpr DoubleDouble two_sum(double a, double b) {
    const double s = a + b;
    const double bb = s - a;
    const double err = (a - (s - bb)) + (b - bb);
    return {s, err};
}

/// a + b = hi + lo exactly, when |a| >= |b| (or a == 0): Dekker's Fast2Sum, three operations.
constexpr DoubleDouble fast_two_sum(double a, double b) {
    const double s = a + b;
    return {s, b - (s - a)};
}

/// a = hi + lo with hi holding the upper 26 bits and lo the lower 26 (Veltkamp's splitting by
/// 2^27 + 1; |a| below 2^995, so that the product cannot overflow).
constexpr DoubleDouble split(double a) {
    const double c = 134217729.0 * a; // 2^27 + 1
    const double hi = c - (c - a);
    return {hi, a - hi};
}

/// a * b = hi + lo exactly (no overflow or underflow): Dekker's product, on the halves.
constexpr DoubleDouble two_product(double a, double b) {
    const double p = a * b;
    const DoubleDouble x = split(a);
    const DoubleDouble y = split(b);
    const double err = ((x.hi * y.hi - p) + x.hi * y.lo + x.lo * y.hi) + x.lo * y.lo;
    return {p, err};
}

} // namespace tamias2d::math
