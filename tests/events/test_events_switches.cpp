// The events' switches and settings: contact begin/end events per shape, the strong guarantee
// of every new call (a refusal names the field or the handle and leaves state_hash() as it
// was), and that setting a switch to what it is, or switching events at all, changes no bit of
// the motion.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "support/pyramid.hpp"
#include "tamias2d/world.hpp"

using namespace tamias2d;

namespace {

constexpr double dt = 1.0 / 60.0;
constexpr double not_a_number = std::numeric_limits<double>::quiet_NaN();
constexpr double inf = std::numeric_limits<double>::infinity();

/// Two discs that meet head on and part again (restitution 1) in a world without gravity.
struct Collision {
    World world{WorldDef{.gravity = {0.0, 0.0}, .enable_sleep = false}};
    BodyId left, right;
    ShapeId a, b;
    Collision() {
        BodyDef d;
        d.position = {-1.0, 0.0};
        d.linear_velocity = {2.0, 0.0};
        left = world.create_body(d);
        a = world.create_shape(left, circle_shape(0.25, Material{1.0, 1.0, 0.0}));
        d.position = {1.0, 0.0};
        d.linear_velocity = {-2.0, 0.0};
        right = world.create_body(d);
        b = world.create_shape(right, circle_shape(0.25, Material{1.0, 1.0, 0.0}));
    }
    /// Begin and end events over 60 steps.
    std::pair<int, int> run() {
        int begins = 0, ends = 0;
        for (int s = 0; s < 60; ++s) {
            world.step(dt);
            begins += int(world.contact_begin_events().size());
            ends += int(world.contact_end_events().size());
        }
        return {begins, ends};
    }
};

/// The bodies' states, bit for bit (positions, velocities, angles, angular velocities).
std::vector<double> motion(const World& w) {
    std::vector<double> out;
    for (const BodyId b : w.bodies()) {
        const BodyState s = w.state(b);
        out.insert(out.end(), {s.position.x, s.position.y, s.velocity.x, s.velocity.y,
                               s.orientation, s.angular_velocity});
    }
    return out;
}

} // namespace

BOOST_AUTO_TEST_SUITE(events_switches, *boost::unit_test::label("reliability"))

// Oracle: the switch's stated rule (a pair's begin and end events are reported when both its
// shapes allow them). Two discs meet and part: one begin and one end event with both on; none
// with either off (at creation or at run time).
BOOST_AUTO_TEST_CASE(contact_events_need_both_shapes) {
    {
        Collision c;
        BOOST_TEST(c.world.contact_events_enabled(c.a));
        const auto [begins, ends] = c.run();
        BOOST_TEST(begins == 1);
        BOOST_TEST(ends == 1);
    }
    {
        Collision c;
        c.world.set_contact_events_enabled(c.b, false);
        BOOST_TEST(!c.world.contact_events_enabled(c.b));
        const auto [begins, ends] = c.run();
        BOOST_TEST(begins == 0);
        BOOST_TEST(ends == 0);
    }
}

