// DD10 (impulse J = integral F dt = m dv), checked by hand and against T1's derivation.
#include <boost/test/unit_test.hpp>

#include "tamias2d/model/dd10_impulse.hpp"
#include "tamias2d/model/t1_newtons_second_law.hpp"

namespace utf = boost::unit_test;
namespace tt = boost::test_tools;
using namespace tamias2d::units;
namespace dd10 = tamias2d::model::dd10;
namespace t1 = tamias2d::model::t1;

BOOST_AUTO_TEST_SUITE(dd10_impulse)

// Oracle: hand derivation. J = m dv = 2 kg (3, -1.5) m/s = (6, -3) N s; conversely
// dv = J / m = (6, -3) N s / 2 kg = (3, -1.5) m/s; F = (4, 0) N for 0.25 s is (1, 0) N s.
BOOST_AUTO_TEST_CASE(hand_values, *utf::label("DD10")) {
    const Vec2<Impulse> J = dd10::impulse(2.0 * kilogram, vec_from_values<Velocity>(3.0, -1.5));
    BOOST_TEST(J.x.value() == 6.0);
    BOOST_TEST(J.y.value() == -3.0);
    const Vec2<Velocity> dv = dd10::velocity_change(J, 1.0 / (2.0 * kilogram));
    BOOST_TEST(dv.x.value() == 3.0);
    BOOST_TEST(dv.y.value() == -1.5);
    const Vec2<Impulse> JF =
        dd10::impulse_of_constant_force(vec_from_values<Force>(4.0, 0.0), 0.25 * second);
    BOOST_TEST(JF.x.value() == 1.0);
    BOOST_TEST(JF.y.value() == 0.0);
}

// Oracle: SRS convention (a static body has 1/m = 0): any impulse leaves it at rest.
BOOST_AUTO_TEST_CASE(static_body_does_not_move, *utf::label("DD10")) {
    const Vec2<Velocity> dv =
        dd10::velocity_change(vec_from_values<Impulse>(1e6, -3.0), 0.0 / (1.0 * kilogram));
    BOOST_TEST(dv.x.value() == 0.0);
    BOOST_TEST(dv.y.value() == 0.0);
}

// Oracle: the seed's derivation of DD10 from T1: a constant force F over dt gives a = F / m and
// dv = a dt, so F dt = m dv. F = (98.1, -20) N (SRS typical force), m = 56.2 kg, dt = 1/60 s:
// both sides agree to a few roundings (1e-14 relative), and velocity_change recovers a dt.
BOOST_AUTO_TEST_CASE(force_times_time_equals_momentum_change,
                     *utf::label("DD10") * utf::label("T1")) {
    const Vec2<Force> F = vec_from_values<Force>(98.1, -20.0);
    const Mass m = 56.2 * kilogram;
    const Time dt = (1.0 / 60.0) * second;
    const Vec2<Velocity> dv = t1::acceleration(F, m) * dt;
    const Vec2<Impulse> J1 = dd10::impulse_of_constant_force(F, dt);
    const Vec2<Impulse> J2 = dd10::impulse(m, dv);
    BOOST_TEST(J1.x.value() == J2.x.value(), tt::tolerance(1e-14));
    BOOST_TEST(J1.y.value() == J2.y.value(), tt::tolerance(1e-14));
    const Vec2<Velocity> back = dd10::velocity_change(J1, 1.0 / m);
    BOOST_TEST(back.x.value() == dv.x.value(), tt::tolerance(1e-14));
    BOOST_TEST(back.y.value() == dv.y.value(), tt::tolerance(1e-14));
}

BOOST_AUTO_TEST_SUITE_END()
