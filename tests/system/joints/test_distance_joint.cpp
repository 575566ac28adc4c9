// Distance joints (DD20: rigid rods, springs and length limits; IM6, LC3) in the engine, against
// independent oracles: the exact period of the simple pendulum (complete elliptic integral,
// GSL), the damped harmonic oscillator, and IM6's rigid relax, which leaves no speed along a rod.
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <gsl/gsl_sf_ellint.h>

#include "support/damped_oscillator.hpp"
#include "system/joints/pendulum.hpp"
#include "system/system_support.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;
using namespace tamias2d::system_test;
using namespace tamias2d::system_test::pendulum;
using tamias2d::test::DampedOscillator;

namespace {

/// A disc on a rigid distance joint (a massless rod of length l) from a static pivot at the
/// origin, held out horizontally at rest: its bob.
BodyId add_rod_pendulum(World& world) {
    BodyDef pivot_def;
    pivot_def.type = BodyType::static_body;
    const BodyId pivot = world.create_body(pivot_def);
    BodyDef bob_def;
    bob_def.position = {l, 0.0};
    const BodyId bob = world.create_body(bob_def);
    world.create_shape(bob, circle_shape(bob_radius));
    world.create_joint(DistanceJointDef{
        .body_a = pivot, .body_b = bob, .anchor_a = {0.0, 0.0}, .anchor_b = {l, 0.0}});
    return bob;
}

} // namespace

BOOST_AUTO_TEST_SUITE(joints)

/// A disc on a distance joint to a static anchor at the origin, no gravity, released at rest
/// `stretch` beyond the rest length L = 1 m; its largest deviation, over 2 s, from `expected`.
template <class F>
double spring_error(int steps_per_second, double hertz, double zeta, double stretch, F expected) {
    World world(WorldDef{.gravity = {0.0, 0.0}});
    BodyDef anchor_def;
    anchor_def.type = BodyType::static_body;
    const BodyId anchor = world.create_body(anchor_def);
    BodyDef bob_def;
    bob_def.position = {1.0 + stretch, 0.0};
    const BodyId bob = world.create_body(bob_def);
    world.create_shape(bob, circle_shape(0.1));
    world.create_joint(DistanceJointDef{.body_a = anchor,
                                        .body_b = bob,
                                        .anchor_a = {0.0, 0.0},
                                        .anchor_b = bob_def.position,
                                        .length = 1.0,
                                        .hertz = hertz,
                                        .damping_ratio = zeta});
    double worst = 0.0;
    for (int k = 1; k <= 2 * steps_per_second; ++k) {
        world.step(1.0 / steps_per_second);
        worst = std::max(
            worst, std::abs(world.position(bob).x - 1.0 - expected(k * 1.0 / steps_per_second)));
    }
    return worst;
}

// Oracle: the damped harmonic oscillator. A distance joint with a spring of frequency f and
// damping ratio zeta holds its body as x'' = -omega^2 x - 2 zeta omega x' (omega = 2 pi f, x
// the stretch; the joint's effective mass is the body's, the anchor being its centre), whose
// solution from rest at x0 is x0 e^(-zeta omega t) (cos omega_d t + zeta omega / omega_d
// sin omega_d t), omega_d = omega sqrt(1 - zeta^2). The soft step integrates the spring
// implicitly, first order: the error over 2 s halves with the step (ratio >= 1.8) and is below
// 2 % of x0 at 1/480 s.
BOOST_AUTO_TEST_CASE(distance_spring_is_a_damped_oscillator,
                     *utf::label("DD20") * utf::label("IM6") * utf::label("LC3")) {
    const double f = 2.0, zeta = 0.1, x0 = 0.2;
    const DampedOscillator osc{f, zeta};
    const auto exact = [&](double t) { return osc.from_rest(x0, t); };
    const double e240 = spring_error(240, f, zeta, x0, exact);
    const double e480 = spring_error(480, f, zeta, x0, exact);
    BOOST_TEST_MESSAGE("spring: max deviation " << e240 << " m at 1/240 s, " << e480
                                                << " m at 1/480 s");
    BOOST_TEST(e480 <= 0.02 * x0);
    BOOST_TEST(e240 / e480 >= 1.8);
}

