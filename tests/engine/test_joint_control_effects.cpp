// Run-time changes of a joint (World's joint_control calls) against independent oracles: the
// limits' bounds (DD22, DD23), a motor's constant-torque and constant-force spin-up (T4, T1)
// until its speed, a spring's period 1 / f about the target it is given (the harmonic
// oscillator's closed form), the distance joint's motor (DD35), the break thresholds against a
// cantilever's static force and torque (DD36), a joint's own soft bias against a spring's
// static deflection (DD37), and collide_connected's effect on a pair.
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "tamias2d/world.hpp"

namespace utf = boost::unit_test;
namespace tt = boost::test_tools;
using namespace tamias2d;

namespace {

constexpr double dt = 1.0 / 240.0;
constexpr double pi = std::numbers::pi;

WorldDef world_def(double g) {
    WorldDef d;
    d.gravity = {0.0, -g};
    d.enable_sleep = false;
    return d;
}

BodyId static_body(World& w, Vec2d at = {}) {
    BodyDef bd;
    bd.type = BodyType::static_body;
    bd.position = at;
    return w.create_body(bd);
}

BodyId disc(World& w, Vec2d at, double radius, double density = 1.0) {
    BodyDef bd;
    bd.position = at;
    const BodyId b = w.create_body(bd);
    w.create_shape(b, circle_shape(radius, Material{density, 0.0, 0.0}));
    return b;
}

/// A beam 2 m x 0.2 m whose centre is 1 m right of the origin, where the tests join it to a wall.
BodyId cantilever(World& w) {
    BodyDef bd;
    bd.position = {1.0, 0.0};
    const BodyId b = w.create_body(bd);
    w.create_shape(b, box_shape(2.0, 0.2));
    return b;
}

bool began(const World& w, BodyId a, BodyId b) {
    for (const ContactEvent& e : w.contact_begin_events())
        if ((e.body_a == a && e.body_b == b) || (e.body_a == b && e.body_b == a))
            return true;
    return false;
}

} // namespace

BOOST_AUTO_TEST_SUITE(joint_control_effects)

// Oracle: DD22's limits as defined: the angle stays in [lower, upper]. A pendulum released
// horizontal would swing to -pi/2 and beyond; limited at run time to [-0.5, 0.5] rad it never
// passes -0.5 by more than the soft limit's give (0.01 rad); its limits switched off, it swings
// on past them.
BOOST_AUTO_TEST_CASE(revolute_limits_bound_the_angle, *utf::label("DD22")) {
    World w(world_def(10.0));
    const BodyId pivot = static_body(w);
    BodyDef bd;
    bd.position = {1.0, 0.0};
    const BodyId bob = w.create_body(bd);
    w.create_shape(bob, box_shape(2.0, 0.1));
    RevoluteJointDef rd;
    rd.body_a = pivot;
    rd.body_b = bob;
    const JointId j = w.create_joint(rd);
    w.set_joint_limits(j, -0.5, 0.5);
    w.enable_joint_limit(j, true);
    BOOST_TEST(w.is_joint_limit_enabled(j));
    BOOST_TEST((w.joint_limits(j) == JointLimits{-0.5, 0.5}));
    double least = 0.0;
    for (int k = 0; k < 480; ++k) {
        w.step(dt);
        least = std::min(least, w.joint_angle(j));
    }
    BOOST_TEST(least > -0.51);
    BOOST_TEST(least < -0.45); // it did reach the bound
    w.enable_joint_limit(j, false);
    for (int k = 0; k < 240; ++k) {
        w.step(dt);
        least = std::min(least, w.joint_angle(j));
    }
    BOOST_TEST(least < -1.0);
}

// Oracle: T4 and the motor's definition (DD22). A disc (I = m r^2 / 2) pinned at its centre,
// no gravity, its motor enabled at run time with tau_max = 2 N m and speed 10 rad s^-1:
// omega = tau_max t / I until it reaches 10, then 10.
BOOST_AUTO_TEST_CASE(revolute_motor_spins_up_at_tau_over_i,
                     *utf::label("DD22") * utf::label("T4")) {
    World w(world_def(0.0));
    const BodyId pivot = static_body(w);
    const BodyId wheel = disc(w, {0.0, 0.0}, 0.5, 2.0);
    RevoluteJointDef rd;
    rd.body_a = pivot;
    rd.body_b = wheel;
    const JointId j = w.create_joint(rd);
    w.set_joint_motor_speed(j, 10.0);
    w.set_joint_max_motor_torque(j, 2.0);
    w.enable_joint_motor(j, true);
    BOOST_TEST(w.is_joint_motor_enabled(j));
    BOOST_TEST(w.joint_motor_speed(j) == 10.0);
    BOOST_TEST(w.joint_max_motor_torque(j) == 2.0);
    const double I = w.inertia(wheel);
    const int n = 60;
    for (int k = 0; k < n; ++k)
        w.step(dt);
    BOOST_TEST_REQUIRE(2.0 * n * dt / I < 10.0);
    BOOST_TEST(w.angular_velocity(wheel) == 2.0 * n * dt / I, tt::tolerance(1e-9));
    for (int k = 0; k < 2400; ++k)
        w.step(dt);
    BOOST_TEST(w.angular_velocity(wheel) == 10.0, tt::tolerance(1e-9));
}

