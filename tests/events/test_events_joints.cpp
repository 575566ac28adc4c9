// Joint events (World::joint_events): thresholds against the static load a joint carries,
// breaking, and joints destroyed with their body.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <limits>

#include "tamias2d/world.hpp"

using namespace tamias2d;

namespace {

constexpr double g = 10.0, dt = 1.0 / 60.0;
constexpr double infinity = std::numeric_limits<double>::infinity();

/// A 2 m x 0.5 m box (density 1: m = 1 kg) hanging from a static pin at its centre by a
/// revolute joint (`def` supplies the thresholds and break force), without sleeping.
struct Hanging {
    World world{WorldDef{.gravity = {0.0, -g}, .enable_sleep = false}};
    BodyId pin, box;
    JointId joint;
    double weight = 0.0;
    explicit Hanging(RevoluteJointDef def) {
        BodyDef sd;
        sd.type = BodyType::static_body;
        pin = world.create_body(sd);
        BodyDef bd;
        bd.position = {0.0, -1.0};
        box = world.create_body(bd);
        world.create_shape(box, box_shape(2.0, 0.5));
        weight = world.mass(box) * g;
        def.body_a = pin;
        def.body_b = box;
        def.anchor = {0.0, -1.0};
        joint = world.create_joint(def);
    }
};

/// A horizontal 2 m x 0.5 m beam (1 kg) welded to a static wall at its end (`def` supplies the
/// thresholds), without sleeping: the weld holds the torque m g L = 10 N m (L = 1 m).
struct Cantilever {
    World world{WorldDef{.gravity = {0.0, -g}, .enable_sleep = false}};
    BodyId wall, beam;
    JointId weld;
    explicit Cantilever(WeldJointDef def) {
        BodyDef sd;
        sd.type = BodyType::static_body;
        wall = world.create_body(sd);
        BodyDef bd;
        bd.position = {1.0, 0.0};
        beam = world.create_body(bd);
        world.create_shape(beam, box_shape(2.0, 0.5));
        def.body_a = wall;
        def.body_b = beam;
        def.anchor = {0.0, 0.0};
        weld = world.create_joint(def);
    }
};

} // namespace

BOOST_AUTO_TEST_SUITE(events_joints, *boost::unit_test::label("reliability"))

// Oracle: statics, closed form. A body hanging at rest from a pin through its centre of mass
// is held by a force equal to its weight m g (Newton's second law with a = 0), and by no
// torque. With the force threshold at 0.9 m g the joint is reported in every step once the
// load is carried (from the first step: the warm-started pin carries it at once, within the
// soft joint's few percent), with its reaction force; at 1.1 m g, never; the torque threshold
// 0.1 N m is never reached. The joint stays (it is not broken).
BOOST_AUTO_TEST_CASE(a_force_threshold_below_the_weight_reports_every_step,
                     *boost::unit_test::label("IM6")) {
    Hanging low(RevoluteJointDef{.force_threshold = 0.9 * 10.0, .torque_threshold = 0.1});
    Hanging high(RevoluteJointDef{.force_threshold = 1.1 * 10.0, .torque_threshold = 0.1});
    BOOST_TEST_REQUIRE(low.weight == 10.0);
    int reported = 0;
    for (int s = 0; s < 120; ++s) {
        low.world.step(dt);
        high.world.step(dt);
        BOOST_TEST(high.world.joint_events().empty());
        const auto events = low.world.joint_events();
        if (s >= 10) // after the first steps' transient
            BOOST_TEST_REQUIRE(events.size() == 1u);
        for (const JointEvent& e : events) {
            ++reported;
            BOOST_TEST((e.joint == low.joint && e.kind == JointEventKind::threshold_exceeded));
            BOOST_TEST((e.body_a == low.pin && e.body_b == low.box));
            const Vec2d f = low.world.joint_reaction_force(low.joint);
            BOOST_TEST(e.force.x == f.x);
            BOOST_TEST(e.force.y == f.y);
            BOOST_TEST(std::abs(e.force.y - low.weight) < 0.05 * low.weight);
            BOOST_TEST(e.torque == low.world.joint_reaction_torque(low.joint));
        }
    }
    BOOST_TEST(reported >= 110);
    BOOST_TEST(low.world.is_valid(low.joint));
    BOOST_TEST(low.world.broken_joints().empty());
}

// Oracle: the event's rule (events.hpp): reported when the reaction force exceeds the
// threshold, not when it equals it. The threshold is set to the force a twin world's joint
// carries after 60 steps (thresholds change no motion, so both worlds move alike): in every step
// the event is reported exactly when the force's length is greater, and at step 60, where they
// are equal, it is not.
BOOST_AUTO_TEST_CASE(a_force_equal_to_the_threshold_does_not_exceed_it) {
    const auto force_length = [](Vec2d f) { return std::sqrt(f.x * f.x + f.y * f.y); };
    Hanging twin(RevoluteJointDef{});
    for (int s = 0; s < 60; ++s)
        twin.world.step(dt);
    const double threshold = force_length(twin.world.joint_reaction_force(twin.joint));
    Hanging h(RevoluteJointDef{.force_threshold = threshold});
    int equal = 0;
    for (int s = 1; s <= 90; ++s) {
        h.world.step(dt);
        const double f = force_length(h.world.joint_reaction_force(h.joint));
        equal += f == threshold;
        BOOST_TEST(h.world.joint_events().size() == (f > threshold ? 1u : 0u), "step " << s);
    }
    BOOST_TEST(equal >= 1);
}

