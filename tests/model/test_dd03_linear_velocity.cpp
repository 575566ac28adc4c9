// DD3 (linear velocity v = dr/dt), checked by hand and against the midpoint property of
// quadratic trajectories.
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "tamias2d/model/dd02_linear_displacement.hpp"
#include "tamias2d/model/dd03_linear_velocity.hpp"

namespace utf = boost::unit_test;
namespace tt = boost::test_tools;
using namespace tamias2d::units;
namespace dd02 = tamias2d::model::dd02;
namespace dd03 = tamias2d::model::dd03;

BOOST_AUTO_TEST_SUITE(dd03_linear_velocity)

// Oracle: hand derivation. v = (2, -1) m/s held for dt = 0.5 s moves the body (1, -0.5) m;
// conversely (1, -0.5) m in 0.5 s is a mean velocity of (2, -1) m/s (exact in binary).
BOOST_AUTO_TEST_CASE(hand_values, *utf::label("DD3")) {
    const Vec2<Velocity> v = vec_from_values<Velocity>(2.0, -1.0);
    const Vec2<Length> r = dd03::displacement_over(v, 0.5 * second);
    BOOST_TEST(r.x.value() == 1.0);
    BOOST_TEST(r.y.value() == -0.5);
    const Vec2<Velocity> vm = dd03::mean_velocity(r, 0.5 * second);
    BOOST_TEST(vm.x.value() == 2.0);
    BOOST_TEST(vm.y.value() == -1.0);
}

// Oracle: textbook calculus. For a quadratic trajectory p(t) = p0 + v0 t + a t^2 / 2 the
// secant slope over [t, t + h] equals the derivative at the midpoint, v(t + h / 2), exactly.
// v0 = (1, 3), a = (2, -4) over [1, 1.5] s: v(1.25) = (3.5, -2) m/s. Round-off: the difference
// of two positions below 5 m divided by h = 0.5 s, so |error| <= 4 x 2.2e-16 x 5 / 0.5 < 1e-14.
BOOST_AUTO_TEST_CASE(secant_of_quadratic_is_midpoint_velocity,
                     *utf::label("DD3") * utf::label("DD2")) {
    const auto p = [](double t) {
        return vec_from_values<Length>(0.5 + 1.0 * t + 0.5 * 2.0 * t * t,
                                       -1.0 + 3.0 * t + 0.5 * -4.0 * t * t);
    };
    const Vec2<Velocity> v =
        dd03::mean_velocity(dd02::linear_displacement(p(1.5), p(1.0)), 0.5 * second);
    BOOST_TEST(std::abs(v.x.value() - 3.5) <= 1e-14);
    BOOST_TEST(std::abs(v.y.value() - -2.0) <= 1e-14);
}

// Oracle: the textbook identity (v dt) / dt = v: mean_velocity of displacement_over's result is
// the velocity put in, for any dt (two roundings: 1e-15 relative). Consistency, not evidence
// (no SRS label): a bug shared by both forms would not break it; the hand values and the
// calculus case above are DD3's oracles.
BOOST_AUTO_TEST_CASE(inverse_forms) {
    const Vec2<Velocity> v = vec_from_values<Velocity>(-0.37, 12.9);
    for (double dt : {1.0 / 60.0, 0.01, 0.3, 7.0}) {
        const Vec2<Velocity> back =
            dd03::mean_velocity(dd03::displacement_over(v, dt * second), dt * second);
        BOOST_TEST(back.x.value() == -0.37, tt::tolerance(1e-15));
        BOOST_TEST(back.y.value() == 12.9, tt::tolerance(1e-15));
    }
}

BOOST_AUTO_TEST_SUITE_END()
