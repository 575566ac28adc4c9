// A world built or restored from a snapshot continues with the same bits as the world the
// snapshot was taken from (World::snapshot, from_snapshot, restore).
//
// Oracle: the uninterrupted run of the original world, step by step (its state_hash() after
// each step), and the snapshot itself: a restored world's own snapshot must be the same bytes,
// so that every field of every store (also those state_hash() does not read: the broad phase's
// trees, the separation hints, the edge inputs) survived the round trip. A determinism property
// of the engine, not an SRS item: the `determinism` tag.
#include <boost/test/unit_test.hpp>

#include <bit>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <random>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

#include "snapshot/snapshot_worlds.hpp"
#include "tamias2d/io/scene.hpp"
#include "tamias2d/world.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;
using namespace snapshot_test;

namespace {

/// The state hashes of `w` after each of `n` steps of dt.
std::vector<std::uint64_t> run(World& w, double dt, int n) {
    std::vector<std::uint64_t> h;
    for (int s = 0; s < n; ++s) {
        w.step(dt);
        h.push_back(w.state_hash());
    }
    return h;
}

/// The first step (1-based) at which `b` differs from `a`, 0 when none.
int first_difference(const std::vector<std::uint64_t>& a, const std::vector<std::uint64_t>& b) {
    for (std::size_t k = 0; k < a.size() && k < b.size(); ++k)
        if (a[k] != b[k])
            return int(k) + 1;
    return a.size() == b.size() ? 0 : -1;
}

/// The scene's load functions set again on `w` (a world from a snapshot has none).
/// A handle of the world a snapshot was taken from, for the world built from it: the same
/// slot and generation under the new world's tag.
BodyId in_world(const World& w, BodyId id) {
    return BodyId{id.index, id.generation, w.tag()};
}

void set_loads(World& w, const io::Scene& scene, const std::vector<BodyId>& ids) {
    for (std::size_t i = 0; i < scene.bodies.size(); ++i)
        if (!scene.bodies[i].loads.empty())
            w.set_load(in_world(w, ids[i]), scene.bodies[i].loads);
}

} // namespace

BOOST_AUTO_TEST_SUITE(snapshot_continuation)

// Oracle: the uninterrupted run of the original world, and world.hpp's contract that a world
// built from a snapshot continues with the same bits on any number of workers: for every example
// scene, a world made from a snapshot at a seeded random step, on 1 and on 4 workers, has the
// original's state_hash(), writes the same snapshot bytes, and has the original's hash after
// each of the next steps, up to 60 (the same inputs give the same bits).
BOOST_AUTO_TEST_CASE(example_scenes_continue_with_the_same_bits, *utf::label("determinism")) {
    std::mt19937_64 r(47);
    for (const fs::path& path : example_scenes()) {
        const std::string name = path.stem().string();
        const io::Scene scene = io::load_scene(path);
        const int steps = steps_for(name, scene.steps);
        const int at = pick(r, steps / 2 + 1);
        const int after = std::min(60, steps - at);
        World original(scene.world);
        const std::vector<BodyId> ids = io::build_world(scene, original);
        for (int s = 0; s < at; ++s)
            original.step(scene.dt);
        const std::vector<std::byte> bytes = original.snapshot();
        const std::uint64_t hash_at = original.state_hash();
        const std::vector<std::uint64_t> expected = run(original, scene.dt, after);
        for (const int workers : {1, 4}) {
            World restored = World::from_snapshot(bytes, workers);
            set_loads(restored, scene, ids);
            BOOST_TEST_INFO(name << " at step " << at << ", " << workers << " workers");
            BOOST_TEST(restored.state_hash() == hash_at);
            BOOST_TEST((restored.snapshot() == bytes));
            BOOST_TEST(first_difference(expected, run(restored, scene.dt, after)) == 0);
        }
    }
}

