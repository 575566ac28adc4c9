// DD15 (kinetic energy m v^2 / 2, plus the rotational I w^2 / 2 the seed omits), checked by
// hand, against the rolling-disc textbook value and against direct particle sums (Koenig).
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <vector>

#include "tamias2d/model/dd14_moment_of_inertia.hpp"
#include "tamias2d/model/dd15_kinetic_energy.hpp"

namespace utf = boost::unit_test;
namespace tt = boost::test_tools;
using namespace tamias2d::units;
namespace dd14 = tamias2d::model::dd14;
namespace dd15 = tamias2d::model::dd15;

namespace {
const auto kg_m2 = kilogram * metre * metre / (radian * radian);
const auto rad_s = radian / second;
} // namespace

BOOST_AUTO_TEST_SUITE(dd15_kinetic_energy)

// Oracle: hand derivation. 2 kg at (3, 4) m/s: KE = 2 x 25 / 2 = 25 J; I = 2 kg m^2 at 3 rad/s:
// 9 J; both: 34 J. The SRS typical body (56.2 kg at 2.51 m/s) has 177.03281 J.
BOOST_AUTO_TEST_CASE(hand_values, *utf::label("DD15")) {
    const Vec2<Velocity> v = vec_from_values<Velocity>(3.0, 4.0);
    BOOST_TEST(dd15::translational(2.0 * kilogram, v).value() == 25.0);
    BOOST_TEST(dd15::rotational(2.0 * kg_m2, 3.0 * rad_s).value() == 9.0);
    BOOST_TEST(dd15::kinetic_energy(2.0 * kilogram, v, 2.0 * kg_m2, 3.0 * rad_s).value() == 34.0);
    BOOST_TEST(dd15::translational(56.2 * kilogram, vec_from_values<Velocity>(2.51, 0.0)).value() ==
                   177.03281,
               tt::tolerance(1e-14));
}

// Oracle: textbook. KE is even in v and w (reversing the motion keeps the energy) and a rolling
// disc (w = -v / R) has KE = 3/4 m v^2: m = 2 kg, R = 0.5 m, v = 3 m/s -> 13.5 J.
BOOST_AUTO_TEST_CASE(rolling_disc_and_reversal, *utf::label("DD15") * utf::label("DD14")) {
    const MomentOfInertia I = dd14::disc(2.0 * kilogram, 0.5 * metre);
    const Vec2<Velocity> v = vec_from_values<Velocity>(3.0, 0.0);
    const Energy KE = dd15::kinetic_energy(2.0 * kilogram, v, I, -6.0 * rad_s);
    BOOST_TEST(KE.value() == 13.5, tt::tolerance(1e-15));
    BOOST_TEST(dd15::kinetic_energy(2.0 * kilogram, -v, I, 6.0 * rad_s).value() == KE.value());
}

// Oracle: direct particle sum (Koenig's theorem). Four particles rigidly attached around their
// centre of mass at the origin, the body moving at v_cm and turning at w: each particle has
// velocity v_cm + w (-y, x) (hand-written), and sum m_i |v_i|^2 / 2 must equal
// M |v_cm|^2 / 2 + I w^2 / 2 with I = sum m_i r_i^2 (DD14). Sums of ~10 terms: 1e-14.
BOOST_AUTO_TEST_CASE(koenig_theorem_vs_particle_sum, *utf::label("DD15") * utf::label("DD14")) {
    const double ms[4] = {1.0, 1.0, 2.0, 2.0};
    const double xs[4] = {1.0, -1.0, 0.0, 0.0}, ys[4] = {0.0, 0.0, 0.5, -0.5};
    const double vx = 0.7, vy = -1.9, w = 2.3;
    double direct = 0.0, M = 0.0;
    std::vector<dd14::Particle> ps;
    for (int i = 0; i < 4; ++i) {
        const double ux = vx - w * ys[i], uy = vy + w * xs[i];
        direct += 0.5 * ms[i] * (ux * ux + uy * uy);
        M += ms[i];
        ps.push_back({ms[i] * kilogram, std::hypot(xs[i], ys[i]) * metre});
    }
    const Energy KE = dd15::kinetic_energy(M * kilogram, vec_from_values<Velocity>(vx, vy),
                                           dd14::moment_of_inertia(ps), w * rad_s);
    BOOST_TEST(KE.value() == direct, tt::tolerance(1e-14));
}

BOOST_AUTO_TEST_SUITE_END()
