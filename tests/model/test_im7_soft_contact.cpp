#include <boost/test/unit_test.hpp>

#include <cmath>
#include <numbers>
#include <random>

#include "tamias2d/model/dd08_collision_impulse.hpp"
#include "tamias2d/model/im7_soft_contact.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d::units;
namespace im7 = tamias2d::model::im7;
namespace dd08 = tamias2d::model::dd08;

BOOST_AUTO_TEST_SUITE(im7_soft_contact)

// Oracle: backward Euler of the damped spring x'' = -w^2 x - 2 z w x' (w = 2 pi f) over one
// substep h, derived by hand: with x2 = x1 + h v2, v2 = v0 + h (-w^2 x2 - 2 z w v2) gives
// v2 = (v0 - h w^2 x1) / (1 + 2 z h w + h^2 w^2). The soft iteration starts from the velocity v
// after the warm start has applied the accumulated impulse P (v0 = v - P / m), so the impulse
// it must add is m (v2 - v0) - P. Here x1 = s + slop (negative: overlap beyond the slop), which
// the engine's target turns into -beta x1. Drawn over 2000 random f, z, h, m, x1, v, P.
BOOST_AUTO_TEST_CASE(soft_impulse_is_backward_euler_of_the_damped_spring, *utf::label("IM7")) {
    std::mt19937_64 g(12);
    auto u = [&](double lo, double hi) { return lo + (hi - lo) * double(g() >> 11) * 0x1.0p-53; };
    double worst = 0.0;
    for (int i = 0; i < 2000; ++i) {
        const double f = u(1.0, 240.0), z = u(0.05, 20.0), h = u(1e-4, 0.05);
        const double m = u(0.01, 100.0), x1 = u(-0.1, 0.0), v = u(-5.0, 5.0), P = u(0.0, 3.0);
        const double w = 2.0 * std::numbers::pi * f;
        const double v0 = v - P / m;
        const double v2 = (v0 - h * w * w * x1) / (1.0 + 2.0 * z * h * w + h * h * w * w);
        const double want = m * (v2 - v0) - P;

        const im7::Softness s = im7::softness(f / second, z, h * second);
        const Velocity target = -(s.bias_rate * (x1 * metre));
        const Impulse rigid = dd08::impulse_to_reach(v * metre / second, target, m * kilogram);
        const Impulse got = im7::soft_impulse(s.mass_scale.value(), rigid, s.impulse_scale.value(),
                                              P * kilogram * metre / second);
        const double err = std::abs(got.value() - want) / (std::abs(want) + m * std::abs(v) + P);
        worst = std::max(worst, err);
    }
    BOOST_TEST_MESSAGE("IM7 soft impulse vs backward Euler: worst relative error " << worst);
    BOOST_TEST(worst < 1e-12);
}

// Oracle: the rigid limit stated by IM7: f = 0 gives mass scale 1, impulse scale 0, no bias,
// so the soft impulse is DD8's rigid one; and the cap min(f, n / (4 dt)) by hand.
BOOST_AUTO_TEST_CASE(zero_frequency_is_rigid_and_the_cap_is_a_quarter_of_the_substep_rate,
                     *utf::label("IM7")) {
    const im7::Softness s = im7::softness(0.0 / second, 10.0, 0.004 * second);
    BOOST_TEST(s.mass_scale.value() == 1.0);
    BOOST_TEST(s.impulse_scale.value() == 0.0);
    BOOST_TEST(s.bias_rate.value() == 0.0);
    const Impulse rigid = 2.5 * kilogram * metre / second;
    BOOST_TEST(im7::soft_impulse(1.0, rigid, 0.0, 7.0 * kilogram * metre / second).value() == 2.5);
    // 4 substeps of 1/60 s: the cap is 60 Hz; 45 Hz passes, 100 Hz is capped.
    BOOST_TEST(im7::frequency(45.0 / second, 4, (1.0 / 60.0) * second).value() == 45.0);
    BOOST_TEST(std::abs(im7::frequency(100.0 / second, 4, (1.0 / 60.0) * second).value() - 60.0) <
               1e-12);
}

BOOST_AUTO_TEST_SUITE_END()
