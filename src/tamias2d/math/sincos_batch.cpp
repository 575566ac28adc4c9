// The lanes compute what sincos.cpp's sincos_reduced computes for the same x, operation for
// operation: Cody and Waite's reduction, the kernels at (r.hi, r.lo), and the quadrant's choice
// and signs. For |x| <= pi/4 the reduction has n = 0 and gives r = (|x|, 0): the kernels at
// (|x|, 0), sincos's own small case. The choice is made on the results' bits rather than by a
// switch, so that the loop has no branch and vectorises: swap sin and cos for an odd quadrant,
// negate sin in quadrants 2 and 3 and cos in 1 and 2 (a sign bit flipped, as -s), and sin for a
// negative x. tests/model/test_dd32_rotation.cpp checks the bits against sincos.
#include "tamias2d/math/sincos_batch.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "tamias2d/math/quadrant_reduction.hpp"
#include "tamias2d/math/sincos.hpp"
#include "tamias2d/math/wide_kernel.hpp"

namespace tamias2d::math {
namespace {

std::uint64_t bits_of(double x) {
    std::uint64_t b = 0;
    std::memcpy(&b, &x, sizeof b);
    return b;
}

double from_bits(std::uint64_t b) {
    double x = 0.0;
    std::memcpy(&x, &b, sizeof x);
    return x;
}

constexpr std::uint64_t sign_bit = std::uint64_t{1} << 63;

/// The lanes' loop, for arguments whose magnitude is below cody_waite::limit (or anything: a
/// lane beyond it is computed wrongly here and redone by the caller).
TAMIAS_WIDE_KERNEL void reduced_lanes(const double* x, double* s, double* c, std::size_t n) {
    for (std::size_t k = 0; k < n; ++k) {
        const std::uint64_t xb = bits_of(x[k]);
        const double ax = from_bits(xb & ~sign_bit);
        const cody_waite::Reduction red = cody_waite::reduce(ax);
        const std::uint64_t q = bits_of(red.n + cody_waite::round_shift) & 3; // n mod 4
        const std::uint64_t sr = bits_of(kernels::sin_kernel(red.r.hi, red.r.lo));
        const std::uint64_t cr = bits_of(kernels::cos_kernel(red.r.hi, red.r.lo));
        const std::uint64_t swap = (sr ^ cr) & (std::uint64_t{0} - (q & 1));
        s[k] = from_bits((sr ^ swap) ^ ((q & 2) << 62) ^ (xb & sign_bit));
        c[k] = from_bits((cr ^ swap) ^ (((q ^ (q >> 1)) & 1) << 63));
    }
}

} // namespace

void sincos_batch(const double* x, double* s, double* c, std::size_t n) {
    reduced_lanes(x, s, c, n);
    for (std::size_t k = 0; k < n; ++k) {
        if (!(std::fabs(x[k]) < cody_waite::limit)) { // (true for NaN)
            const SinCos r = sincos(x[k]);
            s[k] = r.sin;
            c[k] = r.cos;
        }
    }
}

} // namespace tamias2d::math
