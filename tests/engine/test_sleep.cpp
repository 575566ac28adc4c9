// Sleeping (WorldDef::enable_sleep): islands of bodies at rest stop moving and cost almost
// nothing until something wakes them. Off by default; the oracles are the rule itself (the
// tolerances and time_to_sleep), the geometry of the scenes, and the same scene with sleeping
// off.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "support/body_changes.hpp"
#include "tamias2d/errors.hpp"
#include "tamias2d/io/scene.hpp"
#include "tamias2d/io/scene_generators.hpp"
#include "tamias2d/world.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;

namespace {

constexpr double dt = 1.0 / 60.0;
const Material rough{1.0, 0.0, 0.6};

WorldDef def_with_sleep(bool on = true) {
    WorldDef d;
    d.gravity = {0.0, -10.0};
    d.enable_sleep = on;
    return d;
}

/// A static ground 40 m wide whose top face is y = 0.
BodyId ground(World& w) {
    BodyDef g;
    g.type = BodyType::static_body;
    g.position = {0.0, -0.5};
    const BodyId id = w.create_body(g);
    w.create_shape(id, box_shape(40.0, 1.0, rough));
    return id;
}

/// A unit box with its centre at (x, y).
BodyId box(World& w, double x, double y, BodyDef d = {}) {
    d.position = {x, y};
    const BodyId id = w.create_body(d);
    w.create_shape(id, box_shape(1.0, 1.0, rough));
    return id;
}

/// Steps until every listed body sleeps; the number of steps, or -1 after `limit`.
int steps_until_asleep(World& w, const std::vector<BodyId>& ids, int limit) {
    for (int i = 1; i <= limit; ++i) {
        w.step(dt);
        bool all = true;
        for (BodyId b : ids)
            all = all && !w.is_awake(b);
        if (all)
            return i;
    }
    return -1;
}

/// Makes b `via` and dynamic again: it is then awake, and sleeps only after `needed` steps at
/// rest or more.
void made_dynamic_sleeps_after(World& w, BodyId b, BodyType via, int needed) {
    w.set_body_type(b, via);
    w.set_body_type(b, BodyType::dynamic);
    BOOST_TEST(w.is_awake(b));
    const int n = steps_until_asleep(w, {b}, 300);
    BOOST_TEST_MESSAGE("asleep after " << n << " steps");
    BOOST_TEST(n >= needed);
}

/// A generator's bodies built into `w` (io::build_world): their handles, in order.
std::vector<BodyId> build(World& w, std::vector<io::SceneBody> bodies) {
    io::Scene scene;
    scene.world = w.settings();
    scene.bodies = std::move(bodies);
    return io::build_world(scene, w);
}

bool same_bits(Vec2d a, Vec2d b) {
    return a.x == b.x && a.y == b.y;
}

} // namespace

BOOST_AUTO_TEST_SUITE(sleeping)

// Oracle: the rule (at rest for time_to_sleep) and the scene's geometry. A box dropped 0.5 m
// falls for about 0.32 s, so it cannot be asleep before 0.3 s + time_to_sleep; asleep, it has
// no velocity, rests on the ground (centre 0.5 m up) and does not move at all.
BOOST_AUTO_TEST_CASE(a_resting_box_falls_asleep_and_stays_put) {
    World w(def_with_sleep());
    ground(w);
    const BodyId b = box(w, 0.0, 1.0);
    BOOST_TEST(w.is_awake(b));
    const int n = steps_until_asleep(w, {b}, 300);
    BOOST_TEST_MESSAGE("asleep after " << n << " steps");
    BOOST_TEST_REQUIRE(n > 0);
    BOOST_TEST(n * dt >= w.settings().time_to_sleep + 0.3);
    BOOST_TEST(w.velocity(b).x == 0.0);
    BOOST_TEST(w.velocity(b).y == 0.0);
    BOOST_TEST(w.angular_velocity(b) == 0.0);
    BOOST_TEST(std::abs(w.position(b).y - 0.5) < 0.01);
    const Vec2d at = w.position(b);
    for (int i = 0; i < 120; ++i)
        w.step(dt);
    BOOST_TEST(!w.is_awake(b));
    BOOST_TEST(same_bits(w.position(b), at));
    BOOST_TEST(w.contacts().size() == 1u); // it still touches the ground
}

