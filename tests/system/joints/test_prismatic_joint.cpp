// Prismatic joints (LC3: DD23, IM6) in the engine, against independent oracles: the
// frictionless slide down an incline and the motor's force limit (T1, exact per substep), the
// damped harmonic oscillator (the spring), the limits themselves, and the conservation of
// linear momentum (T2) between two free bodies.
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

/// A box on a prismatic joint to a static ground, the anchor at its centre.
struct Slider {
    World world;
    BodyId box;
    JointId joint;
    Slider(Vec2d gravity, const PrismaticJointDef& options, Vec2d velocity = {})
        : world(WorldDef{.gravity = gravity, .enable_sleep = false}) {
        BodyDef ground_def;
        ground_def.type = BodyType::static_body;
        const BodyId ground = world.create_body(ground_def);
        BodyDef box_def;
        box_def.linear_velocity = velocity;
        box = world.create_body(box_def);
        world.create_shape(box, box_shape(0.5, 0.25));
        PrismaticJointDef def = options;
        def.body_a = ground;
        def.body_b = box;
        joint = world.create_joint(def);
    }
};

} // namespace

BOOST_AUTO_TEST_SUITE(prismatic_joint)

// Oracle: IM6's rigid relax ends each substep with no velocity error (mu = 1, gamma = 0: the
// rows' impulses exactly cancel the relative velocity across the axis and in angle). A box on
// a horizontal slider under gravity, at rest: after every step its vertical velocity and its
// spin are 0 to round-off, and it does not slide (no force along the axis).
BOOST_AUTO_TEST_CASE(the_relax_leaves_no_velocity_across_the_axis,
                     *utf::label("DD23") * utf::label("IM6") * utf::label("LC3")) {
    Slider s({0.0, -g}, PrismaticJointDef{.anchor = {0.0, 0.0}, .axis = {1.0, 0.0}});
    for (int k = 0; k < 60; ++k) {
        s.world.step(1.0 / 60.0);
        BOOST_TEST(std::abs(s.world.velocity(s.box).y) < 1e-12);
        BOOST_TEST(std::abs(s.world.angular_velocity(s.box)) < 1e-12);
        BOOST_TEST(std::abs(s.world.velocity(s.box).x) < 1e-12);
    }
}

// Oracle: IM6's soft bias: a joint error decays (the rows ask a correction velocity
// proportional to it), while without the bias a rigid row only holds the relative velocity and
// the error would stay. The box is moved 5 cm off the axis and turned by 0.1 rad after the joint
// is made, with no gravity: within 2 s both errors fall below 1 % of where they started, and
// the slide along the axis stays within 1 mm of 0 (no force acts along it).
BOOST_AUTO_TEST_CASE(an_error_across_the_axis_and_in_angle_is_corrected,
                     *utf::label("DD23") * utf::label("IM6") * utf::label("LC3")) {
    Slider s({0.0, 0.0}, PrismaticJointDef{.anchor = {0.0, 0.0}, .axis = {1.0, 0.0}});
    s.world.set_transform(s.box, {0.0, 0.05}, 0.1);
    for (int k = 0; k < 120; ++k)
        s.world.step(1.0 / 60.0);
    BOOST_TEST(std::abs(s.world.position(s.box).y) < 0.05 * 0.01);
    double angle = s.world.orientation(s.box);
    if (angle > std::numbers::pi)
        angle -= 2.0 * std::numbers::pi;
    BOOST_TEST(std::abs(angle) < 0.1 * 0.01);
    BOOST_TEST(std::abs(s.world.position(s.box).x) < 1e-3);
}

