// DD16 (potential energy m g h), checked by hand, in its vector form, and with energy
// conservation (DD15 + DD16) along an exact free-fall trajectory.
#include <boost/test/unit_test.hpp>

#include "tamias2d/model/dd15_kinetic_energy.hpp"
#include "tamias2d/model/dd16_potential_energy.hpp"

namespace utf = boost::unit_test;
namespace tt = boost::test_tools;
using namespace tamias2d::units;
namespace dd15 = tamias2d::model::dd15;
namespace dd16 = tamias2d::model::dd16;

namespace {
const auto m_s2 = metre / (second * second);
}

BOOST_AUTO_TEST_SUITE(dd16_potential_energy)

// Oracle: hand derivation. 2 kg, g = 9.81 m s^-2, h = 10 m: PE = 196.2 J; h = 0: 0; below the
// reference (h = -1 m): -19.62 J.
BOOST_AUTO_TEST_CASE(hand_values, *utf::label("DD16")) {
    BOOST_TEST(dd16::potential_energy(2.0 * kilogram, 9.81 * m_s2, 10.0 * metre).value() == 196.2,
               tt::tolerance(1e-15));
    BOOST_TEST(dd16::potential_energy(2.0 * kilogram, 9.81 * m_s2, 0.0 * metre).value() == 0.0);
    BOOST_TEST(dd16::potential_energy(2.0 * kilogram, 9.81 * m_s2, -1.0 * metre).value() == -19.62,
               tt::tolerance(1e-15));
}

// Oracle: hand derivation of the vector form PE = -m g . p: g = (0, -9.81), p = (5, 10) gives
// -2 (0 x 5 - 9.81 x 10) = 196.2 J, equal to the scalar m g h with h = p_y and independent of
// the horizontal position; sideways gravity g = (-3, 0) at p = (-2, 7): g . p = 6, PE = -12 J.
BOOST_AUTO_TEST_CASE(vector_form, *utf::label("DD16")) {
    const Vec2<Acceleration> g = vec_from_values<Acceleration>(0.0, -9.81);
    const Mass m = 2.0 * kilogram;
    BOOST_TEST(dd16::potential_energy(m, g, vec_from_values<Length>(5.0, 10.0)).value() == 196.2,
               tt::tolerance(1e-15));
    BOOST_TEST(dd16::potential_energy(m, g, vec_from_values<Length>(-40.0, 10.0)).value() ==
                   dd16::potential_energy(m, 9.81 * m_s2, 10.0 * metre).value(),
               tt::tolerance(1e-15));
    const Vec2<Acceleration> side = vec_from_values<Acceleration>(-3.0, 0.0);
    BOOST_TEST(dd16::potential_energy(m, side, vec_from_values<Length>(-2.0, 7.0)).value() ==
               -12.0);
}

// Oracle: textbook conservation of mechanical energy (SRS 5.2.7) along the exact projectile
// trajectory p(t) = p0 + v0 t + g t^2 / 2, v(t) = v0 + g t: KE (DD15) + PE (DD16) is the same at
// every t. Values up to ~1e3 J with cancellation between the two terms: 1e-13 relative.
BOOST_AUTO_TEST_CASE(energy_conserved_in_free_fall, *utf::label("DD16") * utf::label("DD15")) {
    const Mass m = 1.5 * kilogram;
    const double g[2] = {0.0, -9.81}, p0[2] = {0.5, 20.0}, v0[2] = {4.0, 6.0};
    const Vec2<Acceleration> gv = vec_from_values<Acceleration>(g[0], g[1]);
    const auto E = [&](double t) {
        const Vec2<Length> p = vec_from_values<Length>(p0[0] + v0[0] * t + 0.5 * g[0] * t * t,
                                                       p0[1] + v0[1] * t + 0.5 * g[1] * t * t);
        const Vec2<Velocity> v = vec_from_values<Velocity>(v0[0] + g[0] * t, v0[1] + g[1] * t);
        return (dd15::translational(m, v) + dd16::potential_energy(m, gv, p)).value();
    };
    const double E0 = E(0.0);
    BOOST_TEST(E0 == 0.5 * 1.5 * 52.0 + 1.5 * 9.81 * 20.0, tt::tolerance(1e-15));
    for (double t : {0.1, 0.61, 1.0, 2.5, 3.7})
        BOOST_TEST(E(t) == E0, tt::tolerance(1e-13));
}

BOOST_AUTO_TEST_SUITE_END()
