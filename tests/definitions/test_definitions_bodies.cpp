// The run-time controls a definition sets at creation: BodyDef::enabled, motion_locks and
// sleep_threshold, and the joints' spring_target and constraint_tuning. Oracles: DD39's
// statement (a locked motion is held at zero velocity, so its coordinate never changes); the
// World's own setters (a body or joint made with a field must be bit for bit the one made
// without it and then set before the first step: the definition and the setter promise the
// same object); the definition's documented rules (a bad value refused naming the field, the
// world unchanged); the documented round trips of definitions(), scene_from_world and
// scene_to_json.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <variant>

#include "tamias2d/errors.hpp"
#include "tamias2d/io/scene.hpp"
#include "tamias2d/io/scene_from_world.hpp"
#include "tamias2d/world.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;

namespace {

constexpr double dt = 1.0 / 60.0;

/// A ground and three boxes falling onto it, sideways and turning; body `special` (an index of
/// the three) is made from `d` instead of the default definition.
struct Scene3 {
    World w;
    BodyId boxes[3];
    explicit Scene3(const BodyDef* special_def = nullptr, int special = 1, const WorldDef& def = {})
        : w(def) {
        BodyDef g;
        g.type = BodyType::static_body;
        g.position = {0.0, -0.5};
        g.name = "ground"; // (named: a scene names a joint's bodies, and names are state)
        w.create_shape(w.create_body(g), box_shape(30.0, 1.0, Material{1.0, 0.0, 0.6}));
        for (int i = 0; i < 3; ++i) {
            BodyDef d = (special_def && i == special) ? *special_def : BodyDef{};
            d.position = {1.2 * i - 1.2, 1.0 + 1.3 * i};
            if (d.name.empty())
                d.name = "box" + std::to_string(i);
            d.linear_velocity = {2.0 - i, -1.0};
            d.angular_velocity = 0.5 * i - 0.4;
            boxes[i] = w.create_body(d);
            w.create_shape(boxes[i], box_shape(1.0, 0.8, Material{1.0, 0.2, 0.6}));
        }
    }
};

bool same_history(World& a, World& b, int steps) {
    for (int k = 0; k < steps; ++k) {
        a.step(dt);
        b.step(dt);
        if (a.state_hash() != b.state_hash())
            return false;
    }
    return true;
}

template <class F> std::string refused_field(F&& f) {
    try {
        f();
    } catch (const ValidationError& e) {
        return e.field;
    }
    return "(accepted)";
}

} // namespace

BOOST_AUTO_TEST_SUITE(definitions_bodies)

// Oracle: the setters (World::set_enabled, set_motion_locks, set_sleep_threshold): a body made
// with the fields steps bit for bit as one made without them and set before the first step,
// with sleeping off and on.
BOOST_AUTO_TEST_CASE(body_fields_make_what_the_setters_make, *utf::label("reliability")) {
    for (const bool sleeping : {false, true}) {
        WorldDef wd;
        wd.enable_sleep = sleeping;
        BodyDef d;
        d.motion_locks = {true, false, true};
        d.sleep_threshold = 0.2;
        Scene3 made(&d, 1, wd);
        Scene3 set(nullptr, 1, wd);
        set.w.set_motion_locks(set.boxes[1], {true, false, true});
        set.w.set_sleep_threshold(set.boxes[1], 0.2);
        BOOST_TEST(made.w.state_hash() == set.w.state_hash());
        BOOST_TEST(same_history(made.w, set.w, 240));
        BOOST_TEST((made.w.motion_locks(made.boxes[1]) == MotionLocks{true, false, true}));
        BOOST_TEST(made.w.fixed_rotation(made.boxes[1]));
        BOOST_TEST(made.w.sleep_threshold(made.boxes[1]) == 0.2);

        BodyDef off;
        off.enabled = false;
        Scene3 made_off(&off, 2, wd);
        Scene3 set_off(nullptr, 2, wd);
        set_off.w.set_enabled(set_off.boxes[2], false);
        BOOST_TEST(!made_off.w.is_enabled(made_off.boxes[2]));
        BOOST_TEST(made_off.w.state_hash() == set_off.w.state_hash());
        BOOST_TEST(same_history(made_off.w, set_off.w, 120));
        // Enabled later, both alike again.
        made_off.w.set_enabled(made_off.boxes[2], true);
        set_off.w.set_enabled(set_off.boxes[2], true);
        BOOST_TEST(same_history(made_off.w, set_off.w, 120));
    }
}

