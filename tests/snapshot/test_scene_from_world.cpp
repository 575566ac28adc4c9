// io::scene_from_world: a world's definitions as a scene.
//
// Oracle: the example scene itself. A world built from scene X, written back as a scene before
// its first step and built again, must step with the same state hashes as X's own world (bit for
// bit: World::definitions gives back the definitions X built it from); after N steps, the scene
// of the world (and its written form) must build a world in the same state at that moment
// (origins, orientations, velocities bit for bit) which then steps on, every state finite. How
// closely it follows the original is measured and printed, not asserted: a scene carries
// neither the warm starts nor the joints' stretch (a loaded bridge's joints, made anew at one
// point each, hold the bridge longer), and how much these matter depends on the scene. A
// property of the library's scene API, not an SRS item: the `scene` tag.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "fuzz/fuzz_support.hpp"
#include "snapshot/snapshot_worlds.hpp"
#include "tamias2d/io/scene.hpp"
#include "tamias2d/io/scene_from_world.hpp"
#include "tamias2d/world.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;
using namespace snapshot_test;

namespace {

/// The world a scene builds, its load functions included (build_world sets them).
World build(const io::Scene& scene) {
    World w(scene.world);
    io::build_world(scene, w);
    return w;
}

} // namespace

BOOST_AUTO_TEST_SUITE(scene_from_world)

// Oracle: bitwise equality with the world built from the example scene itself: the world built
// again from scene_from_world of the unstepped world has the same state hash at the start and
// after each of up to 60 steps (the same inputs give the same bits).
BOOST_AUTO_TEST_CASE(an_unstepped_world_steps_as_its_scene, *utf::label("scene")) {
    for (const fs::path& path : example_scenes()) {
        const std::string name = path.stem().string();
        const io::Scene scene = io::load_scene(path);
        const int steps = std::min(60, steps_for(name, scene.steps));
        World original = build(scene);
        World again = build(io::scene_from_world(original));
        BOOST_TEST_INFO(name);
        BOOST_TEST(again.state_hash() == original.state_hash());
        int first = 0;
        for (int s = 1; s <= steps && first == 0; ++s) {
            original.step(scene.dt);
            again.step(scene.dt);
            if (again.state_hash() != original.state_hash())
                first = s;
        }
        BOOST_TEST_INFO(name);
        BOOST_TEST(first == 0);
    }
}

// Oracle: the stepped world itself: the world built from its scene has every body's origin,
// orientation and velocities bit for bit, the scene's JSON form parses back with as many
// bodies, and 30 steps later no state is non-finite (a property; how closely it follows the
// original is printed, not asserted, as a scene carries no warm starts or joint stretch).
BOOST_AUTO_TEST_CASE(a_stepped_world_loads_in_its_state_and_continues, *utf::label("scene")) {
    for (const fs::path& path : example_scenes()) {
        const std::string name = path.stem().string();
        const io::Scene scene = io::load_scene(path);
        World original = build(scene);
        const int at = std::min(40, steps_for(name, scene.steps) / 2);
        for (int s = 0; s < at; ++s)
            original.step(scene.dt);
        const io::Scene written = io::scene_from_world(original);
        // Its written form loads (the JSON round trip of what scene_from_world made).
        const io::Scene parsed = io::parse_scene(io::scene_to_json(written), name);
        BOOST_TEST(parsed.bodies.size() == written.bodies.size());
        World again = build(written);
        const std::vector<BodyId> ids = original.bodies();
        BOOST_TEST_REQUIRE(again.body_count() == ids.size());
        const std::vector<BodyId> again_ids = again.bodies();
        for (std::size_t k = 0; k < ids.size(); ++k) {
            BOOST_TEST_INFO(name << " body " << k);
            BOOST_TEST(again.origin(again_ids[k]).x == original.origin(ids[k]).x);
            BOOST_TEST(again.origin(again_ids[k]).y == original.origin(ids[k]).y);
            BOOST_TEST(again.orientation(again_ids[k]) == original.orientation(ids[k]));
            BOOST_TEST(again.velocity(again_ids[k]).x == original.velocity(ids[k]).x);
            BOOST_TEST(again.velocity(again_ids[k]).y == original.velocity(ids[k]).y);
            BOOST_TEST(again.angular_velocity(again_ids[k]) == original.angular_velocity(ids[k]));
        }
        for (int s = 0; s < 30; ++s) {
            original.step(scene.dt);
            again.step(scene.dt);
        }
        double worst = 0.0;
        for (std::size_t k = 0; k < ids.size(); ++k) {
            const Vec2d d = again.position(again_ids[k]) - original.position(ids[k]);
            worst = std::max(worst, std::hypot(d.x, d.y));
        }
        BOOST_TEST_MESSAGE(name << ": loaded at step " << at << ", largest distance from the "
                                << "original after 30 more steps " << worst << " m");
        BOOST_TEST_INFO(name);
        BOOST_TEST(fuzz::non_finite_state(again).empty());
    }
}

BOOST_AUTO_TEST_SUITE_END()