// Oracle: the rule (at rest for time_to_sleep). A static box is made dynamic (set_body_type): it
// is then awake, and it sleeps only once it has rested for time_to_sleep after the change
// (0.5 s, 30 steps), not at once; the same after it is made kinematic and dynamic again. Both
// for a box resting on the ground (its contact, dropped by the change, wakes it too) and for a
// box alone in the air with gravity scale 0, which nothing else wakes.
BOOST_AUTO_TEST_CASE(a_body_made_dynamic_rests_time_to_sleep_before_it_sleeps) {
    for (const bool on_ground : {true, false}) {
        BOOST_TEST_CONTEXT((on_ground ? "on the ground" : "in the air")) {
            World w(def_with_sleep());
            ground(w);
            BodyDef d;
            d.type = BodyType::static_body;
            d.gravity_scale = on_ground ? 1.0 : 0.0;
            const BodyId b = box(w, 0.0, on_ground ? 0.5 : 10.0, d);
            for (int i = 0; i < 60; ++i)
                w.step(dt);
            const int needed = int(std::ceil(w.settings().time_to_sleep / dt - 1e-9));
            for (const BodyType via : {BodyType::static_body, BodyType::kinematic})
                made_dynamic_sleeps_after(w, b, via, needed);
        }
    }
}

// Oracle: the rule (at rest: no faster than both tolerances, WorldDef::linear_sleep_tolerance
// and angular_sleep_tolerance, as Box2D v3 has it). A box alone in the air (gravity scale 0, no
// damping) turning in place at twice the angular tolerance never rests, so it never sleeps; at
// exactly the tolerance and at half of it, it sleeps once it has turned so for time_to_sleep.
// Linearly it is still in every case.
BOOST_AUTO_TEST_CASE(a_body_turning_faster_than_the_angular_tolerance_does_not_sleep) {
    for (const double factor : {2.0, 1.0, 0.5}) {
        BOOST_TEST_CONTEXT("turning at " << factor << " times the tolerance") {
            World w(def_with_sleep());
            BodyDef d;
            d.gravity_scale = 0.0;
            const BodyId b = box(w, 0.0, 10.0, d);
            w.set_angular_velocity(b, factor * w.settings().angular_sleep_tolerance);
            const int needed = int(std::ceil(w.settings().time_to_sleep / dt - 1e-9));
            const int n = steps_until_asleep(w, {b}, 4 * needed);
            BOOST_TEST_MESSAGE("asleep after " << n << " steps");
            if (factor > 1.0)
                BOOST_TEST(w.is_awake(b));
            else
                BOOST_TEST(n >= needed);
        }
    }
}

// Oracle: the rule at its boundary: an island sleeps once it has rested for time_to_sleep,
// inclusive (as Box2D v3 has it: solver.c keeps an island awake while a body's rest time is
// below the time to sleep). With a step of 1/64 s every rest time is a sum of k/64 s, exact in
// a double, so a box alone in the air (gravity scale 0, at rest from its creation) has rested
// exactly time_to_sleep after time_to_sleep * 64 steps: it sleeps at that step, not one before
// or after. Two times to sleep, both multiples of 1/64 s; and a pair of boxes joined by a weld
// (one island) sleeps at the same step.
BOOST_AUTO_TEST_CASE(an_island_sleeps_the_step_its_rest_reaches_time_to_sleep) {
    constexpr double step = 1.0 / 64.0;
    for (const double time_to_sleep : {0.5, 0.25}) {
        for (const bool pair : {false, true}) {
            BOOST_TEST_CONTEXT("time_to_sleep " << time_to_sleep << (pair ? ", a pair" : "")) {
                WorldDef def = def_with_sleep();
                def.time_to_sleep = time_to_sleep;
                World w(def);
                BodyDef d;
                d.gravity_scale = 0.0;
                std::vector<BodyId> ids{box(w, 0.0, 10.0, d)};
                if (pair) {
                    ids.push_back(box(w, 1.0, 10.0, d));
                    w.create_joint(
                        WeldJointDef{.body_a = ids[0], .body_b = ids[1], .anchor = {0.5, 10.0}});
                }
                const int expected = int(time_to_sleep / step);
                int asleep_at = -1;
                for (int k = 1; k <= expected + 2 && asleep_at < 0; ++k) {
                    w.step(step);
                    if (!w.is_awake(ids[0]))
                        asleep_at = k;
                    for (const BodyId b : ids)
                        BOOST_TEST(w.is_awake(b) == (asleep_at < 0), "body awake at step " << k);
                }
                BOOST_TEST(asleep_at == expected);
            }
        }
    }
}

