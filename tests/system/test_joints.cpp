// Revolute (with motor and limits), distance and target joints (LC3: DD19-DD22, IM6) in the
// engine, against
// independent oracles: the exact large-amplitude pendulum period (complete elliptic integral, GSL),
// a GSL rk8pd solution of the pendulum ODE, the damped harmonic oscillator, the closed-form tension
// at the bottom of the swing, and the conservation of linear momentum by the joint's equal and
// opposite impulses (T2).
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <gsl/gsl_sf_ellint.h>

#include "support/damped_oscillator.hpp"
#include "system/system_support.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;
using namespace tamias2d::system_test;
using tamias2d::test::DampedOscillator;

namespace {

constexpr double g = 9.81, l = 1.0, bob_radius = 0.05;

/// A physical pendulum: a small disc pinned at the origin to a static body, released from rest
/// at angle theta0 from the downward vertical. joint_hertz 1e9 asks for the stiffest joint the
/// soft step allows, a quarter of the substep rate, so that the joint's compliance shrinks
/// with the step (IM6) and the comparison measures convergence.
struct Pendulum {
    World world;
    BodyId bob;
    JointId joint;
    double m = 0.0, I_pivot = 0.0;
    explicit Pendulum(double theta0, double joint_hertz = 1e9, double break_force = INFINITY)
        : world(WorldDef{.gravity = {0.0, -g}, .joint_hertz = joint_hertz}) {
        BodyDef ground_def;
        ground_def.type = BodyType::static_body;
        const BodyId ground = world.create_body(ground_def);
        BodyDef bob_def;
        bob_def.position = {l * std::sin(theta0), -l * std::cos(theta0)};
        bob = world.create_body(bob_def);
        world.create_shape(bob, circle_shape(bob_radius));
        joint = world.create_joint(RevoluteJointDef{
            .body_a = ground, .body_b = bob, .anchor = {0.0, 0.0}, .break_force = break_force});
        m = world.mass(bob);
        I_pivot = world.inertia(bob) + m * l * l; // parallel axes (DD14)
    }
    double angle() const {
        const Vec2d p = world.position(bob);
        return std::atan2(p.x, -p.y);
    }
};

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

/// T = 4 sqrt(I_pivot / (m g l)) K(sin(theta0 / 2)): the exact period of the physical pendulum
/// (GSL's K takes the modulus k).
double exact_period(const Pendulum& p, double theta0) {
    return 4.0 * std::sqrt(p.I_pivot / (p.m * g * l)) *
           gsl_sf_ellint_Kcomp(std::sin(theta0 / 2.0), GSL_PREC_DOUBLE);
}

/// The engine's period: the mean time between upward zero crossings of the angle (linearly
/// interpolated) over four periods, the first crossing three quarters of a period after release.
double measured_period(double theta0, int steps_per_second) {
    Pendulum p(theta0);
    const double dt = 1.0 / steps_per_second, T = exact_period(p, theta0);
    double previous = p.angle(), first = 0.0, last = 0.0;
    int crossings = 0;
    for (int k = 1; k <= int(5.0 * T * steps_per_second); ++k) {
        p.world.step(dt);
        const double theta = p.angle();
        if (previous < 0.0 && theta >= 0.0) {
            const double t = (k - 1) * dt + dt * (-previous) / (theta - previous);
            (crossings == 0 ? first : last) = t;
            ++crossings;
        }
        previous = theta;
    }
    BOOST_TEST_REQUIRE(crossings == 5);
    return (last - first) / 4.0;
}

int pendulum_ode(double, const double y[], double dydt[], void* params) {
    const double w0_squared = *static_cast<const double*>(params);
    dydt[0] = y[1];
    dydt[1] = -w0_squared * std::sin(y[0]);
    return GSL_SUCCESS;
}

} // namespace

BOOST_AUTO_TEST_SUITE(joints)