// Oracle: T1 and DD23's motor and limits. A 1 kg box on a horizontal prismatic joint, no
// gravity, driven at run time with F_max = 4 N towards 3 m s^-1: v = F t / m, then 3 m s^-1;
// its translation limited to [-1, 2] m, it stops at 2 m.
BOOST_AUTO_TEST_CASE(prismatic_motor_and_limits, *utf::label("DD23") * utf::label("T1")) {
    World w(world_def(0.0));
    const BodyId ground = static_body(w);
    BodyDef bd;
    const BodyId slider = w.create_body(bd);
    w.create_shape(slider, box_shape(1.0, 1.0));
    PrismaticJointDef pd;
    pd.body_a = ground;
    pd.body_b = slider;
    pd.axis = {1.0, 0.0};
    const JointId j = w.create_joint(pd);
    w.set_joint_max_motor_force(j, 4.0);
    BOOST_TEST(w.joint_max_motor_force(j) == 4.0);
    w.set_joint_motor_speed(j, 3.0);
    w.enable_joint_motor(j, true);
    for (int k = 0; k < 48; ++k)
        w.step(dt);
    BOOST_TEST(w.velocity(slider).x == 4.0 * 48 * dt / 1.0, tt::tolerance(1e-9));
    w.set_joint_limits(j, -1.0, 2.0);
    w.enable_joint_limit(j, true);
    for (int k = 0; k < 480; ++k)
        w.step(dt);
    BOOST_TEST(w.joint_translation(j) == 2.0, tt::tolerance(0.005));
    BOOST_TEST(std::abs(w.velocity(slider).x) < 1e-3);
}

// Oracle: kinematics. Without gravity, a slider whose centre of mass is off its origin (its box
// centred at (0.5, 0.3) in its frame), set moving along its prismatic joint's axis at 1 m/s,
// keeps that velocity; the joint's translation is how far the anchor on it has moved along the
// axis from the one on the ground: its origin's x, within rounding, at every step.
BOOST_AUTO_TEST_CASE(prismatic_translation_with_an_offset_centre_of_mass,
                     *utf::label("DD23") * utf::label("T1")) {
    World w(world_def(0.0));
    const BodyId ground = static_body(w);
    BodyDef bd;
    bd.linear_velocity = {1.0, 0.0};
    const BodyId slider = w.create_body(bd);
    w.create_shape(slider, box_shape(1.0, 1.0, {}, {0.5, 0.3}));
    PrismaticJointDef pd;
    pd.body_a = ground;
    pd.body_b = slider;
    pd.axis = {1.0, 0.0};
    const JointId j = w.create_joint(pd);
    BOOST_TEST(w.joint_translation(j) == 0.0);
    for (int k = 0; k < 30; ++k) {
        w.step(dt);
        BOOST_TEST(std::abs(w.joint_translation(j) - w.origin(slider).x) <= 1e-12);
    }
    BOOST_TEST(w.origin(slider).x == 30 * dt, tt::tolerance(1e-9));
}