// Oracle: the rule (at rest for time_to_sleep), as above. A dynamic box alone in the air
// (gravity scale 0), awake and at rest for 20 steps, is made static or kinematic and dynamic
// again: its time at rest starts again from the change, so it sleeps only once it has rested
// for time_to_sleep after it (not 20 steps fewer). Nothing else wakes it.
BOOST_AUTO_TEST_CASE(a_body_at_rest_whose_type_changes_rests_time_to_sleep_again) {
    for (const BodyType via : {BodyType::static_body, BodyType::kinematic}) {
        BOOST_TEST_CONTEXT((via == BodyType::static_body ? "via static" : "via kinematic")) {
            World w(def_with_sleep());
            ground(w);
            BodyDef d;
            d.gravity_scale = 0.0;
            const BodyId b = box(w, 0.0, 10.0, d);
            const int needed = int(std::ceil(w.settings().time_to_sleep / dt - 1e-9));
            BOOST_TEST_REQUIRE(needed > 20);
            for (int k = 0; k < 20; ++k)
                w.step(dt);
            BOOST_TEST_REQUIRE(w.is_awake(b));
            made_dynamic_sleeps_after(w, b, via, needed);
        }
    }
}

// Oracle: the rule (at rest for time_to_sleep), as above. A box is disabled and enabled again
// (set_enabled, which wakes it: its time at rest starts again from zero): it is then awake, and
// it sleeps only once it has rested for time_to_sleep after it was enabled, not at once: when
// it was asleep, on the ground and alone in the air, and when it was awake in the air and had
// already rested for 20 steps (not 20 steps fewer; on the ground the contacts found again
// after enabling move it, which restarts its time at rest in any case).
BOOST_AUTO_TEST_CASE(a_body_enabled_again_rests_time_to_sleep_before_it_sleeps) {
    struct Case {
        bool on_ground, asleep;
        const char* name;
    };
    for (const Case c :
         {Case{true, true, "asleep on the ground"}, Case{false, true, "asleep in the air"},
          Case{false, false, "awake in the air, at rest for 20 steps"}}) {
        BOOST_TEST_CONTEXT(c.name) {
            World w(def_with_sleep());
            ground(w);
            BodyDef d;
            d.gravity_scale = c.on_ground ? 1.0 : 0.0;
            const BodyId b = box(w, 0.0, c.on_ground ? 0.5 : 10.0, d);
            const int needed = int(std::ceil(w.settings().time_to_sleep / dt - 1e-9));
            BOOST_TEST_REQUIRE(needed > 20);
            if (c.asleep) {
                BOOST_TEST_REQUIRE(steps_until_asleep(w, {b}, 300) > 0);
            } else {
                for (int k = 0; k < 20; ++k)
                    w.step(dt);
                BOOST_TEST_REQUIRE(w.is_awake(b));
            }
            w.set_enabled(b, false);
            w.set_enabled(b, true);
            BOOST_TEST(w.is_awake(b));
            const int n = steps_until_asleep(w, {b}, 300);
            BOOST_TEST_MESSAGE("asleep after " << n << " steps");
            BOOST_TEST(n >= needed);
        }
    }
}