// Oracle: the exact period of the large-amplitude pendulum, 4 sqrt(I_p / (m g l)) K(sin(theta0/2))
// with GSL's complete elliptic integral K. IM6 is first order in the step (IM1, IM2) plus the
// joint's compliance, which shrinks with it: halving the step must shrink the error at least
// as first order does (ratio >= 1.8 between 1/480 s and 1/960 s), and at 1/960 s the period is
// within 1e-4 of the exact one at 10, 90 and 170 degrees. (170 degrees is the hard case: there
// the period grows without bound as the amplitude nears 180 degrees, so the soft joint's energy
// loss shows most.) The pin's velocity on each body is Chasles' theorem (DD9) at the pin.
BOOST_AUTO_TEST_CASE(pendulum_period_matches_the_elliptic_integral,
                     *utf::label("DD19") * utf::label("IM6") * utf::label("LC3") *
                         utf::label("DD9")) {
    for (const double degrees : {10.0, 90.0, 170.0}) {
        const double theta0 = degrees * std::numbers::pi / 180.0;
        const double T = exact_period(Pendulum(theta0), theta0);
        BOOST_TEST_CONTEXT(degrees << " degrees, exact period " << T << " s") {
            const double e480 = std::abs(measured_period(theta0, 480) - T) / T;
            const double e960 = std::abs(measured_period(theta0, 960) - T) / T;
            BOOST_TEST_MESSAGE(degrees << " deg: relative period error " << e480 << " at 1/480 s, "
                                       << e960 << " at 1/960 s");
            BOOST_TEST(e960 <= 1e-4);
            BOOST_TEST(e480 / e960 >= 1.8);
        }
    }
}

// Oracle: GSL rk8pd (tolerance 1e-12) on theta'' = -(m g l / I_p) sin theta from 90 degrees at
// rest, over two periods. The engine's angle follows it to 2e-3 rad at 1/480 s and the error
// shrinks at least as first order does at 1/960 s.
BOOST_AUTO_TEST_CASE(pendulum_follows_the_gsl_reference_trajectory,
                     *utf::label("DD19") * utf::label("IM6") * utf::label("LC3")) {
    const double theta0 = std::numbers::pi / 2.0;
    std::vector<double> max_error;
    for (const int steps_per_second : {480, 960}) {
        Pendulum p(theta0);
        double w0_squared = p.m * g * l / p.I_pivot;
        gsl_odeiv2_system sys{pendulum_ode, nullptr, 2, &w0_squared};
        gsl_odeiv2_driver* driver =
            gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk8pd, 1e-6, 1e-12, 1e-12);
        double y[2] = {theta0, 0.0}, t = 0.0, worst = 0.0;
        const double dt = 1.0 / steps_per_second;
        const int steps = int(2.0 * exact_period(p, theta0) * steps_per_second);
        for (int k = 1; k <= steps; ++k) {
            p.world.step(dt);
            BOOST_TEST_REQUIRE(gsl_odeiv2_driver_apply(driver, &t, k * dt, y) == GSL_SUCCESS);
            worst = std::max(worst, std::abs(p.angle() - y[0]));
        }
        gsl_odeiv2_driver_free(driver);
        max_error.push_back(worst);
    }
    BOOST_TEST_MESSAGE("max angle error " << max_error[0] << " rad at 1/480 s, " << max_error[1]
                                          << " rad at 1/960 s");
    BOOST_TEST(max_error[0] <= 2e-3);
    BOOST_TEST(max_error[0] / max_error[1] >= 1.8);
}

