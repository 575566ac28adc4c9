// T3 (Newton's law of universal gravitation), checked against hand values, its inverse-square
// scaling and direction, Newton's third law (T2), and the GD2 derivation (g at Earth's surface).
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "tamias2d/model/t3_universal_gravitation.hpp"

namespace utf = boost::unit_test;
namespace tt = boost::test_tools;
using namespace tamias2d::units;
namespace t3 = tamias2d::model::t3;

namespace {
Vec2<Length> L2(double x, double y) {
    return vec_from_values<Length>(x, y);
}
// A handful of roundings (products, a square root, a division): 1e-14 relative is ~45 ulp.
constexpr double rel = 1e-14;
} // namespace

BOOST_AUTO_TEST_SUITE(t3_universal_gravitation)

// Oracle: hand derivation. m1 = 1000 kg, m2 = 2000 kg, r = (3, 4) m so |r| = 5 m:
// |F| = G m1 m2 / 25 = 8e4 G newton, along r_hat = (0.6, 0.8): F = (4.8e4 G, 6.4e4 G) N.
BOOST_AUTO_TEST_CASE(hand_value_3_4_5, *utf::label("T3")) {
    const double G = 6.673e-11; // SRS section 2.2
    const Vec2<Force> F =
        t3::gravitational_force(t3::G_srs, 1000.0 * kilogram, 2000.0 * kilogram, L2(3.0, 4.0));
    BOOST_TEST(F.x.value() == 4.8e4 * G, tt::tolerance(rel));
    BOOST_TEST(F.y.value() == 6.4e4 * G, tt::tolerance(rel));
    BOOST_TEST(norm(F).value() == 8.0e4 * G, tt::tolerance(rel));
}

// Oracle: textbook property (inverse square law): doubling and tripling the separation along
// the same direction divides the force by 4 and by 9; the direction is unchanged.
BOOST_AUTO_TEST_CASE(inverse_square_scaling, *utf::label("T3")) {
    const Mass m1 = 3.0 * kilogram;
    const Mass m2 = 7.0 * kilogram;
    const Vec2<Length> r{-1.2 * metre, 0.5 * metre};
    const Vec2<Force> F1 = t3::gravitational_force(t3::G_srs, m1, m2, r);
    const Vec2<Force> F2 = t3::gravitational_force(t3::G_srs, m1, m2, 2.0 * r);
    const Vec2<Force> F3 = t3::gravitational_force(t3::G_srs, m1, m2, 3.0 * r);
    BOOST_TEST(F2.x.value() * 4.0 == F1.x.value(), tt::tolerance(rel));
    BOOST_TEST(F2.y.value() * 4.0 == F1.y.value(), tt::tolerance(rel));
    BOOST_TEST(F3.x.value() * 9.0 == F1.x.value(), tt::tolerance(rel));
    BOOST_TEST(F3.y.value() * 9.0 == F1.y.value(), tt::tolerance(rel));
}

// Oracle: textbook property. The force on body 1 points toward body 2 (attraction): F is
// parallel to r (F x r = 0 up to round-off, bounded by a few ulp of |F||r|) and F . r > 0.
// It is also linear in each mass (proportional to m1 m2).
BOOST_AUTO_TEST_CASE(direction_is_attractive_and_mass_proportional, *utf::label("T3")) {
    const Vec2<Length> rs[] = {L2(1.0, 0.0), L2(0.0, -2.0), L2(-3.0, 0.25), L2(0.7, 0.7)};
    for (const Vec2<Length>& r : rs) {
        const Vec2<Force> F = t3::gravitational_force(t3::G_srs, 5.0 * kilogram, 2.0 * kilogram, r);
        const double scale = norm(F).value() * norm(r).value();
        BOOST_TEST(std::abs(cross(F, r).value()) <= 4e-16 * scale);
        BOOST_TEST(dot(F, r).value() > 0.0);
        const Vec2<Force> F3m =
            t3::gravitational_force(t3::G_srs, 15.0 * kilogram, 2.0 * kilogram, r);
        BOOST_TEST(F3m.x.value() == 3.0 * F.x.value(), tt::tolerance(rel));
        BOOST_TEST(F3m.y.value() == 3.0 * F.y.value(), tt::tolerance(rel));
    }
}

// Oracle: Newton's third law (T2). The force on body 2 from body 1 uses r_2_to_1 = -r and the
// masses swapped; it must be exactly the opposite of the force on body 1 (every operation is
// symmetric under r -> -r and m1 <-> m2 up to the order of two products: a few ulp).
BOOST_AUTO_TEST_CASE(pair_forces_are_equal_and_opposite, *utf::label("T3") * utf::label("T2")) {
    const Mass m1 = 4.0 * kilogram;
    const Mass m2 = 9.5 * kilogram;
    const Vec2<Length> r = L2(0.3, -2.2);
    const Vec2<Force> F12 = t3::gravitational_force(t3::G_srs, m1, m2, r);
    const Vec2<Force> F21 = t3::gravitational_force(t3::G_srs, m2, m1, -r);
    BOOST_TEST(F21.x.value() == -F12.x.value(), tt::tolerance(rel));
    BOOST_TEST(F21.y.value() == -F12.y.value(), tt::tolerance(rel));
}

// Oracle: the SRS's GD2 derivation and physical data. A 1 kg body on Earth's surface with the
// Earth below (r = -R j_hat, R = 6.371e6 m mean radius, M = 5.9722e24 kg) feels a force along
// -j only (r_hat = -j_hat, so g = [-g_x, -g_y] with g_x = 0), of magnitude close to the
// standard g = 9.81 m s^-2 (SRS 2.2). Tolerance 0.5%: physical, not round-off: measured g
// ranges from 9.780 (equator) to 9.832 m s^-2 (poles), +-0.27% about 9.81; G M / R^2 at the
// mean radius is 9.818 m s^-2, 0.09% from 9.81.
BOOST_AUTO_TEST_CASE(surface_gravity_of_earth, *utf::label("T3") * utf::label("GD2")) {
    const Vec2<Force> F =
        t3::gravitational_force(t3::G_srs, 1.0 * kilogram, 5.9722e24 * kilogram, L2(0.0, -6.371e6));
    BOOST_TEST(F.x.value() == 0.0);
    BOOST_TEST(F.y.value() < 0.0);
    BOOST_TEST(-F.y.value() == 9.81, tt::tolerance(5e-3));
}

BOOST_AUTO_TEST_SUITE_END()
