// Wheel joints (LC3: DD25, IM6) in the engine, against independent oracles: the damped
// harmonic oscillator (the suspension sagging under the wheel's weight) and T4 with the
// motor's torque limit.
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "support/damped_oscillator.hpp"
#include "system/system_support.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;
using namespace tamias2d::system_test;
using tamias2d::test::DampedOscillator;

namespace {

constexpr double g = 9.81;

/// A wheel on a static chassis, the anchor at the wheel's centre, a vertical suspension axis.
struct Wheel {
    World world;
    BodyId wheel;
    JointId joint;
    Wheel(Vec2d gravity, WheelJointDef def)
        : world(WorldDef{.gravity = gravity, .enable_sleep = false}) {
        BodyDef chassis_def;
        chassis_def.type = BodyType::static_body;
        def.body_a = world.create_body(chassis_def);
        wheel = world.create_body(BodyDef{});
        world.create_shape(wheel, circle_shape(0.4));
        def.body_b = wheel;
        def.axis = {0.0, 1.0};
        joint = world.create_joint(def);
    }
};

/// The suspension's largest deviation over 2 s from the oscillator, and its largest sideways
/// drift off the line.
std::pair<double, double> suspension_error(int steps_per_second, const DampedOscillator& osc) {
    Wheel w({0.0, -g}, WheelJointDef{.hertz = osc.hertz, .damping_ratio = osc.zeta});
    const double sag = -g / (osc.omega() * osc.omega());
    double worst = 0.0, sideways = 0.0;
    for (int k = 1; k <= 2 * steps_per_second; ++k) {
        w.world.step(1.0 / steps_per_second);
        const double t = k * 1.0 / steps_per_second;
        const double expected = sag + osc.from_rest(-sag, t);
        worst = std::max(worst, std::abs(w.world.joint_translation(w.joint) - expected));
        sideways = std::max(sideways, std::abs(w.world.position(w.wheel).x));
    }
    return {worst, sideways};
}

} // namespace

BOOST_AUTO_TEST_SUITE(wheel_joint)

// Oracle: the damped harmonic oscillator. The suspension spring (frequency f, damping ratio
// zeta) acts on the wheel's mass along the axis, under its weight: released at s = 0, the
// travel is s* + (0 - s*) e^(-zeta omega t) (cos omega_d t + zeta omega / omega_d sin omega_d
// t) about the sag s* = -g / omega^2. First order: the error halves with the step (ratio >=
// 1.8) and is below 2 % of the sag at 1/480 s; the wheel never leaves its line (1e-12 m).
BOOST_AUTO_TEST_CASE(suspension_is_a_damped_oscillator,
                     *utf::label("DD25") * utf::label("IM6") * utf::label("LC3")) {
    const DampedOscillator osc{2.0, 0.3};
    const auto [e240, side240] = suspension_error(240, osc);
    const auto [e480, side480] = suspension_error(480, osc);
    BOOST_TEST_MESSAGE("suspension: max deviation " << e240 << " m at 1/240 s, " << e480
                                                    << " m at 1/480 s");
    BOOST_TEST(e480 <= 0.02 * g / (osc.omega() * osc.omega()));
    BOOST_TEST(e240 / e480 >= 1.8);
    BOOST_TEST(side240 <= 1e-12);
    BOOST_TEST(side480 <= 1e-12);
}

// Oracle: IM6's soft constraint is a spring of the joints' frequency f_J (WorldDef::joint_hertz)
// on the effective mass across the line: under a constant sideways acceleration g_x its
// equilibrium line error is g_x / omega_J^2 (omega_J = 2 pi f_J), and from rest, damped
// (joint_damping_ratio 2), it never exceeds that. The wheel, pulled sideways by gravity's x
// component while its suspension sags, stays within twice that of its line over 2 s.
BOOST_AUTO_TEST_CASE(wheel_holds_its_line_against_a_sideways_load,
                     *utf::label("DD25") * utf::label("IM6") * utf::label("LC3")) {
    const double gx = -2.0, dt = 1.0 / 240.0;
    Wheel w({gx, -g}, WheelJointDef{.hertz = 2.0, .damping_ratio = 0.3});
    const double omega = 2.0 * std::numbers::pi * WorldDef{}.joint_hertz;
    const double bound = 2.0 * std::abs(gx) / (omega * omega);
    double sideways = 0.0;
    for (int k = 1; k <= 480; ++k) {
        w.world.step(dt);
        sideways = std::max(sideways, std::abs(w.world.position(w.wheel).x));
    }
    BOOST_TEST_MESSAGE("wheel off its line: at most " << sideways << " m (bound " << bound << ")");
    BOOST_TEST(sideways <= bound);
    BOOST_TEST(w.world.joint_translation(w.joint) < -0.01); // it sags meanwhile
}