// Oracle: the harmonic oscillator. A 1 kg box on a prismatic joint with an undamped spring of
// f = 1 Hz (stiffness m (2 pi f)^2 for the sliding direction's effective mass m), given the
// target 0.5 m at rest at 0: x(t) = 0.5 (1 - cos 2 pi f t), which first reaches its top, 1 m,
// at t = 1 / (2 f) = 0.5 s, found within two steps (1.7 %: the soft step's implicit spring
// lengthens the period by about (h omega)^2 / 12, far less).
BOOST_AUTO_TEST_CASE(prismatic_spring_oscillates_about_its_target_with_period_1_over_f,
                     *utf::label("DD23") * utf::label("IM6")) {
    World w(world_def(0.0));
    const BodyId ground = static_body(w);
    const BodyId slider = w.create_body(BodyDef{});
    w.create_shape(slider, box_shape(1.0, 1.0));
    PrismaticJointDef pd;
    pd.body_a = ground;
    pd.body_b = slider;
    pd.axis = {1.0, 0.0};
    const JointId j = w.create_joint(pd);
    w.set_joint_spring(j, 1.0, 0.0);
    w.enable_joint_spring(j, true);
    w.set_joint_spring_target(j, 0.5);
    BOOST_TEST(w.is_joint_spring_enabled(j));
    BOOST_TEST(w.joint_spring_hertz(j) == 1.0);
    BOOST_TEST(w.joint_spring_damping_ratio(j) == 0.0);
    BOOST_TEST(w.joint_spring_target(j) == 0.5);
    double top = 0.0, top_t = 0.0, x_before = 0.0;
    for (int k = 1; k <= 240; ++k) {
        w.step(dt);
        const double x = w.joint_translation(j);
        if (x < x_before && top_t == 0.0) { // the first turn back
            top = x_before;
            top_t = (k - 1) * dt;
        }
        x_before = x;
    }
    BOOST_TEST_REQUIRE(top_t > 0.0);
    BOOST_TEST(std::abs(top_t - 0.5) <= 2.0 * dt);
    BOOST_TEST(top == 1.0, tt::tolerance(0.02));
}

// Oracle: the torsional oscillator. A disc pinned at its centre with a revolute spring of
// f = 2 Hz (stiffness I (2 pi f)^2), target 0.3 rad, undamped: theta(t) = 0.3 (1 - cos 2 pi f
// t), first at its top, 0.6 rad, at t = 0.25 s (within two steps).
BOOST_AUTO_TEST_CASE(revolute_spring_turns_about_its_target,
                     *utf::label("DD22") * utf::label("IM6")) {
    World w(world_def(0.0));
    const BodyId pivot = static_body(w);
    const BodyId wheel = disc(w, {0.0, 0.0}, 0.5);
    RevoluteJointDef rd;
    rd.body_a = pivot;
    rd.body_b = wheel;
    const JointId j = w.create_joint(rd);
    w.set_joint_spring(j, 2.0, 0.0);
    w.enable_joint_spring(j, true);
    w.set_joint_spring_target(j, 0.3);
    double top = 0.0, top_t = 0.0, before = 0.0;
    for (int k = 1; k <= 240; ++k) {
        w.step(dt);
        const double a = w.joint_angle(j);
        if (a < before && top_t == 0.0) {
            top = before;
            top_t = (k - 1) * dt;
        }
        before = a;
    }
    BOOST_TEST_REQUIRE(top_t > 0.0);
    BOOST_TEST(std::abs(top_t - 0.25) <= 2.0 * dt);
    BOOST_TEST(top == 0.6, tt::tolerance(0.02));
}

// Oracle: T1 on each body and GD1. Two free discs (2 kg and 1 kg) 2 m apart, no gravity, joined
// by a rigid distance joint whose motor is enabled at run time (F_max = 3 N, 1 m s^-1 apart):
// each body feels F_max, so the distance grows at the rate F_max t (1 / m_A + 1 / m_B) until it
// reaches 1 m s^-1, then at 1 m s^-1; the total momentum stays zero.
BOOST_AUTO_TEST_CASE(distance_motor_drives_the_length_at_its_speed_with_at_most_its_force,
                     *utf::label("DD35") * utf::label("T1") * utf::label("GD1")) {
    World w(world_def(0.0));
    const double r = 0.5;
    const BodyId a = disc(w, {0.0, 0.0}, r, 2.0 / (pi * r * r));
    const BodyId b = disc(w, {2.0, 0.0}, r, 1.0 / (pi * r * r));
    BOOST_TEST_REQUIRE(w.mass(a) == 2.0, tt::tolerance(1e-14));
    DistanceJointDef dd;
    dd.body_a = a;
    dd.body_b = b;
    dd.anchor_a = {0.0, 0.0};
    dd.anchor_b = {2.0, 0.0};
    const JointId j = w.create_joint(dd);
    w.set_joint_max_motor_force(j, 3.0);
    w.set_joint_motor_speed(j, 1.0);
    w.enable_joint_motor(j, true);
    const int n = 40; // 3 N (1/2 + 1) = 4.5 m s^-2: 0.75 m s^-1 after 1/6 s
    for (int k = 0; k < n; ++k)
        w.step(dt);
    const double rate = w.velocity(b).x - w.velocity(a).x;
    BOOST_TEST(rate == 3.0 * (0.5 + 1.0) * n * dt, tt::tolerance(1e-9));
    BOOST_TEST(std::abs(w.linear_momentum().x) < 1e-12);
    for (int k = 0; k < 240; ++k)
        w.step(dt);
    BOOST_TEST(w.velocity(b).x - w.velocity(a).x == 1.0, tt::tolerance(1e-9));
    BOOST_TEST(std::abs(w.linear_momentum().x) < 1e-12);
    BOOST_TEST(w.joint_reaction_force(j).x == 0.0, tt::tolerance(1e-9)); // at speed: no force
}

