// DD32: a body's rotation R(phi) = (cos phi, sin phi) from the project's own sincos
// (model/dd32_rotation.hpp, math/sincos.hpp), within 1 ulp of the exact values.
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "support/trig_hard_arguments.hpp"
#include "support/trig_reference.hpp"
#include "tamias2d/model/dd32_rotation.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;
using tamias2d::test::LongSinCos;

namespace {

struct MaxError {
    double sin = 0.0, sin_at = 0.0;
    double cos = 0.0, cos_at = 0.0;
};

model::dd32::Rotation rotation(double phi) {
    return model::dd32::rotation(units::from_value<units::Angle>(phi));
}

void accumulate(MaxError& m, double phi, const LongSinCos& ref) {
    const model::dd32::Rotation r = rotation(phi);
    const double es = test::ulp_error(r.sin.value(), ref.sin);
    const double ec = test::ulp_error(r.cos.value(), ref.cos);
    if (es > m.sin)
        m.sin = es, m.sin_at = phi;
    if (ec > m.cos)
        m.cos = ec, m.cos_at = phi;
}

MaxError uniform(double bound, int count, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-bound, bound);
    MaxError m;
    for (int i = 0; i < count; ++i) {
        const double phi = u(rng);
        accumulate(m, phi, test::long_double_sincos(phi));
    }
    return m;
}

} // namespace

BOOST_AUTO_TEST_SUITE(dd32_rotation)

