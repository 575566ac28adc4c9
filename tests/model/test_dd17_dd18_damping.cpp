// DD17 and DD18 (viscous damping of translation and rotation), checked against hand values and
// their units (the result types are the accelerations the SRS states).
#include <boost/test/unit_test.hpp>

#include <type_traits>

#include "tamias2d/model/dd17_linear_damping.hpp"
#include "tamias2d/model/dd18_angular_damping.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d::units;
namespace dd17 = tamias2d::model::dd17;
namespace dd18 = tamias2d::model::dd18;

BOOST_AUTO_TEST_SUITE(dd17_dd18_damping)

// Oracle: hand derivation. c_v = 0.5 s^-1 on v = (2, -4) m s^-1: a_d = (-1, 2) m s^-2, opposed
// to v and half its magnitude per second; the type is an acceleration (m s^-2).
BOOST_AUTO_TEST_CASE(linear_damping_hand_value, *utf::label("DD17")) {
    const auto a = dd17::acceleration(0.5 / second, vec_from_values<Velocity>(2.0, -4.0));
    static_assert(std::is_same_v<decltype(a), const Vec2<Acceleration>>);
    BOOST_TEST(a.x.value() == -1.0);
    BOOST_TEST(a.y.value() == 2.0);
    const auto none = dd17::acceleration(0.0 / second, vec_from_values<Velocity>(2.0, -4.0));
    BOOST_TEST(none.x.value() == 0.0);
    BOOST_TEST(none.y.value() == 0.0);
}

// Oracle: hand derivation. c_omega = 4 s^-1 on omega = -0.25 rad s^-1: alpha_d = 1 rad s^-2.
BOOST_AUTO_TEST_CASE(angular_damping_hand_value, *utf::label("DD18")) {
    const auto alpha = dd18::angular_acceleration(4.0 / second, -0.25 * radian / second);
    static_assert(std::is_same_v<decltype(alpha), const AngularAcceleration>);
    BOOST_TEST(alpha.value() == 1.0);
}

BOOST_AUTO_TEST_SUITE_END()
