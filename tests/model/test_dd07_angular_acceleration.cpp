// DD7 (angular acceleration alpha = d omega / dt), checked by hand and with a quadratic
// angular-velocity history.
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "tamias2d/model/dd07_angular_acceleration.hpp"

namespace utf = boost::unit_test;
namespace tt = boost::test_tools;
using namespace tamias2d::units;
namespace dd07 = tamias2d::model::dd07;

namespace {
const auto rad_s = radian / second;
const auto rad_s2 = radian / (second * second);
} // namespace

BOOST_AUTO_TEST_SUITE(dd07_angular_acceleration)

// Oracle: hand derivation. alpha = 3 rad s^-2 over 0.5 s changes omega by 1.5 rad/s; a change
// of -2.1 rad/s (stopping the SRS typical spin) in 0.7 s is alpha = -3 rad s^-2.
BOOST_AUTO_TEST_CASE(hand_values, *utf::label("DD7")) {
    BOOST_TEST(dd07::angular_velocity_change_over(3.0 * rad_s2, 0.5 * second).value() == 1.5);
    BOOST_TEST(dd07::mean_angular_acceleration(-2.1 * rad_s, 0.7 * second).value() == -3.0,
               tt::tolerance(1e-15));
}

// Oracle: textbook calculus. For omega(t) = w0 + a0 t + j t^2 / 2 the mean angular acceleration
// over [t, t + h] equals alpha(t + h / 2) = a0 + j (t + h / 2) exactly. a0 = -1, j = 4,
// [0.5, 1] s: alpha(0.75) = 2 rad s^-2. Round-off: omega below 3 rad/s over h = 0.5 s, < 1e-14.
BOOST_AUTO_TEST_CASE(mean_of_quadratic_history, *utf::label("DD7")) {
    const auto w = [](double t) { return (0.3 - 1.0 * t + 2.0 * t * t) * rad_s; };
    const AngularAcceleration a = dd07::mean_angular_acceleration(w(1.0) - w(0.5), 0.5 * second);
    BOOST_TEST(std::abs(a.value() - 2.0) <= 1e-14);
}

// Oracle: the textbook identity (alpha dt) / dt = alpha: mean_angular_acceleration of
// angular_velocity_change_over's result is the alpha put in, for any dt (1e-15 relative).
// Consistency, not evidence (no SRS label): a bug shared by both forms would not break it; the
// hand values and the calculus case above are DD7's oracles.
BOOST_AUTO_TEST_CASE(inverse_forms) {
    for (double dt : {1.0 / 60.0, 0.02, 3.0}) {
        const AngularVelocity dw = dd07::angular_velocity_change_over(-0.83 * rad_s2, dt * second);
        BOOST_TEST(dd07::mean_angular_acceleration(dw, dt * second).value() == -0.83,
                   tt::tolerance(1e-15));
    }
}

BOOST_AUTO_TEST_SUITE_END()