// Oracle: the world's own run after the snapshot, and world.hpp's contract for restore: restored
// into the world it was taken from after it stepped on, the snapshot gives back the same bytes,
// the handles issued before it stay valid, and the next 50 steps' state hashes repeat the first
// 50 (the same inputs give the same bits); the custom filter, kept, is asked as often again.
BOOST_AUTO_TEST_CASE(restore_rolls_a_world_back, *utf::label("determinism")) {
    for (const std::string name : {"spinning", "car", "ragdoll", "bridge", "two_bodies"}) {
        const io::Scene scene = io::load_scene(fs::path(TAMIAS_EXAMPLE_SCENES) / (name + ".json"));
        World w(scene.world);
        const std::vector<BodyId> ids = io::build_world(scene, w);
        int filter_calls = 0;
        w.set_custom_filter([&filter_calls](ShapeId a, ShapeId b) {
            ++filter_calls;
            return (a.index + b.index) % 7 != 3;
        });
        for (int s = 0; s < 20; ++s)
            w.step(scene.dt);
        const std::vector<std::byte> bytes = w.snapshot();
        const int calls_before = filter_calls;
        const std::vector<std::uint64_t> first = run(w, scene.dt, 50);
        const int calls_first = filter_calls - calls_before;
        w.restore(bytes);
        BOOST_TEST_INFO(name);
        BOOST_TEST((w.snapshot() == bytes));
        for (const BodyId id : ids)
            BOOST_TEST(w.is_valid(id));
        BOOST_TEST(first_difference(first, run(w, scene.dt, 50)) == 0);
        BOOST_TEST(filter_calls - calls_before ==
                   2 * calls_first); // the filter stayed, asked the same again
    }
}

// Oracle: the uninterrupted run of the original random world (every shape and joint kind,
// sensors, free slots, loads, sleeping on or off): a world made from a snapshot at a seeded
// random step (1 and 4 workers) has the original's state_hash(), snapshot bytes and hashes for
// the next 90 steps, another world restored from it its state_hash() and hashes (the same
// inputs give the same bits); user data comes back as the snapshot holds it (world.hpp's
// contract).
BOOST_AUTO_TEST_CASE(random_worlds_continue_with_the_same_bits, *utf::label("determinism")) {
    const double dt = 1.0 / 60.0;
    for (std::uint64_t seed = 1; seed <= 40; ++seed) {
        BOOST_TEST_CHECKPOINT("seed " << seed);
        std::mt19937_64 r(seed * 7919);
        World original = random_world(seed);
        const int at = pick(r, 150);
        for (int s = 0; s < at; ++s)
            original.step(dt);
        const std::vector<std::byte> bytes = original.snapshot();
        const std::uint64_t hash_at = original.state_hash();
        const std::vector<std::uint64_t> expected = run(original, dt, 90);
        for (const int workers : {1, 4}) {
            World restored = World::from_snapshot(bytes, workers);
            BOOST_TEST_INFO("seed " << seed << " at step " << at << ", " << workers << " workers");
            BOOST_TEST(restored.state_hash() == hash_at);
            BOOST_TEST((restored.snapshot() == bytes));
            BOOST_TEST(first_difference(expected, run(restored, dt, 90)) == 0);
            // User data is not simulation state (not hashed) but is in the snapshot.
            BOOST_TEST(restored.user_data() == UserData(seed));
            for (const BodyId b : original.bodies())
                BOOST_TEST(restored.user_data(in_world(restored, b)) == original.user_data(b));
        }
        World other = random_world(seed + 1000, 2);
        other.restore(bytes);
        BOOST_TEST_INFO("seed " << seed << " restored into another world");
        BOOST_TEST(other.state_hash() == hash_at);
        BOOST_TEST(other.user_data() == UserData(seed)); // the snapshot's, not the world's own
        BOOST_TEST(first_difference(expected, run(other, dt, 90)) == 0);
    }
}