// Oracle: sin and cos in long double (x86-64's 64-bit significand: the C library's sinl and
// cosl of the argument reduced in long double with pi/2 to 160 bits, tests/support/
// trig_reference.hpp), about 2^-10 ulp of a double from the exact values. 2 x 10^5 random
// orientations in [-pi, pi] (where bodies' orientations stay), 2 x 10^5 in [-2^20, 2^20], and
// the double nearest to a multiple of pi/2 in each binade up to 2^31 with its two neighbours
// (the reduction's hardest cases): every cos phi and sin phi within 1 ulp.
BOOST_AUTO_TEST_CASE(within_one_ulp_of_long_double_sin_and_cos, *utf::label("DD32")) {
    for (const auto& [bound, seed] : {std::pair{3.141592653589793, 11}, std::pair{0x1p20, 12}}) {
        const MaxError m = uniform(bound, 200'000, static_cast<std::uint64_t>(seed));
        BOOST_TEST(m.sin < 1.0, "[-" << bound << ", " << bound << "]: sin off by " << m.sin
                                     << " ulp at " << std::hexfloat << m.sin_at);
        BOOST_TEST(m.cos < 1.0, "[-" << bound << ", " << bound << "]: cos off by " << m.cos
                                     << " ulp at " << std::hexfloat << m.cos_at);
        BOOST_TEST_MESSAGE("[-" << bound << ", " << bound << "]: max " << m.sin << " ulp (sin), "
                                << m.cos << " ulp (cos)");
    }
    MaxError hard;
    for (double x : test::trig_hard_arguments) {
        if (x >= 0x1p31)
            break;
        for (double phi : {x, std::nextafter(x, 0.0), std::nextafter(x, 2 * x), -x})
            accumulate(hard, phi, test::long_double_sincos(phi));
    }
    BOOST_TEST(hard.sin < 1.0,
               "sin off by " << hard.sin << " ulp at " << std::hexfloat << hard.sin_at);
    BOOST_TEST(hard.cos < 1.0,
               "cos off by " << hard.cos << " ulp at " << std::hexfloat << hard.cos_at);
}

// Oracle: sin and cos at 1400 bits (Boost.Multiprecision, its own pi and reduction). The engine
// accepts orientations up to 1e24 (DCX_range), and the function is defined for every double:
// the hardest argument of every binade from 1 to 2^1023 (0x1.6ac5b262ca1ffp+849 lies 2^-60.9
// from a multiple of pi/2) and 500 random ones, log-uniform in [2^20, 2^1024), within 1 ulp.
BOOST_AUTO_TEST_CASE(within_one_ulp_for_large_orientations, *utf::label("DD32")) {
    std::vector<double> phis(std::begin(test::trig_hard_arguments),
                             std::end(test::trig_hard_arguments));
    std::mt19937_64 rng(13);
    std::uniform_real_distribution<double> exponent(20.0, 1023.999);
    for (int i = 0; i < 500; ++i)
        phis.push_back((i % 2 ? -1.0 : 1.0) * std::exp2(exponent(rng)));
    MaxError m;
    for (double phi : phis)
        accumulate(m, phi, test::multiprecision_sincos(phi));
    BOOST_TEST(m.sin < 1.0, "sin off by " << m.sin << " ulp at " << std::hexfloat << m.sin_at);
    BOOST_TEST(m.cos < 1.0, "cos off by " << m.cos << " ulp at " << std::hexfloat << m.cos_at);
}

// Oracle: the definitions. sin is odd and cos even, bit for bit (-0 included); R(0) = (1, 0)
// exactly; an infinite or NaN angle has no rotation (NaN).
BOOST_AUTO_TEST_CASE(odd_sine_even_cosine_and_special_values, *utf::label("DD32")) {
    std::mt19937_64 rng(14);
    std::uniform_real_distribution<double> u(-40.0, 40.0);
    for (int i = 0; i < 10'000; ++i) {
        const double phi = std::exp2(u(rng));
        const model::dd32::Rotation p = rotation(phi);
        const model::dd32::Rotation n = rotation(-phi);
        BOOST_TEST(n.sin.value() == -p.sin.value());
        BOOST_TEST(n.cos.value() == p.cos.value());
    }
    BOOST_TEST(rotation(0.0).cos.value() == 1.0);
    BOOST_TEST(rotation(0.0).sin.value() == 0.0);
    BOOST_TEST(!std::signbit(rotation(0.0).sin.value()));
    BOOST_TEST(std::signbit(rotation(-0.0).sin.value()));
    for (double bad :
         {std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
          std::numeric_limits<double>::quiet_NaN()}) {
        BOOST_TEST(std::isnan(rotation(bad).sin.value()));
        BOOST_TEST(std::isnan(rotation(bad).cos.value()));
    }
}

// Oracle: an independent implementation, the C library's sin and cos in long double (each lane
// within 1 ulp where the argument is below 2^31); for the bits, each orientation's own rotation
// by the scalar path (itself within 1 ulp of the same references, above). The batch (the lanes of a
// vector register) must give the same bits for every argument the engine can meet and any other:
// random ones in [-pi, pi] and [-2^20, 2^20], small and signed zeros, each binade's hardest
// argument with its neighbours and negation, arguments beyond the lanes' reduction (2^21 and up),
// infinities and NaN, in batches of every length from 1 to 9 (a vector's lanes and its tail) and of
// 2 x 10^5.
BOOST_AUTO_TEST_CASE(a_batch_has_each_rotations_bits, *utf::label("DD32")) {
    std::vector<double> phis = {0.0,
                                -0.0,
                                0x1p-1074,
                                -0x1p-1060,
                                1e-300,
                                0.785398163397448,
                                -0.7853981633974484,
                                0x1.9p+20,
                                0x1.8ffffffffffffp+20,
                                0x1p21,
                                -1e300,
                                std::numeric_limits<double>::infinity(),
                                -std::numeric_limits<double>::infinity(),
                                std::numeric_limits<double>::quiet_NaN()};
    for (double x : test::trig_hard_arguments)
        for (double phi : {x, std::nextafter(x, 0.0), std::nextafter(x, 2 * x), -x})
            phis.push_back(phi);
    std::mt19937_64 rng(15);
    for (double bound : {3.141592653589793, 0x1p20, 1e-3}) {
        std::uniform_real_distribution<double> u(-bound, bound);
        for (int i = 0; i < 100'000; ++i)
            phis.push_back(u(rng));
    }
    auto same = [](double a, double b) {
        return std::isnan(a) ? std::isnan(b)
                             : std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
    };
    std::vector<double> c(phis.size()), s(phis.size());
    model::dd32::rotations(phis.data(), c.data(), s.data(), phis.size());
    std::size_t differ = 0, first = 0;
    MaxError m;
    for (std::size_t k = 0; k < phis.size(); ++k) {
        const model::dd32::Rotation r = rotation(phis[k]);
        if ((!same(c[k], r.cos.value()) || !same(s[k], r.sin.value())) && differ++ == 0)
            first = k;
        if (std::isfinite(phis[k]) && std::fabs(phis[k]) < 0x1p31) {
            const LongSinCos ref = test::long_double_sincos(phis[k]);
            m.sin = std::max(m.sin, test::ulp_error(s[k], ref.sin));
            m.cos = std::max(m.cos, test::ulp_error(c[k], ref.cos));
        }
    }
    BOOST_TEST(differ == 0u, differ << " of " << phis.size() << " differ from rotation, first at "
                                    << std::hexfloat << phis[first]);
    BOOST_TEST(m.sin < 1.0);
    BOOST_TEST(m.cos < 1.0);
    for (std::size_t n = 1; n <= 9; ++n) { // every tail, from the hard arguments' start
        std::vector<double> cn(n), sn(n);
        model::dd32::rotations(phis.data() + 14, cn.data(), sn.data(), n);
        for (std::size_t k = 0; k < n; ++k)
            BOOST_TEST((same(cn[k], c[14 + k]) && same(sn[k], s[14 + k])), "n = " << n);
    }
}

BOOST_AUTO_TEST_SUITE_END()