// Oracle: IM6's rigid relax ends each substep with no velocity along a rigid rod (mu = 1,
// gamma = 0: the row's impulse exactly cancels the anchors' relative speed along the axis, and
// the positions do not move after it). A disc swings on a rigid distance joint from a static
// pivot: after every step the disc's velocity along the rod is 0 to round-off, while its speed
// across the rod reaches metres per second.
BOOST_AUTO_TEST_CASE(a_rigid_rod_ends_each_step_with_no_speed_along_it,
                     *utf::label("DD20") * utf::label("IM6") * utf::label("LC3")) {
    World world(WorldDef{.gravity = {0.0, -g}});
    const BodyId bob = add_rod_pendulum(world);
    double fastest = 0.0;
    for (int k = 0; k < 120; ++k) {
        world.step(1.0 / 60.0);
        const Vec2d p = world.position(bob), v = world.velocity(bob);
        const double r = std::hypot(p.x, p.y);
        BOOST_TEST(std::abs((p.x * v.x + p.y * v.y) / r) < 1e-12, "step " << k);
        fastest = std::max(fastest, std::hypot(v.x, v.y));
    }
    BOOST_TEST(fastest > 1.0);
}

// Oracle: the exact period of the simple pendulum, 4 sqrt(l / g) K(sin(theta0 / 2)) (GSL). A
// rigid distance joint from the pivot to a disc's centre is a massless rod: the disc's own
// turning is free, so the pendulum is a point mass. At 1/960 s the period is within 1e-4 of
// the exact one from 90 degrees, and the error shrinks at least as first order does.
BOOST_AUTO_TEST_CASE(distance_rod_pendulum_period,
                     *utf::label("DD20") * utf::label("IM6") * utf::label("LC3")) {
    const double theta0 = std::numbers::pi / 2.0;
    const double T =
        4.0 * std::sqrt(l / g) * gsl_sf_ellint_Kcomp(std::sin(theta0 / 2.0), GSL_PREC_DOUBLE);
    std::vector<double> errors;
    for (const int steps_per_second : {480, 960}) {
        World world(WorldDef{.gravity = {0.0, -g}, .joint_hertz = 1e9});
        const BodyId bob = add_rod_pendulum(world);
        const double dt = 1.0 / steps_per_second;
        double previous = theta0, first = 0.0, last = 0.0;
        int crossings = 0;
        for (int k = 1; k <= int(5.0 * T * steps_per_second); ++k) {
            world.step(dt);
            const Vec2d p = world.position(bob);
            const double theta = std::atan2(p.x, -p.y);
            if (previous < 0.0 && theta >= 0.0) {
                const double t = (k - 1) * dt + dt * (-previous) / (theta - previous);
                (crossings == 0 ? first : last) = t;
                ++crossings;
            }
            previous = theta;
        }
        BOOST_TEST_REQUIRE(crossings == 5);
        errors.push_back(std::abs((last - first) / 4.0 - T) / T);
    }
    BOOST_TEST_MESSAGE("rod pendulum: relative period error " << errors[0] << " at 1/480 s, "
                                                              << errors[1] << " at 1/960 s");
    BOOST_TEST(errors[1] <= 1e-4);
    BOOST_TEST(errors[0] / errors[1] >= 1.8);
}