// Oracle: DD39's statement: a motion locked from creation is held at zero velocity, so the
// locked coordinate keeps its initial value exactly, however the body is hit; an unlocked
// one moves (gravity and the ground act on it).
BOOST_AUTO_TEST_CASE(a_body_made_locked_never_moves_along_its_locked_axis, *utf::label("DD39")) {
    BodyDef d;
    d.motion_locks.linear_x = true;
    Scene3 s(&d, 2);
    const BodyId b = s.boxes[2];
    const double x0 = s.w.origin(b).x;
    const double y0 = s.w.origin(b).y;
    BOOST_TEST(s.w.velocity(b).x == 0.0); // the definition's 1 m/s along x, stopped at once
    for (int k = 0; k < 180; ++k) {
        s.w.step(dt);
        BOOST_TEST_REQUIRE(s.w.velocity(b).x == 0.0);
    }
    BOOST_TEST(s.w.origin(b).x == x0);
    BOOST_TEST(s.w.origin(b).y < y0 - 0.5); // it fell, and rests on the pile below
}

// Oracle: the definition's rules, as the setter's: a sleep threshold that is negative or not
// finite is refused naming body.sleep_threshold, and nothing is created.
BOOST_AUTO_TEST_CASE(a_bad_sleep_threshold_is_refused_naming_the_field,
                     *utf::label("reliability")) {
    Scene3 s;
    const std::uint64_t before = s.w.state_hash();
    for (const double bad : {-0.1, std::nan(""), std::numeric_limits<double>::infinity()}) {
        BodyDef d;
        d.sleep_threshold = bad;
        BOOST_TEST(refused_field([&] { s.w.create_body(d); }) == "body.sleep_threshold");
        BOOST_TEST(s.w.state_hash() == before);
        BOOST_TEST(s.w.body_count() == 4u);
    }
    BOOST_TEST(refused_field([&] { s.w.set_sleep_threshold(s.boxes[0], -1.0); }) ==
               "sleep_threshold");
}