// Oracle: energy conservation and Newton's second law at the bottom of the swing. Released
// from theta0 at rest, the pendulum passes the bottom with omega^2 = 2 m g l (1 - cos theta0) /
// I_p; the pin then pulls the bob up with m g + m l omega^2 (centripetal). The reaction force
// of the step nearest the bottom matches to 1 % (the step's angle is within one step of 0).
BOOST_AUTO_TEST_CASE(reaction_force_is_the_tension_at_the_bottom,
                     *utf::label("IM6") * utf::label("LC3")) {
    const double theta0 = std::numbers::pi / 3.0;
    Pendulum p(theta0);
    const double w2 = 2.0 * p.m * g * l * (1.0 - std::cos(theta0)) / p.I_pivot;
    const double tension = p.m * g + p.m * l * w2;
    double previous = p.angle();
    for (int k = 0; k < 2000; ++k) {
        p.world.step(1.0 / 240.0);
        const double theta = p.angle();
        if (previous > 0.0 && theta <= 0.0) {
            const Vec2d f = p.world.joint_reaction_force(p.joint); // on the bob
            BOOST_TEST(f.y == tension, boost::test_tools::tolerance(0.01));
            BOOST_TEST(std::abs(f.x) <= 0.02 * tension);
            return;
        }
        previous = theta;
    }
    BOOST_ERROR("the pendulum never passed the bottom");
}

// Oracle: closed form: the tension of the previous case, m g (1 + 2 (1 - cos theta0) m l^2 / I_p).
// A joint whose break force is below it breaks on the way down (and is listed, and gone); one above
// it holds for a whole period.
BOOST_AUTO_TEST_CASE(joint_breaks_above_its_break_force, *utf::label("IM6") * utf::label("LC3")) {
    const double theta0 = std::numbers::pi / 3.0;
    const Pendulum probe(theta0);
    const double tension =
        probe.m * g * (1.0 + 2.0 * (1.0 - std::cos(theta0)) * probe.m * l * l / probe.I_pivot);
    Pendulum weak(theta0, 1e9, 0.8 * tension);
    Pendulum strong(theta0, 1e9, 1.2 * tension);
    bool broke = false;
    for (int k = 0; k < 600; ++k) {
        weak.world.step(1.0 / 240.0);
        strong.world.step(1.0 / 240.0);
        if (!weak.world.broken_joints().empty()) {
            BOOST_TEST((weak.world.broken_joints()[0] == weak.joint));
            BOOST_TEST(!weak.world.is_valid(weak.joint));
            BOOST_TEST(std::abs(weak.angle()) > 0.0); // before the bottom
            broke = true;
            break;
        }
    }
    BOOST_TEST(broke);
    for (int k = 0; k < 600; ++k)
        strong.world.step(1.0 / 240.0);
    BOOST_TEST(strong.world.is_valid(strong.joint));
    BOOST_TEST(strong.world.joint_count() == 1u);
}

/// Two free bodies pinned together without gravity, pushed and spun, stepped for 2 s at the
/// given rate: the largest pin gap after the first 0.05 s, and the change of linear momentum.
std::pair<double, double> spinning_pair(int steps_per_second) {
    World world(WorldDef{.gravity = {0.0, 0.0}, .joint_hertz = 1e9});
    const BodyId a = add_box(world, {0.0, 0.0}, {1.0, -0.5}, 1.0, 0.4, 2.0);
    const BodyId b = add_circle(world, {1.0, 0.2}, {-0.3, 2.0}, 0.3, 0.7);
    world.set_angular_velocity(a, 3.0);
    const Vec2d pin{0.6, 0.0};
    world.create_joint(RevoluteJointDef{.body_a = a, .body_b = b, .anchor = pin});
    const Vec2d p0 = world.linear_momentum();
    // The pin in each body's frame, followed as the bodies move (origins and angles).
    const Vec2d origin_a = world.origin(a), origin_b = world.origin(b);
    const double angle_a = world.orientation(a), angle_b = world.orientation(b);
    const auto pin_on = [&](BodyId body, Vec2d origin0, double angle0) {
        const double turn = world.orientation(body) - angle0;
        const Vec2d r = pin - origin0;
        return world.origin(body) + Vec2d{std::cos(turn) * r.x - std::sin(turn) * r.y,
                                          std::sin(turn) * r.x + std::cos(turn) * r.y};
    };
    double gap = 0.0;
    for (int k = 1; k <= 2 * steps_per_second; ++k) {
        world.step(1.0 / steps_per_second);
        if (k * 20 >= steps_per_second)
            gap = std::max(gap, norm(pin_on(b, origin_b, angle_b) - pin_on(a, origin_a, angle_a)));
    }
    return {gap, norm(world.linear_momentum() - p0) / norm(p0)};
}

