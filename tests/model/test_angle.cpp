// DCO_phi (SRS Table 2: output orientation 0 <= phi < 2 pi), units/angle.hpp's
// wrap_orientation, checked by hand and against the definition of the remainder modulo 2 pi.
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "tamias2d/units/angle.hpp"

namespace utf = boost::unit_test;
namespace tt = boost::test_tools;
using namespace tamias2d::units;

namespace {
constexpr double pi = std::numbers::pi;
bool in_range(double w) {
    return w >= 0.0 && w < two_pi && !std::signbit(w);
}
// Circular distance between two angles (the double two_pi is the period).
double circ(double a, double b) {
    const double d = std::fabs(a - b);
    return std::min(d, two_pi - d);
}
} // namespace

BOOST_AUTO_TEST_SUITE(angle)

// Oracle: hand values. Angles already in [0, 2 pi) are returned unchanged (fmod is exact):
// 0, pi / 2 (SRS typical orientation), pi, and the largest double below 2 pi.
BOOST_AUTO_TEST_CASE(in_range_values_unchanged, *utf::label("DCO_phi")) {
    const double below_2pi = std::nextafter(two_pi, 0.0);
    for (double x : {0.0, pi / 2, pi, 6.0, below_2pi}) {
        BOOST_TEST(wrap_orientation(x) == x);
        BOOST_TEST(in_range(wrap_orientation(x)));
    }
}

// Oracle: hand values for negative angles: -pi / 2 -> 3 pi / 2, -pi -> pi, -3 pi / 2 ->
// pi / 2, -7 pi / 2 -> pi / 2 (one rounding of the added turn: 1e-15 relative).
BOOST_AUTO_TEST_CASE(negative_angles, *utf::label("DCO_phi")) {
    BOOST_TEST(wrap_orientation(-pi / 2) == 3 * pi / 2, tt::tolerance(1e-15));
    BOOST_TEST(wrap_orientation(-pi) == pi, tt::tolerance(1e-15));
    BOOST_TEST(wrap_orientation(-3 * pi / 2) == pi / 2, tt::tolerance(1e-15));
    BOOST_TEST(wrap_orientation(-7 * pi / 2) == pi / 2, tt::tolerance(1e-14));
    BOOST_TEST(in_range(wrap_orientation(-1.0)));
}

// Oracle: definition of the period. 2 pi, -2 pi, 4 pi and -4 pi (exact multiples of the double
// two_pi) wrap to +0 exactly (not to 2 pi, and not to -0, which the output would print as
// "-0"); k two_pi for other k is itself rounded, so the result is within a few ulp of k two_pi
// of the circle's zero, on either side (0+ or just below 2 pi), and always in range.
BOOST_AUTO_TEST_CASE(multiples_of_two_pi, *utf::label("DCO_phi")) {
    for (double x : {two_pi, -two_pi, 2 * two_pi, -2 * two_pi, 0.0, -0.0}) {
        BOOST_TEST(wrap_orientation(x) == 0.0, "x = " << x);
        BOOST_TEST(!std::signbit(wrap_orientation(x)), "x = " << x);
    }
    for (int k = -50; k <= 50; ++k) {
        const double x = k * two_pi;
        const double w = wrap_orientation(x);
        BOOST_TEST(in_range(w), "k = " << k);
        BOOST_TEST(circ(w, 0.0) <= 4 * std::numeric_limits<double>::epsilon() * std::fabs(x),
                   "k = " << k);
    }
}

// Oracle: hand derivation of -tiny + 2 pi. For 0 < t < ulp(2 pi) / 2 = 4.4e-16, -t + 2 pi rounds to
// 2 pi itself, which is out of range: the result must be 0 (the nearest in-range angle on the
// circle). For larger t it is the largest representable angle below 2 pi, still in range.
// Subnormals, t = 1e-300, 1e-17, 4e-16, 1e-15, 1e-10 are all covered.
BOOST_AUTO_TEST_CASE(minus_tiny, *utf::label("DCO_phi")) {
    for (double t : {std::numeric_limits<double>::denorm_min(), 1e-300, 1e-17, 4e-16}) {
        BOOST_TEST(wrap_orientation(-t) == 0.0, "t = " << t);
        BOOST_TEST(in_range(wrap_orientation(-t)), "t = " << t);
    }
    for (double t : {1e-15, 1e-10}) {
        const double w = wrap_orientation(-t);
        BOOST_TEST(in_range(w), "t = " << t);
        BOOST_TEST(two_pi - w == t, tt::tolerance(0.5)); // t vs the ulp grid near 2 pi
    }
    BOOST_TEST(wrap_orientation(1e-300) == 1e-300); // +tiny is already in range
}

// Oracle: definition of the remainder: for 2000 angles spread over [-1e4, 1e4] rad the result
// is in [0, 2 pi) and differs from the input by an integer number of turns, up to the input's
// own rounding (4 ulp of |x| <= 1e4: 7.3e-12 rad).
BOOST_AUTO_TEST_CASE(remainder_property, *utf::label("DCO_phi")) {
    for (int i = -1000; i < 1000; ++i) {
        const double x = i * 10.0 + 0.123456789 * i;
        const double w = wrap_orientation(x);
        BOOST_TEST_REQUIRE(in_range(w), "x = " << x);
        const double turns = std::round((x - w) / two_pi);
        BOOST_TEST(std::fabs(x - w - turns * two_pi) <=
                       4 * std::numeric_limits<double>::epsilon() * std::max(std::fabs(x), two_pi),
                   "x = " << x);
    }
}

// Oracle: hand value through the Angle overload: -pi / 2 rad wraps to 3 pi / 2 rad.
BOOST_AUTO_TEST_CASE(angle_quantity_overload, *utf::label("DCO_phi")) {
    const Angle w = wrap_orientation((-pi / 2) * radian);
    BOOST_TEST(w.value() == 3 * pi / 2, tt::tolerance(1e-15));
}

BOOST_AUTO_TEST_SUITE_END()
