// Motor joints (LC3: DD26, IM6) in the engine, against independent oracles: T1 and T4 with the
// joint's force and torque limits (exact per substep while a limit is reached), and the target
// pose itself, which the driven body must reach and hold.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <numbers>
#include <vector>

#include "system/system_support.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;
using namespace tamias2d::system_test;

BOOST_AUTO_TEST_SUITE(motor_joint)

// Oracle: T1 and T4 at the limits. A box at rest, no gravity, driven towards an offset 5 m
// away and 2 rad turned with at most F and tau: while the limits hold it is pushed with exactly
// F and turned with exactly tau, so after n substeps of h its displacement is F h^2 n (n + 1)
// / (2 m) and its spin tau n h / I.
BOOST_AUTO_TEST_CASE(drives_with_its_force_and_torque_limits,
                     *utf::label("DD26") * utf::label("IM6") * utf::label("LC3")) {
    World world(WorldDef{.gravity = {0.0, 0.0}, .enable_sleep = false});
    BodyDef ground_def;
    ground_def.type = BodyType::static_body;
    const BodyId ground = world.create_body(ground_def);
    const BodyId box = world.create_body(BodyDef{});
    world.create_shape(box, box_shape(0.5, 0.5));
    const double m = world.mass(box), I = world.inertia(box), F = 2.0 * m, tau = 0.5 * I;
    const JointId j = world.create_joint(MotorJointDef{.body_a = ground,
                                                       .body_b = box,
                                                       .linear_offset = {5.0, 0.0},
                                                       .angular_offset = 2.0,
                                                       .max_force = F,
                                                       .max_torque = tau});
    const int substeps = WorldDef{}.substeps;
    const double dt = 1.0 / 60.0, h = dt / substeps;
    for (int k = 1; k <= 20; ++k) {
        world.step(dt);
        const double n = double(k * substeps);
        BOOST_TEST_REQUIRE(world.position(box).x == F * h * h * n * (n + 1.0) / (2.0 * m),
                           boost::test_tools::tolerance(1e-9));
        BOOST_TEST_REQUIRE(std::abs(world.position(box).y) <= 1e-12);
        BOOST_TEST_REQUIRE(world.angular_velocity(box) == tau * n * h / I,
                           boost::test_tools::tolerance(1e-9));
        BOOST_TEST_REQUIRE(world.joint_reaction_force(j).x == F,
                           boost::test_tools::tolerance(1e-9));
        BOOST_TEST_REQUIRE(world.joint_reaction_torque(j) == tau,
                           boost::test_tools::tolerance(1e-9));
    }
}

// Oracle: closed form of the target pose's approach. With limits that do not bind, each substep
// asks for the velocity that removes the share c of the pose error, so the error decays
// geometrically, as (1 - c) per substep: after 1 s (240 substeps, c = 0.3) the box sits on the
// target pose to 1e-9, whatever pose the reference body has (here moved and turned).
BOOST_AUTO_TEST_CASE(settles_on_the_target_pose,
                     *utf::label("DD26") * utf::label("IM6") * utf::label("LC3")) {
    World world(WorldDef{.gravity = {0.0, 0.0}, .enable_sleep = false});
    BodyDef base_def;
    base_def.type = BodyType::static_body;
    base_def.position = {1.0, -2.0};
    base_def.angle = 0.5;
    const BodyId base = world.create_body(base_def);
    const BodyId box = world.create_body(BodyDef{});
    world.create_shape(box, box_shape(0.5, 0.5));
    const Vec2d offset{3.0, 1.0};
    world.create_joint(MotorJointDef{.body_a = base,
                                     .body_b = box,
                                     .linear_offset = offset,
                                     .angular_offset = -1.0,
                                     .max_force = 1e6,
                                     .max_torque = 1e6});
    for (int k = 0; k < 60; ++k)
        world.step(1.0 / 60.0);
    const Vec2d target{1.0 + std::cos(0.5) * offset.x - std::sin(0.5) * offset.y,
                       -2.0 + std::sin(0.5) * offset.x + std::cos(0.5) * offset.y};
    // The orientation is read wrapped to [0, 2 pi): its error is taken modulo a turn.
    const double turn_error =
        std::remainder(world.orientation(box) - (0.5 - 1.0), 2.0 * std::numbers::pi);
    BOOST_TEST_MESSAGE("motor joint: pose error " << norm(world.position(box) - target) << " m, "
                                                  << turn_error << " rad");
    BOOST_TEST(norm(world.position(box) - target) <= 1e-9);
    BOOST_TEST(std::abs(turn_error) <= 1e-9);
}