// Oracle: the uninterrupted run of the original world (the same inputs give the same bits). In
// contact regions the colouring of the manifolds between regions is redone whenever the pairs
// change, and it must start from what a fresh world starts from: a world made from a snapshot
// has no colouring yet. 300 boxes rain into a bin 12 m wide cut into three regions across
// gravity (the pile crosses the cuts, so manifolds between regions form and change every step);
// worlds made from snapshots at steps 60, 120, 180 and 240 must repeat the original's next 60
// state hashes.
BOOST_AUTO_TEST_CASE(a_world_in_regions_continues_with_the_same_bits, *utf::label("determinism")) {
    const double dt = 1.0 / 60.0;
    const auto rain = [] {
        auto w = std::make_unique<World>(WorldDef{.gravity = {0.0, -10.0}, .contact_regions = 3});
        const BodyId bin = w->create_body({.type = BodyType::static_body});
        w->create_shape(bin, box_shape(12.0, 0.5));
        for (const double x : {-6.25, 6.25})
            w->create_shape(bin, box_shape(0.5, 8.0, Material{}, {x, 4.0}));
        std::mt19937_64 r(5);
        for (int k = 0; k < 300; ++k) {
            const BodyId b = w->create_body({.position = {uniform(r, -5.5, 5.5), 1.0 + 0.65 * k},
                                             .angle = uniform(r, 0.0, 3.0)});
            w->create_shape(b, box_shape(0.5, 0.4));
        }
        return w;
    };
    for (const int at : {60, 120, 180, 240}) {
        const auto original = rain();
        for (int s = 0; s < at; ++s)
            original->step(dt);
        World restored = World::from_snapshot(original->snapshot());
        const std::vector<std::uint64_t> expected = run(*original, dt, 60);
        BOOST_TEST(first_difference(expected, run(restored, dt, 60)) == 0, "from step " << at);
    }
}

// Oracle: the original world stepped on, and world.hpp's contract: a snapshot taken before the
// first step brings the masses attach_shape left pending up to date as a step would, and gives
// a world of its own tag (the original's handle not valid in it) with the original's mass and
// its state hashes for 30 steps (the same inputs give the same bits); an empty world's snapshot
// gives a world with its hash.
BOOST_AUTO_TEST_CASE(a_snapshot_before_the_first_step, *utf::label("determinism")) {
    World w;
    BodyDef d;
    d.position = {0.0, 2.0};
    const BodyId b = w.create_body(d);
    w.create_shape(b, box_shape(1.0, 0.5));
    w.create_shape(b, circle_shape(0.3, {}, {0.5, 0.0}));
    const std::vector<std::byte> bytes = w.snapshot();
    World restored = World::from_snapshot(bytes);
    BOOST_TEST(restored.tag() != w.tag()); // a world of its own
    BOOST_TEST(!restored.is_valid(b));
    BOOST_TEST(restored.mass(in_world(restored, b)) == w.mass(b));
    BOOST_TEST(first_difference(run(w, 0.01, 30), run(restored, 0.01, 30)) == 0);
    World empty;
    BOOST_TEST(World::from_snapshot(empty.snapshot()).state_hash() == empty.state_hash());
}

