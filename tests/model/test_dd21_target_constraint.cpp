// DD21 (the target joint's constraint), checked against hand values: the position error and
// the clamp of the accumulated impulse to F_max h.
#include <boost/test/unit_test.hpp>

#include "tamias2d/model/dd21_target_constraint.hpp"

namespace utf = boost::unit_test;
namespace tt = boost::test_tools;
using namespace tamias2d::units;
namespace dd21 = tamias2d::model::dd21;

BOOST_AUTO_TEST_SUITE(dd21_target_constraint)

// Oracle: hand derivation. Centre (1, 2), grabbed point 0.5 m to its right, target (4, -2):
// C = (1.5, 2) - (4, -2) = (-2.5, 4).
BOOST_AUTO_TEST_CASE(position_error_hand_value, *utf::label("DD21")) {
    const Vec2<Length> c =
        dd21::position_error(vec_from_values<Length>(1.0, 2.0), vec_from_values<Length>(0.5, 0.0),
                             vec_from_values<Length>(4.0, -2.0));
    BOOST_TEST(c.x.value() == -2.5);
    BOOST_TEST(c.y.value() == 4.0);
}

// Oracle: hand derivation. (3, 4) N s has length 5: within a limit of 5 or more it is kept
// bit for bit; against a limit of 2.5 it is halved to (1.5, 2), its direction kept.
BOOST_AUTO_TEST_CASE(clamp_hand_values, *utf::label("DD21")) {
    const Vec2<Impulse> p = vec_from_values<Impulse>(3.0, 4.0);
    const Vec2<Impulse> kept = dd21::clamp(p, Impulse::from_value(5.0));
    BOOST_TEST(kept.x.value() == 3.0);
    BOOST_TEST(kept.y.value() == 4.0);
    const Vec2<Impulse> halved = dd21::clamp(p, Impulse::from_value(2.5));
    BOOST_TEST(halved.x.value() == 1.5, tt::tolerance(1e-15));
    BOOST_TEST(halved.y.value() == 2.0, tt::tolerance(1e-15));
}

// Oracle: DD21's bound with F_max = 0 (a motor joint may have no force, DD26): the joint never
// pulls, so an accumulated impulse of zero stays exactly zero, never 0 / 0.
BOOST_AUTO_TEST_CASE(a_zero_limit_keeps_a_zero_impulse, *utf::label("DD21")) {
    const Vec2<Impulse> zero = vec_from_values<Impulse>(0.0, 0.0);
    const Vec2<Impulse> kept = dd21::clamp(zero, Impulse::from_value(0.0));
    BOOST_TEST(kept.x.value() == 0.0);
    BOOST_TEST(kept.y.value() == 0.0);
    const Vec2<Impulse> stopped =
        dd21::clamp(vec_from_values<Impulse>(3.0, 4.0), Impulse::from_value(0.0));
    BOOST_TEST(stopped.x.value() == 0.0);
    BOOST_TEST(stopped.y.value() == 0.0);
}

BOOST_AUTO_TEST_SUITE_END()
