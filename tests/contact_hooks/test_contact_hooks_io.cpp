// The user material id (Material::user_material_id, DD42) beyond a running world: in scene
// files (read, refused when it is no id, written back) and in snapshots (a restored world,
// given the same mixing function, continues with the original's bits).
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <cstdint>
#include <string>

#include "support/pyramid.hpp"
#include "tamias2d/io/scene.hpp"
#include "tamias2d/world.hpp"

using namespace tamias2d;
namespace utf = boost::unit_test;

namespace {

constexpr double dt = 1.0 / 60.0;

double icy(double a, std::uint64_t ia, double b, std::uint64_t ib) {
    return ia == 7 || ib == 7 ? 0.05 : std::sqrt(a * b);
}

std::string scene_with_id(const std::string& id) {
    return R"({"version": 1, "dt": "1/60", "steps": 0, "materials": {"ice": {"friction": 0.6, "user_material_id": )" +
           id +
           R"(}}, "bodies": [{"name": "rink", "type": "static", "shapes": [{"type": "box",
           "width": 10, "height": 1, "material": "ice"}]}]})";
}

} // namespace

// Oracle: the scene format's stated key (docs/scene-format.md, materials): an integer in
// [0, 2^64 - 1] reaches the shape; anything else is refused at its key; the writer writes it
// back, and a scene read from what it wrote builds the same id.
BOOST_AUTO_TEST_CASE(scenes_carry_the_user_material_id, *utf::label("scene")) {
    const io::Scene scene = io::parse_scene(scene_with_id("18446744073709551615"));
    World world{scene.world};
    io::build_world(scene, world);
    const ShapeId rink = world.shapes(world.bodies().front()).front();
    BOOST_TEST(world.user_material(rink) == 18446744073709551615ull);
    const io::Scene again = io::parse_scene(io::scene_to_json(scene));
    BOOST_TEST(again.bodies.front().shapes.front().material.user_material_id ==
               18446744073709551615ull);
    for (const char* bad : {"-1", "1.5", "\"ice\"", "18446744073709551616"}) {
        try {
            (void)io::parse_scene(scene_with_id(bad));
            BOOST_FAIL("accepted user_material_id " << bad);
        } catch (const io::SceneError& e) {
            BOOST_TEST(std::string(e.what()).find("user_material_id") != std::string::npos);
        }
    }
    // A scene without one writes none (existing scene files read and write as before).
    BOOST_TEST(io::scene_to_json(
                   io::parse_scene(R"({"version": 1, "dt": "1/60", "steps": 0, "bodies": []})"))
                   .find("user_material_id") == std::string::npos);
}

// Oracle: the snapshot's promise (a restored world continues with the original's bits), on a
// pyramid whose shapes' user material ids decide their friction through a mixing function; the
// function is set again after the restore (functions are not data). Were the ids not in the
// snapshot, the restored shapes would mix as ordinary wood and the runs part.
BOOST_AUTO_TEST_CASE(snapshots_carry_the_user_material_id, *utf::label("determinism")) {
    World original{WorldDef{}};
    test::build_pyramid(original, 8);
    int k = 0;
    for (const BodyId b : original.bodies())
        for (const ShapeId s : original.shapes(b))
            if (k++ % 3 == 1)
                original.set_user_material(s, 7);
    original.set_friction_mixing(icy);
    for (int i = 0; i < 40; ++i)
        original.step(dt);
    World restored = World::from_snapshot(original.snapshot());
    restored.set_friction_mixing(icy);
    BOOST_TEST(restored.state_hash() == original.state_hash());
    for (int i = 0; i < 120; ++i) {
        original.step(dt);
        restored.step(dt);
    }
    BOOST_TEST(restored.state_hash() == original.state_hash());
    // (the first box, the pyramid's second shape, is ice)
    BOOST_TEST(restored.user_material(restored.shapes(restored.bodies()[1]).front()) == 7u);
}
