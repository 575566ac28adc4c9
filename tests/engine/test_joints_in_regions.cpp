// DD19, GD1: revolute joints solved in regions (WorldDef::contact_regions, which JointStreams
// applies to the joints once a world has JointStreams::min_joints of them) on one worker. Which
// threads run the streams is tests/reliability's; here the split itself is stepped.
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include "tamias2d/dynamics/joints/joint_streams.hpp"
#include "tamias2d/math/vec2d.hpp"
#include "tamias2d/world.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;

namespace {

constexpr int links = int(JointStreams::min_joints) + 44; // 299 joints: the split applies

/// A free chain in zero gravity: `links` unit boxes in a row along x, each held to the next by
/// a revolute joint at their common edge; no static body, so that nothing outside the chain
/// pushes it.
std::vector<BodyId> free_chain(World& world) {
    std::vector<BodyId> ids;
    for (int k = 0; k < links; ++k) {
        BodyDef def;
        def.position = {0.5 + k, 0.0};
        ids.push_back(world.create_body(def));
        world.create_shape(ids.back(), box_shape(1.0, 0.25, Material{1.0, 0.0, 0.6}));
        if (k > 0)
            world.create_joint(RevoluteJointDef{
                .body_a = ids[k - 1], .body_b = ids[k], .anchor = {double(k), 0.0}});
    }
    return ids;
}

Vec2d momentum(const World& world, const std::vector<BodyId>& ids) {
    Vec2d p{0.0, 0.0};
    for (const BodyId b : ids)
        p += world.mass(b) * world.velocity(b);
    return p;
}

} // namespace

BOOST_AUTO_TEST_SUITE(joints_in_regions)

// Oracle: GD1, conservation of momentum. The chain's joints push its links in equal and opposite
// pairs, so whatever the order the streams solve them in, the chain's total momentum stays its
// initial value to rounding: 1e-12 of the momenta's magnitudes summed. The links start with
// different velocities, so every joint acts from the first step.
BOOST_AUTO_TEST_CASE(a_free_chain_in_regions_keeps_its_momentum,
                     *utf::label("DD19") * utf::label("GD1")) {
    for (const int regions : {1, 2, 4, 8}) {
        BOOST_TEST_CONTEXT("contact_regions = " << regions) {
            World world(WorldDef{.gravity = {0.0, 0.0}, .contact_regions = regions});
            const std::vector<BodyId> ids = free_chain(world);
            double scale = 0.0;
            for (int k = 0; k < links; ++k) {
                world.set_velocity(ids[k], {0.3 * std::sin(0.7 * k), 0.5 * std::cos(1.3 * k)});
                world.set_angular_velocity(ids[k], 0.2 * std::sin(2.1 * k));
                scale += world.mass(ids[k]) * length(world.velocity(ids[k]));
            }
            const Vec2d p0 = momentum(world, ids);
            for (int i = 0; i < 120; ++i)
                world.step(1.0 / 60.0);
            const Vec2d p = momentum(world, ids);
            BOOST_TEST_MESSAGE(regions << " regions: momentum change " << length(p - p0)
                                       << " kg m/s of " << scale);
            BOOST_TEST(length(p - p0) <= 1e-12 * scale);
        }
    }
}

// Oracle: GD1, as above, after the chain loses its last 100 links (their joints go with them):
// its 198 joints are then fewer than the split takes (JointStreams::min_joints), so the step
// solves them unsplit, and the chain that is left keeps its momentum from then on.
BOOST_AUTO_TEST_CASE(a_chain_cut_below_the_split_keeps_its_momentum,
                     *utf::label("DD19") * utf::label("GD1")) {
    World world(WorldDef{.gravity = {0.0, 0.0}, .contact_regions = 2});
    std::vector<BodyId> ids = free_chain(world);
    for (int k = 0; k < links; ++k)
        world.set_velocity(ids[k], {0.3 * std::sin(0.7 * k), 0.5 * std::cos(1.3 * k)});
    for (int i = 0; i < 10; ++i)
        world.step(1.0 / 60.0);
    for (int k = 0; k < 100; ++k) {
        world.destroy_body(ids.back());
        ids.pop_back();
    }
    BOOST_TEST_REQUIRE(world.joint_count() < JointStreams::min_joints);
    double scale = 0.0;
    for (const BodyId b : ids)
        scale += world.mass(b) * length(world.velocity(b));
    const Vec2d p0 = momentum(world, ids);
    for (int i = 0; i < 60; ++i)
        world.step(1.0 / 60.0);
    BOOST_TEST(length(momentum(world, ids) - p0) <= 1e-12 * scale);
}

// Oracle: Newton's first law (TM1) for the chain as one body: every link starts with one
// velocity, the joints then hold nothing apart and push nothing, and after 2 s every link is
// where it started plus v t, to rounding (1e-9 m over the 150 m span).
BOOST_AUTO_TEST_CASE(a_free_chain_in_regions_moving_as_one_keeps_its_shape, *utf::label("DD19")) {
    const Vec2d v{1.5, -0.75};
    for (const int regions : {2, 4}) {
        BOOST_TEST_CONTEXT("contact_regions = " << regions) {
            World world(WorldDef{.gravity = {0.0, 0.0}, .contact_regions = regions});
            const std::vector<BodyId> ids = free_chain(world);
            for (const BodyId b : ids)
                world.set_velocity(b, v);
            for (int i = 0; i < 120; ++i)
                world.step(1.0 / 60.0);
            double worst = 0.0;
            for (int k = 0; k < links; ++k) {
                const Vec2d expected = Vec2d{0.5 + k, 0.0} + 2.0 * v;
                worst = std::max(worst, length(world.position(ids[k]) - expected));
            }
            BOOST_TEST(worst <= 1e-9);
        }
    }
}

BOOST_AUTO_TEST_SUITE_END()
