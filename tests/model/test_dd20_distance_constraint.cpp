// DD20 (the distance joint's constraint), checked against hand values: the axis and the
// position error of a 3-4-5 triangle and of coincident anchors, the velocity error along the axis
// by Chasles' theorem, and the rigid impulse that stops the anchors' relative motion along the axis
// while keeping the total linear momentum.
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "tamias2d/model/dd20_distance_constraint.hpp"

namespace utf = boost::unit_test;
namespace tt = boost::test_tools;
using namespace tamias2d::units;
namespace dd20 = tamias2d::model::dd20;

BOOST_AUTO_TEST_SUITE(dd20_distance_constraint)

// Oracle: hand derivation. d = (3, 4): |d| = 5, n = (0.6, 0.8); against L = 4.5, C = 0.5.
// A at rest spinning at 1 rad/s, arm r_A x n = 2 m: its anchor moves at 2 m/s along n;
// B moves at (1, 1): 1.4 m/s along n. Cdot = 1.4 - 2 = -0.6 m/s.
BOOST_AUTO_TEST_CASE(axis_and_errors_hand_values, *utf::label("DD20")) {
    const dd20::Axis a = dd20::axis(vec_from_values<Length>(3.0, 4.0));
    BOOST_TEST(a.length.value() == 5.0);
    BOOST_TEST(a.n.x == 0.6, tt::tolerance(1e-15));
    BOOST_TEST(a.n.y == 0.8, tt::tolerance(1e-15));
    BOOST_TEST(dd20::position_error(a, 4.5 * metre).value() == 0.5);
    const dd20::Velocities A{vec_from_values<Velocity>(0.0, 0.0), AngularVelocity::from_value(1.0)};
    const dd20::Velocities B{vec_from_values<Velocity>(1.0, 1.0), AngularVelocity::from_value(0.0)};
    const Velocity c_dot = dd20::velocity_error(A, 2.0 * metre, B, 0.0 * metre, a.n);
    BOOST_TEST(c_dot.value() == -0.6, tt::tolerance(1e-15));
}

// Oracle: DD20's convention for anchors that coincide: d = 0 has length 0 and no direction of
// its own, so the axis is (1, 0) (any axis holds), never 0 / 0; against L = 1, C = -1.
BOOST_AUTO_TEST_CASE(coincident_anchors_take_the_x_axis, *utf::label("DD20")) {
    const dd20::Axis a = dd20::axis(vec_from_values<Length>(0.0, 0.0));
    BOOST_TEST(a.length.value() == 0.0);
    BOOST_TEST(a.n.x == 1.0);
    BOOST_TEST(a.n.y == 0.0);
    BOOST_TEST(dd20::position_error(a, 1.0 * metre).value() == -1.0);
}

// Oracle: the rigid impulse's defining property: applied, it leaves the velocity error along
// n zero (to round-off), and m_A v_A + m_B v_B unchanged (T2).
BOOST_AUTO_TEST_CASE(rigid_impulse_stops_the_axial_motion, *utf::label("DD20")) {
    const dd20::InverseInertia a{InverseMass::from_value(0.5),
                                 InverseMomentOfInertia::from_value(1.5)};
    const dd20::InverseInertia b{InverseMass::from_value(0.25),
                                 InverseMomentOfInertia::from_value(0.4)};
    const dd20::Axis ax = dd20::axis(vec_from_values<Length>(-1.0, 2.0));
    dd20::Velocities A{vec_from_values<Velocity>(1.0, 0.5), AngularVelocity::from_value(-0.3)};
    dd20::Velocities B{vec_from_values<Velocity>(-2.0, 1.0), AngularVelocity::from_value(0.7)};
    const Length arm_a = 0.3 * metre, arm_b = -0.45 * metre;
    const double px = 2.0 * 1.0 + 4.0 * -2.0, py = 2.0 * 0.5 + 4.0 * 1.0;
    const Impulse lambda = dd20::impulse(
        a, b, arm_a, arm_b, dd20::velocity_error(A, arm_a, B, arm_b, ax.n),
        Dimensionless::from_value(1.0), Dimensionless::from_value(0.0), Impulse::from_value(0.0));
    dd20::apply(A, B, a, b, arm_a, arm_b, ax.n, lambda);
    BOOST_TEST(std::abs(dd20::velocity_error(A, arm_a, B, arm_b, ax.n).value()) <= 1e-14);
    BOOST_TEST(2.0 * A.v.x.value() + 4.0 * B.v.x.value() == px, tt::tolerance(1e-14));
    BOOST_TEST(2.0 * A.v.y.value() + 4.0 * B.v.y.value() == py, tt::tolerance(1e-14));
}

BOOST_AUTO_TEST_SUITE_END()
