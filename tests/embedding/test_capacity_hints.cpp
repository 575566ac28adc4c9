// WorldDef::capacity: the stores sized when the World is made. Oracle: the counting allocator
// hook (counting_hook.hpp), which counts every block the library takes; a positive control
// without hints shows that the same creations do grow the stores.
#include <boost/test/unit_test.hpp>

#include <cstddef>
#include <string>
#include <vector>

#include "embedding/counting_hook.hpp"
#include "support/pyramid.hpp"
#include "tamias2d/allocator.hpp"
#include "tamias2d/errors.hpp"
#include "tamias2d/joint_def.hpp"
#include "tamias2d/world.hpp"

namespace {

using namespace tamias2d;
using namespace tamias2d::test;
namespace utf = boost::unit_test;

struct Hooked {
    Hooked() { set_allocator(counting_hook()); }
    ~Hooked() { reset_allocator(); }
    Hooked(const Hooked&) = delete;
    Hooked& operator=(const Hooked&) = delete;
};

constexpr int chain_links = 200;

/// A row of chain_links boxes, each pinned to the next (199 revolute joints: two per body at
/// most), on a ground: the hook allocations of making them.
std::size_t allocations_to_build(World& world) {
    reset_hook_counts();
    const BodyId ground = world.create_body(BodyDef{.type = BodyType::static_body});
    world.create_shape(ground, box_shape(400.0, 1.0, {}, {0.0, -0.5}));
    BodyId previous{};
    for (int k = 0; k < chain_links - 1; ++k) {
        BodyDef d;
        d.position = {-200.0 + 2.0 * k, 0.5};
        const BodyId b = world.create_body(d);
        world.create_shape(b, box_shape(1.0, 1.0));
        if (k > 0)
            world.create_joint(RevoluteJointDef{
                .body_a = previous, .body_b = b, .anchor = {-201.0 + 2.0 * k, 0.5}});
        previous = b;
    }
    return hook_counts().allocations;
}

WorldDef hinted() {
    WorldDef def;
    def.capacity = {.bodies = chain_links,
                    .shapes = chain_links,
                    .joints = chain_links,
                    .contacts = 4 * chain_links};
    return def;
}

} // namespace

BOOST_AUTO_TEST_SUITE(capacity_hints)

// Oracle: the stated effect of WorldDef::capacity (world_def.hpp, docs/user-guide.md "Capacity
// hints"): with hints at least the counts made, creating the bodies, shapes and joints grows no
// store, so the counting hook, which sees every block the library takes, counts none; without
// hints the same creations take some (positive control).
BOOST_AUTO_TEST_CASE(hinted_creation_grows_no_store, *utf::label("embedding")) {
    const Hooked hooked;
    std::size_t with = 0, without = 0;
    {
        World world(hinted());
        with = allocations_to_build(world);
    }
    {
        World world;
        without = allocations_to_build(world);
    }
    BOOST_TEST(with == 0u);
    BOOST_TEST(without > 0u);
    BOOST_TEST_MESSAGE("creating " << chain_links << " bodies, shapes and joints: " << with
                                   << " hook allocations with hints, " << without << " without");
}

// Oracle: the rule docs/user-guide.md states ("Capacity hints"): with or without hints, a
// settled world's steps take no block, the stores having stopped growing. The counting hook sees
// every block the library takes and every free: 100 steps after 300 settling ones show none.
BOOST_AUTO_TEST_CASE(steady_steps_take_no_block, *utf::label("embedding")) {
    const Hooked hooked;
    for (const bool hints : {false, true}) {
        WorldDef def;
        def.enable_sleep = false;
        if (hints)
            def.capacity = {.bodies = 64, .shapes = 64, .joints = 0, .contacts = 256};
        World world(def);
        build_pyramid(world, 10);
        reset_hook_counts();
        world.step(1.0 / 60.0);
        const std::size_t first = hook_counts().allocations;
        for (int i = 0; i < 300; ++i)
            world.step(1.0 / 60.0);
        reset_hook_counts();
        for (int i = 0; i < 100; ++i)
            world.step(1.0 / 60.0);
        const HookCounts steady = hook_counts();
        BOOST_TEST(steady.allocations == 0u, (hints ? "hinted" : "not hinted"));
        BOOST_TEST(steady.frees == 0u);
        BOOST_TEST_MESSAGE("pyramid of 55 boxes, "
                           << (hints ? "with" : "without") << " hints: first step " << first
                           << " hook allocations, 100 settled steps " << steady.allocations);
    }
}

// Oracle: the rule docs/user-guide.md states ("Capacity hints"): the first steps of a hinted
// world take fewer blocks. The counting hook counts the first step's blocks of the same 10-row
// pyramid with and without hints; the hinted count must be the lower.
BOOST_AUTO_TEST_CASE(hints_spare_the_first_step, *utf::label("embedding")) {
    const Hooked hooked;
    std::size_t first[2] = {0, 0};
    for (const int hints : {0, 1}) {
        WorldDef def;
        if (hints == 1)
            def.capacity = {.bodies = 64, .shapes = 64, .joints = 0, .contacts = 256};
        World world(def);
        build_pyramid(world, 10);
        reset_hook_counts();
        world.step(1.0 / 60.0);
        first[hints] = hook_counts().allocations;
    }
    BOOST_TEST(first[1] < first[0]);
    BOOST_TEST_MESSAGE("first step of a 10-row pyramid: " << first[0] << " hook allocations "
                                                          << "without hints, " << first[1]
                                                          << " with");
}

// Oracle: the same world built without hints, and the documented contract (world_def.hpp) that
// hints change no result and are not in snapshots: the hinted world's state hashes, step by
// step, and its snapshot bytes equal the plain world's, jointed and stepped; restore keeps the
// world's own hints.
BOOST_AUTO_TEST_CASE(hints_change_no_result, *utf::label("embedding")) {
    World plain, hinted_world(hinted());
    allocations_to_build(plain);
    allocations_to_build(hinted_world);
    for (int i = 0; i < 30; ++i) {
        plain.step(1.0 / 60.0);
        hinted_world.step(1.0 / 60.0);
        BOOST_TEST_REQUIRE(plain.state_hash() == hinted_world.state_hash());
    }
    const std::vector<std::byte> a = plain.snapshot(), b = hinted_world.snapshot();
    BOOST_TEST((a == b));
    hinted_world.restore(a);
    BOOST_TEST(hinted_world.settings().capacity.joints == chain_links);
    BOOST_TEST(hinted_world.state_hash() == plain.state_hash());
}

// Oracle: the stated rule of CapacityHints (world_def.hpp): each hint in [0, max_capacity_hint],
// else a ValidationError naming its field and the rule "capacity"; a hint in range is accepted.
BOOST_AUTO_TEST_CASE(hints_are_checked, *utf::label("embedding")) {
    const auto refused = [](CapacityHints c, const std::string& field) {
        WorldDef def;
        def.capacity = c;
        try {
            const World world(def);
            BOOST_FAIL(field << " accepted");
        } catch (const ValidationError& e) {
            BOOST_TEST(e.field == field);
            BOOST_TEST(e.constraint == "capacity");
        }
    };
    refused({.bodies = -1}, "world.capacity.bodies");
    refused({.shapes = max_capacity_hint + 1}, "world.capacity.shapes");
    refused({.joints = -5}, "world.capacity.joints");
    refused({.contacts = max_capacity_hint + 1}, "world.capacity.contacts");
    WorldDef largest;
    largest.capacity.bodies = 1000;
    BOOST_CHECK_NO_THROW(World{largest});
}

BOOST_AUTO_TEST_SUITE_END()