// Oracle: DD35 with the limits' definition. A motor driving a rigid rod's length apart at
// 2 m s^-1 with a large force stops at max_length (3 m); switched off with the rod's length
// set to 2.5 m, the rod pulls the bodies back to 2.5 m.
BOOST_AUTO_TEST_CASE(distance_motor_stops_at_the_limit, *utf::label("DD35") * utf::label("DD20")) {
    World w(world_def(0.0));
    const BodyId a = static_body(w);
    const BodyId b = disc(w, {2.0, 0.0}, 0.25);
    DistanceJointDef dd;
    dd.body_a = a;
    dd.body_b = b;
    dd.anchor_a = {0.0, 0.0};
    dd.anchor_b = {2.0, 0.0};
    dd.enable_motor = true;
    dd.motor_speed = 2.0;
    dd.max_motor_force = 100.0;
    const JointId j = w.create_joint(dd);
    w.set_joint_limits(j, 0.0, 3.0);
    w.enable_joint_limit(j, true);
    for (int k = 0; k < 480; ++k)
        w.step(dt);
    BOOST_TEST(w.position(b).x == 3.0, tt::tolerance(0.002));
    w.enable_joint_motor(j, false);
    w.set_distance_joint_length(j, 2.5);
    BOOST_TEST(w.distance_joint_length(j) == 2.5);
    for (int k = 0; k < 480; ++k)
        w.step(dt);
    BOOST_TEST(w.position(b).x == 2.5, tt::tolerance(0.002));
}

// Oracle: statics. A beam 2 m x 0.2 m of mass m welded at its left end to a wall carries, at
// rest, the force m g and the torque m g d about the weld, d = 1 m (its centre's distance).
// Settled (the soft weld's start-up overshoots them by up to 6 %), it is given thresholds 1 %
// above both and holds for 2 s; given a break torque 1 % below m g d it breaks at the next
// step, and so it does with a break force 1 % below m g (each alone).
BOOST_AUTO_TEST_CASE(weld_breaks_at_the_closed_form_torque_and_force,
                     *utf::label("DD36") * utf::label("IM6")) {
    const double g = 10.0;
    const auto run = [&](double force_factor, double torque_factor) {
        World w(world_def(g));
        const BodyId wall = static_body(w);
        const BodyId beam = cantilever(w);
        const double m = w.mass(beam);
        WeldJointDef wd;
        wd.body_a = wall;
        wd.body_b = beam;
        wd.anchor = {0.0, 0.0};
        const JointId j = w.create_joint(wd);
        for (int k = 0; k < 480; ++k)
            w.step(dt);
        // At rest: the reaction equals the statics' (the oracle the thresholds rest on).
        BOOST_TEST(w.joint_reaction_torque(j) == m * g * 1.0, tt::tolerance(1e-6));
        BOOST_TEST(w.joint_reaction_force(j).y == m * g, tt::tolerance(1e-6));
        w.set_joint_break_force(j, force_factor * m * g);
        w.set_joint_break_torque(j, torque_factor * m * g * 1.0);
        BOOST_TEST(w.joint_break_force(j) == force_factor * m * g);
        BOOST_TEST(w.joint_break_torque(j) == torque_factor * m * g);
        for (int k = 1; k <= 480; ++k) {
            w.step(dt);
            if (!w.is_valid(j)) {
                BOOST_TEST(w.broken_joints().size() == 1u);
                BOOST_TEST((w.broken_joints()[0] == j));
                return k;
            }
        }
        return 0;
    };
    BOOST_TEST(run(1.01, 1.01) == 0);
    BOOST_TEST(run(1e9, 0.99) == 1);
    BOOST_TEST(run(0.99, 1e9) == 1);
}

