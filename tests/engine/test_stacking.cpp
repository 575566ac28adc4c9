// R8, LC2: stacks that stand and piles that stay in their container (issue acceptance figures).
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "tamias2d/io/scene_generators.hpp"
#include "tamias2d/math/vec2d.hpp"
#include "tamias2d/world.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;
using namespace tamias2d::io;

namespace {

std::vector<BodyId> add(World& world, const std::vector<SceneBody>& bodies) {
    std::vector<BodyId> ids;
    for (const SceneBody& sb : bodies) {
        ids.push_back(world.create_body(sb.def));
        for (const ShapeDef& s : sb.shapes)
            world.create_shape(ids.back(), s);
    }
    return ids;
}

} // namespace

BOOST_AUTO_TEST_SUITE(stacking)

// Oracle: the pyramid's own initial geometry: a pyramid of base 20 (210 unit boxes, friction
// 0.6, g = (0, -10), dt = 1/60) that stands keeps its top box within 0.05 m of where it started
// after 1000 steps (the project's stable-stack figure), and comes to rest.
BOOST_AUTO_TEST_CASE(pyramid20_stands, *utf::label("R8") * utf::label("LC1")) {
    World world(WorldDef{.gravity = {0.0, -10.0}});
    PyramidParams p;
    p.base = 20;
    const std::vector<BodyId> ids = add(world, generate_pyramid(p));
    BOOST_TEST_REQUIRE(ids.size() == 211u);
    const BodyId top = ids.back();
    const Vec2d start = world.position(top);
    for (int i = 0; i < 1000; ++i)
        world.step(1.0 / 60.0);
    const double moved = length(world.position(top) - start);
    BOOST_TEST_MESSAGE("pyramid20 top displacement after 1000 steps: " << moved << " m");
    BOOST_TEST(moved < 0.05);
    BOOST_TEST(world.kinetic_energy() < 1e-6);
}

// Oracle: as pyramid20_stands, with the contact passes in regions (WorldDef::contact_regions):
// the order changes only where manifolds between two slabs wait for the slabs' own, and the
// stack must stand and come to rest as well; up to the largest count validate() accepts, 8.
BOOST_AUTO_TEST_CASE(pyramid20_stands_in_regions, *utf::label("R8")) {
    for (const int regions : {2, 4, 8}) {
        BOOST_TEST_CONTEXT("contact_regions = " << regions) {
            World world(WorldDef{.gravity = {0.0, -10.0}, .contact_regions = regions});
            PyramidParams p;
            p.base = 20;
            const std::vector<BodyId> ids = add(world, generate_pyramid(p));
            const BodyId top = ids.back();
            const Vec2d start = world.position(top);
            for (int i = 0; i < 1000; ++i)
                world.step(1.0 / 60.0);
            const double moved = length(world.position(top) - start);
            BOOST_TEST_MESSAGE("pyramid20 in " << regions << " regions, top displacement: " << moved
                                               << " m");
            BOOST_TEST(moved < 0.05);
            BOOST_TEST(world.kinetic_energy() < 1e-6);
        }
    }
}

// Oracle: hand geometry of the container's walls: 400 boxes rained into a static open-top container
// with friction must all end inside it (between the walls, above the floor), finite, and at rest.
BOOST_AUTO_TEST_CASE(rain_stays_in_container, *utf::label("R7") * utf::label("R8")) {
    World world(WorldDef{.gravity = {0.0, -10.0}});
    RainParams p;
    p.count = 400;
    p.container.width = 12.0;
    const std::vector<BodyId> ids = add(world, generate_rain(p));
    for (int i = 0; i < 600; ++i)
        world.step(1.0 / 60.0);
    const double half = 0.5 * p.container.width;
    int escaped = 0;
    for (BodyId b : ids) {
        if (world.type(b) != BodyType::dynamic)
            continue;
        const Vec2d x = world.position(b);
        BOOST_TEST_REQUIRE(std::isfinite(x.x));
        BOOST_TEST_REQUIRE(std::isfinite(x.y));
        if (std::abs(x.x) > half || x.y < 0.0)
            ++escaped;
    }
    BOOST_TEST(escaped == 0);
    BOOST_TEST(world.kinetic_energy() < 1.0);
}

BOOST_AUTO_TEST_SUITE_END()
