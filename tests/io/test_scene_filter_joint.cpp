// A filter joint in a scene file: read, built, written back. Oracles: docs/scene-format.md's
// "filter" entry (no key beyond type, body_a and body_b), the documented round trip
// parse_scene(scene_to_json(s)) ~ s, and a world built by hand with the same calls.
#include <boost/test/unit_test.hpp>

#include <string>
#include <variant>
#include <vector>

#include "tamias2d/errors.hpp"
#include "tamias2d/io/scene.hpp"
#include "tamias2d/world.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;
using namespace tamias2d::io;

namespace {

const char* const filter_scene = R"({"dt": 0.01, "steps": 10,
  "bodies": [
    {"name": "a", "position": [0, 0], "shapes": [{"type": "box", "width": 1, "height": 1}]},
    {"name": "b", "position": [0.5, 0], "shapes": [{"type": "box", "width": 1, "height": 1}]}],
  "joints": [{"type": "filter", "body_a": "a", "body_b": "b"}]})";

} // namespace

BOOST_AUTO_TEST_SUITE(scene_filter_joint)

// Oracle: the documented round trip (parse_scene(scene_to_json(s)) reproduces s, and the written
// form is a fixed point) and the API: the scene built with its joint hashes as the scene built
// without it and then joined by World::create_joint, before and after a step.
BOOST_AUTO_TEST_CASE(reads_builds_and_writes_back, *utf::label("scene")) {
    const Scene s = parse_scene(filter_scene, "filter");
    BOOST_TEST_REQUIRE(s.joints.size() == 1u);
    BOOST_TEST(std::holds_alternative<FilterJointDef>(s.joints[0].def));
    BOOST_TEST(s.joints[0].body_a == "a");
    BOOST_TEST(s.joints[0].body_b == "b");

    const std::string once = scene_to_json(s);
    BOOST_TEST(once.find(R"("type": "filter")") != std::string::npos);
    const Scene back = parse_scene(once, "filter (written)");
    BOOST_TEST_REQUIRE(back.joints.size() == 1u);
    BOOST_TEST((back.joints[0].def == s.joints[0].def));
    BOOST_TEST(scene_to_json(back) == once);

    // The world built from the file is the same scene built without the joint, then joined by
    // hand with the API's call.
    World from_file(s.world);
    build_world(s, from_file);
    BOOST_TEST(from_file.joint_count() == 1u);
    Scene unjoined = s;
    unjoined.joints.clear();
    World by_hand(s.world);
    const std::vector<BodyId> ids = build_world(unjoined, by_hand);
    BOOST_TEST_REQUIRE(ids.size() == 2u);
    by_hand.create_joint(FilterJointDef{.body_a = ids[0], .body_b = ids[1]});
    BOOST_TEST(from_file.state_hash() == by_hand.state_hash());
    from_file.step(s.dt);
    by_hand.step(s.dt);
    BOOST_TEST(from_file.state_hash() == by_hand.state_hash());
    BOOST_TEST(from_file.contacts().size() == 0u);
}

// Oracle: docs/scene-format.md's "filter" row (no key beyond type, body_a, body_b): an anchor,
// a key of other kinds, is refused, naming it.
BOOST_AUTO_TEST_CASE(refuses_keys_it_does_not_have, *utf::label("scene")) {
    std::string text = filter_scene;
    text.replace(text.find(R"("body_b": "b"})"), 14, R"("body_b": "b", "anchor": [0, 0]})");
    try {
        (void)parse_scene(text, "filter");
        BOOST_FAIL("an anchor on a filter joint was accepted");
    } catch (const SceneError& e) {
        BOOST_TEST(std::string(e.what()).find("anchor") != std::string::npos);
    }
}

BOOST_AUTO_TEST_SUITE_END()