// Oracle: the rule (at rest for time_to_sleep), as above. A box woken by set_awake (world.hpp:
// its time at rest starts again from zero) stays where it is, and sleeps only once it has
// rested for time_to_sleep after it was woken: when it was asleep, and when it was awake and
// had already rested for 20 steps (not 20 steps fewer).
BOOST_AUTO_TEST_CASE(a_woken_body_rests_time_to_sleep_before_it_sleeps) {
    for (const bool asleep : {true, false}) {
        BOOST_TEST_CONTEXT((asleep ? "asleep" : "awake, at rest for 20 steps")) {
            World w(def_with_sleep());
            ground(w);
            const BodyId b = box(w, 0.0, 0.5);
            const int needed = int(std::ceil(w.settings().time_to_sleep / dt - 1e-9));
            BOOST_TEST_REQUIRE(needed > 20);
            if (asleep) {
                BOOST_TEST_REQUIRE(steps_until_asleep(w, {b}, 300) > 0);
            } else {
                for (int k = 0; k < 20; ++k)
                    w.step(dt);
                BOOST_TEST_REQUIRE(w.is_awake(b));
            }
            w.set_awake(b, true);
            BOOST_TEST(w.is_awake(b));
            BOOST_TEST(steps_until_asleep(w, {b}, 300) >= needed);
        }
    }
}

// Oracle: the same scene with sleeping off. Until a body sleeps, sleeping changes nothing: a
// pyramid whose bodies never reach time_to_sleep moves bit for bit as without sleeping.
BOOST_AUTO_TEST_CASE(sleeping_changes_nothing_until_a_body_sleeps) {
    const auto run = [](bool on) {
        WorldDef d = def_with_sleep(on);
        d.time_to_sleep = 1e9;
        World w(d);
        io::PyramidParams p;
        p.base = 8;
        const std::vector<BodyId> ids = build(w, io::generate_pyramid(p));
        for (int i = 0; i < 200; ++i)
            w.step(dt);
        std::vector<double> out;
        for (BodyId b : ids) {
            out.insert(out.end(), {w.position(b).x, w.position(b).y, w.velocity(b).x,
                                   w.velocity(b).y, w.angular_velocity(b)});
        }
        return out;
    };
    const std::vector<double> off = run(false), on = run(true);
    BOOST_TEST_REQUIRE(off.size() == on.size());
    int differ = 0;
    for (std::size_t i = 0; i < off.size(); ++i)
        differ += off[i] != on[i];
    BOOST_TEST(differ == 0);
}

// Oracle: the wake rule. A box dropped onto a sleeping stack wakes the box it lands on, and
// through the island the whole stack, in the step it first touches; once everything has been at
// rest for time_to_sleep again, all four sleep.
BOOST_AUTO_TEST_CASE(an_impact_wakes_the_sleeping_stack) {
    World w(def_with_sleep());
    ground(w);
    const std::vector<BodyId> stack = {box(w, 0.0, 0.5), box(w, 0.0, 1.5), box(w, 0.0, 2.5)};
    BOOST_TEST_REQUIRE(steps_until_asleep(w, stack, 600) > 0);
    const BodyId dropped = box(w, 0.0, 5.0);
    bool woke = false;
    for (int i = 0; i < 120 && !woke; ++i) {
        w.step(dt);
        if (!w.contact_begin_events().empty()) {
            woke = true;
            for (BodyId b : stack)
                BOOST_TEST(w.is_awake(b));
        } else {
            for (BodyId b : stack)
                BOOST_TEST(!w.is_awake(b)); // nothing touched them yet
        }
    }
    BOOST_TEST(woke);
    std::vector<BodyId> all = stack;
    all.push_back(dropped);
    BOOST_TEST(steps_until_asleep(w, all, 900) > 0);
    BOOST_TEST(std::abs(w.position(dropped).y - 3.5) < 0.05); // on top of the stack
}

// Oracle: the rule at its edge: with time_to_sleep 0 a body sleeps at the first step it ends
// slower than the tolerances, and not before (a falling box is not slow). That may be in the
// air, at the top of a small rebound: time_to_sleep is what guards against it.
BOOST_AUTO_TEST_CASE(time_to_sleep_zero_still_needs_rest) {
    WorldDef d = def_with_sleep();
    d.time_to_sleep = 0.0;
    World w(d);
    ground(w);
    const BodyId b = box(w, 0.0, 3.0);
    bool landed = false;
    int steps = 0;
    while (w.is_awake(b) && steps < 300) {
        w.step(dt);
        ++steps;
        landed = landed || !w.contact_begin_events().empty();
    }
    BOOST_TEST(!w.is_awake(b));
    BOOST_TEST(landed); // it was never slow before it reached the ground
    BOOST_TEST(steps > 1);
}

