// The definition fields the joint_control work added to the scene format: a distance joint's
// motor (DD35) and a break torque (DD36). Oracles: docs/scene-format.md's joint tables, the
// documented round trip parse_scene(scene_to_json(s)) ~ s, and the same joints made by hand
// with World::create_joint.
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

const char* const winch_scene = R"({"dt": 0.01, "steps": 10, "world": {"gravity": [0, 0]},
  "bodies": [
    {"name": "a", "type": "static", "position": [0, 0]},
    {"name": "b", "position": [2, 0], "shapes": [{"type": "circle", "radius": 0.25}]},
    {"name": "c", "position": [4, 0], "shapes": [{"type": "box", "width": 1, "height": 1}]}],
  "joints": [
    {"type": "distance", "body_a": "a", "body_b": "b", "anchor_a": [0, 0], "anchor_b": [2, 0],
     "enable_motor": true, "motor_speed": 0.5, "max_motor_force": 3},
    {"type": "revolute", "body_a": "b", "body_b": "c", "anchor": [3, 0], "break_torque": 40}]})";

} // namespace

BOOST_AUTO_TEST_SUITE(scene_joint_control)

// Oracle: the documented round trip and the API: the scene's joints read as the definitions
// with those fields, are written back to a fixed point, and build the world the same joints
// made by hand build, before and after steps.
BOOST_AUTO_TEST_CASE(motor_and_break_torque_read_build_and_write_back, *utf::label("scene")) {
    const Scene s = parse_scene(winch_scene, "winch");
    BOOST_TEST_REQUIRE(s.joints.size() == 2u);
    const auto& d = std::get<DistanceJointDef>(s.joints[0].def);
    BOOST_TEST(d.enable_motor);
    BOOST_TEST(d.motor_speed == 0.5);
    BOOST_TEST(d.max_motor_force == 3.0);
    const auto& r = std::get<RevoluteJointDef>(s.joints[1].def);
    BOOST_TEST(r.break_torque == 40.0);

    const std::string once = scene_to_json(s);
    BOOST_TEST(once.find(R"("break_torque": 40)") != std::string::npos);
    BOOST_TEST(once.find(R"("max_motor_force": 3)") != std::string::npos);
    const Scene back = parse_scene(once, "winch (written)");
    BOOST_TEST((back.joints[0].def == s.joints[0].def));
    BOOST_TEST((back.joints[1].def == s.joints[1].def));
    BOOST_TEST(scene_to_json(back) == once);

    World from_file(s.world);
    build_world(s, from_file);
    Scene unjoined = s;
    unjoined.joints.clear();
    World by_hand(s.world);
    const std::vector<BodyId> ids = build_world(unjoined, by_hand);
    BOOST_TEST_REQUIRE(ids.size() == 3u);
    DistanceJointDef dh;
    dh.body_a = ids[0], dh.body_b = ids[1], dh.anchor_a = {0.0, 0.0}, dh.anchor_b = {2.0, 0.0};
    dh.enable_motor = true, dh.motor_speed = 0.5, dh.max_motor_force = 3.0;
    by_hand.create_joint(dh);
    RevoluteJointDef rh;
    rh.body_a = ids[1], rh.body_b = ids[2], rh.anchor = {3.0, 0.0}, rh.break_torque = 40.0;
    const JointId hinge = by_hand.create_joint(rh);
    BOOST_TEST(by_hand.joint_break_torque(hinge) == 40.0);
    BOOST_TEST(from_file.state_hash() == by_hand.state_hash());
    for (int k = 0; k < s.steps; ++k) {
        from_file.step(s.dt);
        by_hand.step(s.dt);
    }
    BOOST_TEST(from_file.state_hash() == by_hand.state_hash());
}

// Oracle: docs/scene-format.md's constraints: a break torque not > 0 and a negative motor force
// are refused at their keys; a break torque on a distance joint (which carries none) is a key it
// does not have.
BOOST_AUTO_TEST_CASE(refuses_bad_values_and_keys, *utf::label("scene")) {
    const auto refused = [](const std::string& from, const std::string& to,
                            const std::string& named) {
        std::string text = winch_scene;
        text.replace(text.find(from), from.size(), to);
        try {
            (void)parse_scene(text, "winch");
            BOOST_ERROR("accepted: " << to);
        } catch (const SceneError& e) {
            BOOST_TEST(std::string(e.what()).find(named) != std::string::npos, e.what());
        }
    };
    refused(R"("break_torque": 40)", R"("break_torque": 0)", "break_torque");
    refused(R"("max_motor_force": 3)", R"("max_motor_force": -3)", "max_motor_force");
    refused(R"("max_motor_force": 3})", R"("max_motor_force": 3, "break_torque": 1})",
            "break_torque");
}

BOOST_AUTO_TEST_SUITE_END()
