// IM2 (rotational motion alpha = tau / I, integrated by semi-implicit Euler), checked against
// hand-computed step sequences and the scheme's exact closed form under constant angular
// acceleration, and with a torque from DD13 on an inertia from DD14.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <numbers>

#include "tamias2d/model/dd13_torque.hpp"
#include "tamias2d/model/dd14_moment_of_inertia.hpp"
#include "tamias2d/model/im2_rotational_motion.hpp"

namespace utf = boost::unit_test;
namespace tt = boost::test_tools;
using namespace tamias2d::units;
namespace im2 = tamias2d::model::im2;
namespace dd13 = tamias2d::model::dd13;
namespace dd14 = tamias2d::model::dd14;

namespace {
const auto rad_s = radian / second;
const auto rad_s2 = radian / (second * second);
const auto kg_m2 = kilogram * metre * metre / (radian * radian);
} // namespace

BOOST_AUTO_TEST_SUITE(im2_rotational_motion)

// Oracle: hand derivation. tau = 200 N m (SRS typical) on I = 74.5 kg m^2 (SRS typical):
// alpha = 200 / 74.5 = 2.684563758389262 rad s^-2; tau = -6 N m on 2 kg m^2: -3 rad s^-2.
BOOST_AUTO_TEST_CASE(angular_acceleration_hand_value, *utf::label("IM2")) {
    const auto N_m = newton * metre / radian;
    BOOST_TEST(im2::angular_acceleration(200.0 * N_m, 74.5 * kg_m2).value() == 200.0 / 74.5,
               tt::tolerance(1e-15));
    BOOST_TEST(im2::angular_acceleration(-6.0 * N_m, 2.0 * kg_m2).value() == -3.0);
}

// Oracle: hand-computed semi-implicit Euler sequence (omega first, then phi with the new
// omega). phi0 = 0, omega0 = 1 rad/s, alpha = 2 rad s^-2, dt = 0.25 s: omega = 1.5, 2, 2.5 and
// phi = 0.375, 0.875, 1.5 rad. Every value is exact in binary.
BOOST_AUTO_TEST_CASE(hand_computed_steps, *utf::label("IM2")) {
    im2::RotationalState s{0.0 * radian, 1.0 * rad_s};
    const double expected[3][2] = {{0.375, 1.5}, {0.875, 2.0}, {1.5, 2.5}};
    for (const auto& e : expected) {
        s = im2::step(s, 2.0 * rad_s2, 0.25 * second);
        BOOST_TEST(s.phi.value() == e[0]);
        BOOST_TEST(s.omega.value() == e[1]);
    }
}

// Oracle: closed form of semi-implicit Euler under constant alpha: omega_n = omega0 + alpha t_n
// exactly and phi_n = phi0 + omega0 t + alpha t^2 / 2 + alpha dt t / 2 (the first-order term,
// 0.5 alpha dt^2 per step). The torque comes from DD13 (F = (0, 3) N at r = (0.5, 0) m: 1.5 N m)
// and the inertia from DD14 (solid disc, 2 kg, R = 0.5 m: 0.25 kg m^2), so alpha = 6 rad s^-2.
// 90 steps of 1/60 s; phi stays unwrapped (it passes 2 pi). Round-off: 90 additions of terms
// below 40 rad, bound 1e-12 relative.
BOOST_AUTO_TEST_CASE(constant_torque_closed_form,
                     *utf::label("IM2") * utf::label("DD13") * utf::label("DD14")) {
    const Torque tau =
        dd13::torque(vec_from_values<Length>(0.5, 0.0), vec_from_values<Force>(0.0, 3.0));
    const MomentOfInertia I = dd14::disc(2.0 * kilogram, 0.5 * metre);
    const AngularAcceleration alpha = im2::angular_acceleration(tau, I);
    BOOST_TEST(alpha.value() == 6.0, tt::tolerance(1e-15));
    const double w0 = 2.1, phi0 = std::numbers::pi / 2, dt = 1.0 / 60.0; // SRS typical values
    im2::RotationalState s{phi0 * radian, w0 * rad_s};
    for (int n = 1; n <= 90; ++n) {
        s = im2::step(s, alpha, dt * second);
        const double t = n * dt;
        BOOST_TEST(s.omega.value() == w0 + 6.0 * t, tt::tolerance(1e-12));
        BOOST_TEST(s.phi.value() == phi0 + w0 * t + 3.0 * t * t + 3.0 * dt * t,
                   tt::tolerance(1e-12));
    }
    BOOST_TEST(s.phi.value() > 2.0 * std::numbers::pi); // unwrapped (see DCO_phi for output)
}

// Oracle: textbook uniform rotation (no torque): omega is constant and phi advances by exactly
// omega dt per step: 0.5 rad/s for 8 steps of 0.25 s turns 1 rad (exact in binary).
BOOST_AUTO_TEST_CASE(torque_free_rotation, *utf::label("IM2")) {
    im2::RotationalState s{-0.5 * radian, 0.5 * rad_s};
    for (int n = 0; n < 8; ++n)
        s = im2::step(s, 0.0 * rad_s2, 0.25 * second);
    BOOST_TEST(s.omega.value() == 0.5);
    BOOST_TEST(s.phi.value() == 0.5);
}

BOOST_AUTO_TEST_SUITE_END()
