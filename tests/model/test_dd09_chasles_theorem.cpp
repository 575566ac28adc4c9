// DD9 (Chasles' theorem, v_B = v_O + omega x r_OB), checked by hand, against a finite
// difference of rotating point positions, and against rolling without slipping.
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "tamias2d/model/dd09_chasles_theorem.hpp"

namespace utf = boost::unit_test;
namespace tt = boost::test_tools;
using namespace tamias2d::units;
namespace dd09 = tamias2d::model::dd09;

namespace {
Vec2<Length> L2(double x, double y) {
    return vec_from_values<Length>(x, y);
}
Vec2<Velocity> V2(double x, double y) {
    return vec_from_values<Velocity>(x, y);
}
const auto rad_s = radian / second;
} // namespace

BOOST_AUTO_TEST_SUITE(dd09_chasles_theorem)

// Oracle: hand derivation. omega x r = (0, 0, w) x (x, y, 0) = (-w y, w x): v_O = (1, 0) m/s,
// w = 2 rad/s, r = (0, 3) m gives (-6, 0), so v_B = (-5, 0) m/s; r = (3, 0) gives v_B = (1, 6).
// Counter-clockwise rotation (w > 0, A4) moves a point on +x toward +y.
BOOST_AUTO_TEST_CASE(hand_values, *utf::label("DD9")) {
    const Vec2<Velocity> a = dd09::point_velocity(V2(1, 0), 2.0 * rad_s, L2(0, 3));
    BOOST_TEST(a.x.value() == -5.0);
    BOOST_TEST(a.y.value() == 0.0);
    const Vec2<Velocity> b = dd09::point_velocity(V2(1, 0), 2.0 * rad_s, L2(3, 0));
    BOOST_TEST(b.x.value() == 1.0);
    BOOST_TEST(b.y.value() == 6.0);
}

// Oracle: finite difference of rotating point positions. A body translating at v_O and turning
// at w carries a point along p(t) = O + v_O t + R(w t) r. The central difference
// (p(h) - p(-h)) / 2h approximates p'(0) with truncation error <= h^2 / 6 max|p'''| =
// h^2 w^3 |r| / 6 = 1.6e-10 m/s (h = 1e-5 s, w = 1.7 rad/s, |r| = 2 m) plus round-off: each
// coordinate (below 8 m) carries at most ~4 roundings, 4 eps x 8 = 7e-15 m, twice, over 2h:
// 7e-10 m/s. Bound used: 1e-9 m/s.
BOOST_AUTO_TEST_CASE(matches_finite_difference_of_rotating_point, *utf::label("DD9")) {
    const double w = 1.7, h = 1e-5;
    const double vO[2] = {0.3, -1.1};
    for (double ang : {0.0, 0.9, 2.4, 4.0}) {
        const double r[2] = {2.0 * std::cos(ang), 2.0 * std::sin(ang)};
        const auto p = [&](double t, int k) {
            const double c = std::cos(w * t), s = std::sin(w * t);
            const double rot = k == 0 ? c * r[0] - s * r[1] : s * r[0] + c * r[1];
            return 5.0 + vO[k] * t + rot; // O = (5, 5)
        };
        const Vec2<Velocity> v = dd09::point_velocity(V2(vO[0], vO[1]), w * rad_s, L2(r[0], r[1]));
        BOOST_TEST(std::abs(v.x.value() - (p(h, 0) - p(-h, 0)) / (2 * h)) <= 1e-9);
        BOOST_TEST(std::abs(v.y.value() - (p(h, 1) - p(-h, 1)) / (2 * h)) <= 1e-9);
    }
}

// Oracle: textbook rolling without slipping. A wheel of radius R = 0.5 m whose centre moves at
// V = 3 m/s along +x turns clockwise at w = -V / R = -6 rad/s: the contact point (0, -R) is at
// rest, the top point (0, R) moves at 2V = 6 m/s, the front point (R, 0) at (V, -V).
BOOST_AUTO_TEST_CASE(rolling_wheel, *utf::label("DD9")) {
    const Vec2<Velocity> vc = V2(3.0, 0.0);
    const AngularVelocity w = -6.0 * rad_s;
    const Vec2<Velocity> bottom = dd09::point_velocity(vc, w, L2(0.0, -0.5));
    const Vec2<Velocity> top = dd09::point_velocity(vc, w, L2(0.0, 0.5));
    const Vec2<Velocity> front = dd09::point_velocity(vc, w, L2(0.5, 0.0));
    BOOST_TEST(bottom.x.value() == 0.0);
    BOOST_TEST(bottom.y.value() == 0.0);
    BOOST_TEST(top.x.value() == 6.0);
    BOOST_TEST(top.y.value() == 0.0);
    BOOST_TEST(front.x.value() == 3.0);
    BOOST_TEST(front.y.value() == -3.0);
}

// Oracle: textbook rigidity condition. The velocity field of a rigid body preserves distances:
// (v_B - v_A) . (r_B - r_A) = 0 for any two points, and applying DD9 from A instead of O gives
// the same v_B (v_B = v_A + w x r_AB). Terms below 20 m^2/s: round-off bound 1e-13.
BOOST_AUTO_TEST_CASE(rigid_velocity_field, *utf::label("DD9")) {
    const Vec2<Velocity> vO = V2(-0.8, 2.2);
    const AngularVelocity w = 1.3 * rad_s;
    const Vec2<Length> rA = L2(1.5, -0.4), rB = L2(-2.0, 3.1);
    const Vec2<Velocity> vA = dd09::point_velocity(vO, w, rA);
    const Vec2<Velocity> vB = dd09::point_velocity(vO, w, rB);
    BOOST_TEST(std::abs(dot(vB - vA, rB - rA).value()) <= 1e-13);
    const Vec2<Velocity> vB_from_A = dd09::point_velocity(vA, w, rB - rA);
    BOOST_TEST(vB_from_A.x.value() == vB.x.value(), tt::tolerance(1e-14));
    BOOST_TEST(vB_from_A.y.value() == vB.y.value(), tt::tolerance(1e-14));
}

// Oracle: DD9's vector form projected on n. The solver's form v_O . n + omega (r x n) must
// give dot(point_velocity(v_O, omega, r), n): the two differ only by the order of roundings
// (about six products and sums of terms below 10 m/s: bound 1e-13 m/s). Directions in all
// four quadrants, anchors on and off the normal.
BOOST_AUTO_TEST_CASE(along_a_direction_is_the_projected_vector_form, *utf::label("DD9")) {
    for (double ang : {0.0, 0.7, 2.1, 3.5, 5.6}) {
        const Vec2<double> n{std::cos(ang), std::sin(ang)};
        for (double rang : {0.3, 1.9, 4.4}) {
            const Vec2<Length> r = L2(1.3 * std::cos(rang), 0.8 * std::sin(rang));
            const Vec2<Velocity> vO = V2(-0.7, 2.3);
            const auto w = -3.1 * rad_s;
            const double along =
                dd09::point_velocity_along(vO, w, tamias2d::units::cross(r, n), n).value();
            const double projected = dot(dd09::point_velocity(vO, w, r), n).value();
            BOOST_TEST(std::abs(along - projected) <= 1e-13);
        }
    }
}

BOOST_AUTO_TEST_SUITE_END()
