// DD11 (relative velocity at the contact point, v^AB = v^AP - v^BP), checked by hand and with
// Chasles' theorem (DD9) at a common point.
#include <boost/test/unit_test.hpp>

#include "tamias2d/model/dd09_chasles_theorem.hpp"
#include "tamias2d/model/dd11_relative_velocity.hpp"

namespace utf = boost::unit_test;
namespace tt = boost::test_tools;
using namespace tamias2d::units;
namespace dd09 = tamias2d::model::dd09;
namespace dd11 = tamias2d::model::dd11;

namespace {
Vec2<Velocity> V2(double x, double y) {
    return vec_from_values<Velocity>(x, y);
}
} // namespace

BOOST_AUTO_TEST_SUITE(dd11_relative_velocity)

// Oracle: hand derivation. v^AP = (2, 1), v^BP = (-1, 3) m/s: v^AB = (3, -2) m/s; the relative
// velocity of B with respect to A is the opposite, (-3, 2); equal velocities give zero.
BOOST_AUTO_TEST_CASE(hand_values_and_antisymmetry, *utf::label("DD11")) {
    const Vec2<Velocity> ab = dd11::relative_velocity(V2(2, 1), V2(-1, 3));
    const Vec2<Velocity> ba = dd11::relative_velocity(V2(-1, 3), V2(2, 1));
    BOOST_TEST(ab.x.value() == 3.0);
    BOOST_TEST(ab.y.value() == -2.0);
    BOOST_TEST((ba == -ab));
    BOOST_TEST((dd11::relative_velocity(V2(0.4, 0.4), V2(0.4, 0.4)) == Vec2<Velocity>{}));
}

// Oracle: hand derivation at a common point P through DD9. A: v = (1, 0), w = 2 rad/s,
// r_AP = (0, 1) -> v^AP = (1 - 2, 0) = (-1, 0). B: v = (0, -1), w = -1 rad/s, r_BP = (1, 0)
// -> v^BP = (0, -1 - 1) = (0, -2). v^AB = (-1, 2) m/s.
BOOST_AUTO_TEST_CASE(at_contact_point_with_rotation, *utf::label("DD11") * utf::label("DD9")) {
    const auto rad_s = radian / second;
    const Vec2<Velocity> vAP =
        dd09::point_velocity(V2(1, 0), 2.0 * rad_s, vec_from_values<Length>(0, 1));
    const Vec2<Velocity> vBP =
        dd09::point_velocity(V2(0, -1), -1.0 * rad_s, vec_from_values<Length>(1, 0));
    const Vec2<Velocity> ab = dd11::relative_velocity(vAP, vBP);
    BOOST_TEST(ab.x.value() == -1.0);
    BOOST_TEST(ab.y.value() == 2.0);
}

// Oracle: textbook Galilean invariance: adding the same velocity u to both bodies (changing
// the inertial frame) does not change their relative velocity (1e-15 relative round-off).
BOOST_AUTO_TEST_CASE(galilean_invariance, *utf::label("DD11")) {
    const Vec2<Velocity> a = V2(0.7, -2.3), b = V2(-1.9, 0.1), u = V2(10.5, -3.25);
    const Vec2<Velocity> r0 = dd11::relative_velocity(a, b);
    const Vec2<Velocity> r1 = dd11::relative_velocity(a + u, b + u);
    BOOST_TEST(r1.x.value() == r0.x.value(), tt::tolerance(1e-14));
    BOOST_TEST(r1.y.value() == r0.y.value(), tt::tolerance(1e-14));
}

BOOST_AUTO_TEST_SUITE_END()