// Oracle: T1 along a frictionless incline of slope alpha. The joint's impulses act across the
// axis (and about z), never along it, so along the axis the box falls with g sin alpha: after
// n substeps of h, s = g sin(alpha) h^2 n (n + 1) / 2 exactly (semi-implicit Euler, IM1).
// Across it, the joint carries the normal force m g cos alpha, and sags under it by no more
// than a spring of the joint's frequency would, g cos(alpha) / (2 pi f_J)^2 (IM6), where it
// comes to rest: the soft bias's equilibrium, which its relaxation of the accumulated impulse
// (IM6's gamma) sets; a joint made stiffer within the substep would sag less.
BOOST_AUTO_TEST_CASE(slides_down_an_incline_as_newton_says,
                     *utf::label("DD23") * utf::label("IM6") * utf::label("LC3")) {
    const double alpha = std::numbers::pi / 6.0, dt = 1.0 / 60.0;
    Slider s({0.0, -g}, PrismaticJointDef{.axis = {std::cos(alpha), -std::sin(alpha)}});
    const int substeps = WorldDef{}.substeps;
    const double h = dt / substeps, m = s.world.mass(s.box);
    const double omega_J = 2.0 * std::numbers::pi * WorldDef{}.joint_hertz;
    const double sag = g * std::cos(alpha) / (omega_J * omega_J);
    double worst_sag = 0.0;
    for (int k = 1; k <= 120; ++k) {
        s.world.step(dt);
        const double n = double(k * substeps);
        const double expected = g * std::sin(alpha) * h * h * n * (n + 1.0) / 2.0;
        BOOST_TEST_REQUIRE(s.world.joint_translation(s.joint) == expected,
                           boost::test_tools::tolerance(1e-9));
        const Vec2d p = s.world.position(s.box);
        worst_sag = std::max(worst_sag, std::abs(p.x * std::sin(alpha) + p.y * std::cos(alpha)));
        BOOST_TEST_REQUIRE(std::abs(s.world.joint_angle(s.joint)) <= 1e-12);
    }
    const Vec2d end = s.world.position(s.box);
    const double last_sag = std::abs(end.x * std::sin(alpha) + end.y * std::cos(alpha));
    BOOST_TEST_MESSAGE("incline: largest sag across the axis " << worst_sag << " m, last "
                                                               << last_sag << " m, bound " << sag);
    BOOST_TEST(worst_sag <= sag * (1.0 + 1e-9)); // it settles on the bound, overdamped
    BOOST_TEST(last_sag == sag, boost::test_tools::tolerance(1e-3));
    const Vec2d F = s.world.joint_reaction_force(s.joint);
    BOOST_TEST(norm(F) == m * g * std::cos(alpha), boost::test_tools::tolerance(1e-9));
}

// Oracle: T1 with the motor's force limit. A box on a vertical axis, its motor asked for 2 m/s
// upwards with at most F = 3 m g: it rises with (F - m g) / m = 2 g, exactly per substep (the
// clamp), until it reaches 2 m/s, which it then keeps; the reaction along the axis reads F
// while it accelerates.
BOOST_AUTO_TEST_CASE(motor_lifts_under_its_force_limit,
                     *utf::label("DD23") * utf::label("IM6") * utf::label("LC3")) {
    const double dt = 1.0 / 60.0, speed = 2.0;
    Slider probe({0.0, -g}, PrismaticJointDef{.axis = {0.0, 1.0}});
    const double m = probe.world.mass(probe.box), F = 3.0 * m * g;
    Slider s({0.0, -g}, PrismaticJointDef{.axis = {0.0, 1.0},
                                          .enable_motor = true,
                                          .motor_speed = speed,
                                          .max_motor_force = F});
    for (int k = 1; k <= 30; ++k) {
        s.world.step(dt);
        const double expected = std::min((F / m - g) * k * dt, speed);
        BOOST_TEST_REQUIRE(s.world.velocity(s.box).y == expected,
                           boost::test_tools::tolerance(1e-9));
        if ((F / m - g) * k * dt < speed)
            BOOST_TEST_REQUIRE(s.world.joint_reaction_force(s.joint).y == F,
                               boost::test_tools::tolerance(1e-9));
    }
    BOOST_TEST(s.world.velocity(s.box).y == speed, boost::test_tools::tolerance(1e-12));
}

