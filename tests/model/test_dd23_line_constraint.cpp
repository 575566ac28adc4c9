// DD23 (a prismatic joint's line and angle), checked against hand values and the block
// impulse's defining property: applied, it stops both the line's and the angle's velocity
// errors at once.
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "tamias2d/model/dd20_distance_constraint.hpp"
#include "tamias2d/model/dd23_line_constraint.hpp"

namespace utf = boost::unit_test;
namespace tt = boost::test_tools;
using namespace tamias2d::units;
namespace dd20 = tamias2d::model::dd20;
namespace dd22 = tamias2d::model::dd22;
namespace dd23 = tamias2d::model::dd23;

namespace {

/// Two movable bodies with non-zero arms, so that the line and the angle are coupled (k12 != 0).
struct CoupledPair {
    dd23::InverseInertia a, b;
    Length arm_A, arm_B;
};

CoupledPair coupled_pair() {
    return {{InverseMass::from_value(0.5), InverseMomentOfInertia::from_value(1.5)},
            {InverseMass::from_value(2.0), InverseMomentOfInertia::from_value(0.7)},
            Length::from_value(0.8),
            Length::from_value(-0.3)};
}

} // namespace

BOOST_AUTO_TEST_SUITE(dd23_line_constraint)

// Oracle: hand derivation. d = (3, 4), r_A = (1, 0), r_B = (0, 2), a = (1, 0), a_perp = (0, 1):
// s = 3, C_perp = 4; d + r_A = (4, 4): (4, 4) x (1, 0) = -4, (0, 2) x (1, 0) = -2,
// (4, 4) x (0, 1) = 4, (0, 2) x (0, 1) = 0.
BOOST_AUTO_TEST_CASE(line_hand_values, *utf::label("DD23")) {
    const dd23::Line l =
        dd23::line(vec_from_values<Length>(3.0, 4.0), vec_from_values<Length>(1.0, 0.0),
                   vec_from_values<Length>(0.0, 2.0), {1.0, 0.0});
    BOOST_TEST(l.translation.value() == 3.0);
    BOOST_TEST(l.perpendicular.value() == 4.0);
    BOOST_TEST(l.arm_A.value() == -4.0);
    BOOST_TEST(l.arm_B.value() == -2.0);
    BOOST_TEST(l.perp_arm_A.value() == 4.0);
    BOOST_TEST(l.perp_arm_B.value() == 0.0);
}

// Oracle: the rigid block impulse's defining property. Two movable bodies with non-zero arms
// (so that the line and the angle are coupled, k12 != 0): after the impulses are applied
// (lambda along a_perp as DD20 applies an axial impulse, Lambda about z as DD22), the line's
// velocity error and the joint speed are both zero.
BOOST_AUTO_TEST_CASE(rigid_block_stops_line_and_angle, *utf::label("DD23")) {
    const auto [a, b, arm_A, arm_B] = coupled_pair();
    const Vec2<double> n{0.6, 0.8};
    dd20::Velocities A{vec_from_values<Velocity>(1.0, -2.0), AngularVelocity::from_value(0.4)};
    dd20::Velocities B{vec_from_values<Velocity>(-0.5, 3.0), AngularVelocity::from_value(-1.2)};
    const auto P = dd23::block_impulse(
        a, b, arm_A, arm_B, dd20::velocity_error(A, arm_A, B, arm_B, n), dd22::joint_speed(A, B),
        Dimensionless::from_value(1.0), Dimensionless::from_value(0.0),
        {Impulse::from_value(0.0), dd22::AngularImpulse::from_value(0.0)});
    dd20::apply(A, B, a, b, arm_A, arm_B, n, P.linear);
    dd22::apply(A, B, a, b, P.angular);
    BOOST_TEST(std::abs(dd20::velocity_error(A, arm_A, B, arm_B, n).value()) <= 1e-14);
    BOOST_TEST(std::abs(dd22::joint_speed(A, B).value()) <= 1e-14);
}