// Oracle: the motion with every event kind off (the reference world). Switching every kind on
// (hits at threshold 0, moves, thresholds on joints) must not change one bit of any body's state
// after 200 steps of a pyramid with a pendulum: events only report.
BOOST_AUTO_TEST_CASE(events_change_no_bit_of_the_motion) {
    auto build = [](World& w, bool events) {
        test::build_pyramid(w, 6);
        BodyDef sd;
        sd.type = BodyType::static_body;
        sd.position = {20.0, 5.0};
        const BodyId pin = w.create_body(sd);
        BodyDef bd;
        bd.position = {21.0, 5.0};
        const BodyId bob = w.create_body(bd);
        w.create_shape(bob, circle_shape(0.2));
        const JointId j =
            w.create_joint(RevoluteJointDef{.body_a = pin, .body_b = bob, .anchor = {20.0, 5.0}});
        if (!events)
            return;
        w.set_hit_event_threshold(0.0);
        for (const BodyId b : w.bodies()) {
            w.set_move_events_enabled(b, true);
            for (const ShapeId s : w.shapes(b))
                w.set_hit_events_enabled(s, true);
        }
        w.set_joint_event_thresholds(j, 0.0, 0.0);
    };
    for (const bool sleeping : {false, true}) {
        World plain(WorldDef{.enable_sleep = sleeping});
        World reporting(WorldDef{.enable_sleep = sleeping});
        build(plain, false);
        build(reporting, true);
        std::size_t hits = 0, moves = 0, joints = 0;
        for (int s = 0; s < 200; ++s) {
            plain.step(dt);
            reporting.step(dt);
            hits += reporting.contact_hit_events().size();
            moves += reporting.body_move_events().size();
            joints += reporting.joint_events().size();
        }
        BOOST_TEST(hits > 0u);
        BOOST_TEST(moves > 0u);
        BOOST_TEST(joints > 0u);
        BOOST_TEST((motion(plain) == motion(reporting)));
    }
}

// Oracle: state_hash() (bitwise-equal worlds hash equal). Setting every switch and threshold to
// the value it has changes no bit: the hash after 100 steps equals that of a world never asked.
BOOST_AUTO_TEST_CASE(setting_what_is_changes_nothing) {
    auto build = [](World& w) {
        test::build_pyramid(w, 4);
        BodyDef sd;
        sd.type = BodyType::static_body;
        sd.position = {20.0, 5.0};
        const BodyId pin = w.create_body(sd);
        BodyDef bd;
        bd.position = {21.0, 5.0};
        const BodyId bob = w.create_body(bd);
        w.create_shape(bob, circle_shape(0.2));
        return w.create_joint(
            RevoluteJointDef{.body_a = pin, .body_b = bob, .anchor = {20.0, 5.0}});
    };
    World untouched, touched;
    build(untouched);
    const JointId j = build(touched);
    BOOST_TEST(untouched.state_hash() == touched.state_hash());
    touched.set_hit_event_threshold(touched.settings().hit_event_threshold);
    for (const BodyId b : touched.bodies()) {
        touched.set_move_events_enabled(b, touched.move_events_enabled(b));
        for (const ShapeId s : touched.shapes(b)) {
            touched.set_hit_events_enabled(s, touched.hit_events_enabled(s));
            touched.set_contact_events_enabled(s, touched.contact_events_enabled(s));
            touched.set_sensor_events_enabled(s, touched.sensor_events_enabled(s));
        }
    }
    touched.set_joint_event_thresholds(j, touched.joint_force_threshold(j),
                                       touched.joint_torque_threshold(j));
    BOOST_TEST(untouched.state_hash() == touched.state_hash());
    for (int s = 0; s < 100; ++s) {
        untouched.step(dt);
        touched.step(dt);
    }
    BOOST_TEST(untouched.state_hash() == touched.state_hash());
    // A changed switch shows in the hash (so the refusals below would be seen).
    touched.set_hit_events_enabled(touched.shapes(touched.bodies()[1])[0], true);
    BOOST_TEST(untouched.state_hash() != touched.state_hash());
}

