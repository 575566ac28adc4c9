// DD35 (a distance joint's motor), DD36 (breaking) and DD37 (a joint's own soft bias), checked
// against hand evaluations of their equations.
#include <boost/test/unit_test.hpp>

#include <limits>

#include "tamias2d/model/dd35_distance_joint_motor.hpp"
#include "tamias2d/model/dd36_joint_break.hpp"
#include "tamias2d/model/dd37_joint_tuning.hpp"

namespace utf = boost::unit_test;
namespace tt = boost::test_tools;
using namespace tamias2d::units;
namespace m = tamias2d::model;
using m::dd08::InverseInertia;

namespace {
const InverseInertia fixed{InverseMass{}, InverseMomentOfInertia{}};
/// 1/m = 0.5 kg^-1, 1/I = 2 kg^-1 m^-2 rad^2.
const InverseInertia body{0.5 / kilogram, 2.0 * radian* radian / (kilogram * metre * metre)};
const Impulse ns = 1.0 * kilogram * metre / second;
} // namespace

BOOST_AUTO_TEST_SUITE(dd35_dd37_joint_control)

// Oracle: DD35 by hand. A static A and B with 1/m = 0.5 kg^-1, arm_B = 0.5 m: K = 0.5 + 2 x
// 0.25 = 1 kg^-1. Ldot = 0.2 m/s, v_m = 1 m/s: the rigid impulse -(0.2 - 1) / 1 = 0.8 N s; from
// Lambda_acc = 0.1 the accumulation 0.9 N s, within F_max h = 60 x (1/60) = 1 N s; with F_max =
// 30 N, clamped to 0.5 N s; moving apart too fast (Ldot = 3 m/s), -2 + 0.1 clamped to -0.5.
BOOST_AUTO_TEST_CASE(distance_motor_by_hand, *utf::label("DD35")) {
    const Time h = (1.0 / 60.0) * second;
    const Length arm = 0.5 * metre;
    const auto v = [](double x) { return x * metre / second; };
    const Impulse free = m::dd35::motor_update(fixed, body, Length{}, arm, v(0.2), v(1.0),
                                               60.0 * newton, h, 0.1 * ns);
    BOOST_TEST(free.value() == 0.9, tt::tolerance(1e-14));
    const Impulse held = m::dd35::motor_update(fixed, body, Length{}, arm, v(0.2), v(1.0),
                                               30.0 * newton, h, 0.1 * ns);
    BOOST_TEST(held.value() == 0.5, tt::tolerance(1e-14));
    const Impulse back = m::dd35::motor_update(fixed, body, Length{}, arm, v(3.0), v(1.0),
                                               30.0 * newton, h, 0.1 * ns);
    BOOST_TEST(back.value() == -0.5, tt::tolerance(1e-14));
}

// Oracle: DD36's rule by hand: a force 10 N against 9 N breaks; a torque of -5 N m against
// 4 N m breaks (its magnitude); at the thresholds exactly, or with infinite ones, nothing breaks.
BOOST_AUTO_TEST_CASE(break_rule_by_hand, *utf::label("DD36")) {
    const double inf = std::numeric_limits<double>::infinity();
    const auto N = [](double x) { return x * newton; };
    const auto Nm = [](double x) { return Torque::from_value(x); };
    BOOST_TEST(m::dd36::breaks(N(10.0), N(9.0), Nm(0.0), Nm(inf)));
    BOOST_TEST(m::dd36::breaks(N(0.0), N(inf), Nm(-5.0), Nm(4.0)));
    BOOST_TEST(!m::dd36::breaks(N(9.0), N(9.0), Nm(4.0), Nm(4.0)));
    BOOST_TEST(!m::dd36::breaks(N(1e30), N(inf), Nm(-1e30), Nm(inf)));
}

// Oracle: DD37 by hand and IM6. f = 5 Hz, zeta = 1, n = 4, dt = 1/60 s (h = 1/240 s): omega =
// 10 pi, h omega = pi / 24, a1 = 2 + h omega, a2 = h omega a1; beta = omega / a1, mass scale
// a2 / (1 + a2), impulse scale 1 / (1 + a2). A frequency above the cap n / (4 dt) = 60 Hz is
// taken at 60 Hz.
BOOST_AUTO_TEST_CASE(own_softness_by_hand, *utf::label("DD37")) {
    const double pi = 3.14159265358979323846;
    const Time dt = (1.0 / 60.0) * second, h = dt / 4.0;
    const m::im6::Softness s = m::dd37::softness({5.0 / second, 1.0}, 4, dt, h);
    const double omega = 10.0 * pi, ho = omega / 240.0, a1 = 2.0 + ho, a2 = ho * a1;
    BOOST_TEST(s.bias_rate.value() == omega / a1, tt::tolerance(1e-14));
    BOOST_TEST(s.mass_scale.value() == a2 / (1.0 + a2), tt::tolerance(1e-14));
    BOOST_TEST(s.impulse_scale.value() == 1.0 / (1.0 + a2), tt::tolerance(1e-14));
    const m::im6::Softness capped = m::dd37::softness({500.0 / second, 1.0}, 4, dt, h);
    const m::im6::Softness at_cap = m::dd37::softness({60.0 / second, 1.0}, 4, dt, h);
    BOOST_TEST(capped.bias_rate.value() == at_cap.bias_rate.value());
    BOOST_TEST(capped.mass_scale.value() == at_cap.mass_scale.value());
}

BOOST_AUTO_TEST_SUITE_END()