// Oracle: the API's contract (world.hpp): every call that changes a body's transform,
// velocities or loads wakes it.
BOOST_AUTO_TEST_CASE(api_calls_wake_a_sleeping_body) {
    std::vector<test::BodyCall> calls = test::body_changes();
    calls.push_back({"set_awake", [](World& w, BodyId b) { w.set_awake(b, true); }});
    calls.push_back({"set_gravity", [](World& w, BodyId) { w.set_gravity({0.0, -10.0}); }});
    for (const auto& [name, call] : calls) {
        BOOST_TEST_CONTEXT(name) {
            World w(def_with_sleep());
            ground(w);
            const BodyId b = box(w, 0.0, 0.5);
            BOOST_TEST_REQUIRE(steps_until_asleep(w, {b}, 300) > 0);
            call(w, b);
            BOOST_TEST(w.is_awake(b));
        }
    }
}

// Oracle: the wake rule for lost support, and free fall (the box falls 1 m to the ground).
// Destroying the box under a sleeping box, or moving the static ground away, wakes what rested
// on it, which then falls.
BOOST_AUTO_TEST_CASE(removing_the_support_wakes_what_rests_on_it) {
    {
        World w(def_with_sleep());
        ground(w);
        const BodyId lower = box(w, 0.0, 0.5), upper = box(w, 0.0, 1.5);
        BOOST_TEST_REQUIRE(steps_until_asleep(w, {lower, upper}, 600) > 0);
        w.destroy_body(lower);
        BOOST_TEST(w.is_awake(upper));
        for (int i = 0; i < 120; ++i)
            w.step(dt);
        BOOST_TEST(std::abs(w.position(upper).y - 0.5) < 0.01);
    }
    {
        World w(def_with_sleep());
        const BodyId g = ground(w);
        const BodyId b = box(w, 0.0, 0.5);
        BOOST_TEST_REQUIRE(steps_until_asleep(w, {b}, 300) > 0);
        w.set_transform(g, {100.0, -0.5}, 0.0); // the ground goes: the box must fall
        BOOST_TEST(w.is_awake(b));
        for (int i = 0; i < 30; ++i)
            w.step(dt);
        BOOST_TEST(w.position(b).y < 0.0);
    }
}

// Oracle: the rule's exceptions. A body that may not sleep keeps its island awake, and a body
// with a persistent load is never at rest.
BOOST_AUTO_TEST_CASE(what_may_not_sleep_keeps_its_island_awake) {
    World w(def_with_sleep());
    ground(w);
    BodyDef restless;
    restless.enable_sleep = false;
    const BodyId lower = box(w, 0.0, 0.5, restless), upper = box(w, 0.0, 1.5);
    const BodyId alone = box(w, 5.0, 0.5);
    BodyDef pushed;
    pushed.force = {0.1, 0.0}; // less than friction can hold: it stays at rest
    const BodyId held = box(w, -5.0, 0.5, pushed);
    for (int i = 0; i < 300; ++i)
        w.step(dt);
    BOOST_TEST(w.is_awake(lower));
    BOOST_TEST(w.is_awake(upper));
    BOOST_TEST(w.is_awake(held));
    BOOST_TEST(!w.is_awake(alone));
}

// Oracle: the API's contract. With sleeping on, a body defined asleep hangs where it is until
// woken; set_awake(false) does the same to a falling body; with sleeping off both are ignored.
BOOST_AUTO_TEST_CASE(bodies_put_to_sleep_wait_to_be_woken) {
    BodyDef asleep;
    asleep.awake = false;
    {
        World w(def_with_sleep());
        const BodyId b = box(w, 0.0, 10.0, asleep);
        const BodyId c = box(w, 5.0, 10.0);
        w.step(dt);
        w.set_awake(c, false);
        for (int i = 0; i < 30; ++i)
            w.step(dt);
        BOOST_TEST(!w.is_awake(b));
        BOOST_TEST(w.position(b).y == 10.0);
        BOOST_TEST(!w.is_awake(c));
        const double c_y = w.position(c).y;
        w.set_awake(b, true);
        w.step(dt);
        BOOST_TEST(w.position(b).y < 10.0);
        BOOST_TEST(w.position(c).y == c_y);
    }
    {
        World w(def_with_sleep(false));
        const BodyId b = box(w, 0.0, 10.0, asleep);
        w.set_awake(b, false);
        w.step(dt);
        BOOST_TEST(w.is_awake(b));
        BOOST_TEST(w.position(b).y < 10.0);
    }
}

