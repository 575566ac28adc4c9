// DD13 (torque tau = r x F, counter-clockwise positive, A4), checked by hand, by the lever-arm
// formula |r| |F| sin(angle), and with couples of equal and opposite forces (T2).
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "tamias2d/model/dd13_torque.hpp"
#include "tamias2d/model/t2_newtons_third_law.hpp"

namespace utf = boost::unit_test;
namespace tt = boost::test_tools;
using namespace tamias2d::units;
namespace dd13 = tamias2d::model::dd13;
namespace t2 = tamias2d::model::t2;

namespace {
Vec2<Length> L2(double x, double y) {
    return vec_from_values<Length>(x, y);
}
Vec2<Force> F2(double x, double y) {
    return vec_from_values<Force>(x, y);
}
} // namespace

BOOST_AUTO_TEST_SUITE(dd13_torque)

// Oracle: hand derivation, z component of the 3D cross product: r = (2, 0) m, F = (0, 3) N is
// +6 N m (counter-clockwise, A4); r = (0, 2), F = (3, 0) is -6 N m (clockwise); a force along
// the arm has no torque.
BOOST_AUTO_TEST_CASE(hand_values_and_sign, *utf::label("DD13")) {
    BOOST_TEST(dd13::torque(L2(2, 0), F2(0, 3)).value() == 6.0);
    BOOST_TEST(dd13::torque(L2(0, 2), F2(3, 0)).value() == -6.0);
    BOOST_TEST(dd13::torque(L2(1, 1), F2(-4, -4)).value() == 0.0);
}

// Oracle: textbook lever-arm formula tau = |r| |F| sin(b - a) for r at angle a and F at angle
// b. |r| = 1.5 m, |F| = 98.1 N (SRS typical), so every term is below 150 N m; about a dozen
// roundings (cos, sin, products, b - a) of at most eps x 150 = 3.3e-14 N m each: bound 1e-12.
BOOST_AUTO_TEST_CASE(lever_arm_formula, *utf::label("DD13")) {
    for (double a : {0.0, 0.7, 2.0, -1.1})
        for (double b : {0.3, 1.5707963267948966, 3.0, -2.4}) {
            const Vec2<Length> r = L2(1.5 * std::cos(a), 1.5 * std::sin(a));
            const Vec2<Force> F = F2(98.1 * std::cos(b), 98.1 * std::sin(b));
            BOOST_TEST(std::abs(dd13::torque(r, F).value() - 1.5 * 98.1 * std::sin(b - a)) <=
                       1e-12);
        }
}

// Oracle: textbook couple. Equal and opposite forces F and -F (T2) at points r1 and r2 have a
// total torque (r1 - r2) x F, the same about every reference point; here F = (0, 2) N at
// (1, 0) and (-1, 0): 4 N m about the origin and about (5, -7) (exact small integers).
BOOST_AUTO_TEST_CASE(couple_is_independent_of_reference_point,
                     *utf::label("DD13") * utf::label("T2")) {
    const Vec2<Force> F = F2(0, 2);
    const Vec2<Length> p1 = L2(1, 0), p2 = L2(-1, 0);
    for (const Vec2<Length>& O : {L2(0, 0), L2(5, -7), L2(-0.5, 3.25)}) {
        const Torque total = dd13::torque(p1 - O, F) + dd13::torque(p2 - O, t2::reaction(F));
        BOOST_TEST(total.value() == 4.0, tt::tolerance(1e-15));
    }
}

// Oracle: textbook identity (only the perpendicular component turns the body): adding to F any
// multiple of r leaves the torque unchanged, and the torque is linear in F.
BOOST_AUTO_TEST_CASE(only_perpendicular_component_matters, *utf::label("DD13")) {
    const Vec2<Length> r = L2(0.6, -0.8);
    const Vec2<Force> F = F2(2.0, 5.0);
    const double tau = dd13::torque(r, F).value();
    const Vec2<Force> along = F2(0.6 * 7.0, -0.8 * 7.0); // 7 N along r_hat
    BOOST_TEST(dd13::torque(r, F + along).value() == tau, tt::tolerance(1e-14));
    BOOST_TEST(dd13::torque(r, 3.0 * F).value() == 3.0 * tau, tt::tolerance(1e-15));
    BOOST_TEST(tau == 0.6 * 5.0 + 0.8 * 2.0, tt::tolerance(1e-15));
}

BOOST_AUTO_TEST_SUITE_END()
