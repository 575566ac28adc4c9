// DD2 (linear displacement r(t) = p(t) - p(t0); the seed's r = dp/dt is an erratum, see
// tests/compile_fail/dd02_displacement_as_derivative.cpp), checked by hand and by kinematics.
#include <boost/test/unit_test.hpp>

#include "tamias2d/model/dd02_linear_displacement.hpp"

namespace utf = boost::unit_test;
namespace tt = boost::test_tools;
using namespace tamias2d::units;
namespace dd02 = tamias2d::model::dd02;

namespace {
Vec2<Length> L2(double x, double y) {
    return vec_from_values<Length>(x, y);
}
} // namespace

BOOST_AUTO_TEST_SUITE(dd02_linear_displacement)

// Oracle: hand derivation. From (1, 2) m to (3, -1) m the displacement is (2, -3) m; staying put
// is a zero displacement (exact subtractions of small integers).
BOOST_AUTO_TEST_CASE(hand_values, *utf::label("DD2")) {
    const Vec2<Length> r = dd02::linear_displacement(L2(3, -1), L2(1, 2));
    BOOST_TEST(r.x.value() == 2.0);
    BOOST_TEST(r.y.value() == -3.0);
    const Vec2<Length> z = dd02::linear_displacement(L2(0.3, 0.7), L2(0.3, 0.7));
    BOOST_TEST(z.x.value() == 0.0);
    BOOST_TEST(z.y.value() == 0.0);
}

// Oracle: textbook kinematics. For uniform motion p(t) = p0 + v t, r(t) = v t: v = (2.51, -1)
// m/s (SRS typical speed) over t = 4 s gives (10.04, -4) m. Displacements add along a path
// (Chasles' relation for vectors): r(t0 -> t2) = r(t0 -> t1) + r(t1 -> t2). A few roundings of
// quantities below 20 m: 1e-14 relative.
BOOST_AUTO_TEST_CASE(uniform_motion_and_additivity, *utf::label("DD2")) {
    const Vec2<Length> p0 = L2(0.412, 0.502); // SRS Table 1 typical position
    const Vec2<Velocity> v = vec_from_values<Velocity>(2.51, -1.0);
    const Vec2<Length> p4 = p0 + v * (4.0 * second);
    const Vec2<Length> r = dd02::linear_displacement(p4, p0);
    BOOST_TEST(r.x.value() == 10.04, tt::tolerance(1e-14));
    BOOST_TEST(r.y.value() == -4.0, tt::tolerance(1e-14));
    const Vec2<Length> p1 = L2(-3.3, 8.1);
    const Vec2<Length> sum = dd02::linear_displacement(p1, p0) + dd02::linear_displacement(p4, p1);
    BOOST_TEST(sum.x.value() == r.x.value(), tt::tolerance(1e-14));
    BOOST_TEST(sum.y.value() == r.y.value(), tt::tolerance(1e-14));
}

BOOST_AUTO_TEST_SUITE_END()
