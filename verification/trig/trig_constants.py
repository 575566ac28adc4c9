#!/usr/bin/python3
"""The constants of src/tamias2d/math/sincos_kernels.hpp and quadrant_reduction.hpp/.cpp,
computed from scratch with Python's standard library only (integers, fractions, decimal):

* pi to 1400 bits by Machin's formula (pi/4 = 4 atan(1/5) - atan(1/239)), in integers; its
  first hexadecimal digits are checked against the well-known expansion 3.243f6a8885a308d3...;
* the Cody-Waite split of pi/2 (Cody and Waite, Software Manual for the Elementary Functions,
  1980, ch. 8): C1, C2, C3 of 33 significant bits each, so that n * Ck is exact for |n| <= 2^20,
  and C4, the rest rounded to a double;
* pi/2 as a double-double (PIO2_HI + PIO2_LO) and the bits of 2/pi as 32-bit words, for the
  Payne-Hanek reduction of large arguments (Payne and Hanek, "Radian reduction for trigonometric
  functions", SIGNUM Newsletter 18(1), 1983);
* minimax polynomials (Remez's second algorithm, weighted for the relative error of the
  result) on [0, (pi/4)^2] in z = x^2:
      sin x = x + x^3 S(z),         S of degree 5,
      cos x = 1 - z/2 + z^2 K(z),   K of degree 5,
  computed in Decimal with 60 digits from the Taylor series, then rounded to doubles; the
  printed error bounds are those of the rounded coefficients, evaluated exactly (Fraction) on a
  dense grid;
* the doubles below 2^20 pi/2 (and a few binades above) nearest to a multiple of pi/2, by the
  continued fraction of pi/2 scaled to each binade (the method of Kahan and McDonald, as in
  Muller, Elementary Functions, 3rd ed., section 11.3): the arguments where a reduction loses
  the most bits, which the tests include.

Run: /usr/bin/python3 verification/trig/trig_constants.py [--words] [--hard]
"""
import argparse
import decimal
import math
from decimal import Decimal
from fractions import Fraction

decimal.getcontext().prec = 60
BITS = 1400


