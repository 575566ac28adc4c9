// T2 (Newton's third law, F1 = -F2), and its consequence GD1 for two bodies.
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "tamias2d/model/dd10_impulse.hpp"
#include "tamias2d/model/gd1_conservation_of_momentum.hpp"
#include "tamias2d/model/t2_newtons_third_law.hpp"

namespace utf = boost::unit_test;
namespace tt = boost::test_tools;
using namespace tamias2d::units;
namespace t2 = tamias2d::model::t2;
namespace dd10 = tamias2d::model::dd10;
namespace gd1 = tamias2d::model::gd1;

BOOST_AUTO_TEST_SUITE(t2_newtons_third_law)

// Oracle: hand derivation. The reaction to (3, -4) N is (-3, 4) N; negation is exact in
// IEEE arithmetic, and the reaction of the reaction is the action again.
BOOST_AUTO_TEST_CASE(reaction_is_opposite_force, *utf::label("T2")) {
    const Vec2<Force> F{3.0 * newton, -4.0 * newton};
    const Vec2<Force> R = t2::reaction(F);
    BOOST_TEST(R.x.value() == -3.0);
    BOOST_TEST(R.y.value() == 4.0);
    BOOST_TEST((t2::reaction(R) == F));
    BOOST_TEST((F + R == Vec2<Force>{})); // the pair sums to zero exactly
}

// Oracle: textbook identity (T2 integrated over the same interval): impulses obey it too,
// J2 = -J1, and equal magnitudes hold for any direction (|J1| = |J2|, exact).
BOOST_AUTO_TEST_CASE(reaction_of_impulse, *utf::label("T2")) {
    const Vec2<Impulse> J{0.25 * newton * second, 1.5 * newton * second};
    const Vec2<Impulse> K = t2::reaction(J);
    BOOST_TEST(K.x.value() == -0.25);
    BOOST_TEST(K.y.value() == -1.5);
    BOOST_TEST(norm(K).value() == norm(J).value());
}

// Oracle: textbook identity, the seed's own derivation of GD1 from T2: equal and opposite
// impulses J and -J on bodies of mass 2 kg and 5 kg change the velocities by J/2 and -J/5, so
// m1 dv1 + m2 dv2 = J - J = 0 and the total momentum is unchanged. Hand values: before,
// 2 (1, -2) + 5 (-0.4, 0.6) = (0, -1) N s. After J = (3, 7) N s: v1' = (2.5, 1.5),
// v2' = (-1, -0.8), and 2 (2.5, 1.5) + 5 (-1, -0.8) = (0, -1) N s again. Round-off: a few
// ulp of the largest term (|m v| <= 5), so 5e-15 absolute.
BOOST_AUTO_TEST_CASE(equal_and_opposite_impulses_conserve_momentum,
                     *utf::label("T2") * utf::label("GD1")) {
    const Mass m1 = 2.0 * kilogram;
    const Mass m2 = 5.0 * kilogram;
    const Vec2<Velocity> v1{1.0 * metre / second, -2.0 * metre / second};
    const Vec2<Velocity> v2{-0.4 * metre / second, 0.6 * metre / second};
    const Vec2<Impulse> J{3.0 * newton * second, 7.0 * newton * second};
    const Vec2<Velocity> v1f = v1 + dd10::velocity_change(J, 1.0 / m1);
    const Vec2<Velocity> v2f = v2 + dd10::velocity_change(t2::reaction(J), 1.0 / m2);
    BOOST_TEST(v1f.x.value() == 2.5, tt::tolerance(1e-15));
    BOOST_TEST(v1f.y.value() == 1.5, tt::tolerance(1e-15));
    BOOST_TEST(v2f.x.value() == -1.0, tt::tolerance(1e-15));
    BOOST_TEST(v2f.y.value() == -0.8, tt::tolerance(1e-15));
    const gd1::MassVelocity before[] = {{m1, v1}, {m2, v2}};
    const gd1::MassVelocity after[] = {{m1, v1f}, {m2, v2f}};
    const Vec2<Momentum> P0 = gd1::total_momentum(before);
    const Vec2<Momentum> P1 = gd1::total_momentum(after);
    BOOST_TEST(std::abs(P0.x.value() - 0.0) <= 5e-15);
    BOOST_TEST(P0.y.value() == -1.0, tt::tolerance(5e-15));
    BOOST_TEST(std::abs(P1.x.value() - P0.x.value()) <= 5e-15);
    BOOST_TEST(std::abs(P1.y.value() - P0.y.value()) <= 5e-15);
}

BOOST_AUTO_TEST_SUITE_END()