// Oracle: the setters (set_joint_spring_target, set_constraint_tuning): joints made with the
// fields step bit for bit as the same joints made without them and set before the first step.
BOOST_AUTO_TEST_CASE(joint_fields_make_what_the_setters_make, *utf::label("reliability")) {
    const auto build = [](bool in_definition) {
        auto w = std::make_unique<World>(WorldDef{});
        BodyDef g;
        g.type = BodyType::static_body;
        const BodyId ground = w->create_body(g);
        BodyDef d;
        d.position = {1.0, 0.0};
        const BodyId arm = w->create_body(d);
        w->create_shape(arm, box_shape(2.0, 0.2));
        d.position = {4.0, 0.0};
        const BodyId slider = w->create_body(d);
        w->create_shape(slider, box_shape(0.5, 0.5));
        d.position = {7.0, 0.0};
        const BodyId wheel = w->create_body(d);
        w->create_shape(wheel, circle_shape(0.4));
        d.position = {10.0, 0.0};
        const BodyId hanging = w->create_body(d);
        w->create_shape(hanging, circle_shape(0.3));
        d.position = {12.0, 0.0};
        const BodyId glued = w->create_body(d);
        w->create_shape(glued, box_shape(0.5, 0.5));

        RevoluteJointDef r{.body_a = ground, .body_b = arm, .anchor = {0.0, 0.0}};
        r.enable_spring = true;
        r.hertz = 2.0;
        r.damping_ratio = 0.3;
        PrismaticJointDef p{.body_a = ground, .body_b = slider, .anchor = {4.0, 0.0}};
        p.axis = {0.0, 1.0};
        p.enable_spring = true;
        p.hertz = 1.5;
        p.damping_ratio = 0.2;
        WheelJointDef wh{.body_a = ground, .body_b = wheel, .anchor = {7.0, 0.0}};
        DistanceJointDef dj{
            .body_a = ground, .body_b = hanging, .anchor_a = {10.0, 2.0}, .anchor_b = {10.0, 0.0}};
        WeldJointDef we{.body_a = ground, .body_b = glued, .anchor = {12.0, 0.0}};
        const ConstraintTuning tuning{20.0, 0.7};
        if (in_definition) {
            r.spring_target = 0.6;
            r.constraint_tuning = tuning;
            p.spring_target = -0.4;
            wh.spring_target = 0.25;
            wh.constraint_tuning = tuning;
            dj.constraint_tuning = tuning;
            we.constraint_tuning = tuning;
        }
        const JointId jr = w->create_joint(r);
        const JointId jp = w->create_joint(p);
        const JointId jw = w->create_joint(wh);
        const JointId jd = w->create_joint(dj);
        const JointId je = w->create_joint(we);
        if (!in_definition) {
            w->set_joint_spring_target(jr, 0.6);
            w->set_constraint_tuning(jr, tuning.hertz, tuning.damping_ratio);
            w->set_joint_spring_target(jp, -0.4);
            w->set_joint_spring_target(jw, 0.25);
            w->set_constraint_tuning(jw, tuning.hertz, tuning.damping_ratio);
            w->set_constraint_tuning(jd, tuning.hertz, tuning.damping_ratio);
            w->set_constraint_tuning(je, tuning.hertz, tuning.damping_ratio);
        }
        BOOST_TEST(w->joint_spring_target(jr) == 0.6);
        BOOST_TEST(w->joint_spring_target(jp) == -0.4);
        BOOST_TEST((w->constraint_tuning(jd) == tuning));
        return w;
    };
    auto made = build(true);
    auto set = build(false);
    BOOST_TEST(made->state_hash() == set->state_hash());
    BOOST_TEST(same_history(*made, *set, 180));
}

// Oracle: the definition's rules, as the setters': a spring target beyond the supported range
// and a tuning that is not > 0 are refused naming the definition's field; nothing is created.
BOOST_AUTO_TEST_CASE(bad_joint_fields_are_refused_naming_the_field, *utf::label("reliability")) {
    World w;
    BodyDef g;
    g.type = BodyType::static_body;
    const BodyId ground = w.create_body(g);
    BodyDef d;
    d.position = {1.0, 0.0};
    const BodyId b = w.create_body(d);
    w.create_shape(b, circle_shape(0.5));
    const std::uint64_t before = w.state_hash();
    RevoluteJointDef r{.body_a = ground, .body_b = b, .anchor = {0.0, 0.0}};
    r.spring_target = std::nan("");
    BOOST_TEST(refused_field([&] { w.create_joint(r); }) == "joint.spring_target");
    r.spring_target = 0.0;
    r.constraint_tuning = ConstraintTuning{0.0, 1.0};
    BOOST_TEST(refused_field([&] { w.create_joint(r); }) == "joint.constraint_tuning.hertz");
    DistanceJointDef dj{.body_a = ground, .body_b = b, .anchor_a = {0, 1}, .anchor_b = {1, 0}};
    dj.constraint_tuning = ConstraintTuning{10.0, -1.0};
    BOOST_TEST(refused_field([&] { w.create_joint(dj); }) ==
               "joint.constraint_tuning.damping_ratio");
    BOOST_TEST(w.joint_count() == 0u);
    BOOST_TEST(w.state_hash() == before);
}

