// DD6 (angular velocity omega = d theta / dt), checked by hand and with uniform rotation.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <numbers>

#include "tamias2d/model/dd05_angular_displacement.hpp"
#include "tamias2d/model/dd06_angular_velocity.hpp"

namespace utf = boost::unit_test;
namespace tt = boost::test_tools;
using namespace tamias2d::units;
namespace dd05 = tamias2d::model::dd05;
namespace dd06 = tamias2d::model::dd06;

namespace {
const auto rad_s = radian / second;
}

BOOST_AUTO_TEST_SUITE(dd06_angular_velocity)

// Oracle: hand derivation. omega = 2 rad/s for 0.25 s turns 0.5 rad; 2.1 rad/s (SRS typical)
// for 2 s turns 4.2 rad; clockwise -3 rad/s for 0.5 s turns -1.5 rad.
BOOST_AUTO_TEST_CASE(angle_over_hand_values, *utf::label("DD6")) {
    BOOST_TEST(dd06::angle_over(2.0 * rad_s, 0.25 * second).value() == 0.5);
    BOOST_TEST(dd06::angle_over(2.1 * rad_s, 2.0 * second).value() == 4.2);
    BOOST_TEST(dd06::angle_over(-3.0 * rad_s, 0.5 * second).value() == -1.5);
}

// Oracle: textbook uniform rotation. One revolution (2 pi rad) in a period T = 0.5 s is
// omega = 2 pi / T = 4 pi rad/s; the DD5 displacement of a body spun at omega for t is
// omega t. One or two roundings: 1e-15 relative.
BOOST_AUTO_TEST_CASE(uniform_rotation, *utf::label("DD6") * utf::label("DD5")) {
    const double pi = std::numbers::pi;
    const AngularVelocity w = dd06::mean_angular_velocity(2.0 * pi * radian, 0.5 * second);
    BOOST_TEST(w.value() == 4.0 * pi, tt::tolerance(1e-15));
    const Angle phi0 = 0.7 * radian;
    const Angle phi1 = phi0 + dd06::angle_over(w, 0.125 * second);
    BOOST_TEST(dd05::angular_displacement(phi1, phi0).value() == pi / 2.0, tt::tolerance(1e-15));
}

// Oracle: textbook calculus. For theta(t) = sin(t) rad (a pendulum-like history), the mean
// angular velocity over [t - h, t + h] is a central difference of theta, which approximates
// theta'(t) = cos(t) with error h^2 / 6 |theta'''| <= h^2 / 6; with h = 1e-4 that is 1.7e-9,
// plus round-off 2.2e-16 / 1e-4 ~ 2e-12. Bound used: 2e-9.
BOOST_AUTO_TEST_CASE(central_difference_of_smooth_history, *utf::label("DD6")) {
    const double h = 1e-4;
    for (double t : {0.0, 0.4, 1.3, 2.9}) {
        const Angle dtheta = (std::sin(t + h) - std::sin(t - h)) * radian;
        const AngularVelocity w = dd06::mean_angular_velocity(dtheta, 2.0 * h * second);
        BOOST_TEST(std::abs(w.value() - std::cos(t)) <= 2e-9);
    }
}

BOOST_AUTO_TEST_SUITE_END()
