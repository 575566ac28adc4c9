// ShapeDef::enable_pre_solve: the pre-solve callback is asked only about pairs where a shape
// allows it; a pair neither shape allows is solved without asking. In snapshots and scene files.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "tamias2d/io/scene.hpp"
#include "tamias2d/io/scene_from_world.hpp"
#include "tamias2d/world.hpp"

using namespace tamias2d;
namespace utf = boost::unit_test;

namespace {

constexpr double dt = 1.0 / 60.0;

/// A box resting on a static floor (top y = 0), each shape's switch as given, and a callback
/// that refuses every contact and counts its calls.
struct Rest {
    World world;
    BodyId box;
    int asked = 0;
    Rest(bool floor_asks, bool box_asks) {
        BodyDef sd;
        sd.type = BodyType::static_body;
        sd.position = {0.0, -0.5};
        ShapeDef floor = box_shape(20.0, 1.0);
        floor.enable_pre_solve = floor_asks;
        world.create_shape(world.create_body(sd), floor);
        BodyDef bd;
        bd.position = {0.0, 0.25};
        box = world.create_body(bd);
        ShapeDef b = box_shape(0.5, 0.5);
        b.enable_pre_solve = box_asks;
        world.create_shape(box, b);
        world.set_pre_solve([this](const PreSolveContact&) {
            ++asked;
            return false;
        });
    }
};

} // namespace

BOOST_AUTO_TEST_SUITE(contact_hooks_pre_solve_switch, *utf::label("reliability"))

// Oracle: the switch's contract (include/tamias2d/shape_def.hpp): a callback refusing every
// contact leaves the box without the floor's support when either shape allows it to be asked
// (it sinks into the floor, its centre well below its rest height 0.25 m: only the continuous
// pass's time of impact keeps it from passing through), and is never called (the box rests,
// its centre at 0.25 m within the soft contact's millimetre) when neither does.
BOOST_AUTO_TEST_CASE(the_callback_is_asked_only_where_a_shape_allows_it) {
    for (const auto& [floor_asks, box_asks] :
         std::vector<std::pair<bool, bool>>{{true, true}, {true, false}, {false, true}}) {
        Rest r(floor_asks, box_asks);
        for (int i = 0; i < 60; ++i)
            r.world.step(dt);
        BOOST_TEST(r.asked > 0);
        BOOST_TEST(r.world.position(r.box).y < 0.15); // unsupported
    }
    Rest r(false, false);
    for (int i = 0; i < 60; ++i)
        r.world.step(dt);
    BOOST_TEST(r.asked == 0);
    BOOST_TEST(std::abs(r.world.position(r.box).y - 0.25) < 1e-3);
}

// Oracle: the snapshot's and the scene format's promises: the switch survives a snapshot (the
// restored world's callback is not asked either) and a scene file's round trip, where it is
// written only when off.
BOOST_AUTO_TEST_CASE(the_switch_is_in_snapshots_and_scene_files) {
    Rest r(false, false);
    r.world.step(dt);
    World restored = World::from_snapshot(r.world.snapshot());
    int asked = 0;
    restored.set_pre_solve([&asked](const PreSolveContact&) {
        ++asked;
        return false;
    });
    for (int i = 0; i < 30; ++i)
        restored.step(dt);
    BOOST_TEST(asked == 0);
    const std::string json = io::scene_to_json(io::scene_from_world(r.world));
    BOOST_TEST(json.find("\"enable_pre_solve\": false") != std::string::npos);
    const io::Scene scene = io::parse_scene(json);
    for (const io::SceneBody& b : scene.bodies)
        for (const ShapeDef& s : b.shapes)
            BOOST_TEST(!s.enable_pre_solve);
    Rest on(true, true);
    BOOST_TEST(io::scene_to_json(io::scene_from_world(on.world)).find("enable_pre_solve") ==
               std::string::npos);
}

BOOST_AUTO_TEST_SUITE_END()
