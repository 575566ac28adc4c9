// The pre-solve callback (World::set_pre_solve) on a one-way platform: a box rising through it
// from below passes, in free flight also where the continuous pass sweeps it, a box falling
// onto it rests on it at the closed-form height, and a fast disc is still stopped on it; what
// the callback sees, the events of the pairs it refuses, its exception, and equal results on 1
// to 4 workers.
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <span>
#include <stdexcept>
#include <vector>

#include "support/pyramid.hpp"
#include "tamias2d/world.hpp"

using namespace tamias2d;
namespace utf = boost::unit_test;

namespace {

constexpr double dt = 1.0 / 60.0;
constexpr double g = 9.81;
constexpr double platform_top = 3.1; // m: a 4 m x 0.2 m platform centred at y = 3
constexpr double half_height = 0.25; // m: the 0.5 m box

/// A static floor (top y = 0), a static platform above it, and a box under the platform.
struct Level {
    World world;
    ShapeId platform;
    BodyId box;
    ShapeId box_shape_id;
    explicit Level(WorldDef def = {}) : world(def) {
        BodyDef sd;
        sd.type = BodyType::static_body;
        sd.position = {0.0, -0.5};
        world.create_shape(world.create_body(sd), box_shape(20.0, 1.0));
        sd.position = {0.0, 3.0};
        platform = world.create_shape(world.create_body(sd), box_shape(4.0, 0.2));
        BodyDef bd;
        bd.position = {0.0, half_height};
        box = world.create_body(bd);
        box_shape_id = world.create_shape(box, box_shape(0.5, 0.5, Material{1.0, 0.0, 0.5}));
    }
    /// The one-way rule: a contact with the platform is solved only when its normal pushes the
    /// other body up (the normal runs from shape_a into shape_b).
    void make_one_way() {
        world.set_pre_solve([p = platform](const PreSolveContact& c) {
            if (c.shape_a == p)
                return c.normal.y > 0.7;
            if (c.shape_b == p)
                return c.normal.y < -0.7;
            return true;
        });
    }
};

} // namespace

BOOST_AUTO_TEST_SUITE(contact_hooks_pre_solve, *utf::label("reliability"))

// Oracle: closed form. The box leaves the floor at 10 m/s: free, it would rise to
// 0.25 + 10^2 / (2 g) = 5.35 m, above the platform's top, so it passes through and its bottom
// rises above the top (3.1 m); it falls back and rests on the platform with its centre at
// top + half height = 3.35 m. The soft contact holds it within its static overlap,
// g / (2 pi f)^2 with f = 45 Hz (WorldDef::contact_hertz; 1.2e-4 m), plus the linear slop (0 by
// default): 2e-4 m bounds it. Without the callback the platform stops it from below.
BOOST_AUTO_TEST_CASE(one_way_platform_passes_from_below_and_holds_from_above) {
    Level level;
    level.make_one_way();
    level.world.set_velocity(level.box, {0.0, 10.0});
    double highest = 0.0;
    for (int i = 0; i < 300; ++i) {
        level.world.step(dt);
        highest = std::max(highest, level.world.position(level.box).y);
    }
    BOOST_TEST(highest - half_height > platform_top);                         // it passed
    BOOST_TEST(std::abs(highest - (half_height + 100.0 / (2.0 * g))) < 0.05); // unhindered
    const double rest = platform_top + half_height;
    const double overlap = g / std::pow(2.0 * std::numbers::pi * 45.0, 2);
    BOOST_TEST(std::abs(level.world.position(level.box).y - rest) <= 2.0 * overlap);
    BOOST_TEST(std::abs(level.world.velocity(level.box).y) < 1e-6);

    Level two_way; // the control: no callback
    two_way.world.set_velocity(two_way.box, {0.0, 10.0});
    double top_reached = 0.0;
    for (int i = 0; i < 300; ++i) {
        two_way.world.step(dt);
        top_reached = std::max(top_reached, two_way.world.position(two_way.box).y);
    }
    BOOST_TEST(top_reached < 3.0); // its centre never reached the platform's
    BOOST_TEST(std::abs(two_way.world.position(two_way.box).y - half_height) <= 2.0 * overlap);
}

// Oracle: closed form, free flight. The box leaves the floor at 10 m/s and, the platform
// switched off for it by the one-way rule, flies freely: its height after t seconds is
// 0.25 + 10 t - g t^2 / 2, which the step's substeps (h = dt / 4) follow to within g t h / 2
// (semi-implicit Euler under constant gravity), 0.021 m over the first second; 0.03 m bounds
// it. The box moves 0.17 m a step, more than the speculative distance, so the continuous pass
// sweeps it each step, and its core crosses the platform: the pass asks the same rule, which
// lets it through. (A pass that stopped it would hold it under the platform, as when time
// stood still: its height and speed those of the step before.)
BOOST_AUTO_TEST_CASE(a_fast_box_rises_through_the_platform_in_free_flight) {
    Level level;
    level.make_one_way();
    const double v0 = 10.0;
    level.world.set_velocity(level.box, {0.0, v0});
    double worst = 0.0;
    for (int i = 1; i <= 60; ++i) {
        level.world.step(dt);
        const double t = i * dt;
        worst = std::max(worst, std::abs(level.world.position(level.box).y -
                                         (half_height + v0 * t - 0.5 * g * t * t)));
    }
    BOOST_TEST(worst < 0.03);
}

