// A world in steady state steps without touching the heap: a performance design rule, tagged
// `performance` (it times nothing against a peer, so it is no evidence for NFR1). Games step
// 60 times a second for hours; an allocation per step costs time and fragments memory. The
// global operator new and delete of this executable are replaced by counting versions
// (support/replaced_new.cpp); a small pyramid is built and settled, then 100 more steps must
// allocate nothing.
#include <boost/test/unit_test.hpp>

#include <cstddef>
#include <vector>

#include "support/pyramid.hpp"
#include "support/replaced_new.hpp"
#include "tamias2d/memory/large_array.hpp"
#include "tamias2d/world.hpp"

namespace {

using namespace tamias2d;
namespace utf = boost::unit_test;

using test::build_pyramid;

struct Counted {
    std::size_t allocations, deallocations;
};

template <class F> Counted count_heap(F&& f) {
    const long allocated = test::allocation_count(), released = test::deallocation_count();
    f();
    return {static_cast<std::size_t>(test::allocation_count() - allocated),
            static_cast<std::size_t>(test::deallocation_count() - released)};
}

/// `steps` steps of `world` at 60 Hz.
void run_steps(World& world, int steps) {
    for (int i = 0; i < steps; ++i)
        world.step(1.0 / 60.0);
}

/// The heap calls of `steps` steps of `world`.
Counted count_steps(World& world, int steps) {
    return count_heap([&] { run_steps(world, steps); });
}

} // namespace

BOOST_AUTO_TEST_SUITE(allocation)

// Oracle: the replaced global operator new counts every C++ heap allocation in this process; a
// settled world's step must not call it (zero, exactly). Positive control: the counter sees
// the allocations of creating a body.
BOOST_AUTO_TEST_CASE(settled_world_steps_without_allocating, *utf::label("performance")) {
    World world(WorldDef{.gravity = {0.0, -10.0}});
    build_pyramid(world, 10);
    run_steps(world, 300);

    // Positive control, on a world of its own: the counting operator new is the one the
    // library calls.
    World scratch;
    const Counted control = count_heap([&] { scratch.create_body(BodyDef{}); });
    BOOST_TEST_REQUIRE(control.allocations > 0u);

    const Counted steady = count_steps(world, 100);
    BOOST_TEST(steady.allocations == 0u);
    BOOST_TEST(steady.deallocations == 0u);
    BOOST_TEST_MESSAGE("100 settled steps: " << steady.allocations << " allocations, "
                                             << steady.deallocations << " deallocations");
}

// Oracle: the same counting operator new, on a world with joints: a chain of five links
// swinging from a static pin (awake, so its joints are solved, and copied at every step's start
// for a refusal, SolverDivergence) must not allocate once it has swung for 600 steps (after 10,
// two allocations were still seen: the first swings may grow the world's storage).
BOOST_AUTO_TEST_CASE(jointed_world_steps_without_allocating, *utf::label("performance")) {
    World world(WorldDef{.gravity = {0.0, -10.0}, .enable_sleep = false});
    BodyDef pin_def;
    pin_def.type = BodyType::static_body;
    BodyId previous = world.create_body(pin_def);
    for (int k = 0; k < 5; ++k) {
        BodyDef link;
        link.position = {0.5 + k, 0.0};
        const BodyId b = world.create_body(link);
        world.create_shape(b, box_shape(1.0, 0.2));
        world.create_joint(
            RevoluteJointDef{.body_a = previous, .body_b = b, .anchor = {double(k), 0.0}});
        previous = b;
    }
    run_steps(world, 600);
    const Counted steady = count_steps(world, 100);
    BOOST_TEST(steady.allocations == 0u);
    BOOST_TEST(steady.deallocations == 0u);
}