// Oracle: DD36's rule against the statics of a braked hinge: a beam 2 m long pinned at one end
// to a wall by a revolute joint whose motor holds it still (speed 0, torque ample) carries the
// torque m g d about the pin, d = 1 m. Given in the joint's definition, a break torque of half
// that breaks it within the first steps; one of twice that holds it for 2 s.
BOOST_AUTO_TEST_CASE(a_braked_hinge_breaks_at_its_defined_torque,
                     *utf::label("DD36") * utf::label("DD22")) {
    const double g = 10.0;
    const auto run = [&](double torque_factor) {
        World w(world_def(g));
        const BodyId wall = static_body(w);
        const BodyId beam = cantilever(w);
        const double m = w.mass(beam);
        RevoluteJointDef rd;
        rd.body_a = wall;
        rd.body_b = beam;
        rd.anchor = {0.0, 0.0};
        rd.enable_motor = true;
        rd.motor_speed = 0.0;
        rd.max_motor_torque = 100.0 * m * g;
        rd.break_torque = torque_factor * m * g * 1.0;
        const JointId j = w.create_joint(rd);
        BOOST_TEST(w.joint_break_torque(j) == rd.break_torque);
        for (int k = 1; k <= 480; ++k) {
            w.step(dt);
            if (!w.is_valid(j))
                return k;
        }
        // Held: the motor carries the statics' torque (the oracle the thresholds rest on).
        BOOST_TEST(std::abs(w.joint_reaction_torque(j)) == m * g * 1.0, tt::tolerance(1e-3));
        return 0;
    };
    BOOST_TEST(run(2.0) == 0);
    const int broke = run(0.5);
    BOOST_TEST(broke >= 1);
    BOOST_TEST(broke <= 10);
}

// Oracle: the definitions' documented fields: a break threshold given in a joint's definition
// is the joint's (World::joint_break_force, joint_break_torque), for every kind that has one.
BOOST_AUTO_TEST_CASE(break_thresholds_come_from_the_definition, *utf::label("reliability")) {
    World w(world_def(10.0));
    const BodyId a = static_body(w);
    const BodyId b = disc(w, {1.0, 0.0}, 0.25);
    const auto check = [&](auto def, const char* kind) {
        def.body_a = a;
        def.body_b = b;
        def.break_force = 123.0;
        if constexpr (requires { def.break_torque; })
            def.break_torque = 45.0;
        const JointId j = w.create_joint(def);
        BOOST_TEST(w.joint_break_force(j) == 123.0, kind);
        if constexpr (requires { def.break_torque; })
            BOOST_TEST(w.joint_break_torque(j) == 45.0, kind);
    };
    check(RevoluteJointDef{}, "revolute");
    check(DistanceJointDef{.length = 1.0}, "distance");
    check(PrismaticJointDef{}, "prismatic");
    check(WeldJointDef{}, "weld");
    check(WheelJointDef{}, "wheel");
    check(MotorJointDef{}, "motor");
}

// Oracle: the static deflection of a spring, x = m g / k with k = m (2 pi f)^2: a disc hanging
// from a pin at its centre, the pin's soft bias tuned to f = 3 Hz (critically damped), settles
// g / (2 pi f)^2 = 28 mm below the pin, where the world's 60 Hz would leave 0.07 mm. (IM6's
// relax removes the bias's velocity each substep, so the pin creeps to its deflection, with a
// time constant of about 2.6 s here: 40 s is over 15 of them.)
BOOST_AUTO_TEST_CASE(a_joints_own_tuning_sags_as_its_spring,
                     *utf::label("DD37") * utf::label("IM6")) {
    const double g = 10.0, f = 3.0;
    World w(world_def(g));
    const BodyId pivot = static_body(w);
    const BodyId bob = disc(w, {0.0, 0.0}, 0.25);
    RevoluteJointDef rd;
    rd.body_a = pivot;
    rd.body_b = bob;
    const JointId j = w.create_joint(rd);
    BOOST_TEST((w.constraint_tuning(j) == ConstraintTuning{60.0, 2.0}));
    w.set_constraint_tuning(j, f, 1.0);
    BOOST_TEST((w.constraint_tuning(j) == ConstraintTuning{f, 1.0}));
    for (int k = 0; k < 40 * 240; ++k)
        w.step(dt);
    const double sag = g / ((2.0 * pi * f) * (2.0 * pi * f));
    BOOST_TEST(-w.position(bob).y == sag, tt::tolerance(1e-4));
}