// Oracle: IM6's soft form as IM7 states it, P <- mu P_rigid - gamma P_accumulated, row by row:
// the soft block impulse is the rigid one (whose defining property the case above checks)
// scaled by mu, less gamma times what each row has accumulated (here of opposite signs).
BOOST_AUTO_TEST_CASE(soft_block_scales_the_rigid_one_and_relaxes_each_row, *utf::label("DD23")) {
    const auto [a, b, arm_A, arm_B] = coupled_pair();
    const auto rhs_perp = Velocity::from_value(1.3);
    const auto rhs_angle = AngularVelocity::from_value(-0.9);
    const dd23::BlockImpulse none{Impulse::from_value(0.0), dd22::AngularImpulse::from_value(0.0)};
    const dd23::BlockImpulse held{Impulse::from_value(0.4),
                                  dd22::AngularImpulse::from_value(-0.25)};
    const double mu = 0.7, gamma = 0.2;
    const auto rigid =
        dd23::block_impulse(a, b, arm_A, arm_B, rhs_perp, rhs_angle, Dimensionless::from_value(1.0),
                            Dimensionless::from_value(0.0), none);
    const auto soft =
        dd23::block_impulse(a, b, arm_A, arm_B, rhs_perp, rhs_angle, Dimensionless::from_value(mu),
                            Dimensionless::from_value(gamma), held);
    BOOST_TEST(soft.linear.value() == mu * rigid.linear.value() - gamma * 0.4,
               tt::tolerance(1e-14));
    BOOST_TEST(soft.angular.value() == mu * rigid.angular.value() + gamma * 0.25,
               tt::tolerance(1e-14));
}

// Oracle: the line row's defining property with no body able to turn (1/I_A = 1/I_B = 0, so
// k22 = 0 and the block is singular): the impulse along a_perp alone stops the line's velocity
// error, and there is no angular impulse (T4: none could change the joint speed).
BOOST_AUTO_TEST_CASE(no_turning_body_solves_the_line_alone, *utf::label("DD23")) {
    const dd23::InverseInertia a{InverseMass::from_value(0.5),
                                 InverseMomentOfInertia::from_value(0.0)};
    const dd23::InverseInertia b{InverseMass::from_value(0.0),
                                 InverseMomentOfInertia::from_value(0.0)};
    const auto arm_A = Length::from_value(0.8), arm_B = Length::from_value(-0.3);
    const Vec2<double> n{0.6, 0.8};
    dd20::Velocities A{vec_from_values<Velocity>(1.0, -2.0), AngularVelocity::from_value(0.0)};
    dd20::Velocities B{vec_from_values<Velocity>(-0.5, 3.0), AngularVelocity::from_value(2.0)};
    const auto P = dd23::block_impulse(
        a, b, arm_A, arm_B, dd20::velocity_error(A, arm_A, B, arm_B, n), dd22::joint_speed(A, B),
        Dimensionless::from_value(1.0), Dimensionless::from_value(0.0),
        {Impulse::from_value(0.0), dd22::AngularImpulse::from_value(0.0)});
    BOOST_TEST(std::isfinite(P.linear.value()));
    BOOST_TEST(P.angular.value() == 0.0);
    dd20::apply(A, B, a, b, arm_A, arm_B, n, P.linear);
    BOOST_TEST(std::abs(dd20::velocity_error(A, arm_A, B, arm_B, n).value()) <= 1e-14);
    BOOST_TEST(A.omega.value() == 0.0);
    BOOST_TEST(B.omega.value() == 2.0);
}

// Oracle: hand values of the motor clamp to [-max, max].
BOOST_AUTO_TEST_CASE(motor_clamp_hand_values, *utf::label("DD23")) {
    const auto m = Impulse::from_value(0.5);
    BOOST_TEST(dd23::clamp(Impulse::from_value(0.2), m).value() == 0.2);
    BOOST_TEST(dd23::clamp(Impulse::from_value(0.9), m).value() == 0.5);
    BOOST_TEST(dd23::clamp(Impulse::from_value(-0.9), m).value() == -0.5);
}

BOOST_AUTO_TEST_SUITE_END()