def arctan_inv(k, scale):
    """atan(1/k) * scale, in integers (scale a power of two)."""
    total, term, n, sign = 0, scale // k, 1, 1
    k2 = k * k
    while term:
        total += sign * (term // n)
        term //= k2
        n += 2
        sign = -sign
    return total


def pi_fraction():
    guard = 64
    scale = 1 << (BITS + guard)
    pi_scaled = 4 * (4 * arctan_inv(5, scale) - arctan_inv(239, scale))
    return Fraction(pi_scaled >> guard, 1 << BITS)  # pi, to 2^-1400 (truncated)


PI = pi_fraction()
# The first hexadecimal digits of pi (the fractional part's are the first words of Blowfish's
# P-array, from the expansion published by Bailey, Borwein and Plouffe): a check of Machin.
KNOWN_HEX = "3243f6a8885a308d313198a2e03707344a4093822299f31d0082efa98ec4e6c89452821e638d01377be5466cf34e90c6cc0ac29b7c97c50dd3f84d5b5b5470917"
PIO2 = PI / 2
TWO_OVER_PI = 2 / PI


def check_pi():
    n = len(KNOWN_HEX) - 1  # hexadecimal digits after the point
    value = (PI.numerator * 16**n) // PI.denominator
    got = format(value, "x")
    if got[:-1] != KNOWN_HEX[:-1]:  # (the last digit may differ by the truncation)
        raise SystemExit("Machin's pi disagrees with the known hexadecimal expansion")


def to_double(q, bits=53):
    """The binary number of `bits` significant bits nearest to the rational q (ties to even):
    a double for 53 (returned as a Python float), x86's long double for 64 (a Fraction)."""
    if q == 0:
        return 0.0
    sign = -1 if q < 0 else 1
    q = abs(q)
    e = q.numerator.bit_length() - q.denominator.bit_length()
    # scale so that the integer part has 53 bits
    while Fraction(2) ** e > q:
        e -= 1
    while Fraction(2) ** (e + 1) <= q:
        e += 1
    shift = bits - 1 - e
    scaled = q * Fraction(2) ** shift
    m = scaled.numerator // scaled.denominator
    rem = scaled - m
    if rem > Fraction(1, 2) or (rem == Fraction(1, 2) and m % 2 == 1):
        m += 1
    value = sign * Fraction(m) / Fraction(2) ** shift
    return float(value) if bits == 53 else value


def truncate_bits(q, bits):
    """q (> 0) truncated to `bits` significant bits."""
    e = 0
    while Fraction(2) ** e > q:
        e -= 1
    while Fraction(2) ** (e + 1) <= q:
        e += 1
    shift = bits - 1 - e
    scaled = q * Fraction(2) ** shift
    return Fraction(scaled.numerator // scaled.denominator) / Fraction(2) ** shift


def hexf(x):
    return float(x).hex()


def cody_waite():
    c1 = truncate_bits(PIO2, 33)
    c2 = truncate_bits(PIO2 - c1, 33)
    c3 = truncate_bits(PIO2 - c1 - c2, 33)
    c4 = to_double(PIO2 - c1 - c2 - c3)
    rest = PIO2 - c1 - c2 - c3 - Fraction(c4)
    return [float(c1), float(c2), float(c3), c4], rest


def long_double_hex(q):
    """A hexadecimal long double literal of q (64 significant bits at most)."""
    sign = "-" if q < 0 else ""
    q = abs(q)
    e = 0
    while Fraction(2) ** e > q:
        e -= 1
    while Fraction(2) ** (e + 1) <= q:
        e += 1
    m = q / Fraction(2) ** e * 2**63
    assert m.denominator == 1
    digits = format(m.numerator, "x")  # 64 bits: 16 digits, the first 8..f
    return f"{sign}0x{digits[0]}.{digits[1:].rstrip('0') or '0'}p{e - 3:+d}L"


def long_double_split():
    """pi/2 = P1 + P2 + P3 + P4 for the long double reference of the tests
    (tests/support/trig_reference.hpp): P1 to P3 of 32 bits, P4 the rest to 64 bits."""
    parts, rest = [], PIO2
    for _ in range(3):
        parts.append(truncate_bits(rest, 32))
        rest = PIO2 - sum(parts)
    parts.append(to_double(rest, 64))
    return parts


def two_over_pi_words(count=41, pad_words=2):
    """2/pi's bits after the binary point as 32-bit words, after pad_words zero words."""
    value = (TWO_OVER_PI.numerator << (32 * (count - pad_words))) // TWO_OVER_PI.denominator
    words = []
    for k in range(count - pad_words):
        words.append((value >> (32 * (count - pad_words - 1 - k))) & 0xFFFFFFFF)
    return [0] * pad_words + words


# ---------------------------------------------------------------------------------------------
# Remez
# ---------------------------------------------------------------------------------------------
def series(z, coefficient, terms=40):
    total, power = Decimal(0), Decimal(1)
    for k in range(terms):
        total += coefficient(k) * power
        power *= z
    return total


FACT = [Decimal(1)]
for i in range(1, 100):
    FACT.append(FACT[-1] * i)


def sin_target(z):  # (sin x - x) / x^3 = sum_{k>=1} (-1)^k z^(k-1) / (2k+1)!
    return series(z, lambda k: (-1) ** (k + 1) / FACT[2 * k + 3])


def sin_weight(z):  # x^3 / sin x = z / (sin x / x)
    return z / series(z, lambda k: (-1) ** k / FACT[2 * k + 1])


def cos_target(z):  # (cos x - 1 + z/2) / z^2 = sum_{k>=2} (-1)^k z^(k-2) / (2k)!
    return series(z, lambda k: (-1) ** k / FACT[2 * k + 4])


def cos_weight(z):  # z^2 / cos x
    return z * z / series(z, lambda k: (-1) ** k / FACT[2 * k])


def solve(matrix, rhs):
    n = len(rhs)
    a = [row[:] + [r] for row, r in zip(matrix, rhs)]
    for col in range(n):
        pivot = max(range(col, n), key=lambda r: abs(a[r][col]))
        a[col], a[pivot] = a[pivot], a[col]
        for r in range(n):
            if r != col and a[r][col] != 0:
                f = a[r][col] / a[col][col]
                a[r] = [x - f * y for x, y in zip(a[r], a[col])]
    return [a[i][n] / a[i][i] for i in range(n)]


def poly(c, z):
    total = Decimal(0)
    for coefficient in reversed(c):
        total = total * z + coefficient
    return total


def remez(target, weight, degree, b, iterations=30):
    n = degree + 1
    points = [b * (1 - Decimal(str(math.cos((i + 0.5) * math.pi / (n + 1))))) / 2
              for i in range(n + 1)]
    points[-1] = b
    grid = [b * Decimal(i) / 4000 for i in range(1, 4001)]
    for _ in range(iterations):
        matrix = [[weight(z) * z**j for j in range(n)] + [Decimal((-1) ** i)] for i, z in enumerate(points)]
        rhs = [weight(z) * target(z) for z in points]
        sol = solve(matrix, rhs)
        c, e = sol[:n], sol[n]

        def err(z):
            return weight(z) * (poly(c, z) - target(z))

        values = [err(z) for z in grid]
        # one extremum per run of equal sign
        extrema, start = [], 0
        for i in range(1, len(grid) + 1):
            if i == len(grid) or (values[i] > 0) != (values[start] > 0):
                j = max(range(start, i), key=lambda k: abs(values[k]))
                extrema.append(j)
                start = i
        while len(extrema) > n + 1:  # drop the smallest at either end
            if abs(values[extrema[0]]) < abs(values[extrema[-1]]):
                extrema.pop(0)
            else:
                extrema.pop()
        new_points = []
        for j in extrema:  # refine each extremum by golden-section search
            lo = grid[max(j - 1, 0)] if j > 0 else grid[0] / 2
            hi = grid[min(j + 1, len(grid) - 1)]
            sign = 1 if values[j] > 0 else -1
            for _ in range(60):
                m1 = lo + (hi - lo) * Decimal("0.381966011250105")
                m2 = hi - (hi - lo) * Decimal("0.381966011250105")
                if sign * err(m1) < sign * err(m2):
                    lo = m1
                else:
                    hi = m2
            z = (lo + hi) / 2
            new_points.append(b if j == len(grid) - 1 and sign * err(b) >= sign * err(z) else z)
        if len(new_points) != n + 1:
            raise SystemExit(f"Remez: {len(new_points)} extrema, expected {n + 1}")
        points = new_points
        levels = [abs(err(z)) for z in points]
        if max(levels) / min(levels) < Decimal("1.000001"):
            break
    return c, abs(e)


def exact_error(c_doubles, target_kind, b, samples=3000):
    """Max relative error of the polynomial with the rounded coefficients, over a grid, exactly
    (Fraction for the polynomial, Decimal for the function)."""
    worst = Decimal(0)
    for i in range(1, samples + 1):
        z = b * Decimal(i) / samples
        p = poly([Decimal(x) for x in c_doubles], z)
        if target_kind == "sin":
            e = sin_weight(z) * (p - sin_target(z))
        else:
            e = cos_weight(z) * (p - cos_target(z))
        worst = max(worst, abs(e))
    return worst


# ---------------------------------------------------------------------------------------------
# Hard arguments: doubles close to multiples of pi/2
# ---------------------------------------------------------------------------------------------
def convergents(q, limit):
    """Convergents p/r of the continued fraction of q with r <= limit."""
    a = []
    x = q
    h0, h1, k0, k1 = 0, 1, 1, 0
    out = []
    for _ in range(200):
        ai = x.numerator // x.denominator
        h0, h1 = h1, ai * h1 + h0
        k0, k1 = k1, ai * k1 + k0
        if k1 > limit:
            break
        out.append((h1, k1))
        frac = x - ai
        if frac == 0:
            break
        x = 1 / frac
        a.append(ai)
    return out


def hard_arguments(exponents):
    """For each binade [2^e, 2^(e+1)) with e in `exponents`: the double m 2^(e-52) nearest to a
    multiple n pi/2 (smallest |x - n pi/2|) among the candidates the convergents n/m of
    2^(e-52) / (pi/2) give (and their multiples within the binade)."""
    found = []
    for e in exponents:
        unit = Fraction(2) ** (e - 52)
        best = None
        for num, den in convergents(unit / PIO2, 1 << 53):
            if den == 0:
                continue
            k = max(1, (1 << 52) // den)
            for kk in (k, k + 1):
                m = kk * den
                if (1 << 52) <= m < (1 << 53):
                    x = m * unit
                    n = round(x / PIO2)
                    r = x - n * PIO2
                    if best is None or abs(r) < abs(best[1]):
                        best = (x, r)
        if best:
            found.append((e, float(best[0]), float(best[1])))
    return found


def write_hard_header(path):
    rows = hard_arguments(range(0, 1024))
    with open(path, "w", encoding="utf-8") as out:
        out.write("// Generated by verification/trig/trig_constants.py --hard-header: for each binade\n"
                  "// [2^e, 2^(e+1)), e = 0 .. 1023, the double nearest to a multiple of pi/2 among the\n"
                  "// candidates of the continued fraction of pi/2 (the arguments whose reduction cancels\n"
                  "// the most bits; 0x1.6ac5b262ca1ffp+849 is the closest of all doubles, 2^-60.9 away).\n"
                  "#pragma once\n\nnamespace tamias2d::test {\n\n"
                  f"inline constexpr double trig_hard_arguments[{len(rows)}] = {{\n")
        # The comments aligned one column after the longest literal, as clang-format does.
        width = max(len(float(x).hex()) for _, x, _ in rows) + 2
        for e, x, r in rows:
            out.write(f"    {(float(x).hex() + ',').ljust(width)}// x - n pi/2 = {r:.3e}\n")
        out.write("};\n\n} // namespace tamias2d::test\n")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--words", action="store_true", help="print the 2/pi table")
    parser.add_argument("--hard", action="store_true", help="print the hard arguments")
    parser.add_argument("--no-remez", action="store_true")
    parser.add_argument("--hard-header", metavar="FILE",
                        help="write the hard arguments as a C++ header (tests/support/trig_hard_arguments.hpp)")
    args = parser.parse_args()
    check_pi()
    if args.hard_header:
        write_hard_header(args.hard_header)
        return
    print("// pi checked against its known hexadecimal expansion (%d digits)" % (len(KNOWN_HEX) - 1))
    c, rest = cody_waite()
    for i, x in enumerate(c, 1):
        print(f"C{i} = {hexf(x)}")
    print(f"// pi/2 - (C1 + C2 + C3 + C4) = {float(rest):.3e}")
    hi = to_double(PIO2)
    lo = to_double(PIO2 - Fraction(hi))
    print(f"PIO2_HI = {hexf(hi)}\nPIO2_LO = {hexf(lo)}")
    print(f"TWO_OVER_PI = {hexf(to_double(TWO_OVER_PI))}")
    print(f"PIO4 = {hexf(to_double(PI / 4))}")
    for i, q in enumerate(long_double_split(), 1):
        print(f"P{i} (long double) = {long_double_hex(q)}")
    print(f"TWO_OVER_PI (long double) = {long_double_hex(to_double(TWO_OVER_PI, 64))}")
    if args.words:
        words = two_over_pi_words()
        print("TWO_OVER_PI_BITS (after two zero words) =")
        for i in range(0, len(words), 6):
            print("    " + ", ".join(f"0x{w:08x}" for w in words[i:i + 6]) + ",")
    if not args.no_remez:
        b = Decimal(str(float(PI / 4) ** 2 * 1.0000001))  # (pi/4)^2 and a little beyond
        for kind, target, weight in (("sin", sin_target, sin_weight), ("cos", cos_target, cos_weight)):
            coefficients, level = remez(target, weight, 5, b)
            rounded = [float(x) for x in coefficients]
            print(f"{kind}: minimax relative error {float(level):.3e} (2^{math.log2(float(level)):.2f})")
            for i, x in enumerate(rounded, 1):
                print(f"  {'S' if kind == 'sin' else 'K'}{i} = {hexf(x)}   // {x:.17e}")
            bound = exact_error(rounded, kind, b)
            print(f"  with the rounded coefficients: {float(bound):.3e} (2^{math.log2(float(bound)):.2f})")
    if args.hard:
        for e, x, r in hard_arguments(range(0, 1024)):
            print(f"hard: 2^{e}: x = {hexf(x)}, x - n pi/2 = {r:.3e} (2^{math.log2(abs(r)):.1f})")


if __name__ == "__main__":
    main()