// Oracle: statics, closed form. A horizontal 2 m beam (1 kg) welded to a wall at its end has
// its centre of mass L = 1 m from the weld: the weld holds the torque m g L = 10 N m. A torque
// threshold of 9 N m is exceeded in every step once the load is carried (after a transient of
// 30 steps, in which the torque settles within 5 % of m g L); 11 N m never; alike whether the
// threshold comes with the joint's definition or from set_joint_event_thresholds.
BOOST_AUTO_TEST_CASE(a_torque_threshold_below_the_moment_reports,
                     *boost::unit_test::label("DD22")) {
    for (const auto& [threshold, by_definition] : {std::pair{9.0, false}, std::pair{11.0, false},
                                                   std::pair{9.0, true}, std::pair{11.0, true}}) {
        BOOST_TEST_CONTEXT(threshold << " N m " << (by_definition ? "defined" : "set")) {
            Cantilever c(WeldJointDef{.torque_threshold = by_definition ? threshold : infinity});
            World& world = c.world;
            const JointId weld = c.weld;
            BOOST_TEST_REQUIRE(world.mass(c.beam) == 1.0);
            if (!by_definition)
                world.set_joint_event_thresholds(weld, infinity, threshold);
            BOOST_TEST(world.joint_torque_threshold(weld) == threshold);
            BOOST_TEST(world.joint_force_threshold(weld) == infinity);
            int reported = 0;
            for (int s = 0; s < 120; ++s) {
                world.step(dt);
                if (s < 30)
                    continue; // the first steps' transient: the beam sags into the weld's hold
                reported += int(world.joint_events().size());
                BOOST_TEST(std::abs(std::abs(world.joint_reaction_torque(weld)) - 10.0) < 0.5);
            }
            if (threshold < 10.0)
                BOOST_TEST(reported >= 90);
            else
                BOOST_TEST(reported == 0);
        }
    }
}

// Oracle: the event's rule (events.hpp): reported when the reaction torque exceeds the
// threshold in magnitude, not when it equals it. The threshold is set to the torque a twin
// world's weld carries after 60 steps (thresholds change no motion, so both worlds move alike):
// in every step the event is reported exactly when the torque's magnitude is greater, and at
// step 60, where they are equal, it is not.
BOOST_AUTO_TEST_CASE(a_torque_equal_to_the_threshold_does_not_exceed_it) {
    Cantilever twin(WeldJointDef{});
    for (int s = 0; s < 60; ++s)
        twin.world.step(dt);
    const double threshold = std::abs(twin.world.joint_reaction_torque(twin.weld));
    Cantilever c(WeldJointDef{.torque_threshold = threshold});
    int equal = 0;
    for (int s = 1; s <= 90; ++s) {
        c.world.step(dt);
        const double t = std::abs(c.world.joint_reaction_torque(c.weld));
        equal += t == threshold;
        BOOST_TEST(c.world.joint_events().size() == (t > threshold ? 1u : 0u), "step " << s);
    }
    BOOST_TEST(equal >= 1);
}

// Oracle: the break rule (the weight m g is above a 5 N break force): the joint breaks in the
// first step, is listed by broken_joints() and by joint_events() as broke, once.
BOOST_AUTO_TEST_CASE(a_broken_joint_is_a_joint_event) {
    Hanging h(RevoluteJointDef{.break_force = 5.0});
    h.world.step(dt);
    BOOST_TEST_REQUIRE(h.world.broken_joints().size() == 1u);
    BOOST_TEST((h.world.broken_joints()[0] == h.joint));
    const auto events = h.world.joint_events();
    BOOST_TEST_REQUIRE(events.size() == 1u);
    BOOST_TEST((events[0].joint == h.joint && events[0].kind == JointEventKind::broke));
    BOOST_TEST(std::hypot(events[0].force.x, events[0].force.y) > 5.0);
    BOOST_TEST(!h.world.is_valid(h.joint));
    h.world.step(dt);
    BOOST_TEST(h.world.joint_events().empty());
}

// Oracle: destroy_body's stated effect (it destroys the body's joints): each joint of the body
// is reported as body_destroyed, last made first, until the next step; the other body's other
// joint is not.
BOOST_AUTO_TEST_CASE(joints_destroyed_with_their_body_are_reported) {
    Hanging h(RevoluteJointDef{});
    BodyDef bd;
    bd.position = {3.0, -1.0};
    const BodyId other = h.world.create_body(bd);
    h.world.create_shape(other, box_shape(0.5, 0.5));
    const JointId rod = h.world.create_joint(DistanceJointDef{
        .body_a = h.box, .body_b = other, .anchor_a = {1.0, -1.0}, .anchor_b = {3.0, -1.0}});
    const JointId other_pin = h.world.create_joint(
        RevoluteJointDef{.body_a = h.pin, .body_b = other, .anchor = {3.0, -1.0}});
    h.world.step(dt);
    BOOST_TEST(h.world.joint_events().empty());
    h.world.destroy_body(h.box);
    const auto events = h.world.joint_events();
    BOOST_TEST_REQUIRE(events.size() == 2u);
    BOOST_TEST((events[0].joint == rod && events[1].joint == h.joint));
    for (const JointEvent& e : events) {
        BOOST_TEST((e.kind == JointEventKind::body_destroyed));
        BOOST_TEST((e.body_a == h.box || e.body_b == h.box));
        BOOST_TEST(!h.world.is_valid(e.joint));
    }
    BOOST_TEST(h.world.is_valid(other_pin));
    BOOST_TEST(to_string(events[0].kind) == "body_destroyed");
    h.world.step(dt);
    BOOST_TEST(h.world.joint_events().empty());
}

BOOST_AUTO_TEST_SUITE_END()