// Oracle: the limits themselves (DD23). A box falling along a vertical axis with travel
// [-0.5, 0.25] m stops at the lower limit: it never passes it by more than 1 cm and rests on it
// within 2 mm (the soft bias's sag under its weight); thrown upwards, the upper limit stops it.
BOOST_AUTO_TEST_CASE(limits_hold_the_translation,
                     *utf::label("DD23") * utf::label("IM6") * utf::label("LC3")) {
    const double lower = -0.5, upper = 0.25;
    for (const double v0 : {0.0, 8.0}) {
        Slider s({0.0, -g},
                 PrismaticJointDef{.axis = {0.0, 1.0},
                                   .enable_limit = true,
                                   .lower_translation = lower,
                                   .upper_translation = upper},
                 {0.0, v0});
        double lowest = 0.0, highest = 0.0;
        for (int k = 0; k < 120; ++k) {
            s.world.step(1.0 / 60.0);
            lowest = std::min(lowest, s.world.joint_translation(s.joint));
            highest = std::max(highest, s.world.joint_translation(s.joint));
        }
        BOOST_TEST_MESSAGE("v0 " << v0 << ": lowest " << lowest << " m, highest " << highest
                                 << " m");
        BOOST_TEST(lowest >= lower - 0.01);
        BOOST_TEST(highest <= upper + 0.01);
        BOOST_TEST(std::abs(s.world.joint_translation(s.joint) - lower) <= 2e-3);
        if (v0 > 0.0)
            BOOST_TEST(highest >= upper - 0.01); // it did reach the upper limit
    }
}

// Oracle: T1 at rest. A box resting on its joint's lower limit under gravity, vertical axis:
// once settled, only the limit holds it up, so the joint's reaction on it is its weight,
// (0, m g), the limit pushing up. Its sign says which way the limit pushes.
BOOST_AUTO_TEST_CASE(resting_on_the_lower_limit_the_reaction_is_the_weight,
                     *utf::label("DD23") * utf::label("IM6")) {
    Slider s({0.0, -g}, PrismaticJointDef{.axis = {0.0, 1.0},
                                          .enable_limit = true,
                                          .lower_translation = -0.2,
                                          .upper_translation = 0.5});
    const double m = s.world.mass(s.box);
    for (int k = 0; k < 240; ++k)
        s.world.step(1.0 / 60.0);
    BOOST_TEST_REQUIRE(std::abs(s.world.velocity(s.box).y) < 1e-9); // settled
    const Vec2d F = s.world.joint_reaction_force(s.joint);
    BOOST_TEST(F.y == m * g, boost::test_tools::tolerance(1e-6));
    BOOST_TEST(std::abs(F.x) < 1e-9 * m * g);
}

// Oracle: T1 at rest, and Hooke's law for the spring's stiffness. A box hanging on a vertical
// axis from a spring of frequency f (stiffness k = m (2 pi f)^2 for its mass), critically
// damped: once settled, the spring alone holds it, so the joint's reaction is its weight,
// (0, m g), and it hangs at x = -m g / k = -g / (2 pi f)^2.
BOOST_AUTO_TEST_CASE(hanging_on_the_spring_the_reaction_is_the_weight,
                     *utf::label("DD23") * utf::label("IM6")) {
    const double f = 2.0;
    Slider s({0.0, -g},
             PrismaticJointDef{
                 .axis = {0.0, 1.0}, .enable_spring = true, .hertz = f, .damping_ratio = 1.0});
    const double m = s.world.mass(s.box), omega = 2.0 * std::numbers::pi * f;
    for (int k = 0; k < 300; ++k)
        s.world.step(1.0 / 60.0);
    BOOST_TEST_REQUIRE(std::abs(s.world.velocity(s.box).y) < 1e-9); // settled
    BOOST_TEST(s.world.joint_translation(s.joint) == -g / (omega * omega),
               boost::test_tools::tolerance(1e-6));
    const Vec2d F = s.world.joint_reaction_force(s.joint);
    BOOST_TEST(F.y == m * g, boost::test_tools::tolerance(1e-6));
    BOOST_TEST(std::abs(F.x) < 1e-9 * m * g);
}

