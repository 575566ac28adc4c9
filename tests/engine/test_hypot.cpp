// math/hypot.hpp: the length of a vector without libm's hypot (whose last bit differs between C
// libraries), used by the joint axis check. A plainer form of the same quantity is the oracle,
// so the cases carry the category label "internals".
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <limits>
#include <random>

#include "support/trig_reference.hpp"
#include "tamias2d/math/hypot.hpp"

namespace utf = boost::unit_test;
namespace dm = tamias2d::math;

BOOST_AUTO_TEST_SUITE(deterministic_hypot)

// Oracle: sqrt(x^2 + y^2) in long double (x86-64's 64-bit significand: the squares and their
// sum carry 11 more bits than a double, and the exponent range holds squares of any double),
// about 2^-11 ulp of a double from the exact length. 10^6 random pairs, the larger component
// in 2^[-1000, 1000] and the smaller up to 2^60 times smaller: every result within 1 ulp (the
// method's correction step makes it nearly correctly rounded).
BOOST_AUTO_TEST_CASE(within_one_ulp_of_long_double_length, *utf::label("internals")) {
    std::mt19937_64 rng(21);
    std::uniform_real_distribution<double> exponent(-1000.0, 1000.0);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    double worst = 0.0;
    for (int i = 0; i < 1'000'000; ++i) {
        const double x = unit(rng) * std::exp2(exponent(rng));
        const double y = x * std::exp2(-60.0 * std::fabs(unit(rng)));
        const long double lx = x, ly = y;
        const long double exact = std::sqrt(lx * lx + ly * ly);
        worst = std::max(worst, tamias2d::test::ulp_error(dm::hypot(x, y), exact));
        worst = std::max(worst, tamias2d::test::ulp_error(dm::hypot(y, x), exact));
    }
    BOOST_TEST(worst < 1.0);
    BOOST_TEST_MESSAGE("hypot: max " << worst << " ulp");
}

// Oracle: C's hypot rules (C17 F.10.4.3) and hand values: exact Pythagorean triples, no
// overflow or underflow of the squares at the ends of the range, infinities before NaN.
BOOST_AUTO_TEST_CASE(exact_cases_range_and_special_values, *utf::label("internals")) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    BOOST_TEST(dm::hypot(3.0, 4.0) == 5.0);
    BOOST_TEST(dm::hypot(-5.0, 12.0) == 13.0);
    BOOST_TEST(dm::hypot(0.0, 0.0) == 0.0);
    BOOST_TEST(dm::hypot(0.0, -7.5) == 7.5);
    BOOST_TEST(dm::hypot(3e300, 4e300) == 5e300);       // the squares would overflow
    BOOST_TEST(dm::hypot(3e-300, 4e-300) == 5e-300);    // and underflow
    BOOST_TEST(dm::hypot(0x1p-1074, 0.0) == 0x1p-1074); // the smallest subnormal
    BOOST_TEST(dm::hypot(0x1.fffffffffffffp+1023, 0.0) == 0x1.fffffffffffffp+1023);
    BOOST_TEST(dm::hypot(inf, nan) == inf);
    BOOST_TEST(dm::hypot(nan, -inf) == inf);
    BOOST_TEST(std::isnan(dm::hypot(nan, 1.0)));
}

BOOST_AUTO_TEST_SUITE_END()