// Oracle: closed form, rest on the platform's top (top + radius, within the soft contact's
// overlap as above), and the continuous pass's purpose (DD29). A disc of 0.1 m falling at
// 40 m/s moves 0.67 m a step, more than the platform's 0.2 m and its own 0.2 m together. It is
// dropped from the height at which free flight (semi-implicit Euler on the substeps, as above:
// y0 + v0 t - g t^2 / 2 - g t h / 2) puts its bottom 5 cm above the platform after 12 steps,
// beyond the speculative distance (2 cm), and below the platform's bottom after 13: with the
// pass off it falls through the platform to the floor (the control). With the pass on and the
// one-way rule set, the rule admits the platform pushing it up, so the pass still stops it
// above the platform and it comes to rest on it.
BOOST_AUTO_TEST_CASE(a_fast_disc_falling_onto_the_platform_is_still_stopped) {
    const double radius = 0.1, v0 = -40.0, h = dt / 4.0, t = 12 * dt;
    const double y0 = platform_top + 0.05 + radius - (v0 * t - 0.5 * g * t * t - 0.5 * g * t * h);
    const auto drop = [&](bool continuous) {
        WorldDef def;
        def.enable_continuous = continuous;
        Level level(def);
        level.make_one_way();
        BodyDef bd;
        bd.position = {1.0, y0};
        bd.linear_velocity = {0.0, v0};
        const BodyId disc = level.world.create_body(bd);
        level.world.create_shape(disc, circle_shape(radius));
        for (int i = 0; i < 120; ++i)
            level.world.step(dt);
        return level.world.position(disc).y;
    };
    const double overlap = g / std::pow(2.0 * std::numbers::pi * 45.0, 2);
    BOOST_TEST(std::abs(drop(true) - (platform_top + radius)) <= 2.0 * overlap);
    BOOST_TEST(std::abs(drop(false) - radius) <= 2.0 * overlap); // through it, on the floor
}

// Oracle: the callback's stated input: touching pairs only, each body the one carrying its
// shape (World::body), unit normal from shape_a into shape_b, 1 or 2 points; for the box
// resting on the floor, the normal is (0, +-1) and its two points lie on the floor's top face
// (y = 0, within the soft contact's overlap).
BOOST_AUTO_TEST_CASE(the_callback_sees_the_manifold) {
    Level level;
    std::vector<PreSolveContact> seen;
    level.world.set_pre_solve([&](const PreSolveContact& c) {
        seen.push_back(c);
        return true;
    });
    for (int i = 0; i < 30; ++i)
        level.world.step(dt);
    BOOST_TEST_REQUIRE(!seen.empty());
    const PreSolveContact& c = seen.back();
    BOOST_TEST(c.point_count == 2);
    BOOST_TEST(std::abs(std::abs(c.normal.y) - 1.0) < 1e-12);
    BOOST_TEST((c.body_a == level.box || c.body_b == level.box));
    BOOST_TEST((c.body_a == level.world.body(c.shape_a)));
    BOOST_TEST((c.body_b == level.world.body(c.shape_b)));
    for (int j = 0; j < c.point_count; ++j)
        BOOST_TEST(std::abs(c.points[j].point.y) < 1e-3);
    // A callback that always answers true changes no bit.
    Level plain;
    for (int i = 0; i < 30; ++i)
        plain.world.step(dt);
    BOOST_TEST(plain.world.state_hash() == level.world.state_hash());
}