/// The spring slider's largest deviation over 2 s from the oscillator, at the given rate.
double spring_error(int steps_per_second, const DampedOscillator& osc, double v0) {
    Slider s({0.0, 0.0},
             PrismaticJointDef{.axis = {1.0, 1.0},
                               .enable_spring = true,
                               .hertz = osc.hertz,
                               .damping_ratio = osc.zeta},
             {v0 / std::sqrt(2.0), v0 / std::sqrt(2.0)});
    double worst = 0.0;
    for (int k = 1; k <= 2 * steps_per_second; ++k) {
        s.world.step(1.0 / steps_per_second);
        const double t = k * 1.0 / steps_per_second;
        worst =
            std::max(worst, std::abs(s.world.joint_translation(s.joint) - osc.from_speed(v0, t)));
    }
    return worst;
}

// Oracle: the damped harmonic oscillator. The spring of frequency f and damping ratio zeta
// acts on the sliding direction's effective mass, here the box's (anchor at its centre, the
// ground static), so the translation from s = 0 at speed v0 is v0 / omega_d e^(-zeta omega t)
// sin(omega_d t). The soft step integrates it implicitly, first order: the error halves with
// the step (ratio >= 1.8) and is below 2 % of the amplitude v0 / omega at 1/480 s.
BOOST_AUTO_TEST_CASE(spring_is_a_damped_oscillator,
                     *utf::label("DD23") * utf::label("IM6") * utf::label("LC3")) {
    const DampedOscillator osc{2.0, 0.1};
    const double v0 = 1.0;
    const double e240 = spring_error(240, osc, v0), e480 = spring_error(480, osc, v0);
    BOOST_TEST_MESSAGE("prismatic spring: max deviation " << e240 << " m at 1/240 s, " << e480
                                                          << " m at 1/480 s");
    BOOST_TEST(e480 <= 0.02 * v0 / osc.omega());
    BOOST_TEST(e240 / e480 >= 1.8);
}

// Oracle: T2 (equal and opposite impulses conserve linear momentum) and the constraint itself.
// Two boxes joined off their centres by a prismatic joint, drifting and spinning together in
// free space: the total momentum stays what it was to round-off and the relative angle within
// the soft joint's compliance (1e-3), which exercises DD23's coupled line-and-angle block.
BOOST_AUTO_TEST_CASE(two_free_bodies_conserve_momentum,
                     *utf::label("DD23") * utf::label("IM6") * utf::label("LC3")) {
    World world(WorldDef{.gravity = {0.0, 0.0}, .enable_sleep = false});
    BodyDef a_def;
    a_def.linear_velocity = {1.0, 0.5};
    a_def.angular_velocity = 1.5;
    const BodyId a = world.create_body(a_def);
    world.create_shape(a, box_shape(1.0, 0.5));
    BodyDef b_def;
    b_def.position = {1.5, 0.3};
    b_def.linear_velocity = {-0.5, 2.0};
    const BodyId b = world.create_body(b_def);
    world.create_shape(b, box_shape(0.6, 0.3));
    const JointId j = world.create_joint(
        PrismaticJointDef{.body_a = a, .body_b = b, .anchor = {0.8, 0.2}, .axis = {1.0, 0.2}});
    const Vec2d p0 = world.linear_momentum();
    double worst_angle = 0.0;
    for (int k = 0; k < 300; ++k) {
        world.step(1.0 / 60.0);
        worst_angle = std::max(worst_angle, std::abs(world.joint_angle(j)));
    }
    const Vec2d p1 = world.linear_momentum();
    BOOST_TEST_MESSAGE("largest relative angle " << worst_angle << " rad");
    BOOST_TEST(norm(p1 - p0) <= 1e-12 * norm(p0));
    BOOST_TEST(worst_angle <= 1e-3);
}

BOOST_AUTO_TEST_SUITE_END()
