#include "tamias2d/math/quadrant_reduction.hpp"

#include <cstdint>
#include <cstring>

namespace tamias2d::math {
namespace {

// Every constant below (and cody_waite's) is computed from pi to 1400 bits (Machin's formula,
// checked against pi's known hexadecimal digits) by verification/trig/trig_constants.py.
/// pi/2 as a double-double.
constexpr double pio2_hi = 0x1.921fb54442d18p+0;
constexpr double pio2_lo = 0x1.1a62633145c07p-54;

/// 2/pi's bits after the binary point, 32 to a word, after 64 zero bits (so that a window may
/// start before the point): enough for every finite double (x < 2^1024 needs bits up to 1162).
constexpr std::uint32_t two_over_pi_bits[41] = {
    0x00000000, 0x00000000, 0xa2f9836e, 0x4e441529, 0xfc2757d1, 0xf534ddc0, 0xdb629599,
    0x3c439041, 0xfe5163ab, 0xdebbc561, 0xb7246e3a, 0x424dd2e0, 0x06492eea, 0x09d1921c,
    0xfe1deb1c, 0xb129a73e, 0xe88235f5, 0x2ebb4484, 0xe99c7026, 0xb45f7e41, 0x3991d639,
    0x835339f4, 0x9c845f8b, 0xbdf9283b, 0x1ff897ff, 0xde05980f, 0xef2f118b, 0x5a0a6d1f,
    0x6d367ecf, 0x27cb09b7, 0x4f463f66, 0x9e5fea2d, 0x7527bac7, 0xebe5f17b, 0x3d0739f7,
    0x8a5292ea, 0x6bfb5fb1, 0x1f8d5d08, 0x56033046, 0xfc7b6bab, 0xf0cfbc20};

constexpr std::uint64_t low32 = 0xffffffffu;

/// Payne and Hanek ("Radian reduction for trigonometric functions", SIGNUM Newsletter 18(1),
/// 1983): x = m 2^e (m < 2^53) times 2/pi modulo 4, from the 192 bits of 2/pi that matter: the
/// earlier ones make multiples of 4, the later ones less than 2^-135 of a quarter turn.
QuadrantReduction payne_hanek(double x) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &x, sizeof bits); // (no std::bit_cast in the WebAssembly build's libc++)
    const int e = static_cast<int>(bits >> 52) - 1075; // x >= 2^20: normal
    const std::uint64_t m = (bits & ((std::uint64_t{1} << 52) - 1)) | (std::uint64_t{1} << 52);
    // The window: bits e - 1 .. e + 190 of 2/pi (bit i weighs 2^-i), as six words, least
    // significant first; m W 2^-190 is x 2/pi modulo 4.
    const int start = e - 1 + 63;
    const int word = start / 32;
    const int shift = start % 32;
    std::uint64_t w[6];
    for (int t = 0; t < 6; ++t) {
        const int k = word + 5 - t;
        const std::uint64_t pair =
            (std::uint64_t{two_over_pi_bits[k]} << 32) | two_over_pi_bits[k + 1];
        w[t] = (pair >> (32 - shift)) & low32;
    }
    // P = m W mod 2^192, in six 32-bit limbs.
    std::uint64_t p[6];
    const std::uint64_t m0 = m & low32;
    const std::uint64_t m1 = m >> 32;
    std::uint64_t carry = 0;
    for (int s = 0; s < 6; ++s) {
        const std::uint64_t t = m0 * w[s] + carry;
        p[s] = t & low32;
        carry = t >> 32;
    }
    carry = 0;
    for (int s = 0; s + 1 < 6; ++s) {
        const std::uint64_t t = m1 * w[s] + p[s + 1] + carry;
        p[s + 1] = t & low32;
        carry = t >> 32;
    }
    // The top two bits are the quadrant, the 190 below the fraction f of a quarter turn; from
    // f >= 1/2 on, the next quadrant and f - 1 (its magnitude: the 190-bit complement).
    int quadrant = static_cast<int>(p[5] >> 30);
    p[5] &= 0x3fffffffu;
    const bool negative = ((p[5] >> 29) & 1) != 0;
    if (negative) {
        ++quadrant;
        std::uint64_t add = 1;
        for (int s = 0; s < 6; ++s) {
            const std::uint64_t t = ((~p[s]) & (s == 5 ? 0x3fffffffu : low32)) + add;
            p[s] = t & low32;
            add = t >> 32;
        }
        p[5] &= 0x3fffffffu;
    }
    // |f| as a double-double: the limbs (exact as doubles) scaled by powers of two, summed from
    // the most significant (all of one sign: no cancellation).
    DoubleDouble f;
    double scale = 0x1p-30; // limb 5's weight, 2^(160 - 190)
    for (int s = 5; s >= 0; --s, scale *= 0x1p-32) {
        const DoubleDouble sum = two_sum(f.hi, static_cast<double>(p[s]) * scale);
        f = fast_two_sum(sum.hi, sum.lo + f.lo);
    }
    // r = f pi/2.
    DoubleDouble r = two_product(f.hi, pio2_hi);
    r = fast_two_sum(r.hi, r.lo + (f.hi * pio2_lo + f.lo * pio2_hi));
    if (negative)
        r = {-r.hi, -r.lo};
    return {quadrant & 3, r};
}

} // namespace

QuadrantReduction reduce_quadrant(double x) {
    if (x < cody_waite::limit) {
        const cody_waite::Reduction red = cody_waite::reduce(x);
        return {static_cast<int>(static_cast<std::int64_t>(red.n) & 3), red.r};
    }
    return payne_hanek(x);
}

} // namespace tamias2d::math
