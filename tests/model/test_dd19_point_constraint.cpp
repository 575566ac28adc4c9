// DD19 (the revolute joint's pin constraint), checked against hand values: the velocity error
// by Chasles' theorem, K's entries, the impulse that zeroes the velocity error, and the
// conservation of linear momentum by the equal and opposite impulse.
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "tamias2d/model/dd19_point_constraint.hpp"

namespace utf = boost::unit_test;
namespace tt = boost::test_tools;
using namespace tamias2d::units;
namespace dd19 = tamias2d::model::dd19;

namespace {
dd19::InverseInertia inverse(double inv_m, double inv_I) {
    return {InverseMass::from_value(inv_m), InverseMomentOfInertia::from_value(inv_I)};
}
dd19::Velocities velocities(double vx, double vy, double w) {
    return {vec_from_values<Velocity>(vx, vy), AngularVelocity::from_value(w)};
}
} // namespace

BOOST_AUTO_TEST_SUITE(dd19_point_constraint)

// Oracle: hand derivation. A at rest spinning at 2 rad/s with the pin at r_A = (1, 0): the pin
// moves at omega x r = (0, 2). B moves at (1, 0) without spin: Cdot = (1, 0) - (0, 2) = (1, -2).
// C from centres 3 m apart with r_A = (1, 0), r_B = (-2, 0): (3, 0) + (-2 - 1, 0) = 0.
BOOST_AUTO_TEST_CASE(errors_hand_values, *utf::label("DD19")) {
    const auto r_a = vec_from_values<Length>(1.0, 0.0), r_b = vec_from_values<Length>(-2.0, 0.0);
    const Vec2<Velocity> c_dot =
        dd19::velocity_error(velocities(0.0, 0.0, 2.0), r_a, velocities(1.0, 0.0, 0.0), r_b);
    BOOST_TEST(c_dot.x.value() == 1.0);
    BOOST_TEST(c_dot.y.value() == -2.0);
    const Vec2<Length> c = dd19::position_error(vec_from_values<Length>(3.0, 0.0), r_a, r_b);
    BOOST_TEST(c.x.value() == 0.0);
    BOOST_TEST(c.y.value() == 0.0);
}

// Oracle: hand derivation of K = (1/m_A + 1/m_B) 1 + [r_A]x^T [r_A]x / I_A + ... with
// 1/m_A = 0.5, 1/I_A = 2, r_A = (1, 2); 1/m_B = 0.25, 1/I_B = 0 (B does not turn):
// k11 = 0.75 + 2 * 4 = 8.75, k12 = -2 * 2 * 1 = -4, k22 = 0.75 + 2 * 1 = 2.75.
BOOST_AUTO_TEST_CASE(effective_mass_hand_values, *utf::label("DD19")) {
    const dd19::PinMass K = dd19::effective_mass_inverse(inverse(0.5, 2.0), inverse(0.25, 0.0),
                                                         vec_from_values<Length>(1.0, 2.0),
                                                         vec_from_values<Length>(5.0, 7.0));
    BOOST_TEST(K.k11.value() == 8.75);
    BOOST_TEST(K.k12.value() == -4.0);
    BOOST_TEST(K.k22.value() == 2.75);
}

// Oracle: the defining property of the rigid impulse (mass_scale 1, impulse_scale 0): applied
// to the bodies it leaves Cdot = 0 (to round-off), and m_A v_A + m_B v_B is unchanged (T2).
BOOST_AUTO_TEST_CASE(rigid_impulse_stops_the_pin_and_conserves_momentum, *utf::label("DD19")) {
    const dd19::InverseInertia a = inverse(1.0 / 3.0, 0.8), b = inverse(0.5, 1.5);
    const auto r_a = vec_from_values<Length>(0.4, -0.3), r_b = vec_from_values<Length>(-0.2, 0.6);
    dd19::Velocities va = velocities(1.0, -2.0, 0.7), vb = velocities(-0.5, 0.25, -1.2);
    const double px = 3.0 * 1.0 + 2.0 * -0.5, py = 3.0 * -2.0 + 2.0 * 0.25;
    const dd19::PinMass K = dd19::effective_mass_inverse(a, b, r_a, r_b);
    const Vec2<Impulse> P =
        dd19::impulse(K, dd19::velocity_error(va, r_a, vb, r_b), Dimensionless::from_value(1.0),
                      Dimensionless::from_value(0.0), vec_from_values<Impulse>(0.0, 0.0));
    dd19::apply(va, vb, a, b, r_a, r_b, P);
    const Vec2<Velocity> after = dd19::velocity_error(va, r_a, vb, r_b);
    BOOST_TEST(std::abs(after.x.value()) <= 1e-14);
    BOOST_TEST(std::abs(after.y.value()) <= 1e-14);
    BOOST_TEST(3.0 * va.v.x.value() + 2.0 * vb.v.x.value() == px, tt::tolerance(1e-14));
    BOOST_TEST(3.0 * va.v.y.value() + 2.0 * vb.v.y.value() == py, tt::tolerance(1e-14));
}

BOOST_AUTO_TEST_SUITE_END()
