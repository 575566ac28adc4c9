// A world in steady state steps without touching the heap with its events off, the default,
// and with every kind on once the lists have grown: the events' passes and lists reuse their
// memory (a performance design rule, tagged `performance`, as tests/memory/test_no_allocation.cpp
// is for the step itself). The global operator new and delete of this executable are replaced
// by the counting versions of support/replaced_new.cpp.
#include <boost/test/unit_test.hpp>

#include <cstddef>

#include "support/pyramid.hpp"
#include "support/replaced_new.hpp"
#include "tamias2d/world.hpp"

namespace {

using namespace tamias2d;
namespace utf = boost::unit_test;

struct Counted {
    std::size_t allocations, deallocations;
};

template <class F> Counted count_heap(F&& f) {
    const long a = test::allocation_count(), d = test::deallocation_count();
    f();
    return {std::size_t(test::allocation_count() - a), std::size_t(test::deallocation_count() - d)};
}

/// A base-10 pyramid with a sensor zone over it and a pendulum, stepped 300 times at 60 Hz;
/// with `events`, every kind on (hits at threshold 0, moves, joint thresholds at 0).
void settle(World& world, bool events) {
    test::build_pyramid(world, 10);
    BodyDef sd;
    sd.type = BodyType::static_body;
    sd.position = {0.0, 3.0};
    ShapeDef zone = box_shape(12.0, 4.0);
    zone.is_sensor = true;
    world.create_shape(world.create_body(sd), zone);
    sd.position = {20.0, 5.0};
    const BodyId pin = world.create_body(sd);
    BodyDef bd;
    bd.position = {21.0, 5.0};
    const BodyId bob = world.create_body(bd);
    world.create_shape(bob, circle_shape(0.2));
    const JointId j =
        world.create_joint(RevoluteJointDef{.body_a = pin, .body_b = bob, .anchor = {20.0, 5.0}});
    if (events) {
        world.set_hit_event_threshold(0.0);
        world.set_joint_event_thresholds(j, 0.0, 0.0);
        for (const BodyId b : world.bodies()) {
            world.set_move_events_enabled(b, true);
            for (const ShapeId s : world.shapes(b))
                world.set_hit_events_enabled(s, true);
        }
    }
    for (int i = 0; i < 300; ++i)
        world.step(1.0 / 60.0);
}

} // namespace

BOOST_AUTO_TEST_SUITE(events_allocation)

// Oracle: the replaced global operator new counts every C++ heap allocation in this process;
// 100 more steps of the settled world must call it zero times, events off and on (with them on,
// every step lists the moving bodies, the pendulum's joint event and its hits: the lists are
// refilled, not regrown). Positive control: the counter sees a body's creation.
BOOST_AUTO_TEST_CASE(settled_world_steps_without_allocating_events_off_or_on,
                     *utf::label("performance")) {
    World scratch;
    const Counted control = count_heap([&] { scratch.create_body(BodyDef{}); });
    BOOST_TEST_REQUIRE(control.allocations > 0u);
    for (const bool events : {false, true}) {
        World world(WorldDef{.gravity = {0.0, -10.0}, .enable_sleep = false});
        settle(world, events);
        const Counted steady = count_heap([&] {
            for (int i = 0; i < 100; ++i)
                world.step(1.0 / 60.0);
        });
        BOOST_TEST(steady.allocations == 0u, "events " << (events ? "on" : "off"));
        BOOST_TEST(steady.deallocations == 0u, "events " << (events ? "on" : "off"));
        if (events) {
            BOOST_TEST(!world.body_move_events().empty());
            BOOST_TEST(!world.joint_events().empty());
        }
    }
}

BOOST_AUTO_TEST_SUITE_END()
