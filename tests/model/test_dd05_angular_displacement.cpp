// DD5 (angular displacement theta(t) = phi(t) - phi(t0), unwrapped; the seed's
// theta = d phi / dt is an erratum, see tests/compile_fail/dd05_angle_as_derivative.cpp).
#include <boost/test/unit_test.hpp>

#include <numbers>

#include "tamias2d/model/dd05_angular_displacement.hpp"

namespace utf = boost::unit_test;
namespace tt = boost::test_tools;
using namespace tamias2d::units;
namespace dd05 = tamias2d::model::dd05;

namespace {
constexpr double pi = std::numbers::pi;
Angle rad(double x) {
    return x * radian;
}
} // namespace

BOOST_AUTO_TEST_SUITE(dd05_angular_displacement)

// Oracle: hand derivation. From 0.5 rad to 2.5 rad: +2 rad (counter-clockwise, A4); back again:
// -2 rad (clockwise). Exact subtractions.
BOOST_AUTO_TEST_CASE(hand_values_and_sign, *utf::label("DD5")) {
    BOOST_TEST(dd05::angular_displacement(rad(2.5), rad(0.5)).value() == 2.0);
    BOOST_TEST(dd05::angular_displacement(rad(0.5), rad(2.5)).value() == -2.0);
    BOOST_TEST(dd05::angular_displacement(rad(1.0), rad(1.0)).value() == 0.0);
}

// Oracle: hand derivation with unwrapped orientations. Turning from 350 deg to 370 deg is a
// displacement of +20 deg = pi / 9 rad, not the -340 deg that wrapped outputs (10 deg) would
// suggest; and three full turns are 6 pi rad, not 0. Round-off: differences of numbers below
// 7 rad and 19 rad, ~1e-15 absolute, so 1e-14 relative on pi / 9 and 6 pi.
BOOST_AUTO_TEST_CASE(unwrapped_across_full_turns, *utf::label("DD5")) {
    const double deg = pi / 180.0;
    const Angle theta = dd05::angular_displacement(rad(370.0 * deg), rad(350.0 * deg));
    BOOST_TEST(theta.value() == pi / 9.0, tt::tolerance(1e-14));
    BOOST_TEST(dd05::angular_displacement(rad(0.25 + 6.0 * pi), rad(0.25)).value() == 6.0 * pi,
               tt::tolerance(1e-14));
}

// Oracle: textbook identity (additivity of rotations about one axis): theta(t0 -> t2) =
// theta(t0 -> t1) + theta(t1 -> t2).
BOOST_AUTO_TEST_CASE(additive_along_a_path, *utf::label("DD5")) {
    const Angle a = rad(0.3), b = rad(-4.2), c = rad(11.0);
    const double sum =
        dd05::angular_displacement(b, a).value() + dd05::angular_displacement(c, b).value();
    BOOST_TEST(sum == dd05::angular_displacement(c, a).value(), tt::tolerance(1e-14));
}

BOOST_AUTO_TEST_SUITE_END()
