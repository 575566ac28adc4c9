// The accuracy of the project's sincos (src/tamias2d/math/sincos.hpp) and hypot
// (math/hypot.hpp), measured against independent references (tests/support/trig_reference.hpp):
//   trig_accuracy [COUNT]     (default 10^7 arguments per range)
// Ranges, each sampled uniformly by a fixed-seed generator:
//   [-2^20, 2^20]        against the long double reference;
//   [-pi, pi]            the angles the example scenes' bodies turn through (the engine calls
//                        sincos with the unwrapped orientation, which stays within a few turns);
//   [-2^32, 2^32]        the long double reference's whole range;
//   |x| in [2^20, 2^1024), log-uniform, COUNT / 1000 arguments, and the hardest argument of
//                        every binade (tests/support/trig_hard_arguments.hpp), against
//                        Boost.Multiprecision at 1400 bits;
// and hypot against long double's sqrtl of the long double sum of squares. Prints, for each
// range and function, the largest error in ulps and where it occurred.
#include <chrono>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>

#include "support/trig_hard_arguments.hpp"
#include "support/trig_reference.hpp"
#include "tamias2d/math/hypot.hpp"
#include "tamias2d/math/sincos.hpp"

namespace {

using tamias2d::test::LongSinCos;
using tamias2d::test::ulp_error;

struct Worst {
    double ulp = 0.0;
    double at = 0.0;
    void note(double e, double x) {
        if (e > ulp) {
            ulp = e;
            at = x;
        }
    }
};

struct Result {
    Worst sin, cos;
    long long count = 0;
    long long sin_inexact = 0; ///< results not equal to the reference rounded to nearest
    long long cos_inexact = 0;
};

void check(Result& r, double x, const LongSinCos& ref) {
    const tamias2d::math::SinCos got = tamias2d::math::sincos(x);
    r.sin.note(ulp_error(got.sin, ref.sin), x);
    r.cos.note(ulp_error(got.cos, ref.cos), x);
    r.sin_inexact += got.sin != static_cast<double>(ref.sin);
    r.cos_inexact += got.cos != static_cast<double>(ref.cos);
    ++r.count;
}

void print(const char* range, const Result& r, double seconds) {
    std::printf("%-34s %10lld args  sin max %.4f ulp at %a  cos max %.4f ulp at %a"
                "  (not the nearest double: sin %.4f%%, cos %.4f%%)  [%.1f s]\n",
                range, r.count, r.sin.ulp, r.sin.at, r.cos.ulp, r.cos.at,
                100.0 * static_cast<double>(r.sin_inexact) / static_cast<double>(r.count),
                100.0 * static_cast<double>(r.cos_inexact) / static_cast<double>(r.count), seconds);
}

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void uniform_range(const char* name, double lo, double hi, long long count, std::uint64_t seed) {
    const auto start = std::chrono::steady_clock::now();
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(lo, hi);
    Result r;
    for (long long i = 0; i < count; ++i) {
        const double x = u(rng);
        check(r, x, tamias2d::test::long_double_sincos(x));
    }
    print(name, r, seconds_since(start));
}

} // namespace

int main(int argc, char** argv) {
    const long long count = argc > 1 ? std::atoll(argv[1]) : 10'000'000;
    uniform_range("[-2^20, 2^20] (long double ref)", -0x1p20, 0x1p20, count, 1);
    uniform_range("[-pi, pi] (long double ref)", -3.141592653589793, 3.141592653589793, count, 2);
    uniform_range("[-2^32, 2^32] (long double ref)", -0x1p32, 0x1p32, count, 3);
    {
        const auto start = std::chrono::steady_clock::now();
        Result r;
        std::mt19937_64 rng(4);
        std::uniform_real_distribution<double> exponent(20.0, 1023.999);
        std::uniform_real_distribution<double> sign(-1.0, 1.0);
        for (long long i = 0; i < count / 1000; ++i) {
            const double x = std::copysign(std::exp2(exponent(rng)), sign(rng));
            check(r, x, tamias2d::test::multiprecision_sincos(x));
        }
        for (double x : tamias2d::test::trig_hard_arguments)
            for (double y : {x, std::nextafter(x, 0.0), std::nextafter(x, 2 * x)})
                check(r, y, tamias2d::test::multiprecision_sincos(y));
        print("|x| in [2^20, 2^1024) + hard (MP)", r, seconds_since(start));
    }
    {
        const auto start = std::chrono::steady_clock::now();
        std::mt19937_64 rng(5);
        std::uniform_real_distribution<double> exponent(-1000.0, 1000.0);
        std::uniform_real_distribution<double> unit(-1.0, 1.0);
        Worst worst;
        double worst_y = 0.0;
        for (long long i = 0; i < count; ++i) {
            const double x = unit(rng) * std::exp2(exponent(rng));
            const double y = x * std::exp2(-60.0 * std::fabs(unit(rng)));
            const long double lx = x, ly = y;
            const long double ref = std::sqrt(lx * lx + ly * ly);
            const double e = ulp_error(tamias2d::math::hypot(x, y), ref);
            if (e > worst.ulp)
                worst_y = y;
            worst.note(e, x);
        }
        std::printf("%-34s %10lld args  max %.4f ulp at (%a, %a)  [%.1f s]\n",
                    "hypot, |x| in 2^[-1000, 1000]", count, worst.ulp, worst.at, worst_y,
                    seconds_since(start));
    }
    return 0;
}
