// What every joint kind shares, in the engine (IM6, LC3, DD27): breaking above the break force
// (the closed-form tension of a pendulum's pin), DD27's rule that bodies a joint keeps apart do
// not collide unless asked and collide again once the joint is gone, and Newton's first law at
// rest for every kind. Each kind's own cases are in this folder's test_<kind>_joint.cpp.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <numbers>

#include "system/joints/pendulum.hpp"
#include "system/system_support.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;
using namespace tamias2d::system_test;
using namespace tamias2d::system_test::pendulum;

BOOST_AUTO_TEST_SUITE(joints)

// Oracle: closed form: the tension at the bottom of the swing (as in test_revolute_joint.cpp),
// m g (1 + 2 (1 - cos theta0) m l^2 / I_p). A joint whose break force is below it breaks on the
// way down (and is listed, and gone); one above it holds for a whole period.
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

// Oracle: DD27's rule, "bodies a joint keeps apart never collide": two overlapping boxes touch
// until a joint without collide_connected joins them, then never; with collide_connected they
// still do. A second overlapping pair, joined by nothing, keeps its contact throughout (the
// joint removes its own pair's contacts only, wherever they sit in the contact list, and
// whichever of the pair it names first).
BOOST_AUTO_TEST_CASE(connected_bodies_collide_only_when_asked, *utf::label("DD27")) {
    for (const bool collide : {false, true}) {
        for (const int layout : {0, 1, 2}) {
            const bool pair_first = layout != 0, reversed = layout == 2;
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
            world.create_joint(RevoluteJointDef{.body_a = reversed ? b : a,
                                                .body_b = reversed ? a : b,
                                                .anchor = {0.25, 0.0},
                                                .collide_connected = collide});
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
// poses exactly as created, and the reported reaction (force, and DD22's torque) exactly 0. A
// joint's rows start from no impulse (a new joint has nothing to warm-start). Every kind: the
// last three (a rod at its length, a target at its grabbed point, a filter) have no angular
// part at all.
BOOST_AUTO_TEST_CASE(joints_at_rest_without_load_stay_exactly_at_rest,
                     *utf::label("IM6") * utf::label("DD22")) {
    for (int kind = 0; kind < 11; ++kind) {
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
        case 8:
            j = world.create_joint(DistanceJointDef{
                .body_a = a, .body_b = b, .anchor_a = mid, .anchor_b = {1.5, 0.0}});
            break;
        case 9:
            j = world.create_joint(TargetJointDef{.body = b, .target = {2.0, 0.25}});
            break;
        case 10:
            j = world.create_joint(FilterJointDef{.body_a = a, .body_b = b});
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

BOOST_AUTO_TEST_SUITE_END()
