// Revolute joints (DD19, DD22 with their motor, limits and spring; IM6, LC3) in the engine,
// against independent oracles: the exact large-amplitude pendulum period (complete elliptic
// integral, GSL), a GSL rk8pd solution of the pendulum ODE, the closed-form tension at the bottom
// of the swing, the conservation of linear momentum by the joint's equal and opposite impulses
// (T2), T4 under the motor's torque limit, and the damped harmonic oscillator. The suite `joints`
// holds the revolute, distance and target cases and the cross-kind ones (test_joints.cpp).
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
#include "system/joints/pendulum.hpp"
#include "system/system_support.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;
using namespace tamias2d::system_test;
using namespace tamias2d::system_test::pendulum;
using tamias2d::test::DampedOscillator;

namespace {

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

BOOST_AUTO_TEST_SUITE_END()