// Oracle: the documented rule of set_awake, a body put to sleep has zero velocities, loads and
// time at rest, as one defined asleep has; state_hash reads the sleep timers. Without gravity a
// box rests awake for 20 steps (a third of time_to_sleep) and is put to sleep; a second world
// whose box is defined asleep steps as often. Their states are equal.
BOOST_AUTO_TEST_CASE(a_body_put_to_sleep_is_as_one_defined_asleep) {
    WorldDef d = def_with_sleep();
    d.gravity = {0.0, 0.0};
    World rested(d), defined(d);
    const BodyId a = box(rested, 0.0, 1.0);
    BodyDef asleep;
    asleep.awake = false;
    box(defined, 0.0, 1.0, asleep);
    for (int i = 0; i < 20; ++i) {
        rested.step(dt);
        defined.step(dt);
    }
    BOOST_TEST_REQUIRE(rested.is_awake(a));
    BOOST_TEST(rested.state_hash() != defined.state_hash()); // its time at rest is counted
    rested.set_awake(a, false);
    BOOST_TEST(rested.state_hash() == defined.state_hash());
}

// Oracle: the body_control rule (world.hpp): setting a value a body already has changes no bit
// of the simulation. A box on the ground that the sleep rule put to sleep is asleep, so
// set_awake(false) on it (which zeroes velocities, one-step loads and time at rest) must leave
// the world's state_hash, which reads the sleep timers, as it was; and its world steps on with
// the bits of a twin that was not told.
BOOST_AUTO_TEST_CASE(a_body_the_rule_put_to_sleep_is_asleep_as_set_awake_puts_it) {
    World told(def_with_sleep()), twin(def_with_sleep());
    ground(told);
    ground(twin);
    const BodyId a = box(told, 0.0, 1.0), b = box(twin, 0.0, 1.0);
    const int n = steps_until_asleep(told, {a}, 300);
    BOOST_TEST_REQUIRE(n > 0);
    BOOST_TEST_REQUIRE(steps_until_asleep(twin, {b}, 300) == n);
    const std::uint64_t before = told.state_hash();
    told.set_awake(a, false);
    BOOST_TEST(told.state_hash() == before);
    for (int i = 0; i < 30; ++i) {
        told.step(dt);
        twin.step(dt);
    }
    BOOST_TEST(told.state_hash() == twin.state_hash());
    BOOST_TEST((told.snapshot() == twin.snapshot()));
}

// Oracle: the documented rule of set_awake, a body put to sleep loses its one-step loads. A
// force and a torque applied before it sleeps are gone when it wakes: without gravity the next
// step leaves the box exactly where it was, unturned and at rest. Newton's first law for a box
// with no load.
BOOST_AUTO_TEST_CASE(a_body_put_to_sleep_drops_its_one_step_loads) {
    WorldDef d = def_with_sleep();
    d.gravity = {0.0, 0.0};
    World w(d);
    const BodyId a = box(w, 0.0, 1.0);
    w.apply_force(a, {30.0, 0.0}, {0.0, 1.4});
    w.apply_torque(a, 2.0);
    w.set_awake(a, false);
    w.set_awake(a, true);
    w.step(dt);
    BOOST_TEST(same_bits(w.position(a), {0.0, 1.0}));
    BOOST_TEST(w.orientation(a) == 0.0);
    BOOST_TEST(same_bits(w.velocity(a), {0.0, 0.0}));
    BOOST_TEST(w.angular_velocity(a) == 0.0);
}

