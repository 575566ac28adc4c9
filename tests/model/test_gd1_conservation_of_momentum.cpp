// GD1 (conservation of momentum): the total momentum by hand, and its conservation under
// internal pair interactions that obey T2 (DD10's dv = J / m on each body).
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "tamias2d/model/dd10_impulse.hpp"
#include "tamias2d/model/gd1_conservation_of_momentum.hpp"
#include "tamias2d/model/t2_newtons_third_law.hpp"

namespace utf = boost::unit_test;
namespace tt = boost::test_tools;
using namespace tamias2d::units;
namespace gd1 = tamias2d::model::gd1;
namespace dd10 = tamias2d::model::dd10;
namespace t2 = tamias2d::model::t2;

namespace {
Vec2<Velocity> V2(double x, double y) {
    return vec_from_values<Velocity>(x, y);
}
// Deterministic pseudo-random numbers in [-1, 1) (64-bit LCG, Knuth's MMIX constants).
struct Lcg {
    std::uint64_t s;
    double next() {
        s = s * 6364136223846793005ULL + 1442695040888963407ULL;
        return static_cast<double>(s >> 11) * 0x1.0p-52 - 1.0;
    }
};
} // namespace

BOOST_AUTO_TEST_SUITE(gd1_conservation_of_momentum)

// Oracle: hand derivation. 2 kg at (1, 2) m/s and 3 kg at (-1, 0.5) m/s:
// P = (2 - 3, 4 + 1.5) = (-1, 5.5) N s (exact in binary).
BOOST_AUTO_TEST_CASE(total_momentum_hand_value, *utf::label("GD1")) {
    const gd1::MassVelocity bodies[] = {{2.0 * kilogram, V2(1.0, 2.0)},
                                        {3.0 * kilogram, V2(-1.0, 0.5)}};
    const Vec2<Momentum> P = gd1::total_momentum(bodies);
    BOOST_TEST(P.x.value() == -1.0, tt::tolerance(1e-15));
    BOOST_TEST(P.y.value() == 5.5, tt::tolerance(1e-15));
}

// Oracle: definition (empty sum). No bodies carry no momentum.
BOOST_AUTO_TEST_CASE(empty_system_has_zero_momentum, *utf::label("GD1")) {
    const Vec2<Momentum> P = gd1::total_momentum({});
    BOOST_TEST(P.x.value() == 0.0);
    BOOST_TEST(P.y.value() == 0.0);
}

// Oracle: the seed's derivation of GD1 (T2 + DD10): in an isolated system every interaction
// is a pair of equal and opposite impulses, so 1000 pseudo-random pair impulses among 8 bodies
// leave sum m v unchanged. The bound is round-off: each interaction adds two roundings of
// size <= eps |m v| to the sum, so |dP| <= 2000 x 2.2e-16 x max|m v| (max|m v| < 200 here).
BOOST_AUTO_TEST_CASE(pairwise_impulses_conserve_total_momentum,
                     *utf::label("GD1") * utf::label("T2")) {
    Lcg rng{12345};
    std::vector<gd1::MassVelocity> bodies;
    for (int k = 0; k < 8; ++k)
        bodies.push_back({(1.5 + rng.next()) * kilogram, V2(rng.next(), rng.next())});
    const Vec2<Momentum> P0 = gd1::total_momentum(bodies);
    double max_mv = 0.0;
    for (int n = 0; n < 1000; ++n) {
        const auto a = static_cast<std::size_t>(n % 8);
        const auto b = static_cast<std::size_t>((n * 5 + 3) % 8);
        if (a == b)
            continue;
        const Vec2<Impulse> J = vec_from_values<Impulse>(rng.next(), rng.next());
        bodies[a].v += dd10::velocity_change(J, 1.0 / bodies[a].m);
        bodies[b].v += dd10::velocity_change(t2::reaction(J), 1.0 / bodies[b].m);
        for (const gd1::MassVelocity& body : bodies)
            max_mv = std::max(max_mv, norm(body.m * body.v).value());
    }
    BOOST_TEST_REQUIRE(max_mv < 200.0);
    const Vec2<Momentum> P1 = gd1::total_momentum(bodies);
    const double bound = 2000.0 * 2.3e-16 * 200.0;
    BOOST_TEST(std::abs(P1.x.value() - P0.x.value()) <= bound);
    BOOST_TEST(std::abs(P1.y.value() - P0.y.value()) <= bound);
}

// Oracle: textbook counter-example (GD1 needs an isolated system): an external impulse J on one
// body changes the total momentum by exactly J (here J = (0, -2) N s on a 4 kg body at rest).
BOOST_AUTO_TEST_CASE(external_impulse_changes_momentum_by_itself, *utf::label("GD1")) {
    gd1::MassVelocity bodies[] = {{4.0 * kilogram, V2(0.0, 0.0)}, {1.0 * kilogram, V2(3.0, 0.0)}};
    const Vec2<Impulse> J = vec_from_values<Impulse>(0.0, -2.0);
    bodies[0].v += dd10::velocity_change(J, 1.0 / bodies[0].m);
    const Vec2<Momentum> P = gd1::total_momentum(bodies);
    BOOST_TEST(P.x.value() == 3.0, tt::tolerance(1e-15));
    BOOST_TEST(P.y.value() == -2.0, tt::tolerance(1e-15));
}

BOOST_AUTO_TEST_SUITE_END()