// Oracle: the original world stepped on (a restored world continues as the world the snapshot
// was taken from, its events included). Balls with move events on, whose shapes have hit events
// on, are dropped at staggered heights onto the ground; a snapshot is taken while they fall and
// read back. Over the next 90 steps the restored world reports, step by step, the same move
// events and the same hit events as the original, and it reports some of each (the scene's
// balls keep moving and land in that time).
BOOST_AUTO_TEST_CASE(a_restored_world_reports_the_same_events, *utf::label("determinism")) {
    World w;
    BodyDef gd;
    gd.type = BodyType::static_body;
    w.create_shape(w.create_body(gd), box_shape(40.0, 1.0, {}, {0.0, -0.5}));
    for (int k = 0; k < 6; ++k) {
        BodyDef d;
        d.position = {-10.0 + 4.0 * k, 1.0 + 0.5 * k};
        d.enable_move_events = true;
        ShapeDef ball = circle_shape(0.25, Material{1.0, 0.5, 0.3});
        ball.enable_hit_events = true;
        w.create_shape(w.create_body(d), ball);
    }
    for (int s = 0; s < 10; ++s)
        w.step(1.0 / 60.0);
    World restored = World::from_snapshot(w.snapshot());
    std::size_t moves = 0, hits = 0;
    for (int s = 0; s < 90; ++s) {
        w.step(1.0 / 60.0);
        restored.step(1.0 / 60.0);
        const auto m0 = w.body_move_events(), m1 = restored.body_move_events();
        BOOST_TEST_REQUIRE(m0.size() == m1.size());
        for (std::size_t k = 0; k < m0.size(); ++k) {
            BOOST_TEST(m0[k].body.index == m1[k].body.index);
            BOOST_TEST(m0[k].origin.x == m1[k].origin.x);
            BOOST_TEST(m0[k].origin.y == m1[k].origin.y);
        }
        const auto h0 = w.contact_hit_events(), h1 = restored.contact_hit_events();
        BOOST_TEST_REQUIRE(h0.size() == h1.size());
        for (std::size_t k = 0; k < h0.size(); ++k) {
            BOOST_TEST(h0[k].shape_a.index == h1[k].shape_a.index);
            BOOST_TEST(h0[k].approach_speed == h1[k].approach_speed);
        }
        moves += m0.size();
        hits += h0.size();
    }
    BOOST_TEST(moves > 0u);
    BOOST_TEST(hits > 0u);
}

// Oracle: world.hpp's contract for restore (the world is put in the state the snapshot holds)
// and the world's own report at the snapshot: contacts(), read just before a restore rolls the
// world back, reads after it what it read when the snapshot was taken, pair by pair and point by
// point, not the report of the state the world left.
BOOST_AUTO_TEST_CASE(the_contact_report_after_a_restore_is_the_snapshots,
                     *utf::label("determinism")) {
    const io::Scene scene = io::load_scene(fs::path(TAMIAS_EXAMPLE_SCENES) / "pyramid20.json");
    World w(scene.world);
    io::build_world(scene, w);
    for (int s = 0; s < 30; ++s)
        w.step(scene.dt);
    const std::vector<std::byte> bytes = w.snapshot();
    const std::vector<ContactInfo> then(w.contacts().begin(), w.contacts().end());
    BOOST_TEST_REQUIRE(!then.empty());
    for (int s = 0; s < 30; ++s) // the pyramid settles on: other impulses, other separations
        w.step(scene.dt);
    const std::vector<ContactInfo> later(w.contacts().begin(), w.contacts().end());
    w.restore(bytes);
    const std::span<const ContactInfo> now = w.contacts();
    // Field by field (bit for bit on the doubles), not the structs' bytes: padding is not state.
    const auto same_bits = [](auto u, auto v) {
        if constexpr (std::is_same_v<decltype(u), Vec2d>)
            return std::bit_cast<std::uint64_t>(u.x) == std::bit_cast<std::uint64_t>(v.x) &&
                   std::bit_cast<std::uint64_t>(u.y) == std::bit_cast<std::uint64_t>(v.y);
        else
            return std::bit_cast<std::uint64_t>(u) == std::bit_cast<std::uint64_t>(v);
    };
    const auto same = [&](const ContactInfo& x, const ContactInfo& y) {
        bool eq = x.shape_a == y.shape_a && x.shape_b == y.shape_b && x.body_a == y.body_a &&
                  x.body_b == y.body_b && same_bits(x.normal, y.normal) &&
                  x.point_count == y.point_count;
        for (int j = 0; eq && j < x.point_count; ++j) {
            const ContactPointInfo &p = x.points[j], &q = y.points[j];
            eq = same_bits(p.point, q.point) && same_bits(p.separation, q.separation) &&
                 same_bits(p.normal_impulse, q.normal_impulse) &&
                 same_bits(p.tangent_impulse, q.tangent_impulse);
        }
        return eq;
    };
    BOOST_TEST_REQUIRE(now.size() == then.size());
    bool differs_later = later.size() != then.size();
    for (std::size_t k = 0; k < then.size(); ++k) {
        BOOST_TEST(same(now[k], then[k]), "contact " << k);
        differs_later = differs_later || k >= later.size() || !same(later[k], then[k]);
    }
    BOOST_TEST(differs_later); // so that a stale report could not pass
}

