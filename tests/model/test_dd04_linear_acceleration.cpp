// DD4 (linear acceleration a = dv/dt), checked by hand and against the midpoint property of
// quadratic velocity histories.
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "tamias2d/model/dd04_linear_acceleration.hpp"

namespace utf = boost::unit_test;
namespace tt = boost::test_tools;
using namespace tamias2d::units;
namespace dd04 = tamias2d::model::dd04;

BOOST_AUTO_TEST_SUITE(dd04_linear_acceleration)

// Oracle: hand derivation. a = (0, -9.81) m s^-2 for dt = 0.5 s changes v by (0, -4.905) m/s
// (halving is exact); conversely dv = (3, -6) m/s over 1.5 s is a = (2, -4) m s^-2.
BOOST_AUTO_TEST_CASE(hand_values, *utf::label("DD4")) {
    const Vec2<Acceleration> g = vec_from_values<Acceleration>(0.0, -9.81);
    const Vec2<Velocity> dv = dd04::velocity_change_over(g, 0.5 * second);
    BOOST_TEST(dv.x.value() == 0.0);
    BOOST_TEST(dv.y.value() == -4.905);
    const Vec2<Acceleration> a =
        dd04::mean_acceleration(vec_from_values<Velocity>(3.0, -6.0), 1.5 * second);
    BOOST_TEST(a.x.value() == 2.0, tt::tolerance(1e-15));
    BOOST_TEST(a.y.value() == -4.0, tt::tolerance(1e-15));
}

// Oracle: textbook calculus. For v(t) = v0 + a0 t + j t^2 / 2 (constant jerk j) the mean
// acceleration over [t, t + h] is a(t + h / 2) = a0 + j (t + h / 2) exactly. a0 = (1, -2),
// j = (0.5, 3), [2, 2.25] s: a(2.125) = (2.0625, 4.375) m s^-2. Round-off: a difference of
// velocities below 10 m/s over h = 0.25 s, <= 4 x 2.2e-16 x 10 / 0.25 < 1e-13.
BOOST_AUTO_TEST_CASE(mean_acceleration_of_quadratic_velocity, *utf::label("DD4")) {
    const auto v = [](double t) {
        return vec_from_values<Velocity>(0.2 + 1.0 * t + 0.25 * t * t, 1.0 - 2.0 * t + 1.5 * t * t);
    };
    const Vec2<Acceleration> a = dd04::mean_acceleration(v(2.25) - v(2.0), 0.25 * second);
    BOOST_TEST(std::abs(a.x.value() - 2.0625) <= 1e-13);
    BOOST_TEST(std::abs(a.y.value() - 4.375) <= 1e-13);
}

// Oracle: textbook identity (a dt) / dt = a: velocity_change_over and mean_acceleration are
// inverse for any dt, to 1e-15 relative. Consistency, not evidence (no SRS label): a bug shared
// by both forms would not break it; the hand values and the calculus case above are the oracles.
BOOST_AUTO_TEST_CASE(inverse_forms) {
    const Vec2<Acceleration> a = vec_from_values<Acceleration>(0.11, -9.81);
    for (double dt : {1.0 / 60.0, 0.001, 2.0}) {
        const Vec2<Acceleration> back =
            dd04::mean_acceleration(dd04::velocity_change_over(a, dt * second), dt * second);
        BOOST_TEST(back.x.value() == 0.11, tt::tolerance(1e-15));
        BOOST_TEST(back.y.value() == -9.81, tt::tolerance(1e-15));
    }
}

BOOST_AUTO_TEST_SUITE_END()