// Oracle: the same counting operator new, on a net of pins: 12 x 12 discs, each pinned to its
// left and upper neighbours, the top row pinned to static points, so that the pins are solved
// in packs of four level by level (PinPacks); once it hangs, 100 more steps must not allocate.
BOOST_AUTO_TEST_CASE(a_net_of_pins_steps_without_allocating, *utf::label("performance")) {
    World world(WorldDef{.gravity = {0.0, -10.0}, .enable_sleep = false});
    const BodyId anchor = world.create_body(BodyDef{.type = BodyType::static_body});
    constexpr int n = 12;
    std::vector<BodyId> grid;
    for (int row = 0; row < n; ++row)
        for (int col = 0; col < n; ++col) {
            const BodyId b = world.create_body(BodyDef{.position = {double(col), -double(row)}});
            world.create_shape(b, circle_shape(0.2));
            if (col > 0)
                world.create_joint(RevoluteJointDef{
                    .body_a = grid.back(), .body_b = b, .anchor = {col - 0.5, -double(row)}});
            const BodyId above = row > 0 ? grid[std::size_t((row - 1) * n + col)] : anchor;
            world.create_joint(
                RevoluteJointDef{.body_a = above, .body_b = b, .anchor = {double(col), 0.5 - row}});
            grid.push_back(b);
        }
    run_steps(world, 300);
    const Counted steady = count_steps(world, 100);
    BOOST_TEST(steady.allocations == 0u);
    BOOST_TEST(steady.deallocations == 0u);
}

// Oracle: the same counting operator new, on a world stepped on two workers (the World's own
// pool) and large enough (a base-48 pyramid: 1176 boxes, ~3400 contacts) that every parallel
// loop of the step runs in blocks: once settled, no allocation either (the pool's threads are
// started when the world is made; a loop hands them items through atomics).
BOOST_AUTO_TEST_CASE(settled_world_steps_on_two_workers_without_allocating,
                     *utf::label("performance")) {
    WorldDef def{.gravity = {0.0, -10.0}};
    def.workers = 2;
    World world(def);
    build_pyramid(world, 48);
    run_steps(world, 120);
    const Counted steady = count_steps(world, 50);
    BOOST_TEST(steady.allocations == 0u);
    BOOST_TEST(steady.deallocations == 0u);
}

// The large arrays' blocks (1 MiB and more) are mapped from the kernel, not taken from operator
// new, so the counter above does not see them. Oracle: large_array_stats(), the library's own
// count of its mappings, on a world big enough that its contacts and packs are large blocks
// (two rows of 1500 touching boxes on the ground: about 12000 contacts of 192 bytes, 1500 packs
// of 1184).
// Positive control: building and settling it mapped some.
BOOST_AUTO_TEST_CASE(large_world_steps_without_mapping, *utf::label("performance")) {
    const LargeArrayStats before = large_array_stats();
    World world(WorldDef{.gravity = {0.0, -10.0}});
    const Material m{1.0, 0.0, 0.6};
    BodyDef ground;
    ground.type = BodyType::static_body;
    ground.position = {0.0, -0.5};
    world.create_shape(world.create_body(ground), box_shape(1600.0, 1.0, m));
    for (int row = 0; row < 2; ++row) {
        for (int col = 0; col < 1500; ++col) {
            BodyDef d;
            d.position = {col - 750.0, 0.5 + row}; // side by side, touching
            world.create_shape(world.create_body(d), box_shape(1.0, 1.0, m));
        }
    }
    run_steps(world, 30);
    const LargeArrayStats settled = large_array_stats();
    BOOST_TEST_REQUIRE(settled.maps > before.maps);

    const Counted steady = count_steps(world, 20);
    const LargeArrayStats after = large_array_stats();
    BOOST_TEST(steady.allocations == 0u);
    BOOST_TEST(steady.deallocations == 0u);
    BOOST_TEST(after.maps == settled.maps);
    BOOST_TEST(after.remaps == settled.remaps);
    BOOST_TEST(after.unmaps == settled.unmaps);
    BOOST_TEST_MESSAGE("large blocks: " << settled.maps - before.maps << " mapped, "
                                        << settled.remaps - before.remaps
                                        << " grown by remapping while building and settling");
}

BOOST_AUTO_TEST_SUITE_END()
