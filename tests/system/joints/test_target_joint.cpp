// Target joints (DD21, IM6, LC3) in the engine, against independent oracles: the critically
// damped oscillator, and Newton's second law (T1) under the joint's force limit.
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "system/system_support.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;
using namespace tamias2d::system_test;

BOOST_AUTO_TEST_SUITE(joints)

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

// Oracle: the critically damped oscillator, about a target given at creation. A free disc at
// (2, 1), grabbed at its centre by a target joint whose definition puts the target there, is
// set moving at v0 = 5 m/s along x: x - 2 = v0 t e^(-omega t), which peaks at v0 / (omega e)
// when t = 1 / omega and has died out after 2 s. The disc swings out that far (within 10 %) and
// comes back to (2, 1) (within a millimetre); y never moves.
BOOST_AUTO_TEST_CASE(target_joint_holds_the_target_of_its_definition,
                     *utf::label("DD21") * utf::label("IM6")) {
    const double f = 3.0, w = 2.0 * std::numbers::pi * f, v0 = 5.0;
    World world(WorldDef{.gravity = {0.0, 0.0}});
    BodyDef def;
    def.position = {2.0, 1.0};
    const BodyId disc = world.create_body(def);
    world.create_shape(disc, circle_shape(0.25));
    world.create_joint(TargetJointDef{.body = disc,
                                      .target = {2.0, 1.0},
                                      .hertz = f,
                                      .damping_ratio = 1.0,
                                      .max_force = INFINITY});
    world.set_velocity(disc, {v0, 0.0});
    double peak = 0.0;
    for (int k = 1; k <= 960; ++k) { // 2 s
        world.step(1.0 / 480.0);
        peak = std::max(peak, world.position(disc).x - 2.0);
        BOOST_TEST_REQUIRE(std::abs(world.position(disc).y - 1.0) <= 1e-9);
    }
    BOOST_TEST(peak == v0 / (w * std::numbers::e), boost::test_tools::tolerance(0.1));
    BOOST_TEST(std::abs(world.position(disc).x - 2.0) <= 1e-3);
}

// Oracle: the soft step's definition (LC3; Catto, "Soft Step", 2024): a step of n substeps of
// h = dt / n is n steps of one substep of h, each substep seeing the positions the ones before
// it moved to, the joint's impulse carried from substep to substep as from step to step (warm
// starting). A disc dragged by a target joint over 1 s at 1/60 s with 4 substeps is where the
// same disc is after every 4th step at 1/240 s with 1 substep, to 1e-12 m (the positions sum
// their substeps' moves in another order).
BOOST_AUTO_TEST_CASE(a_targets_substeps_are_steps_of_one_substep,
                     *utf::label("DD21") * utf::label("IM6") * utf::label("LC3")) {
    const auto run = [](int substeps, double dt, int steps, int every) {
        World world(WorldDef{.gravity = {0.0, 0.0}, .substeps = substeps});
        const BodyId disc = world.create_body(BodyDef{});
        world.create_shape(disc, circle_shape(0.25));
        const JointId j = world.create_joint(TargetJointDef{
            .body = disc, .hertz = 3.0, .damping_ratio = 0.7, .max_force = INFINITY});
        world.set_joint_target(j, {1.0, 0.5});
        std::vector<Vec2d> at;
        for (int k = 1; k <= steps; ++k) {
            world.step(dt);
            if (k % every == 0)
                at.push_back(world.position(disc));
        }
        return at;
    };
    const std::vector<Vec2d> substepped = run(4, 1.0 / 60.0, 60, 1);
    const std::vector<Vec2d> stepped = run(1, 1.0 / 240.0, 240, 4);
    BOOST_TEST_REQUIRE(substepped.size() == stepped.size());
    for (std::size_t k = 0; k < stepped.size(); ++k) {
        BOOST_TEST_CONTEXT("step " << k + 1) {
            BOOST_TEST(std::abs(substepped[k].x - stepped[k].x) <= 1e-12);
            BOOST_TEST(std::abs(substepped[k].y - stepped[k].y) <= 1e-12);
        }
    }
    BOOST_TEST(stepped.back().x > 0.9); // it moved most of the way to the target
}

// Oracle: T1 at equilibrium. A free disc at (2, 1), grabbed on its rim at (2.25, 1) by a target
// joint whose target is that same point, feels no force (the grabbed point is on the target),
// so it stays where it is: after 1 s its centre is at (2, 1) and its angle 0, to 1e-9. Grabbed
// at its centre instead, the same target would pull it 0.25 m to the right.
BOOST_AUTO_TEST_CASE(a_body_grabbed_off_its_centre_stays_where_it_is,
                     *utf::label("DD21") * utf::label("IM6")) {
    World world(WorldDef{.gravity = {0.0, 0.0}});
    const BodyId disc = world.create_body(BodyDef{.position = {2.0, 1.0}});
    world.create_shape(disc, circle_shape(0.25));
    world.create_joint(TargetJointDef{.body = disc, .target = {2.25, 1.0}, .hertz = 3.0});
    for (int k = 1; k <= 60; ++k)
        world.step(1.0 / 60.0);
    BOOST_TEST(std::abs(world.position(disc).x - 2.0) <= 1e-9);
    BOOST_TEST(std::abs(world.position(disc).y - 1.0) <= 1e-9);
    BOOST_TEST(std::abs(std::remainder(world.orientation(disc), 2.0 * std::numbers::pi)) <= 1e-9);
}

BOOST_AUTO_TEST_SUITE_END()