// Oracle: the documented rule of set_awake, a body put to sleep has zero velocities, and
// Newton's first law once it is woken: without gravity a box moving at (1, 0.5) m/s and turning
// at 2 rad/s, put to sleep and woken, reads zero velocities and stays exactly where it was,
// unturned, over the next step.
BOOST_AUTO_TEST_CASE(a_moving_body_put_to_sleep_stops_moving_and_turning) {
    WorldDef d = def_with_sleep();
    d.gravity = {0.0, 0.0};
    World w(d);
    const BodyId a =
        box(w, 0.0, 1.0, BodyDef{.linear_velocity = {1.0, 0.5}, .angular_velocity = 2.0});
    w.step(dt);
    const Vec2d p = w.position(a);
    const double phi = w.orientation(a);
    w.set_awake(a, false);
    BOOST_TEST(same_bits(w.velocity(a), {0.0, 0.0}));
    BOOST_TEST(w.angular_velocity(a) == 0.0);
    w.set_awake(a, true);
    w.step(dt);
    BOOST_TEST(same_bits(w.position(a), p));
    BOOST_TEST(w.orientation(a) == phi);
}

// Oracle: the rule "an island falls asleep ... Its velocities become zero" (docs/user-guide.md,
// "Sleeping"). Without gravity a box drifts at 1 cm/s and turns at 0.01 rad/s, both below the
// tolerances, so it falls asleep after time_to_sleep while still moving; asleep, its velocities
// read zero and it stays where it fell asleep.
BOOST_AUTO_TEST_CASE(a_drifting_body_that_falls_asleep_stops) {
    WorldDef d = def_with_sleep();
    d.gravity = {0.0, 0.0};
    World w(d);
    BodyDef drift;
    drift.linear_velocity = {0.01, 0.0};
    drift.angular_velocity = 0.01;
    const BodyId b = box(w, 0.0, 1.0, drift);
    const int n = steps_until_asleep(w, {b}, 120);
    BOOST_TEST_REQUIRE(n > 0);
    BOOST_TEST(n * dt >= d.time_to_sleep);
    BOOST_TEST(w.velocity(b).x == 0.0);
    BOOST_TEST(w.velocity(b).y == 0.0);
    BOOST_TEST(w.angular_velocity(b) == 0.0);
    const Vec2d at = w.position(b);
    w.step(dt);
    BOOST_TEST(same_bits(w.position(b), at));
    w.set_awake(b, true); // woken, it starts from rest
    w.step(dt);
    BOOST_TEST(same_bits(w.position(b), at));
}

// Oracle: a kinematic body's given motion. A moving kinematic body that reaches a sleeping box
// wakes it and pushes it along; a kinematic body at rest falls asleep like any other.
BOOST_AUTO_TEST_CASE(kinematic_bodies_wake_what_they_reach) {
    World w(def_with_sleep());
    ground(w);
    const BodyId b = box(w, 0.0, 0.5);
    BodyDef still;
    still.type = BodyType::kinematic;
    const BodyId parked = box(w, 10.0, 3.0, still);
    BOOST_TEST_REQUIRE(steps_until_asleep(w, {b, parked}, 300) > 0);
    BodyDef pusher;
    pusher.type = BodyType::kinematic;
    pusher.linear_velocity = {2.0, 0.0};
    const BodyId k = box(w, -3.0, 0.5, pusher);
    for (int i = 0; i < 120; ++i)
        w.step(dt);
    BOOST_TEST(w.is_awake(k));
    BOOST_TEST(w.is_awake(b));
    BOOST_TEST(w.position(b).x > 0.5); // pushed
}

// Oracle: determinism (the brief's standard): the same input gives the same bits, sleeping on.
BOOST_AUTO_TEST_CASE(sleeping_is_deterministic) {
    const auto run = [] {
        World w(def_with_sleep());
        io::RainParams p;
        p.count = 120;
        p.container.width = 6.0;
        build(w, io::generate_rain(p));
        int asleep = 0;
        for (int i = 0; i < 600; ++i)
            w.step(dt);
        for (BodyId b : w.bodies())
            asleep += w.type(b) == BodyType::dynamic && !w.is_awake(b);
        return std::pair{w.state_hash(), asleep};
    };
    const auto [h1, asleep] = run();
    const auto [h2, asleep2] = run();
    BOOST_TEST(h1 == h2);
    BOOST_TEST(asleep == asleep2);
    BOOST_TEST_MESSAGE(asleep << " of 120 rain boxes asleep after 10 s");
    BOOST_TEST(asleep > 0);
}

