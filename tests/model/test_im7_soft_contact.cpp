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

// Oracle: IM7's cases by hand, 240 substeps per second (1/h = 240 s^-1), bias rate 10 s^-1,
// slop 0.005 m, v_push 3 m s^-1: a gap of 0.02 m closes at 0.02 x 240 = 4.8 m s^-1 (rigid
// scales, soft or not); an overlap of 0.03 m is pushed out at 10 x (0.03 - 0.005) = 0.25 m s^-1
// with the softness' scales, one of 1 m at the cap 3 m s^-1; the relax stops any overlap
// (v* = 0, rigid). The joints' form from h itself: a gap of 0.5 rad over h = 0.25 s closes
// at 2 rad s^-1.
BOOST_AUTO_TEST_CASE(target_velocity_cases_by_hand, *utf::label("IM7")) {
    const Rate inv_h = 240.0 / second, beta = 10.0 / second;
    const Length slop = 0.005 * metre;
    const Velocity push = 3.0 * metre / second;
    const auto soft = [&](double s) {
        return im7::target_velocity<true>(s * metre, inv_h, beta, 0.4, 0.3, slop, push);
    };
    const auto rigid = [&](double s) {
        return im7::target_velocity<false>(s * metre, inv_h, beta, 0.4, 0.3, slop, push);
    };
    for (const auto& t : {soft(0.02), rigid(0.02)}) {
        BOOST_TEST(t.velocity.value() == -4.8, boost::test_tools::tolerance(1e-15));
        BOOST_TEST(t.mass_scale == 1.0);
        BOOST_TEST(t.impulse_scale == 0.0);
    }
    const auto pushed = soft(-0.03);
    BOOST_TEST(pushed.velocity.value() == 0.25, boost::test_tools::tolerance(1e-14));
    BOOST_TEST(pushed.mass_scale == 0.4);
    BOOST_TEST(pushed.impulse_scale == 0.3);
    BOOST_TEST(soft(-1.0).velocity.value() == 3.0);
    BOOST_TEST(soft(-0.004).velocity.value() == 0.0); // within the slop: no push
    const auto held = rigid(-0.03);
    BOOST_TEST(held.velocity.value() == 0.0);
    BOOST_TEST(held.mass_scale == 1.0);
    BOOST_TEST(held.impulse_scale == 0.0);
    BOOST_TEST(im7::closing_velocity(0.5 * radian, 0.25 * second).value() == -2.0);
}

namespace {
/// K = [k11 k12; k12 k22] (kg^-1) as IM7's pair takes it, with its inverse.
im7::PairMass<double> pair_mass(double k11, double k12, double k22) {
    const double det = k11 * k22 - k12 * k12;
    return {k11 / kilogram,         k12 / kilogram,          k22 / kilogram,
            (k22 / det) * kilogram, (-k12 / det) * kilogram, (k11 / det) * kilogram};
}
} // namespace