namespace {
/// A box resting on a floor for 10 steps: sleeping off (so a wake changes nothing) and a
/// restitution threshold no resting contact reaches (so the restitution pass applies nothing,
/// whatever the coefficient). `change` runs between the steps and the snapshot.
std::vector<std::byte> resting_box(double box_restitution, MaterialMixFunction mix,
                                   const std::function<void(World&, ShapeId)>& change) {
    WorldDef def;
    def.enable_sleep = false;
    def.restitution_threshold = 1.0; // m/s; the box approaches at most g dt = 0.16 m/s
    World w(def);
    w.create_shape(w.create_body({.type = BodyType::static_body}), box_shape(4.0, 1.0));
    const ShapeId box = w.create_shape(w.create_body({.position = {0.0, 1.0}}),
                                       box_shape(1.0, 1.0, Material{1.0, box_restitution, 0.5}));
    if (mix)
        w.set_restitution_mixing(std::move(mix));
    for (int s = 0; s < 10; ++s)
        w.step(1.0 / 60.0);
    BOOST_TEST_REQUIRE(w.contacts().size() == 1u); // the box rests on the floor
    if (change)
        change(w, box);
    return w.snapshot();
}
} // namespace

// A contact whose restitution a mixing rule or a material changes between steps writes the
// bytes of a world in which it had that restitution from the start. Oracle: one state, one
// snapshot (World::snapshot writes the world's state and nothing of how it got there). The two
// worlds share every bit: the restitution pass applies nothing to a resting box (the threshold
// above), so the coefficient changes no motion, and only the contact's restitution and what the
// step reads of it differ until the change.
BOOST_AUTO_TEST_CASE(a_changed_restitution_writes_the_bytes_of_a_world_made_with_it,
                     *utf::label("determinism")) {
    const auto rule = [](double value) {
        return MaterialMixFunction(
            [value](double, std::uint64_t, double, std::uint64_t) { return value; });
    };
    const auto to_rule = [&](double value) {
        return [&, value](World& w, ShapeId) { w.set_restitution_mixing(rule(value)); };
    };
    // The rule raises the contact's restitution from 0 to 0.5, and lowers it from 0.5 to 0.
    BOOST_TEST((resting_box(0.0, rule(0.0), to_rule(0.5)) == resting_box(0.0, rule(0.5), {})));
    BOOST_TEST((resting_box(0.0, rule(0.5), to_rule(0.0)) == resting_box(0.0, rule(0.0), {})));
    // The box's material does (the default rule: the larger of the two).
    const auto to_material = [](double value) {
        return [value](World& w, ShapeId box) { w.set_restitution(box, value); };
    };
    BOOST_TEST((resting_box(0.0, {}, to_material(0.5)) == resting_box(0.5, {}, {})));
    BOOST_TEST((resting_box(0.5, {}, to_material(0.0)) == resting_box(0.0, {}, {})));
    // And the change is seen: a world that keeps its restitution writes other bytes.
    BOOST_TEST((resting_box(0.0, {}, {}) != resting_box(0.5, {}, {})));
}