// Oracle: the callback's stated rule for events: a pair it switches off counts as not touching,
// "with the end and begin events that follow" (contact_hooks.hpp). The box resting on the floor
// has begun touching it; refused for one step, it ends (one end event, no begin), and accepted
// again it begins (one begin event, no end). A box dropped onto the floor and refused from the
// step it first touches gives neither event while refused.
BOOST_AUTO_TEST_CASE(a_refused_pair_ends_and_an_accepted_one_begins_again) {
    const auto count = [](std::span<const ContactEvent> events, BodyId body) {
        return std::count_if(events.begin(), events.end(), [&](const ContactEvent& e) {
            return e.body_a == body || e.body_b == body;
        });
    };
    Level level;
    for (int i = 0; i < 30; ++i)
        level.world.step(dt);
    BOOST_TEST_REQUIRE(level.world.contacts().size() == 1u); // resting on the floor
    bool refuse = true;
    level.world.set_pre_solve([&](const PreSolveContact&) { return !refuse; });
    level.world.step(dt);
    BOOST_TEST(count(level.world.contact_end_events(), level.box) == 1);
    BOOST_TEST(count(level.world.contact_begin_events(), level.box) == 0);
    refuse = false;
    level.world.step(dt);
    BOOST_TEST(count(level.world.contact_begin_events(), level.box) == 1);
    BOOST_TEST(count(level.world.contact_end_events(), level.box) == 0);

    Level dropped;
    dropped.world.set_transform(dropped.box, {0.0, 1.0}, 0.0);
    int touched = 0, begun = 0, ended = 0;
    dropped.world.set_pre_solve([&](const PreSolveContact&) {
        ++touched;
        return false;
    });
    for (int i = 0; i < 40; ++i) {
        dropped.world.step(dt);
        begun += int(count(dropped.world.contact_begin_events(), dropped.box));
        ended += int(count(dropped.world.contact_end_events(), dropped.box));
    }
    BOOST_TEST_REQUIRE(touched > 0); // it reached the floor and was refused
    BOOST_TEST(begun == 0);
    BOOST_TEST(ended == 0);
}

// Oracle: the callback's stated rule: a refused contact's manifold is emptied, so the next
// narrow phase computes it afresh and no point keeps the impulse of the steps before (no warm
// start). A twin world whose box is filtered out of the floor for that step (DD27: the contact
// removed) and let in again meets the floor the next step as a new pair, also without a warm
// start: every step after gives the same bits. The resting box's contact carries an impulse
// (its weight), so a warm start from it would show.
BOOST_AUTO_TEST_CASE(a_refused_pair_starts_again_without_a_warm_start) {
    Level refused, filtered;
    for (Level* l : {&refused, &filtered})
        for (int i = 0; i < 30; ++i)
            l->world.step(dt);
    BOOST_TEST_REQUIRE(refused.world.contacts().size() == 1u); // resting on the floor
    bool refuse = true;
    refused.world.set_pre_solve([&](const PreSolveContact&) { return !refuse; });
    refused.world.step(dt);
    refuse = false;
    const Filter admits = filtered.world.filter(filtered.box_shape_id);
    filtered.world.set_filter(filtered.box_shape_id, Filter{.mask_bits = 0});
    filtered.world.step(dt);
    filtered.world.set_filter(filtered.box_shape_id, admits);
    for (int i = 0; i < 10; ++i) {
        refused.world.step(dt);
        filtered.world.step(dt);
        const BodyState a = refused.world.state(refused.box),
                        b = filtered.world.state(filtered.box);
        BOOST_TEST_REQUIRE(a.position.y == b.position.y);
        BOOST_TEST_REQUIRE(a.velocity.y == b.velocity.y);
        BOOST_TEST_REQUIRE(a.position.x == b.position.x);
        BOOST_TEST_REQUIRE(a.orientation == b.orientation);
    }
    BOOST_TEST(refused.world.contacts().size() == 1u); // resting again
}

// Oracle: the stated rule for an exception of the callback: the step finishes with the
// contact solved (as a true) and then rethrows it.
BOOST_AUTO_TEST_CASE(an_exception_is_rethrown_after_a_whole_step) {
    Level level, plain;
    for (int i = 0; i < 5; ++i) {
        level.world.step(dt);
        plain.world.step(dt);
    }
    level.world.set_pre_solve(
        [](const PreSolveContact&) -> bool { throw std::runtime_error("game bug"); });
    BOOST_CHECK_THROW(level.world.step(dt), std::runtime_error);
    plain.world.step(dt);
    BOOST_TEST(level.world.state_hash() == plain.world.state_hash());
    level.world.set_pre_solve({});
    level.world.step(dt); // and the next step runs without it
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(contact_hooks_pre_solve_workers, *utf::label("determinism"))

// Oracle: the determinism requirement: a pyramid whose every third box is let fall through
// the ground by the callback gives the same state hash on 1, 2, 3 and 4 workers, step by step;
// and the callback changes the run.
BOOST_AUTO_TEST_CASE(equal_on_one_to_four_workers) {
    std::uint64_t reference[90];
    for (int workers = 1; workers <= 4; ++workers) {
        World w{WorldDef{.workers = workers}};
        test::build_pyramid(w, 10);
        w.set_pre_solve(
            [](const PreSolveContact& c) { return (c.body_a.index + c.body_b.index) % 3 != 0; });
        for (int i = 0; i < 90; ++i) {
            w.step(dt);
            if (workers == 1)
                reference[i] = w.state_hash();
            else
                BOOST_TEST_REQUIRE(w.state_hash() == reference[i]);
        }
    }
    World plain{WorldDef{}};
    test::build_pyramid(plain, 10);
    for (int i = 0; i < 90; ++i)
        plain.step(dt);
    BOOST_TEST(plain.state_hash() != reference[89]);
}

BOOST_AUTO_TEST_SUITE_END()