// Oracle: the rule's invariants, after every step of a rain disturbed at random (impulses,
// teleports, destroyed boxes, boxes put to sleep by hand): two touching non-static bodies are
// both awake or both asleep (islands sleep and wake whole), and a sleeping body has no velocity
// and has not moved since the step before, if it slept then too.
BOOST_AUTO_TEST_CASE(sleep_invariants_hold_under_random_changes) {
    World w(def_with_sleep());
    io::RainParams p;
    p.count = 150;
    p.container.width = 6.0;
    std::vector<BodyId> boxes;
    for (BodyId id : build(w, io::generate_rain(p))) {
        if (w.type(id) == BodyType::dynamic)
            boxes.push_back(id);
    }
    std::mt19937_64 rng(7);
    // Often in the first 10 s, rarely in the last 10 (so that the pile also sleeps for long).
    std::uniform_int_distribution<int> often(0, 59), rarely(0, 599);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::vector<std::pair<BodyId, Vec2d>> asleep_before;
    int violations = 0, slept = 0, checked_pairs = 0;
    for (int step = 0; step < 1200; ++step) {
        w.step(dt);
        for (const ContactInfo& c : w.contacts()) {
            if (w.type(c.body_a) == BodyType::static_body ||
                w.type(c.body_b) == BodyType::static_body)
                continue;
            ++checked_pairs;
            violations += w.is_awake(c.body_a) != w.is_awake(c.body_b);
        }
        for (const auto& [b, at] : asleep_before) {
            if (w.is_valid(b) && !w.is_awake(b))
                violations += !same_bits(w.position(b), at);
        }
        asleep_before.clear();
        for (BodyId b : boxes) {
            if (!w.is_valid(b) || w.is_awake(b))
                continue;
            ++slept;
            violations +=
                w.velocity(b).x != 0.0 || w.velocity(b).y != 0.0 || w.angular_velocity(b) != 0.0;
            asleep_before.push_back({b, w.position(b)});
        }
        // Now and then a change through the API, after the checks (it may wake one body of an
        // island until the next step joins the rest).
        const BodyId target = boxes[std::size_t(step * 7919) % boxes.size()];
        if (!w.is_valid(target))
            continue;
        switch (step < 600 ? often(rng) : rarely(rng)) {
        case 0:
            w.apply_impulse(target, {u(rng), 2.0 * std::abs(u(rng))}, w.position(target));
            break;
        case 1:
            w.set_transform(target, {2.0 * u(rng), 8.0}, u(rng));
            break;
        case 2:
            w.destroy_body(target);
            break;
        case 3:
            w.set_awake(target, false);
            break;
        default:
            break;
        }
    }
    BOOST_TEST_MESSAGE(slept << " sleeping box-steps, " << checked_pairs
                             << " touching pairs checked");
    BOOST_TEST(slept > 10000); // the rule was exercised
    BOOST_TEST(violations == 0);
}

// Oracle: data constraints (R4): the sleep settings are non-negative and finite, and an error
// names the field.
BOOST_AUTO_TEST_CASE(sleep_settings_are_validated, *utf::label("R4")) {
    const auto field_of = [](WorldDef d) -> std::string {
        try {
            World w(d);
        } catch (const ValidationError& e) {
            return e.field;
        }
        return "";
    };
    WorldDef d = def_with_sleep();
    d.time_to_sleep = -1.0;
    BOOST_TEST(field_of(d) == "world.time_to_sleep");
    d = def_with_sleep();
    d.linear_sleep_tolerance = std::numeric_limits<double>::quiet_NaN();
    BOOST_TEST(field_of(d) == "world.linear_sleep_tolerance");
    d = def_with_sleep();
    d.angular_sleep_tolerance = std::numeric_limits<double>::infinity();
    BOOST_TEST(field_of(d) == "world.angular_sleep_tolerance");
}

BOOST_AUTO_TEST_SUITE_END()
