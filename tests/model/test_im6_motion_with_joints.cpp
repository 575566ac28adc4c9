// IM6 (motion with joints, the soft constraints), checked against backward Euler of the damped
// spring a soft joint stands for, and hand values.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <numbers>

#include "tamias2d/model/im6_motion_with_joints.hpp"
#include "tamias2d/units/vec2.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d::units;
namespace im6 = tamias2d::model::im6;

BOOST_AUTO_TEST_SUITE(im6_motion_with_joints)

// Oracle: backward Euler of the spring x'' = -w^2 x - 2 z w x' (w = 2 pi f) over one substep h
// for a unit effective mass, derived by hand: v1 = (v0 - h w^2 x0) / (1 + h w (2 z + h w)). A
// joint row with position error C = x0 and velocity error Cdot = v0, from nothing accumulated,
// takes the soft impulse -(Cdot + beta C) / K scaled by the mass scale (K = 1 kg^-1) and must
// leave v1; over f = 1 ... 120 Hz, z = 0.1 ... 10, h = 1/30 ... 1/960 s.
BOOST_AUTO_TEST_CASE(soft_joint_row_is_backward_euler_of_its_spring, *utf::label("IM6")) {
    double worst = 0.0;
    for (const double f : {1.0, 5.0, 30.0, 120.0})
        for (const double z : {0.1, 0.7, 1.0, 10.0})
            for (const double h : {1.0 / 30.0, 1.0 / 240.0, 1.0 / 960.0}) {
                const double x0 = 0.03, v0 = -0.4;
                const double w = 2.0 * std::numbers::pi * f;
                const double v1 = (v0 - h * w * w * x0) / (1.0 + h * w * (2.0 * z + h * w));
                const im6::Softness s = im6::softness(f / second, z, h * second);
                const Velocity rhs =
                    im6::biased_velocity_error(v0 * metre / second, s.bias_rate, x0 * metre);
                const Impulse rigid = -(rhs / (1.0 / kilogram));
                const Impulse P =
                    im6::soft_impulse(s.mass_scale, rigid, s.impulse_scale, Impulse{});
                worst = std::max(worst, std::abs(v0 + P.value() - v1) / (std::abs(v1) + 1.0));
            }
    BOOST_TEST(worst < 1e-14);
}

// Oracle: hand values. Cdot + beta C = 2 + 3 x 0.5 = 3.5 m s^-1 (and for an angle, -1 + 4 x
// 0.25 = 0 rad s^-1); the soft impulse 0.5 x 4 - 0.25 x 2 = 1.5 N s, on each component of a
// vector alike; the joints' frequency capped as the contacts' at a quarter of the substep rate
// (4 substeps of 1/60 s: 60 Hz), f = 0 rigid (mass scale 1, nothing relaxed).
BOOST_AUTO_TEST_CASE(bias_impulse_and_cap_by_hand, *utf::label("IM6")) {
    BOOST_TEST(
        im6::biased_velocity_error(2.0 * metre / second, 3.0 / second, 0.5 * metre).value() == 3.5);
    BOOST_TEST(
        im6::biased_velocity_error(-1.0 * radian / second, 4.0 / second, 0.25 * radian).value() ==
        0.0);
    const Impulse ns = 1.0 * kilogram * metre / second;
    BOOST_TEST(
        im6::soft_impulse(Dimensionless{0.5}, 4.0 * ns, Dimensionless{0.25}, 2.0 * ns).value() ==
        1.5);
    const Vec2<Impulse> P =
        im6::soft_impulse(Dimensionless{0.5}, Vec2<Impulse>{4.0 * ns, -4.0 * ns},
                          Dimensionless{0.25}, Vec2<Impulse>{2.0 * ns, -2.0 * ns});
    BOOST_TEST(P.x.value() == 1.5);
    BOOST_TEST(P.y.value() == -1.5);
    BOOST_TEST(std::abs(im6::frequency(100.0 / second, 4, (1.0 / 60.0) * second).value() - 60.0) <
               1e-12);
    BOOST_TEST(im6::frequency(45.0 / second, 4, (1.0 / 60.0) * second).value() == 45.0);
    const im6::Softness rigid = im6::softness(0.0 / second, 1.0, 0.01 * second);
    BOOST_TEST(rigid.mass_scale.value() == 1.0);
    BOOST_TEST(rigid.impulse_scale.value() == 0.0);
}

BOOST_AUTO_TEST_SUITE_END()