// Oracle: DD37's definition: a joint tuned to the world's own values is solved with the same
// coefficients, so a chain of three such links moves bit for bit as the untuned chain.
BOOST_AUTO_TEST_CASE(tuning_to_the_worlds_values_changes_no_bit, *utf::label("DD37")) {
    std::vector<std::vector<double>> states;
    for (const bool tuned : {false, true}) {
        World w(world_def(9.81));
        BodyId prev = static_body(w);
        std::vector<BodyId> links;
        for (int i = 0; i < 3; ++i) {
            BodyDef bd;
            bd.position = {0.5 + i, 0.0};
            const BodyId link = w.create_body(bd);
            w.create_shape(link, box_shape(1.0, 0.1));
            RevoluteJointDef rd;
            rd.body_a = prev;
            rd.body_b = link;
            rd.anchor = {double(i), 0.0};
            const JointId j = w.create_joint(rd);
            if (tuned)
                w.set_constraint_tuning(j, w.settings().joint_hertz,
                                        w.settings().joint_damping_ratio);
            links.push_back(link);
            prev = link;
        }
        for (int k = 0; k < 240; ++k)
            w.step(dt);
        std::vector<double> s;
        for (const BodyId b : links)
            for (const double v : {w.position(b).x, w.position(b).y, w.orientation(b),
                                   w.velocity(b).x, w.velocity(b).y, w.angular_velocity(b)})
                s.push_back(v);
        states.push_back(s);
    }
    BOOST_TEST(states[0] == states[1], tt::per_element());
}

// Oracle: DD27's joint filter as each kind's definition sets it: two unit boxes overlapping by
// half their width (no gravity), joined by a joint of each kind that has the field, touch
// after a step exactly when the definition says collide_connected, and the joint reads it back.
BOOST_AUTO_TEST_CASE(each_kinds_definition_sets_whether_its_bodies_collide, *utf::label("DD27")) {
    for (const bool collide : {false, true}) {
        for (int kind = 0; kind < 6; ++kind) {
            BOOST_TEST_CONTEXT("kind " << kind << ", collide_connected " << collide) {
                World w(world_def(0.0));
                BodyDef bd;
                const BodyId a = w.create_body(bd);
                bd.position = {0.5, 0.0};
                const BodyId b = w.create_body(bd);
                w.create_shape(a, box_shape(1.0, 1.0));
                w.create_shape(b, box_shape(1.0, 1.0));
                const Vec2d at{0.25, 0.0};
                JointId j;
                switch (kind) {
                case 0:
                    j = w.create_joint(RevoluteJointDef{
                        .body_a = a, .body_b = b, .anchor = at, .collide_connected = collide});
                    break;
                case 1:
                    j = w.create_joint(DistanceJointDef{.body_a = a,
                                                        .body_b = b,
                                                        .anchor_a = {0.0, 0.0},
                                                        .anchor_b = {0.5, 0.0},
                                                        .collide_connected = collide});
                    break;
                case 2:
                    j = w.create_joint(PrismaticJointDef{
                        .body_a = a, .body_b = b, .anchor = at, .collide_connected = collide});
                    break;
                case 3:
                    j = w.create_joint(WeldJointDef{
                        .body_a = a, .body_b = b, .anchor = at, .collide_connected = collide});
                    break;
                case 4:
                    j = w.create_joint(WheelJointDef{
                        .body_a = a, .body_b = b, .anchor = at, .collide_connected = collide});
                    break;
                default:
                    j = w.create_joint(MotorJointDef{.body_a = a,
                                                     .body_b = b,
                                                     .linear_offset = {0.5, 0.0},
                                                     .collide_connected = collide});
                    break;
                }
                BOOST_TEST(w.joint_collide_connected(j) == collide);
                w.step(dt);
                BOOST_TEST(w.contacts().size() == (collide ? 1u : 0u));
            }
        }
    }
}