// Oracle: the definition of the problem's solution, the linear complementarity conditions, checked
// on the result: x >= 0, w = K x + b >= 0 and x_i w_i = 0 (to round-off), where b = v - t - K
// x_acc, for 2000 random positive definite K, velocities, targets and accumulated impulses, among
// which each of the four cases (both points pushed, only the first, only the second, neither) comes
// up.
BOOST_AUTO_TEST_CASE(two_point_impulses_solve_the_complementarity_problem,
                     *utf::label("IM7") * utf::label("LC1")) {
    std::mt19937_64 g(7);
    auto u = [&](double lo, double hi) { return lo + (hi - lo) * double(g() >> 11) * 0x1.0p-53; };
    int cases[4] = {0, 0, 0, 0};
    for (int i = 0; i < 2000; ++i) {
        const double k11 = u(0.1, 3.0), k22 = u(0.1, 3.0);
        const double k12 = u(-0.9, 0.9) * std::sqrt(k11 * k22);
        const double v1 = u(-3.0, 3.0), v2 = u(-3.0, 3.0), t1 = u(-1.0, 1.0), t2 = u(-1.0, 1.0);
        const double a1 = u(0.0, 2.0), a2 = u(0.0, 2.0);
        const auto K = pair_mass(k11, k12, k22);
        const auto x = im7::two_point_impulses(
            K, (1.0 / k11) * kilogram, (1.0 / k22) * kilogram, v1 * metre / second,
            v2 * metre / second, t1 * metre / second, t2 * metre / second,
            a1 * kilogram * metre / second, a2 * kilogram * metre / second);
        const double x1 = x.x1.value(), x2 = x.x2.value();
        const double b1 = v1 - t1 - (k11 * a1 + k12 * a2), b2 = v2 - t2 - (k12 * a1 + k22 * a2);
        const double w1 = k11 * x1 + k12 * x2 + b1, w2 = k12 * x1 + k22 * x2 + b2;
        const double tol = 1e-12 * (1.0 + std::abs(b1) + std::abs(b2)) * (1.0 + x1 + x2);
        BOOST_TEST(x1 >= 0.0);
        BOOST_TEST(x2 >= 0.0);
        BOOST_TEST(w1 >= -tol);
        BOOST_TEST(w2 >= -tol);
        BOOST_TEST(std::abs(x1 * w1) <= tol);
        BOOST_TEST(std::abs(x2 * w2) <= tol);
        ++cases[(x1 > 0.0 ? 1 : 0) + (x2 > 0.0 ? 2 : 0)];
    }
    for (int c = 0; c < 4; ++c)
        BOOST_TEST(cases[c] > 50, "case " << c << " drawn " << cases[c] << " times");
}

// Oracle: the linear complementarity conditions and the uniqueness of their solution for a
// positive definite K (LC1): with K = [[2, 0.3], [0.3, 0.5]] kg^-1, b = (-0.81, -1.35) m s^-1
// and no accumulated impulse, x = (0, 2.7) N s (only the second point pushes) gives
// w = (0.3 * 2.7 - 0.81, 0) = (0, 0): the first point lies exactly on the boundary between
// "only the second" and "both". There the formula of "both" rounds x1 to -6e-17, so only the
// boundary's own case (w1 >= 0, not > 0) keeps the solution. The same with the points swapped.
BOOST_AUTO_TEST_CASE(a_point_exactly_on_the_boundary_between_cases_keeps_the_solution,
                     *utf::label("IM7") * utf::label("LC1")) {
    for (const bool swapped : {false, true}) {
        const double k11 = swapped ? 0.5 : 2.0, k22 = swapped ? 2.0 : 0.5, k12 = 0.3;
        const double v_free = -1.35, v_edge = -(k12 * 2.7); // exactly -0.81 in binary
        const double v1 = swapped ? v_free : v_edge, v2 = swapped ? v_edge : v_free;
        const auto x = im7::two_point_impulses(
            pair_mass(k11, k12, k22), (1.0 / k11) * kilogram, (1.0 / k22) * kilogram,
            v1 * metre / second, v2 * metre / second, 0.0 * metre / second, 0.0 * metre / second,
            0.0 * kilogram * metre / second, 0.0 * kilogram * metre / second);
        const double pushed = swapped ? x.x1.value() : x.x2.value();
        const double idle = swapped ? x.x2.value() : x.x1.value();
        BOOST_TEST(idle == 0.0, "swapped " << swapped);
        BOOST_TEST(pushed == 2.7, boost::test_tools::tolerance(1e-15));
        const double w1 = k11 * x.x1.value() + k12 * x.x2.value() + v1;
        const double w2 = k12 * x.x1.value() + k22 * x.x2.value() + v2;
        BOOST_TEST(w1 >= -1e-15, "swapped " << swapped);
        BOOST_TEST(w2 >= -1e-15, "swapped " << swapped);
    }
}

BOOST_AUTO_TEST_SUITE_END()