// Oracle: definitions()'s documented promise (a world built from them before its first step
// steps bit for bit as this one) and scene_to_json's round trip: the new fields are carried,
// and a scene written, read and written again is the same text.
BOOST_AUTO_TEST_CASE(definitions_and_scenes_carry_the_fields, *utf::label("scene")) {
    WorldDef wd;
    wd.enable_sleep = true;
    wd.enable_warm_starting = false;
    BodyDef d;
    d.motion_locks = {false, true, false};
    d.sleep_threshold = 0.125;
    d.name = "locked";
    Scene3 s(&d, 0, wd);
    s.w.set_enabled(s.boxes[2], false);
    BodyDef g;
    g.type = BodyType::static_body;
    g.position = {0.0, 6.0};
    g.name = "hook";
    const BodyId hook = s.w.create_body(g);
    RevoluteJointDef r{.body_a = hook, .body_b = s.boxes[1], .anchor = {0.0, 5.0}};
    r.enable_spring = true;
    r.hertz = 1.0;
    r.spring_target = 0.3;
    r.constraint_tuning = ConstraintTuning{30.0, 1.5};
    s.w.create_joint(r);

    const WorldDefinitions defs = s.w.definitions();
    BOOST_TEST(!defs.world.enable_warm_starting);
    BOOST_TEST((defs.bodies[1].def.motion_locks == MotionLocks{false, true, false}));
    BOOST_TEST((defs.bodies[1].def.sleep_threshold == std::optional<double>(0.125)));
    BOOST_TEST(!defs.bodies[3].def.enabled);
    const auto& rd = std::get<RevoluteJointDef>(defs.joints[0]);
    BOOST_TEST(rd.spring_target == 0.3);
    BOOST_TEST((rd.constraint_tuning == ConstraintTuning{30.0, 1.5}));

    const io::Scene scene = io::scene_from_world(s.w);
    const std::string text = io::scene_to_json(scene);
    const io::Scene read = io::parse_scene(text, "round trip");
    BOOST_TEST(io::scene_to_json(read) == text);
    BOOST_TEST(!read.world.enable_warm_starting);

    World rebuilt(read.world);
    io::build_world(read, rebuilt);
    BOOST_TEST(rebuilt.state_hash() == s.w.state_hash());
    BOOST_TEST(!rebuilt.warm_starting());
    BOOST_TEST(same_history(rebuilt, s.w, 120));
}

// Oracle: docs/scene-format.md's rules: a bad value of a new key is a SceneError at its JSON
// pointer naming the field; a key of the wrong type likewise.
BOOST_AUTO_TEST_CASE(scene_keys_are_checked_at_their_pointer, *utf::label("scene")) {
    const auto pointer_of = [](const std::string& body_keys, const std::string& joint_keys) {
        const std::string text =
            R"({"dt": 0.01, "steps": 1, "world": {"gravity": [0, -9.81]}, "bodies": [
                {"name": "a", "type": "static"},
                {"name": "b", "position": [1, 0], "shapes": [{"type": "circle", "radius": 0.5}])" +
            body_keys + R"(}],
              "joints": [{"type": "revolute", "body_a": "a", "body_b": "b", "anchor": [0, 0])" +
            joint_keys + "}]}";
        try {
            io::parse_scene(text, "t");
        } catch (const io::SceneError& e) {
            return e.pointer + " " + e.field;
        }
        return std::string("(accepted)");
    };
    BOOST_TEST(pointer_of("", "") == "(accepted)");
    BOOST_TEST(pointer_of(R"(, "sleep_threshold": -1)", "") ==
               "/bodies/1/sleep_threshold sleep_threshold");
    BOOST_TEST(pointer_of(R"(, "lock_linear_x": 1)", "") ==
               "/bodies/1/lock_linear_x lock_linear_x");
    BOOST_TEST(pointer_of(R"(, "enabled": "no")", "") == "/bodies/1/enabled enabled");
    BOOST_TEST(pointer_of("", R"(, "constraint_tuning": {"hertz": 0, "damping_ratio": 1})") ==
               "/joints/0/constraint_tuning/hertz constraint_tuning.hertz");
    BOOST_TEST(pointer_of("", R"(, "constraint_tuning": {"hertz": 5})") ==
               "/joints/0/constraint_tuning/damping_ratio damping_ratio");
    BOOST_TEST(pointer_of("", R"(, "spring_target": "x")") ==
               "/joints/0/spring_target spring_target");
}

BOOST_AUTO_TEST_SUITE_END()
