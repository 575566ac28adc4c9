// DD8 (impulse for collision response), checked against hand-derived values.
#include <boost/test/unit_test.hpp>

#include "tamias2d/model/dd08_collision_impulse.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d::units;
namespace dd08 = tamias2d::model::dd08;

BOOST_AUTO_TEST_SUITE(dd08_collision_impulse)

// Oracle: hand derivation. Head-on, centres on the normal (r x n = 0), m_A = 1, m_B = 3,
// v^AB . n = -4, C_R = 0.5: K = 1 + 1/3 = 4/3, j = -(1.5)(-4)/(4/3) = 4.5 N s.
BOOST_AUTO_TEST_CASE(head_on_unequal_masses, *utf::label("DD8")) {
    const dd08::InverseInertia A{1.0 / (1.0 * kilogram),
                                 0.0 / (1.0 * kilogram * metre * metre / (radian * radian))};
    const dd08::InverseInertia B{1.0 / (3.0 * kilogram),
                                 0.0 / (1.0 * kilogram * metre * metre / (radian * radian))};
    const Vec2<Length> r{0.0 * metre, 0.0 * metre};
    const auto K = dd08::effective_mass_inverse(A, B, r, r, dd08::Normal{1.0, 0.0});
    BOOST_TEST(K.value() == 4.0 / 3.0, boost::test_tools::tolerance(1e-15));
    const Impulse j = dd08::collision_impulse(0.5, -4.0 * metre / second, K);
    BOOST_TEST(j.value() == 4.5, boost::test_tools::tolerance(1e-15));
}

// Oracle: hand derivation. Lever arm r_AP = (0, 2) m with n = (1, 0): r x n = -2 m, so the
// rotational term is 4 / I_A = 4 / 8 = 0.5 kg^-1; K = 1/2 + 0 + 0.5 = 1.
BOOST_AUTO_TEST_CASE(off_centre_lever_arm, *utf::label("DD8")) {
    const auto per_I = 1.0 / (1.0 * kilogram * metre * metre / (radian * radian));
    const dd08::InverseInertia A{1.0 / (2.0 * kilogram), (1.0 / 8.0) * per_I};
    const dd08::InverseInertia B{0.0 / (1.0 * kilogram), 0.0 * per_I}; // static
    const Vec2<Length> rA{0.0 * metre, 2.0 * metre};
    const Vec2<Length> rB{5.0 * metre, 0.0 * metre}; // irrelevant: B is static
    const auto K = dd08::effective_mass_inverse(A, B, rA, rB, dd08::Normal{1.0, 0.0});
    BOOST_TEST(K.value() == 1.0, boost::test_tools::tolerance(1e-15));
}

BOOST_AUTO_TEST_SUITE_END()