// Oracle: the stated errors. Each refused call throws ValidationError naming the field and the
// rule "events", InvalidHandle for a destroyed body, shape or joint, or WrongKind for a filter
// joint's thresholds; state_hash() is unchanged after each.
BOOST_AUTO_TEST_CASE(refusals_name_the_field_and_change_nothing) {
    World w;
    BodyDef sd;
    sd.type = BodyType::static_body;
    const BodyId ground = w.create_body(sd);
    const BodyId box = w.create_body(BodyDef{.position = {0.0, 2.0}});
    const ShapeId shape = w.create_shape(box, box_shape(1.0, 1.0));
    const JointId pin =
        w.create_joint(RevoluteJointDef{.body_a = ground, .body_b = box, .anchor = {0.0, 2.0}});
    const JointId filter = w.create_joint(FilterJointDef{.body_a = ground, .body_b = box});
    const BodyId gone = w.create_body(BodyDef{});
    const ShapeId gone_shape = w.create_shape(gone, circle_shape(1.0));
    const JointId gone_joint =
        w.create_joint(WeldJointDef{.body_a = ground, .body_b = gone, .anchor = {}});
    w.destroy_body(gone);
    w.step(dt);

    auto refused = [&](const std::function<void()>& call, const std::string& field) {
        const std::uint64_t before = w.state_hash();
        try {
            call();
            BOOST_ERROR("accepted: " << field);
        } catch (const ValidationError& e) {
            BOOST_TEST(e.field == field);
            // The events' own rule, or the supported range (DCX_range) for a huge speed.
            BOOST_TEST((e.constraint == "events" || e.constraint == "DCX_range"));
        } catch (const InvalidHandle& e) {
            BOOST_TEST(field == "handle");
            BOOST_TEST(std::string(e.what()).find("stale") != std::string::npos);
        } catch (const WrongKind& e) {
            BOOST_TEST(field == "kind");
            BOOST_TEST(e.call == "set_joint_event_thresholds");
            BOOST_TEST(e.kind == "filter joint");
        }
        BOOST_TEST(w.state_hash() == before);
    };
    for (const double bad : {-1.0, not_a_number, inf, -inf, 2e12})
        refused([&] { w.set_hit_event_threshold(bad); }, "hit_event_threshold");
    for (const double bad : {-1.0, not_a_number, -inf}) {
        refused([&] { w.set_joint_event_thresholds(pin, bad, 1.0); }, "joint.force_threshold");
        refused([&] { w.set_joint_event_thresholds(pin, 1.0, bad); }, "joint.torque_threshold");
        refused(
            [&] {
                w.create_joint(DistanceJointDef{.body_a = ground,
                                                .body_b = box,
                                                .anchor_a = {1.0, 0.0},
                                                .anchor_b = {0.0, 2.0},
                                                .force_threshold = bad});
            },
            "joint.force_threshold");
        refused(
            [&] {
                w.create_joint(
                    TargetJointDef{.body = box, .target = {0.0, 2.0}, .torque_threshold = bad});
            },
            "joint.torque_threshold");
    }
    refused([&] { w.set_joint_event_thresholds(filter, 1.0, 1.0); }, "kind");
    refused([&] { w.set_joint_event_thresholds(gone_joint, 1.0, 1.0); }, "handle");
    refused([&] { w.set_move_events_enabled(gone, true); }, "handle");
    refused([&] { w.set_hit_events_enabled(gone_shape, true); }, "handle");
    refused([&] { w.set_contact_events_enabled(gone_shape, false); }, "handle");
    refused([&] { w.set_sensor_events_enabled(gone_shape, false); }, "handle");
    refused([&] { (void)w.hit_events_enabled(gone_shape); }, "handle");
    refused([&] { (void)w.move_events_enabled(gone); }, "handle");
    refused([&] { (void)w.joint_force_threshold(gone_joint); }, "handle");
    BOOST_CHECK_THROW(World(WorldDef{.hit_event_threshold = -1.0}), ValidationError);
    try {
        World bad(WorldDef{.hit_event_threshold = not_a_number});
    } catch (const ValidationError& e) {
        BOOST_TEST(e.field == "world.hit_event_threshold");
    }
    BOOST_TEST(w.hit_events_enabled(shape) == false);
    // Accepted: zero and infinite joint thresholds.
    w.set_joint_event_thresholds(pin, 0.0, inf);
    BOOST_TEST(w.joint_force_threshold(pin) == 0.0);
    BOOST_TEST(w.joint_torque_threshold(pin) == inf);
}

BOOST_AUTO_TEST_SUITE_END()