// Oracle: the snapshot's round trip (a world's own snapshot is read back and written again as
// the same bytes) for a world in which a body with a load function was destroyed: its slot is
// dead, and a dead slot holds no load (the reader's rule), so the world's snapshot holds none
// there either. The load's captured state is released with the body.
BOOST_AUTO_TEST_CASE(a_world_whose_loaded_body_was_destroyed_is_read_back,
                     *utf::label("determinism")) {
    World w;
    const auto held = std::make_shared<int>(0);
    const BodyId loaded = w.create_body({.position = {0.0, 2.0}, .load = [held](double) {
                                             return Load{{1.0, 0.0}, 0.0};
                                         }});
    w.create_shape(loaded, circle_shape(0.25));
    const BodyId other = w.create_body({.position = {3.0, 2.0}});
    w.create_shape(other, circle_shape(0.25));
    w.step(1.0 / 60.0);
    BOOST_TEST(held.use_count() == 2);
    w.destroy_body(loaded);
    BOOST_TEST(held.use_count() == 1); // released with its body
    w.step(1.0 / 60.0);
    const std::vector<std::byte> bytes = w.snapshot();
    BOOST_TEST(World::from_snapshot(bytes).snapshot() == bytes);
}

// A body given a persistent force and torque that are set back to zero before the step writes,
// after the step, the bytes of the same body never given them. Oracle: one state, one snapshot
// (as above): the loads are zero in both worlds at the step, so the motion is the same bits,
// and how the world got there is not its state.
BOOST_AUTO_TEST_CASE(loads_set_back_to_zero_leave_no_trace_after_the_step,
                     *utf::label("determinism")) {
    const auto world = [](bool pushed) {
        World w(WorldDef{.gravity = {0.0, -10.0}});
        const BodyId b = w.create_body(BodyDef{.position = {0.0, 5.0}});
        w.create_shape(b, box_shape(1.0, 1.0));
        if (pushed) {
            w.set_force(b, {3.0, 1.0});
            w.set_torque(b, 2.0);
            w.set_force(b, {0.0, 0.0});
            w.set_torque(b, 0.0);
        }
        w.step(1.0 / 60.0);
        return w.snapshot();
    };
    BOOST_TEST((world(true) == world(false)));
}

// Oracle: world.hpp's contract for user data (any value of UserData, the game's own, kept as
// given) and the snapshot's promise: the extreme values 0, 1, the largest UserData and the top
// bit alone, on the world, a body, a shape and a joint, come back from a snapshot unchanged.
BOOST_AUTO_TEST_CASE(user_data_of_any_value_comes_back_from_a_snapshot,
                     *utf::label("reliability")) {
    constexpr UserData largest = std::numeric_limits<UserData>::max();
    for (const UserData v : {UserData(0), UserData(1), largest, largest - largest / 2}) {
        BOOST_TEST_CONTEXT("user data " << v) {
            World w;
            const BodyId a = w.create_body({});
            BodyDef bd;
            bd.position = {2.0, 0.0};
            const BodyId b = w.create_body(bd);
            const ShapeId s = w.create_shape(a, circle_shape(0.5));
            const JointId j = w.create_joint(RevoluteJointDef{.body_a = a, .body_b = b});
            w.set_user_data(v);
            w.set_user_data(b, v);
            w.set_user_data(s, v);
            w.set_user_data(j, v);
            const World copy = World::from_snapshot(w.snapshot());
            const BodyId a2 = in_world(copy, a), b2 = in_world(copy, b);
            BOOST_TEST_REQUIRE(copy.shapes(a2).size() == 1u);
            BOOST_TEST_REQUIRE(copy.joints(b2).size() == 1u);
            BOOST_TEST(copy.user_data() == v);
            BOOST_TEST(copy.user_data(b2) == v);
            BOOST_TEST(copy.user_data(copy.shapes(a2)[0]) == v);
            BOOST_TEST(copy.user_data(copy.joints(b2)[0]) == v);
            BOOST_TEST(copy.user_data(a2) == UserData(0));
            BOOST_TEST(w.user_data(s) == v);
            BOOST_TEST(w.user_data(j) == v);
        }
    }
}

BOOST_AUTO_TEST_SUITE_END()