// Oracle: T2 and GD1. The joint's impulses are equal and opposite, so two free bodies pinned
// together keep their total linear momentum (to round-off). And IM6's compliance: the pins'
// gap is the stretch of a spring of frequency f_J, a quarter of the substep rate here, under
// the pin's load, so it scales as 1 / f_J^2: halving the step must divide it by about 4
// (at least 3), once the first 0.05 s have absorbed the bodies' mismatched velocities.
BOOST_AUTO_TEST_CASE(joint_impulses_conserve_linear_momentum,
                     *utf::label("DD19") * utf::label("IM6") * utf::label("LC3")) {
    const auto [gap240, drift240] = spinning_pair(240);
    const auto [gap480, drift480] = spinning_pair(480);
    BOOST_TEST_MESSAGE("pin gap " << gap240 << " m at 1/240 s, " << gap480 << " m at 1/480 s");
    BOOST_TEST(drift240 <= 1e-12);
    BOOST_TEST(drift480 <= 1e-12);
    BOOST_TEST(gap240 <= 1e-4);
    BOOST_TEST(gap240 / gap480 >= 3.0);
}

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

/// A free disc (no gravity) held by a target joint grabbed at its centre, the target moved to
/// (x_target, 0) at t = 0: the disc's x after each step.
std::vector<double> dragged(int steps_per_second, double seconds, double x_target, double hertz,
                            double zeta, double max_force, double* mass = nullptr,
                            Vec2d* reaction = nullptr) {
    World world(WorldDef{.gravity = {0.0, 0.0}});
    BodyDef def;
    const BodyId disc = world.create_body(def);
    world.create_shape(disc, circle_shape(0.25));
    const JointId j = world.create_joint(TargetJointDef{.body = disc,
                                                        .target = {0.0, 0.0},
                                                        .hertz = hertz,
                                                        .damping_ratio = zeta,
                                                        .max_force = max_force});
    world.set_joint_target(j, {x_target, 0.0});
    std::vector<double> x;
    for (int k = 1; k <= int(seconds * steps_per_second); ++k) {
        world.step(1.0 / steps_per_second);
        x.push_back(world.position(disc).x);
    }
    if (mass)
        *mass = world.mass(disc);
    if (reaction)
        *reaction = world.joint_reaction_force(j);
    return x;
}

// Oracle: the critically damped oscillator. A target joint of frequency f and damping ratio 1
// grabbed at the disc's centre pulls it as x'' = -omega^2 (x - 1) - 2 omega x' towards a
// target 1 m away, whose solution from rest at 0 is x = 1 - (1 + omega t) e^(-omega t). The
// soft step is first order: the largest error over 2 s halves with the step (ratio >= 1.8)
// and is below 1 cm at 1/480 s.
BOOST_AUTO_TEST_CASE(target_joint_is_a_critically_damped_spring,
                     *utf::label("DD21") * utf::label("IM6") * utf::label("LC3")) {
    const double f = 3.0, w = 2.0 * std::numbers::pi * f;
    std::vector<double> errors;
    for (const int steps_per_second : {240, 480}) {
        const std::vector<double> x = dragged(steps_per_second, 2.0, 1.0, f, 1.0, INFINITY);
        double worst = 0.0;
        for (std::size_t k = 0; k < x.size(); ++k) {
            const double t = double(k + 1) / steps_per_second;
            worst = std::max(worst, std::abs(x[k] - (1.0 - (1.0 + w * t) * std::exp(-w * t))));
        }
        errors.push_back(worst);
    }
    BOOST_TEST_MESSAGE("target joint: max error " << errors[0] << " m at 1/240 s, " << errors[1]
                                                  << " m at 1/480 s");
    BOOST_TEST(errors[1] <= 0.01);
    BOOST_TEST(errors[0] / errors[1] >= 1.8);
}