// Oracle: free fall (IM1) and DD27's joint filter. A box on a vertical prismatic joint above a
// static floor, not colliding with it (collide_connected false) falls through it freely; a
// second one, switched to collide at run time, lands and rests on it; switched back while
// resting, its contact ends at once and it falls again.
BOOST_AUTO_TEST_CASE(collide_connected_switches_the_pair, *utf::label("DD27") * utf::label("IM1")) {
    World w(world_def(10.0));
    const BodyId floor = static_body(w, {0.0, -0.5});
    w.create_shape(floor, box_shape(10.0, 1.0));
    BodyId boxes[2];
    JointId joints[2];
    for (int i = 0; i < 2; ++i) {
        BodyDef bd;
        bd.position = {-2.0 + 4.0 * i, 1.0};
        boxes[i] = w.create_body(bd);
        w.create_shape(boxes[i], box_shape(0.5, 0.5));
        PrismaticJointDef pd;
        pd.body_a = floor;
        pd.body_b = boxes[i];
        pd.anchor = bd.position;
        pd.axis = {0.0, 1.0};
        joints[i] = w.create_joint(pd);
    }
    w.set_joint_collide_connected(joints[1], true);
    BOOST_TEST(w.joint_collide_connected(joints[1]));
    BOOST_TEST(!w.joint_collide_connected(joints[0]));
    bool landed = false;
    for (int k = 0; k < 480; ++k) {
        w.step(dt);
        landed = landed || began(w, floor, boxes[1]);
    }
    BOOST_TEST(landed);
    BOOST_TEST(w.position(boxes[0]).y < -10.0); // through the floor: 1 - 5 t^2 at t = 2 s
    BOOST_TEST(w.position(boxes[1]).y == 0.25, tt::tolerance(0.01));
    w.set_joint_collide_connected(joints[1], false);
    bool ended = false;
    for (const ContactEvent& e : w.contact_end_events())
        ended = ended || e.body_a == boxes[1] || e.body_b == boxes[1];
    BOOST_TEST(ended);
    const double y0 = w.position(boxes[1]).y;
    w.set_velocity(boxes[1], {0.0, 0.0});
    const int n = 24;
    for (int k = 0; k < n; ++k)
        w.step(dt);
    BOOST_TEST(w.velocity(boxes[1]).y == -10.0 * n * dt, tt::tolerance(1e-6));
    BOOST_TEST(w.position(boxes[1]).y < y0 - 0.05);
}

// Oracle: DD27's joint filter: a joint whose bodies do not collide ends the contacts between
// them when it is made, and no other. Two boxes rest side by side on a static floor, touching:
// each touches the floor (the floor made first, so it is each pair's first body) and the other.
// Welded, the pair's contact ends (one end event) and both keep their floor's.
BOOST_AUTO_TEST_CASE(a_joint_ends_the_contacts_between_its_bodies_only, *utf::label("DD27")) {
    World w(world_def(10.0));
    const BodyId floor = static_body(w, {0.0, -0.5});
    w.create_shape(floor, box_shape(10.0, 1.0));
    BodyId boxes[2];
    for (int i = 0; i < 2; ++i) {
        BodyDef bd;
        bd.position = {1.0 * i, 0.5};
        boxes[i] = w.create_body(bd);
        w.create_shape(boxes[i], box_shape(1.0, 1.0));
    }
    for (int k = 0; k < 30; ++k)
        w.step(dt);
    const auto touches = [&](BodyId b, BodyId other) {
        for (const ContactInfo& c : w.contacts(b))
            if (c.body_a == other || c.body_b == other)
                return true;
        return false;
    };
    BOOST_TEST_REQUIRE(touches(boxes[0], boxes[1]));
    WeldJointDef weld;
    weld.body_a = boxes[0];
    weld.body_b = boxes[1];
    weld.anchor = {0.5, 0.5};
    w.create_joint(weld);
    BOOST_TEST(!touches(boxes[0], boxes[1]));
    BOOST_TEST(touches(boxes[0], floor));
    BOOST_TEST(touches(boxes[1], floor));
    BOOST_TEST_REQUIRE(w.contact_end_events().size() == 1u);
    const ContactEvent& e = w.contact_end_events()[0];
    BOOST_TEST(((e.body_a == boxes[0] && e.body_b == boxes[1]) ||
                (e.body_a == boxes[1] && e.body_b == boxes[0])));
}

// Oracle: DD27's joint filter and DD20's rigid rod. A box rests on a static floor, held by a
// horizontal 1 m distance rod to an anchor on the floor's body. Made with collide_connected (in
// its definition) the pair collides: the box stays on the floor, touching it. Made without, the
// floor does not hold it: it swings down through the floor as a pendulum, to 1 m below its
// start. Either way the rod
// keeps its length (DD20: the anchors' distance, within a millimetre).
BOOST_AUTO_TEST_CASE(a_distance_rod_made_to_collide_connected_keeps_its_box_on_the_floor,
                     *utf::label("DD27") * utf::label("DD20")) {
    for (const bool collide : {true, false}) {
        BOOST_TEST_CONTEXT("collide_connected " << collide) {
            World w(world_def(10.0));
            const BodyId floor = static_body(w, {0.0, -0.5});
            w.create_shape(floor, box_shape(10.0, 1.0));
            BodyDef bd;
            bd.position = {0.0, 0.25};
            const BodyId box = w.create_body(bd);
            w.create_shape(box, box_shape(0.5, 0.5));
            DistanceJointDef dd;
            dd.body_a = floor;
            dd.body_b = box;
            dd.anchor_a = {-1.0, 0.25};
            dd.anchor_b = bd.position;
            dd.collide_connected = collide;
            const JointId rod = w.create_joint(dd);
            BOOST_TEST(w.joint_collide_connected(rod) == collide);
            bool touching = false;
            double lowest = w.position(box).y;
            for (int k = 0; k < 240; ++k) { // 1 s
                w.step(dt);
                lowest = std::min(lowest, w.position(box).y);
                touching = false;
                for (const ContactInfo& c : w.contacts())
                    touching = touching || c.body_a == box || c.body_b == box;
                const Vec2d d = w.position(box) - Vec2d{-1.0, 0.25};
                BOOST_TEST_REQUIRE(std::abs(std::hypot(d.x, d.y) - 1.0) < 1e-3);
            }
            BOOST_TEST(touching == collide);
            if (collide)
                BOOST_TEST(w.position(box).y == 0.25, tt::tolerance(0.01));
            else
                BOOST_TEST(lowest < -0.7); // the pendulum's bottom: 0.25 - 1 m
        }
    }
}

