// GD2 (force due to gravity F_g = m g with g = [-g_x, -g_y]), checked by hand and against T1.
#include <boost/test/unit_test.hpp>

#include "tamias2d/model/gd2_gravity.hpp"
#include "tamias2d/model/t1_newtons_second_law.hpp"

namespace utf = boost::unit_test;
namespace tt = boost::test_tools;
using namespace tamias2d::units;
namespace gd2 = tamias2d::model::gd2;
namespace t1 = tamias2d::model::t1;

namespace {
const auto m_s2 = metre / (second * second);
}

BOOST_AUTO_TEST_SUITE(gd2_gravity)

// Oracle: the SRS text (section 2.2: g = 9.81 m s^-2), transcribed: a transcription check, no
// evidence of GD2 (a constant compared with its own literal cannot fail independently); GD2's
// value is verified against T3 (test_t3_universal_gravitation.cpp, surface gravity of Earth).
BOOST_AUTO_TEST_CASE(standard_gravity_value) {
    BOOST_TEST(gd2::g_srs.value() == 9.81);
}

// Oracle: the SRS's own definition g = [-g_x, -g_y]: magnitudes (0, 9.81) pull along -y, and
// (2, 0) along -x (negation is exact).
BOOST_AUTO_TEST_CASE(gravity_vector_signs, *utf::label("GD2")) {
    const Vec2<Acceleration> down = gd2::gravity_vector(0.0 * m_s2, gd2::g_srs);
    BOOST_TEST(down.x.value() == 0.0);
    BOOST_TEST(down.y.value() == -9.81);
    const Vec2<Acceleration> left = gd2::gravity_vector(2.0 * m_s2, 0.0 * m_s2);
    BOOST_TEST(left.x.value() == -2.0);
    BOOST_TEST(left.y.value() == 0.0);
}

// Oracle: hand derivation. F_g = m g = 2 kg (0, -9.81) m s^-2 = (0, -19.62) N, and for the SRS
// typical mass 56.2 kg, F_g,y = -551.322 N.
BOOST_AUTO_TEST_CASE(gravitational_force_hand_value, *utf::label("GD2")) {
    const Vec2<Acceleration> g = gd2::gravity_vector(0.0 * m_s2, gd2::g_srs);
    const Vec2<Force> F = gd2::gravitational_force(2.0 * kilogram, g);
    BOOST_TEST(F.x.value() == 0.0);
    BOOST_TEST(F.y.value() == -19.62, tt::tolerance(1e-15));
    BOOST_TEST(gd2::gravitational_force(56.2 * kilogram, g).y.value() == -551.322,
               tt::tolerance(1e-15));
}

// Oracle: T1 / equivalence principle. Under gravity alone every body accelerates at g whatever
// its mass: T1's a = F_g / m returns g (two roundings: m g / m, within 1e-15 relative).
BOOST_AUTO_TEST_CASE(free_fall_acceleration_is_g_for_any_mass,
                     *utf::label("GD2") * utf::label("T1")) {
    const Vec2<Acceleration> g = gd2::gravity_vector(1.25 * m_s2, gd2::g_srs);
    for (double m : {0.001, 0.3, 1.0, 56.2, 7.0e4}) {
        const Vec2<Acceleration> a =
            t1::acceleration(gd2::gravitational_force(m * kilogram, g), m * kilogram);
        BOOST_TEST(a.x.value() == -1.25, tt::tolerance(1e-15));
        BOOST_TEST(a.y.value() == -9.81, tt::tolerance(1e-15));
    }
}

BOOST_AUTO_TEST_SUITE_END()
