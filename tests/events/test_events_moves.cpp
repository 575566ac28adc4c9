// Body move events (World::body_move_events): each event's pose against the state getters, the
// bodies listed against the awake ones, and fell_asleep against is_awake's transitions.
#include <boost/test/unit_test.hpp>

#include <map>
#include <vector>

#include "support/pyramid.hpp"
#include "tamias2d/world.hpp"

using namespace tamias2d;

namespace {

constexpr double dt = 1.0 / 60.0;

} // namespace

BOOST_AUTO_TEST_SUITE(events_moves, *boost::unit_test::label("reliability"))

// Oracle: the state getters (origin, orientation, is_awake, type) after the same step. A falling
// box, a kinematic platform and a static ground with move events, a box without: the events
// list exactly the first two, in body order, with the getters' poses bit for bit.
BOOST_AUTO_TEST_CASE(move_events_carry_the_getters_poses) {
    World world(WorldDef{.enable_sleep = false});
    BodyDef sd;
    sd.type = BodyType::static_body;
    sd.enable_move_events = true;
    const BodyId ground = world.create_body(sd);
    world.create_shape(ground, box_shape(20.0, 1.0));
    BodyDef fd;
    fd.position = {0.0, 3.0};
    fd.angular_velocity = 1.3;
    fd.enable_move_events = true;
    const BodyId box = world.create_body(fd);
    world.create_shape(box, box_shape(1.0, 1.0));
    BodyDef kd;
    kd.type = BodyType::kinematic;
    kd.position = {5.0, 2.0};
    kd.linear_velocity = {1.0, 0.0};
    kd.enable_move_events = true;
    const BodyId platform = world.create_body(kd);
    BodyDef quiet;
    quiet.position = {-5.0, 3.0};
    const BodyId other = world.create_body(quiet);
    world.create_shape(other, box_shape(1.0, 1.0));
    BOOST_TEST(world.move_events_enabled(box));
    BOOST_TEST(!world.move_events_enabled(other));
    for (int s = 0; s < 120; ++s) {
        world.step(dt);
        const auto moves = world.body_move_events();
        BOOST_TEST_REQUIRE(moves.size() == 2u);
        BOOST_TEST((moves[0].body == box && moves[1].body == platform));
        for (const BodyMoveEvent& e : moves) {
            BOOST_TEST(e.origin.x == world.origin(e.body).x);
            BOOST_TEST(e.origin.y == world.origin(e.body).y);
            BOOST_TEST(e.angle == world.orientation(e.body));
            BOOST_TEST(!e.fell_asleep);
        }
    }
    // Switched off at run time: the box is no longer listed.
    world.set_move_events_enabled(box, false);
    world.step(dt);
    BOOST_TEST_REQUIRE(world.body_move_events().size() == 1u);
    BOOST_TEST((world.body_move_events()[0].body == platform));
}

// Oracle: is_awake before and after each step. With sleeping on, a pyramid settles and falls
// asleep: a body is listed in a step exactly when it was awake during it (awake after the step,
// or awake before it and asleep after: fell_asleep), and fell_asleep is set exactly for the
// latter. Every body falls asleep once, so every body has exactly one fell_asleep event.
BOOST_AUTO_TEST_CASE(fell_asleep_matches_is_awake_transitions) {
    World world(WorldDef{.gravity = {0.0, -10.0}, .enable_sleep = true});
    test::build_pyramid(world, 5);
    std::vector<BodyId> boxes;
    for (const BodyId b : world.bodies()) {
        if (world.type(b) == BodyType::dynamic) {
            world.set_move_events_enabled(b, true);
            boxes.push_back(b);
        }
    }
    std::map<std::uint32_t, int> fell;
    int listed_total = 0;
    for (int s = 0; s < 600; ++s) {
        std::map<std::uint32_t, bool> before;
        for (const BodyId b : boxes)
            before[b.index] = world.is_awake(b);
        world.step(dt);
        std::map<std::uint32_t, const BodyMoveEvent*> listed;
        for (const BodyMoveEvent& e : world.body_move_events())
            listed[e.body.index] = &e;
        for (const BodyId b : boxes) {
            const bool now = world.is_awake(b);
            const auto it = listed.find(b.index);
            // (A body asleep before the step and after it did not move; one awake after it
            // moved, whether it was woken by the step or not.)
            const bool expected = now || before[b.index];
            BOOST_TEST((it != listed.end()) == expected);
            if (it == listed.end())
                continue;
            ++listed_total;
            BOOST_TEST(it->second->fell_asleep == (before[b.index] && !now));
            if (it->second->fell_asleep)
                ++fell[b.index];
        }
    }
    BOOST_TEST(listed_total > 0);
    BOOST_TEST(fell.size() == boxes.size());
    for (const auto& [index, n] : fell)
        BOOST_TEST(n == 1);
    // Asleep, nothing moves: no event.
    world.step(dt);
    BOOST_TEST(world.body_move_events().empty());
}

BOOST_AUTO_TEST_SUITE_END()