// Oracle: T4 with the motor's torque limit. The wheel's motor, asked for 10 rad/s with at most
// tau, turns it at omega = tau t / I exactly per substep (the clamp) until the speed is
// reached, then holds it; the reaction torque reads tau meanwhile.
BOOST_AUTO_TEST_CASE(motor_spins_up_under_its_torque_limit,
                     *utf::label("DD25") * utf::label("IM6") * utf::label("LC3")) {
    const double tau = 0.3, target = 10.0, dt = 1.0 / 60.0;
    Wheel w({0.0, 0.0},
            WheelJointDef{.enable_motor = true, .motor_speed = target, .max_motor_torque = tau});
    const double I = w.world.inertia(w.wheel);
    for (int k = 1; k <= 300; ++k) {
        w.world.step(dt);
        const double expected = std::min(tau * k * dt / I, target);
        BOOST_TEST_REQUIRE(w.world.angular_velocity(w.wheel) == expected,
                           boost::test_tools::tolerance(1e-9));
        if (tau * k * dt / I < target)
            BOOST_TEST_REQUIRE(w.world.joint_reaction_torque(w.joint) == tau,
                               boost::test_tools::tolerance(1e-9));
    }
    BOOST_TEST(w.world.angular_velocity(w.wheel) == target, boost::test_tools::tolerance(1e-12));
}

// Oracle: static equilibrium (T1 with zero acceleration). A wheel without its spring, under
// its weight m g, falls onto the lower limit of its travel and rests there: the limit alone
// then carries the weight, so the joint's reaction on the wheel is (0, m g), the wheel is
// still and its travel is the limit's less IM6's soft error under that load, g / omega_J^2
// (omega_J = 2 pi f_J of WorldDef::joint_hertz) at equilibrium; half of it again is allowed for
// the substeps' discrete soft step. Each substep's first impulse is the limit's last (warm
// starting): a first impulse of the wrong sign shows as a wheel that is not at rest.
BOOST_AUTO_TEST_CASE(a_wheel_resting_on_its_lower_limit_is_held_by_it,
                     *utf::label("DD25") * utf::label("IM6") * utf::label("LC3")) {
    const double lower = -0.1, dt = 1.0 / 60.0;
    Wheel w({0.0, -g}, WheelJointDef{.enable_spring = false,
                                     .enable_limit = true,
                                     .lower_translation = lower,
                                     .upper_translation = 0.1});
    for (int k = 1; k <= 120; ++k)
        w.world.step(dt);
    const double m = w.world.mass(w.wheel);
    const double omega = 2.0 * std::numbers::pi * WorldDef{}.joint_hertz;
    const Vec2d reaction = w.world.joint_reaction_force(w.joint);
    BOOST_TEST_MESSAGE("on the limit: travel " << w.world.joint_translation(w.joint)
                                               << " m, reaction (" << reaction.x << ", "
                                               << reaction.y << ") N, m g " << m * g << " N");
    BOOST_TEST(std::abs(w.world.joint_translation(w.joint) - lower) <= 1.5 * g / (omega * omega));
    BOOST_TEST(std::abs(w.world.velocity(w.wheel).y) <= 1e-6);
    BOOST_TEST(reaction.y == m * g, boost::test_tools::tolerance(1e-6));
    BOOST_TEST(std::abs(reaction.x) <= 1e-9);
}

// Oracle: static equilibrium, as above, with gravity turned upwards: the wheel rises onto the
// upper limit of its travel and rests there, so the limit carries its weight the other way and
// the joint's reaction on the wheel is (0, -m g), with its travel at the upper limit within the
// same soft error.
BOOST_AUTO_TEST_CASE(a_wheel_pressed_against_its_upper_limit_is_held_by_it,
                     *utf::label("DD25") * utf::label("IM6") * utf::label("LC3")) {
    const double upper = 0.1, dt = 1.0 / 60.0;
    Wheel w({0.0, g}, WheelJointDef{.enable_spring = false,
                                    .enable_limit = true,
                                    .lower_translation = -0.1,
                                    .upper_translation = upper});
    for (int k = 1; k <= 120; ++k)
        w.world.step(dt);
    const double m = w.world.mass(w.wheel);
    const double omega = 2.0 * std::numbers::pi * WorldDef{}.joint_hertz;
    const Vec2d reaction = w.world.joint_reaction_force(w.joint);
    BOOST_TEST(std::abs(w.world.joint_translation(w.joint) - upper) <= 1.5 * g / (omega * omega));
    BOOST_TEST(std::abs(w.world.velocity(w.wheel).y) <= 1e-6);
    BOOST_TEST(reaction.y == -m * g, boost::test_tools::tolerance(1e-6));
    BOOST_TEST(std::abs(reaction.x) <= 1e-9);
}

BOOST_AUTO_TEST_SUITE_END()