// Oracle: DD23's translation s = a . (p_B + r_B - p_A - r_A) and uniform motion (IM1, no
// force): a box on a prismatic joint along x, anchored 0.5 m off its centre (and off the
// static body's origin), is set sliding at 1.5 m/s: after t its anchors are 1.5 t apart along
// the axis, so the joint reads s = 1.5 t, at every step (to round-off). The same with body A a
// free dynamic carriage whose centre of mass lies off its origin (a box centred at (0.7, 0.4)
// in its frame): sliding along the axis, the box pulls on nothing, so A stays where it is.
BOOST_AUTO_TEST_CASE(joint_translation_reads_the_slide_of_an_anchor_off_the_centre,
                     *utf::label("DD23")) {
    for (const bool carriage : {false, true}) {
        BOOST_TEST_CONTEXT((carriage ? "a dynamic carriage" : "a static body")) {
            World w(world_def(0.0));
            BodyId a;
            if (carriage) {
                a = w.create_body(BodyDef{.position = {-3.0, 0.0}});
                w.create_shape(a, box_shape(1.0, 1.0, {}, {0.7, 0.4}));
            } else {
                a = static_body(w, {-3.0, 0.0});
            }
            const BodyId slider = w.create_body(BodyDef{.position = {1.0, 0.0}});
            w.create_shape(slider, box_shape(2.0, 0.5));
            PrismaticJointDef pd;
            pd.body_a = a;
            pd.body_b = slider;
            pd.anchor = {1.5, 0.0};
            pd.axis = {1.0, 0.0};
            const JointId j = w.create_joint(pd);
            BOOST_TEST(std::abs(w.joint_translation(j)) <= 1e-15);
            w.set_velocity(slider, {1.5, 0.0});
            for (int k = 1; k <= 120; ++k) {
                w.step(dt);
                BOOST_TEST_REQUIRE(w.joint_translation(j) == 1.5 * k * dt, tt::tolerance(1e-9));
            }
        }
    }
}

// Oracle: the definitions the joints were made from: each joint's kind and bodies read back.
BOOST_AUTO_TEST_CASE(kind_and_bodies_read_back, *utf::label("reliability")) {
    World w(world_def(10.0));
    const BodyId a = static_body(w);
    const BodyId b = disc(w, {1.0, 0.0}, 0.25);
    RevoluteJointDef rd;
    rd.body_a = a;
    rd.body_b = b;
    const JointId r = w.create_joint(rd);
    TargetJointDef td;
    td.body = b;
    const JointId t = w.create_joint(td);
    const BodyId c = disc(w, {3.0, 0.0}, 0.25);
    FilterJointDef fd; // of two bodies past the first: a body left unset would read as body 0
    fd.body_a = b;
    fd.body_b = c;
    const JointId f = w.create_joint(fd);
    BOOST_TEST((w.joint_kind(r) == JointKind::revolute));
    BOOST_TEST((w.joint_kind(t) == JointKind::target));
    BOOST_TEST((w.joint_kind(f) == JointKind::filter));
    BOOST_TEST((w.joint_body_a(r) == a));
    BOOST_TEST((w.joint_body_b(r) == b));
    BOOST_TEST((w.joint_body_a(t) == b));
    BOOST_TEST((w.joint_body_b(t) == b));
    BOOST_TEST((w.joint_body_a(f) == b));
    BOOST_TEST((w.joint_body_b(f) == c));
}

BOOST_AUTO_TEST_SUITE_END()