// Oracle: the target pose, as above, with a reference body that moves, and momentum. Two equal
// free boxes at rest, no gravity, the second driven to (3, 1) in the first's frame at the same
// angle, with limits that do not bind: the joint's impulses are equal and opposite, so the
// pair's centre of mass stays where it was (T1: no external force), while the second box
// reaches its target pose relative to the first, which recoils. The joint's force couple sets
// the pair turning, and a turning reference leaves the soft correction a steady lag: the pose
// is held within 1 mm and 1 mrad, not to round-off.
BOOST_AUTO_TEST_CASE(settles_on_the_target_pose_of_a_moving_reference,
                     *utf::label("DD26") * utf::label("IM6")) {
    World world(WorldDef{.gravity = {0.0, 0.0}, .enable_sleep = false});
    const BodyId a = world.create_body(BodyDef{});
    world.create_shape(a, box_shape(0.5, 0.5));
    const BodyId b = world.create_body(BodyDef{.position = {0.5, 0.0}});
    world.create_shape(b, box_shape(0.5, 0.5));
    const Vec2d offset{3.0, 1.0};
    world.create_joint(MotorJointDef{
        .body_a = a, .body_b = b, .linear_offset = offset, .max_force = 1e6, .max_torque = 1e6});
    const auto middle = [&] { return 0.5 * (world.position(a) + world.position(b)); };
    const Vec2d start = middle();
    for (int k = 0; k < 360; ++k)
        world.step(1.0 / 60.0);
    const double turn = world.orientation(a);
    const Vec2d d = world.position(b) - world.position(a);
    const Vec2d in_a{std::cos(turn) * d.x + std::sin(turn) * d.y,
                     -std::sin(turn) * d.x + std::cos(turn) * d.y};
    BOOST_TEST_MESSAGE("moving reference: pose error " << norm(in_a - offset) << " m, turned "
                                                       << turn << " rad");
    BOOST_TEST(norm(world.position(a) - Vec2d{}) > 0.1); // the reference recoiled
    BOOST_TEST(norm(in_a - offset) <= 1e-3);
    BOOST_TEST(std::abs(std::remainder(world.orientation(b) - turn, 2.0 * std::numbers::pi)) <=
               1e-3);
    BOOST_TEST(norm(middle() - start) <= 1e-9);
}

// Oracle: DD26 with F_max = tau_max = 0 (DD21's bound F_max h = 0): the joint never pushes or
// turns, so its bodies move as free bodies do: bit for bit as in a twin world without the joint
// (the same bodies in the same order), and the joint reports no reaction. One pair starts on its
// target pose at rest (a zero impulse against a zero bound), the other off it and moving.
BOOST_AUTO_TEST_CASE(a_motor_without_force_or_torque_leaves_its_bodies_free,
                     *utf::label("DD26") * utf::label("DD21") * utf::label("LC3")) {
    struct Pair {
        Vec2d offset, velocity_b;
        double omega_b;
    };
    for (const Pair& pair :
         {Pair{{2.0, 0.0}, {0.0, 0.0}, 0.0}, Pair{{3.0, 1.0}, {-1.0, 2.0}, 1.5}}) {
        World joined(WorldDef{.enable_sleep = false}), free(WorldDef{.enable_sleep = false});
        std::vector<BodyId> bodies[2];
        for (World* w : {&joined, &free}) {
            const BodyId a = w->create_body(BodyDef{});
            w->create_shape(a, box_shape(0.5, 0.5));
            const BodyId b = w->create_body(BodyDef{.position = {2.0, 0.0}});
            w->create_shape(b, box_shape(0.5, 0.5));
            w->set_velocity(b, pair.velocity_b);
            w->set_angular_velocity(b, pair.omega_b);
            bodies[w == &free].assign({a, b});
        }
        const JointId j = joined.create_joint(MotorJointDef{.body_a = bodies[0][0],
                                                            .body_b = bodies[0][1],
                                                            .linear_offset = pair.offset,
                                                            .max_force = 0.0,
                                                            .max_torque = 0.0});
        for (int k = 0; k < 60; ++k) {
            joined.step(1.0 / 60.0);
            free.step(1.0 / 60.0);
        }
        for (int i = 0; i < 2; ++i) {
            const BodyState s = joined.state(bodies[0][i]), t = free.state(bodies[1][i]);
            BOOST_TEST(s.position.x == t.position.x);
            BOOST_TEST(s.position.y == t.position.y);
            BOOST_TEST(s.velocity.x == t.velocity.x);
            BOOST_TEST(s.velocity.y == t.velocity.y);
            BOOST_TEST(s.orientation == t.orientation);
            BOOST_TEST(s.angular_velocity == t.angular_velocity);
        }
        BOOST_TEST(joined.joint_reaction_force(j).x == 0.0);
        BOOST_TEST(joined.joint_reaction_force(j).y == 0.0);
        BOOST_TEST(joined.joint_reaction_torque(j) == 0.0);
    }
}

BOOST_AUTO_TEST_SUITE_END()