// Oracle: the length limits themselves (DD20). A disc hangs from a static point on a very
// soft distance spring (0.05 Hz: it barely holds the disc) whose travel is limited to
// [0.5, 1.2] m: the disc falls until the maximum length stops it, never beyond it by more than
// 1 cm, and rests on it within 2 mm (the soft bias's sag under its weight); flung upwards, the
// minimum length stops it.
BOOST_AUTO_TEST_CASE(distance_limits_bound_a_soft_spring,
                     *utf::label("DD20") * utf::label("IM6") * utf::label("LC3")) {
    for (const double v0 : {0.0, 12.0}) {
        World world(WorldDef{.gravity = {0.0, -g}, .enable_sleep = false});
        BodyDef anchor_def;
        anchor_def.type = BodyType::static_body;
        const BodyId anchor = world.create_body(anchor_def);
        BodyDef bob_def;
        bob_def.position = {0.0, -1.0};
        bob_def.linear_velocity = {0.0, v0};
        const BodyId bob = world.create_body(bob_def);
        world.create_shape(bob, circle_shape(0.1));
        world.create_joint(DistanceJointDef{.body_a = anchor,
                                            .body_b = bob,
                                            .anchor_a = {0.0, 0.0},
                                            .anchor_b = {0.0, -1.0},
                                            .hertz = 0.05,
                                            .damping_ratio = 0.0,
                                            .enable_limit = true,
                                            .min_length = 0.5,
                                            .max_length = 1.2});
        double shortest = 1.0, longest = 1.0;
        for (int k = 0; k < 180; ++k) {
            world.step(1.0 / 60.0);
            const double d = norm(world.position(bob));
            shortest = std::min(shortest, d);
            longest = std::max(longest, d);
        }
        BOOST_TEST_MESSAGE("v0 " << v0 << ": shortest " << shortest << " m, longest " << longest
                                 << " m");
        BOOST_TEST(longest <= 1.2 + 0.01);
        BOOST_TEST(shortest >= 0.5 - 0.01);
        BOOST_TEST(std::abs(norm(world.position(bob)) - 1.2) <= 2e-3);
        if (v0 > 0.0)
            BOOST_TEST(shortest <= 0.5 + 0.01); // it did reach the minimum length
    }
}

// Oracle: Newton's first law at rest. Without gravity a persistent force F = 10 N pushes a
// disc towards a static point, to which a soft distance spring (1 Hz, rest length 1 m) holds it
// with its travel limited to [0.9, 2] m: the spring alone would yield to 0.75 m, so the disc
// comes to rest on the minimum length, where the spring and the limit together push it back
// with F. The joint's reaction force on the disc is then -F, and the disc rests at 0.9 m
// within 5 mm (the soft bias's give under the load).
BOOST_AUTO_TEST_CASE(a_spring_resting_on_its_minimum_length_holds_the_load,
                     *utf::label("DD20") * utf::label("LC3")) {
    constexpr double F = 10.0;
    World world(WorldDef{.gravity = {0.0, 0.0}, .enable_sleep = false});
    const BodyId anchor = world.create_body(BodyDef{.type = BodyType::static_body});
    const BodyId disc = world.create_body(BodyDef{.position = {1.0, 0.0}, .force = {-F, 0.0}});
    world.create_shape(disc, circle_shape(0.1));
    const JointId j = world.create_joint(DistanceJointDef{.body_a = anchor,
                                                          .body_b = disc,
                                                          .anchor_a = {0.0, 0.0},
                                                          .anchor_b = {1.0, 0.0},
                                                          .hertz = 1.0,
                                                          .damping_ratio = 1.0,
                                                          .enable_limit = true,
                                                          .min_length = 0.9,
                                                          .max_length = 2.0});
    for (int k = 0; k < 300; ++k)
        world.step(1.0 / 60.0);
    BOOST_TEST(std::abs(world.velocity(disc).x) < 1e-9);
    BOOST_TEST(std::abs(world.position(disc).x - 0.9) <= 5e-3);
    BOOST_TEST(world.joint_reaction_force(j).x == F, boost::test_tools::tolerance(1e-9));
    BOOST_TEST(world.joint_reaction_force(j).y == 0.0);
}

BOOST_AUTO_TEST_SUITE_END()