// Oracle: Newton's second law (T1) with the force limit. Dragged towards a target 100 m away
// by a stiff spring, the joint pulls with exactly its max force F from the first substep on,
// so the disc's velocity is F t / m and its position the semi-implicit Euler sum of it, to
// round-off, and the reaction force reads F.
BOOST_AUTO_TEST_CASE(target_joint_pulls_with_at_most_its_max_force,
                     *utf::label("DD21") * utf::label("IM6") * utf::label("LC3")) {
    const double F = 2.0;
    const int steps_per_second = 60, substeps = 4;
    double m = 0.0;
    Vec2d reaction{};
    const std::vector<double> x =
        dragged(steps_per_second, 1.0, 100.0, 30.0, 1.0, F, &m, &reaction);
    const double h = 1.0 / (steps_per_second * substeps);
    for (std::size_t k = 0; k < x.size(); ++k) {
        const double n = double((k + 1) * substeps); // substeps so far
        // v_i = i F h / m after substep i; x = h sum_{i=1..n} v_i = F h^2 n (n + 1) / (2 m).
        const double expected = F * h * h * n * (n + 1.0) / (2.0 * m);
        BOOST_TEST_REQUIRE(x[k] == expected, boost::test_tools::tolerance(1e-12));
    }
    BOOST_TEST(reaction.x == F, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(std::abs(reaction.y) <= 1e-15);
}

// Oracle: T4 with the motor's torque limit. A disc pinned at its centre to the ground (no
// gravity), its motor asked for 10 rad/s with at most tau: the motor applies tau until the
// speed is reached, so omega = tau t / I exactly per substep (the clamp), then omega = 10 rad/s
// exactly; the reaction torque reads tau while accelerating.
BOOST_AUTO_TEST_CASE(revolute_motor_spins_up_under_its_torque_limit,
                     *utf::label("DD22") * utf::label("IM6") * utf::label("LC3")) {
    World world(WorldDef{.gravity = {0.0, 0.0}});
    BodyDef ground_def;
    ground_def.type = BodyType::static_body;
    const BodyId ground = world.create_body(ground_def);
    const BodyId wheel = world.create_body(BodyDef{});
    world.create_shape(wheel, circle_shape(0.5));
    const double tau = 0.2, target = 10.0;
    const JointId j = world.create_joint(RevoluteJointDef{.body_a = ground,
                                                          .body_b = wheel,
                                                          .anchor = {0.0, 0.0},
                                                          .enable_motor = true,
                                                          .motor_speed = target,
                                                          .max_motor_torque = tau});
    const double I = world.inertia(wheel), dt = 1.0 / 60.0;
    for (int k = 1; k <= 600; ++k) {
        world.step(dt);
        const double expected = std::min(tau * k * dt / I, target);
        BOOST_TEST_REQUIRE(world.angular_velocity(wheel) == expected,
                           boost::test_tools::tolerance(1e-9));
        if (tau * k * dt / I < target)
            BOOST_TEST_REQUIRE(world.joint_reaction_torque(j) == tau,
                               boost::test_tools::tolerance(1e-9));
    }
    BOOST_TEST(world.angular_velocity(wheel) == target, boost::test_tools::tolerance(1e-12));
}

// Oracle: the limits themselves (DD22). A bar pinned at one end, released horizontal under
// gravity with limits [-30, +10] degrees, swings down onto the lower limit: the joint angle
// never passes it by more than 0.01 rad, and the bar comes to rest on it (within 2e-3 rad,
// the soft bias's sag under the bar's weight). The upper limit stops a bar thrown upwards.
BOOST_AUTO_TEST_CASE(revolute_limits_hold_the_angle,
                     *utf::label("DD22") * utf::label("IM6") * utf::label("LC3")) {
    const double lower = -std::numbers::pi / 6.0, upper = std::numbers::pi / 18.0;
    for (const double spin : {0.0, 20.0}) {
        World world(WorldDef{.gravity = {0.0, -g}});
        BodyDef ground_def;
        ground_def.type = BodyType::static_body;
        const BodyId ground = world.create_body(ground_def);
        BodyDef bar_def;
        bar_def.position = {0.5, 0.0};
        bar_def.angular_velocity = spin;
        bar_def.linear_velocity = {0.0, 0.5 * spin};
        const BodyId bar = world.create_body(bar_def);
        world.create_shape(bar, box_shape(1.0, 0.1));
        const JointId j = world.create_joint(RevoluteJointDef{.body_a = ground,
                                                              .body_b = bar,
                                                              .anchor = {0.0, 0.0},
                                                              .enable_limit = true,
                                                              .lower_angle = lower,
                                                              .upper_angle = upper});
        double lowest = 0.0, highest = 0.0;
        for (int k = 0; k < 600; ++k) {
            world.step(1.0 / 60.0);
            lowest = std::min(lowest, world.joint_angle(j));
            highest = std::max(highest, world.joint_angle(j));
        }
        BOOST_TEST_CONTEXT("initial spin " << spin << " rad/s") {
            BOOST_TEST(lowest >= lower - 0.01);
            BOOST_TEST(highest <= upper + 0.01);
            BOOST_TEST(std::abs(world.joint_angle(j) - lower) <= 2e-3);
            if (spin > 0.0)
                BOOST_TEST(highest >= upper - 0.01); // it reached the upper limit
        }
    }
}

// Oracle: DD27's rule, "bodies a joint keeps apart never collide": two overlapping boxes touch
// until a joint without collide_connected joins them, then never; with collide_connected they
// still do. A second overlapping pair, joined by nothing, keeps its contact throughout (the
// joint removes its own pair's contacts only, wherever they sit in the contact list).
BOOST_AUTO_TEST_CASE(connected_bodies_collide_only_when_asked, *utf::label("DD27")) {
    for (const bool collide : {false, true}) {
        for (const bool pair_first : {false, true}) {
            // Falling (no ground), the boxes leave their fat boxes, so the broad phase looks
            // for their pairs anew and the rule is asked again, not only when the joint is made.
            World world(WorldDef{.gravity = {0.0, -9.81}, .enable_sleep = false});
            BodyId a{}, b{}, c{}, d{};
            const auto add_pair = [&] {
                a = add_box(world, {0.0, 0.0}, {}, 1.0, 1.0, 1.0);
                b = add_box(world, {0.5, 0.0}, {}, 1.0, 1.0, 1.0); // overlapping a
            };
            if (pair_first)
                add_pair();
            c = add_box(world, {10.0, 0.0}, {}, 1.0, 1.0, 1.0);
            d = add_box(world, {10.5, 0.0}, {}, 1.0, 1.0, 1.0); // overlapping c
            if (!pair_first)
                add_pair();
            world.step(1.0 / 60.0);
            BOOST_TEST_REQUIRE(world.contacts().size() == 2u);
            world.create_joint(RevoluteJointDef{
                .body_a = a, .body_b = b, .anchor = {0.25, 0.0}, .collide_connected = collide});
            for (int k = 0; k < 60; ++k) {
                world.step(1.0 / 60.0);
                bool ab = false, cd = false;
                for (const ContactInfo& info : world.contacts()) {
                    const auto joins = [&](BodyId x, BodyId y) {
                        return (info.body_a == x && info.body_b == y) ||
                               (info.body_a == y && info.body_b == x);
                    };
                    ab = ab || joins(a, b);
                    cd = cd || joins(c, d);
                }
                BOOST_TEST(ab == collide);
                BOOST_TEST(cd);
                BOOST_TEST(world.contacts().size() == (collide ? 2u : 1u));
            }
        }
    }
}

// Oracle: DD27's rule read the other way: once no joint keeps two bodies apart, their shapes
// collide. Two overlapping boxes at rest (no gravity), pinned without collide_connected, touch
// again at the first step after the joint is destroyed; a box pinned to an overlapping static
// box by a joint that breaks under its weight touches that box at the first step after.
BOOST_AUTO_TEST_CASE(bodies_collide_again_once_their_joint_is_gone, *utf::label("DD27")) {
    {
        World world(WorldDef{.gravity = {0.0, 0.0}});
        const BodyId a = add_box(world, {0.0, 0.0}, {}, 1.0, 1.0, 1.0);
        const BodyId b = add_box(world, {0.5, 0.0}, {}, 1.0, 1.0, 1.0); // overlapping a
        const JointId j =
            world.create_joint(RevoluteJointDef{.body_a = a, .body_b = b, .anchor = {0.25, 0.0}});
        for (int k = 0; k < 10; ++k)
            world.step(1.0 / 60.0);
        BOOST_TEST(world.contacts().empty());
        world.destroy_joint(j);
        world.step(1.0 / 60.0);
        BOOST_TEST(world.contacts().size() == 1u);
    }
    {
        World world(WorldDef{.gravity = {0.0, -9.81}});
        BodyDef ground_def;
        ground_def.type = BodyType::static_body;
        const BodyId ground = world.create_body(ground_def);
        world.create_shape(ground, box_shape(1.0, 1.0));
        const BodyId b = add_box(world, {0.5, 0.0}, {}, 1.0, 1.0, 1.0); // overlapping it
        world.create_joint(RevoluteJointDef{
            .body_a = ground, .body_b = b, .anchor = {0.25, 0.0}, .break_force = 1.0});
        world.step(1.0 / 60.0); // the pin carries m g = 9.81 N > 1 N: it breaks
        BOOST_TEST_REQUIRE(world.broken_joints().size() == 1u);
        BOOST_TEST(world.contacts().empty());
        world.step(1.0 / 60.0);
        BOOST_TEST(world.contacts().size() == 1u);
    }
}

// Oracle: Newton's first law (TM1 with no force) and IM6's rows at zero error: two bodies at
// rest, joined where they are, with no gravity or load, have no joint error and no relative
// speed, so every row's impulse is 0 and nothing moves, bit for bit: velocities stay exactly 0,
// poses exactly as created, and the reported reaction exactly 0. A joint's rows start from no
// impulse (a new joint has nothing to warm-start).
BOOST_AUTO_TEST_CASE(joints_at_rest_without_load_stay_exactly_at_rest, *utf::label("IM6")) {
    for (int kind = 0; kind < 8; ++kind) {
        World world(WorldDef{.gravity = {0.0, 0.0}, .enable_sleep = false});
        const BodyId a = add_box(world, {0.0, 0.0}, {}, 1.0, 1.0, 1.0);
        const BodyId b = add_box(world, {2.0, 0.0}, {}, 0.5, 0.5, 3.0);
        const Vec2d mid{1.0, 0.0};
        JointId j{};
        switch (kind) {
        case 0:
            j = world.create_joint(WeldJointDef{.body_a = a, .body_b = b, .anchor = mid});
            break;
        case 1:
            j = world.create_joint(WeldJointDef{.body_a = a,
                                                .body_b = b,
                                                .anchor = mid,
                                                .angular_hertz = 4.0,
                                                .angular_damping_ratio = 0.5});
            break;
        case 2:
            j = world.create_joint(PrismaticJointDef{.body_a = a, .body_b = b, .anchor = mid});
            break;
        case 3:
            j = world.create_joint(MotorJointDef{.body_a = a,
                                                 .body_b = b,
                                                 .linear_offset = {2.0, 0.0},
                                                 .max_force = 50.0,
                                                 .max_torque = 50.0});
            break;
        case 4:
            j = world.create_joint(RevoluteJointDef{.body_a = a, .body_b = b, .anchor = mid});
            break;
        case 5: // every axial row in use: the limit (at its bound), the motor (held still)
            j = world.create_joint(PrismaticJointDef{.body_a = a,
                                                     .body_b = b,
                                                     .anchor = mid,
                                                     .enable_limit = true,
                                                     .lower_translation = 0.0,
                                                     .upper_translation = 0.5,
                                                     .enable_motor = true,
                                                     .motor_speed = 0.0,
                                                     .max_motor_force = 20.0});
            break;
        case 6:
            j = world.create_joint(WheelJointDef{.body_a = a,
                                                 .body_b = b,
                                                 .anchor = {2.0, 0.0},
                                                 .enable_motor = true,
                                                 .motor_speed = 0.0,
                                                 .max_motor_torque = 20.0});
            break;
        default:
            j = world.create_joint(RevoluteJointDef{.body_a = a,
                                                    .body_b = b,
                                                    .anchor = mid,
                                                    .enable_limit = true,
                                                    .lower_angle = 0.0,
                                                    .upper_angle = 0.5,
                                                    .enable_motor = true,
                                                    .motor_speed = 0.0,
                                                    .max_motor_torque = 20.0});
        }
        for (int k = 0; k < 30; ++k) {
            world.step(1.0 / 60.0);
            for (const BodyId body : {a, b}) {
                BOOST_TEST(world.velocity(body).x == 0.0);
                BOOST_TEST(world.velocity(body).y == 0.0);
                BOOST_TEST(world.angular_velocity(body) == 0.0);
                BOOST_TEST(world.orientation(body) == 0.0);
            }
            BOOST_TEST(world.position(a).x == 0.0);
            BOOST_TEST(world.position(b).x == 2.0);
            BOOST_TEST(world.position(b).y == 0.0);
            BOOST_TEST(world.joint_reaction_torque(j) == 0.0);
            BOOST_TEST(world.joint_reaction_force(j).x == 0.0);
        }
    }
}

/// A bar pinned at its centre to a static body with a torsional spring, set turning at w0:
/// its largest deviation over 2 s from the oscillator.
double torsion_error(int steps_per_second, const DampedOscillator& osc, double w0) {
    World world(WorldDef{.gravity = {0.0, -g}, .enable_sleep = false});
    BodyDef ground_def;
    ground_def.type = BodyType::static_body;
    const BodyId ground = world.create_body(ground_def);
    BodyDef bar_def;
    bar_def.angular_velocity = w0;
    const BodyId bar = world.create_body(bar_def);
    world.create_shape(bar, box_shape(1.0, 0.1));
    const JointId j = world.create_joint(RevoluteJointDef{.body_a = ground,
                                                          .body_b = bar,
                                                          .anchor = {0.0, 0.0},
                                                          .enable_spring = true,
                                                          .hertz = osc.hertz,
                                                          .damping_ratio = osc.zeta});
    double worst = 0.0;
    for (int k = 1; k <= 2 * steps_per_second; ++k) {
        world.step(1.0 / steps_per_second);
        const double t = k * 1.0 / steps_per_second;
        worst = std::max(worst, std::abs(world.joint_angle(j) - osc.from_speed(w0, t)));
    }
    return worst;
}

// Oracle: the damped harmonic oscillator. A bar pinned at its centre (gravity exerts no torque
// about it) with a torsional spring of frequency f and damping ratio zeta for its inertia:
// from theta = 0 at speed w0, theta(t) = w0 / omega_d e^(-zeta omega t) sin(omega_d t). First
// order: the error halves with the step (ratio >= 1.8) and is below 2 % of the amplitude
// w0 / omega at 1/480 s.
BOOST_AUTO_TEST_CASE(revolute_spring_is_a_damped_oscillator,
                     *utf::label("DD22") * utf::label("IM6") * utf::label("LC3")) {
    const DampedOscillator osc{1.0, 0.15};
    const double w0 = 3.0;
    const double e240 = torsion_error(240, osc, w0), e480 = torsion_error(480, osc, w0);
    BOOST_TEST_MESSAGE("revolute spring: max deviation " << e240 << " rad at 1/240 s, " << e480
                                                         << " rad at 1/480 s");
    BOOST_TEST(e480 <= 0.02 * w0 / osc.omega());
    BOOST_TEST(e240 / e480 >= 1.8);
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

BOOST_AUTO_TEST_SUITE_END()
