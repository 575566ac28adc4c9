// DD24 (the weld's angle), DD25 (the wheel's line) and DD26 (the motor joint's rows), checked
// against hand evaluations of their equations.
#include <boost/test/unit_test.hpp>

#include "tamias2d/model/dd24_weld_constraint.hpp"
#include "tamias2d/model/dd25_wheel_constraint.hpp"
#include "tamias2d/model/dd26_motor_constraint.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d::units;
namespace m = tamias2d::model;
using m::dd08::InverseInertia;
using m::dd22::AngularImpulse;

namespace {
const InverseInertia fixed{InverseMass{}, InverseMomentOfInertia{}};
/// 1/m = 1 kg^-1, 1/I = 2 kg^-1 m^-2 rad^2.
const InverseInertia body{1.0 / kilogram, 2.0 * radian* radian / (kilogram * metre * metre)};
const Impulse ns = 1.0 * kilogram * metre / second;
const AngularImpulse nms = AngularImpulse::from_value(1.0);
} // namespace

BOOST_AUTO_TEST_SUITE(dd24_dd26_joint_rows)

// Oracle: DD24's Lambda = -gamma_m (thetadot + beta C_theta) / k - gamma_i Lambda_acc by hand:
// a static A and k = 2, thetadot = 1 rad/s, C_theta = 0.1 rad, beta = 10 s^-1, gamma_m = 0.5,
// gamma_i = 0.25, Lambda_acc = 0.4: -(0.5 x 2 / 2) - 0.1 = -0.6; the relax stops the speed
// alone, rigidly: -(1 / 2) = -0.5.
BOOST_AUTO_TEST_CASE(weld_angular_impulse_by_hand, *utf::label("DD24")) {
    const m::im6::Softness s{10.0 / second, 0.5, 0.25};
    const auto soft = m::dd24::angular_impulse(fixed, body, 1.0 * radian / second, 0.1 * radian, s,
                                               true, 0.4 * nms);
    BOOST_TEST(soft.value() == -0.6, boost::test_tools::tolerance(1e-15));
    const auto relax = m::dd24::angular_impulse(fixed, body, 1.0 * radian / second, 0.1 * radian, s,
                                                false, 0.4 * nms);
    BOOST_TEST(relax.value() == -0.5);
}

// Oracle: DD25's lambda_perp = -gamma_m (Cdot + beta C_perp) / K_perp - gamma_i lambda_acc by
// hand: K_perp = 1/m_B + (r_B x a_perp)^2 / I_B = 1 + 2 x 0.5^2 = 1.5 kg^-1 (A static),
// Cdot = 0.3 m/s, C_perp = 0.02 m, beta = 10 s^-1: Cdot + beta C = 0.5; gamma_m = 0.6,
// gamma_i = 0.2, lambda_acc = 1: -0.6 x 0.5 / 1.5 - 0.2 = -0.4; the relax: -0.3 / 1.5 = -0.2.
BOOST_AUTO_TEST_CASE(wheel_line_impulse_by_hand, *utf::label("DD25")) {
    const m::im6::Softness s{10.0 / second, 0.6, 0.2};
    const auto soft = m::dd25::line_impulse(fixed, body, Length{}, 0.5 * metre,
                                            0.3 * metre / second, 0.02 * metre, s, true, 1.0 * ns);
    BOOST_TEST(soft.value() == -0.4, boost::test_tools::tolerance(1e-14));
    const auto relax = m::dd25::line_impulse(
        fixed, body, Length{}, 0.5 * metre, 0.3 * metre / second, 0.02 * metre, s, false, 1.0 * ns);
    BOOST_TEST(relax.value() == -0.2, boost::test_tools::tolerance(1e-14));
}

// Oracle: DD26 by hand. c / h = 0.3 x 60 = 18 s^-1. The angular row from rest with k = 2:
// thetadot = 0, C_theta = 0.01 rad: -(18 x 0.01) / 2 = -0.09 N m s, within tau_max h =
// 12 x (1/60) = 0.2; with C_theta = 1 rad it would be -9, clamped to -0.2. The linear row with
// A static, B's origin the pin (r_B = 0, K = 1 kg^-1): C = (0.01, 0) m, Cdot = 0: P =
// -(18 x 0.01, 0) = (-0.18, 0) N s within F_max h = 30 / 60 = 0.5; with C = (0, 1) m,
// (0, -18) clamped to length 0.5.
BOOST_AUTO_TEST_CASE(motor_rows_by_hand, *utf::label("DD26")) {
    const Time h = (1.0 / 60.0) * second;
    const Rate rate = m::dd26::correction_rate(0.3, h);
    BOOST_TEST(rate.value() == 18.0, boost::test_tools::tolerance(1e-15));
    const Torque tau = 12.0 * newton * metre / radian;
    BOOST_TEST(m::dd26::angular_update(fixed, body, AngularVelocity{}, 0.01 * radian, rate, tau, h,
                                       AngularImpulse{})
                       .value() == -0.09,
               boost::test_tools::tolerance(1e-14));
    BOOST_TEST(m::dd26::angular_update(fixed, body, AngularVelocity{}, 1.0 * radian, rate, tau, h,
                                       AngularImpulse{})
                       .value() == -0.2,
               boost::test_tools::tolerance(1e-15));
    const Force F = 30.0 * newton;
    const Vec2<Length> r{};
    const Vec2<Velocity> still{};
    const auto near = m::dd26::linear_update(fixed, body, r, r, still,
                                             vec_from_values<Length>(0.01, 0.0), rate, F, h, {});
    BOOST_TEST(near.x.value() == -0.18, boost::test_tools::tolerance(1e-14));
    BOOST_TEST(near.y.value() == 0.0);
    const auto far = m::dd26::linear_update(fixed, body, r, r, still,
                                            vec_from_values<Length>(0.0, 1.0), rate, F, h, {});
    BOOST_TEST(far.x.value() == 0.0);
    BOOST_TEST(far.y.value() == -0.5, boost::test_tools::tolerance(1e-15));
}

BOOST_AUTO_TEST_SUITE_END()
