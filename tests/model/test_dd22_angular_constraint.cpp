// DD22 (a revolute joint's motor and limits), checked against hand values: the joint angle
// and speed, the angular impulse that stops the relative turn (and conserves the total
// angular momentum about a common axis, T2 for torques), and the motor clamp.
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "tamias2d/model/dd22_angular_constraint.hpp"

namespace utf = boost::unit_test;
namespace tt = boost::test_tools;
using namespace tamias2d::units;
namespace dd22 = tamias2d::model::dd22;

BOOST_AUTO_TEST_SUITE(dd22_angular_constraint)

// Oracle: hand derivation. phi_A = 0.5, phi_B = 2, reference 1: theta = 0.5 rad.
BOOST_AUTO_TEST_CASE(joint_angle_hand_value, *utf::label("DD22")) {
    BOOST_TEST(dd22::joint_angle(0.5 * radian, 2.0 * radian, 1.0 * radian).value() == 0.5);
}

// Oracle: the rigid impulse's defining property: applied, the joint speed is zero, and
// I_A omega_A + I_B omega_B is unchanged. I_A = 2, I_B = 0.5 (1/I: 0.5, 2); omega 3 and -1.
BOOST_AUTO_TEST_CASE(rigid_impulse_stops_the_turn, *utf::label("DD22")) {
    const dd22::InverseInertia a{InverseMass::from_value(1.0),
                                 InverseMomentOfInertia::from_value(0.5)};
    const dd22::InverseInertia b{InverseMass::from_value(1.0),
                                 InverseMomentOfInertia::from_value(2.0)};
    dd22::Velocities A{vec_from_values<Velocity>(0.0, 0.0), AngularVelocity::from_value(3.0)};
    dd22::Velocities B{vec_from_values<Velocity>(0.0, 0.0), AngularVelocity::from_value(-1.0)};
    const double L = 2.0 * 3.0 + 0.5 * -1.0;
    const auto lambda =
        dd22::impulse(a, b, dd22::joint_speed(A, B), Dimensionless::from_value(1.0),
                      Dimensionless::from_value(0.0), dd22::AngularImpulse::from_value(0.0));
    dd22::apply(A, B, a, b, lambda);
    BOOST_TEST(std::abs(dd22::joint_speed(A, B).value()) <= 1e-15);
    BOOST_TEST(2.0 * A.omega.value() + 0.5 * B.omega.value() == L, tt::tolerance(1e-15));
}

// Oracle: T4 (omega changes by Lambda / I): when neither body can turn (1/I_A = 1/I_B = 0: a
// fixed-rotation body jointed to a kinematic one), no angular impulse changes the joint speed,
// so the row's impulse is 0 and finite, whatever the speed error (-rhs / 0 was inf and turned
// both bodies NaN through 0 * inf).
BOOST_AUTO_TEST_CASE(no_turning_body_gives_no_impulse, *utf::label("DD22")) {
    const dd22::InverseInertia fixed{InverseMass::from_value(1.0),
                                     InverseMomentOfInertia::from_value(0.0)};
    const dd22::InverseInertia kinematic{InverseMass::from_value(0.0),
                                         InverseMomentOfInertia::from_value(0.0)};
    for (const double rhs : {-81.3, 0.0, 5.0}) {
        const auto lambda = dd22::impulse(
            fixed, kinematic, AngularVelocity::from_value(rhs), Dimensionless::from_value(0.9),
            Dimensionless::from_value(0.1), dd22::AngularImpulse::from_value(0.0));
        BOOST_TEST(lambda.value() == 0.0);
    }
}

// Oracle: hand values of the clamp to [-max, max].
BOOST_AUTO_TEST_CASE(motor_clamp_hand_values, *utf::label("DD22")) {
    const auto m = dd22::AngularImpulse::from_value(0.5);
    BOOST_TEST(dd22::clamp(dd22::AngularImpulse::from_value(0.2), m).value() == 0.2);
    BOOST_TEST(dd22::clamp(dd22::AngularImpulse::from_value(0.9), m).value() == 0.5);
    BOOST_TEST(dd22::clamp(dd22::AngularImpulse::from_value(-0.9), m).value() == -0.5);
}

BOOST_AUTO_TEST_SUITE_END()
