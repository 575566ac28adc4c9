// World::set_profiling, profile and counters: the stage times are consistent with the whole
// step's and cost no simulated bit, and the counters equal counts made by hand on a known
// scene (and from World::contacts()).
#include <boost/test/unit_test.hpp>

#include <chrono>
#include <cstdint>
#include <vector>

#include "tamias2d/world.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;

namespace {

constexpr double dt = 1.0 / 60.0;

/// A ground, three stacks of two 1 m boxes 4 m apart, a ball high above, two boxes joined by
/// a revolute joint falling freely far from everything, and (for the stages that need them) a
/// sensor and a bullet.
struct KnownScene {
    World world;
    std::vector<BodyId> stack_boxes;
    explicit KnownScene(WorldDef def) : world(def) {
        BodyDef g;
        g.type = BodyType::static_body;
        world.create_shape(world.create_body(g), box_shape(40.0, 1.0, {}, {0.0, -0.5}));
        for (int s = 0; s < 3; ++s) {
            for (int k = 0; k < 2; ++k) {
                BodyDef d;
                d.position = {-4.0 + 4.0 * s, 0.5 + 1.0 * k};
                const BodyId b = world.create_body(d);
                world.create_shape(b, box_shape(1.0, 1.0));
                stack_boxes.push_back(b);
            }
        }
        BodyDef ball;
        ball.position = {12.0, 100.0};
        world.create_shape(world.create_body(ball), circle_shape(0.5));
        BodyDef pa, pb;
        pa.position = {-12.0, 60.0};
        pb.position = {-11.0, 60.0};
        const BodyId a = world.create_body(pa);
        const BodyId b = world.create_body(pb);
        world.create_shape(a, box_shape(0.5, 0.5));
        world.create_shape(b, box_shape(0.5, 0.5));
        world.create_joint(RevoluteJointDef{.body_a = a, .body_b = b, .anchor = {-11.5, 60.0}});
    }
};

/// KnownScene plus a sensor the stacks' left box falls through and a bullet: every stage of
/// the step has work.
void add_sensor_and_bullet(World& w) {
    BodyDef s;
    s.type = BodyType::static_body;
    s.position = {-4.0, 1.0};
    ShapeDef sensor = box_shape(2.0, 2.0);
    sensor.is_sensor = true;
    w.create_shape(w.create_body(s), sensor);
    BodyDef b;
    b.position = {20.0, 3.0};
    b.linear_velocity = {-200.0, 0.0};
    b.bullet = true;
    w.create_shape(w.create_body(b), circle_shape(0.1));
}

} // namespace

BOOST_AUTO_TEST_SUITE(profile_counters)

// Oracle: a second world stepped without profiling (state_hash, bitwise), on 1 to 4 workers,
// with sleeping on and off: timing reads a clock and writes only the profile.
BOOST_AUTO_TEST_CASE(profiling_changes_no_bit, *utf::label("determinism")) {
    for (const bool sleep : {false, true}) {
        for (int workers = 1; workers <= 4; ++workers) {
            const WorldDef def{.enable_sleep = sleep, .workers = workers};
            KnownScene plain(def), timed(def);
            add_sensor_and_bullet(plain.world);
            add_sensor_and_bullet(timed.world);
            timed.world.set_profiling(true);
            for (int k = 0; k < 90; ++k) {
                plain.world.step(dt);
                timed.world.step(dt);
                if (k == 30) // on and off again, and the same value twice: no bit changes
                    timed.world.set_profiling(false);
                if (k == 40) {
                    timed.world.set_profiling(true);
                    timed.world.set_profiling(true);
                }
            }
            BOOST_TEST(timed.world.state_hash() == plain.world.state_hash(),
                       "sleep " << sleep << ", workers " << workers);
        }
    }
}

// Oracle: the definitions in profile.hpp: each stage a part of the step (non-negative, their
// sum at most the whole step's time), the step's time a part of the call (at most the time the
// same steady clock reads around World::step), zero before a profiled step and after profiling
// is turned off.
BOOST_AUTO_TEST_CASE(stage_times_add_up, *utf::label("reliability")) {
    KnownScene s(WorldDef{.enable_sleep = true});
    add_sensor_and_bullet(s.world);
    BOOST_TEST(!s.world.profiling());
    s.world.step(dt);
    BOOST_TEST(s.world.profile().step == 0.0); // off: nothing measured
    s.world.set_profiling(true);
    BOOST_TEST(s.world.profiling());
    for (int k = 0; k < 20; ++k) {
        const auto called = std::chrono::steady_clock::now();
        s.world.step(dt);
        const double call =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - called).count();
        const StepProfile p = s.world.profile();
        BOOST_TEST(p.step <= call);
        const double stages[] = {p.prepare,  p.broad_phase, p.narrow_phase, p.solve,
                                 p.finalize, p.continuous,  p.events,       p.sleep};
        double sum = 0.0;
        for (const double t : stages) {
            BOOST_TEST(t >= 0.0);
            sum += t;
        }
        BOOST_TEST(p.step > 0.0);
        BOOST_TEST(p.solve > 0.0);
        BOOST_TEST(sum <= p.step);
    }
    s.world.set_profiling(false);
    BOOST_TEST(s.world.profile().step == 0.0);
    BOOST_TEST(s.world.profile().solve == 0.0);
}

// Oracle: hand count of KnownScene after one second at rest: 10 bodies and shapes (ground,
// six stack boxes, a ball, two joined boxes), one joint; each stack touches twice (bottom box
// on the ground, top box on the bottom one), two points each: 6 touching pairs, 12 points; no
// other boxes come near (stacks 4 m apart, the ball and the joined pair far above), so 6
// pairs; islands: the three stacks, the ball, the joined pair: 5. The solver's packs: the three
// ground manifolds share no moving body (one pack), each upper manifold follows one of them on
// its bottom box (a second pack): 2. The touching pairs and points also from World::contacts().
BOOST_AUTO_TEST_CASE(counters_equal_a_hand_count, *utf::label("internals")) {
    KnownScene s(WorldDef{.enable_sleep = false});
    for (int k = 0; k < 60; ++k)
        s.world.step(dt);
    const WorldCounters c = s.world.counters();
    BOOST_TEST(c.bodies == 10u);
    BOOST_TEST(c.shapes == 10u);
    BOOST_TEST(c.joints == 1u);
    BOOST_TEST(c.awake_bodies == 9u); // sleeping off: every movable body
    BOOST_TEST(c.touching == 6u);
    BOOST_TEST(c.contact_points == 12u);
    BOOST_TEST(c.pairs == 6u);
    BOOST_TEST(c.islands == 5u);
    BOOST_TEST(c.solver_packs == 2u);
    std::size_t points = 0;
    for (const ContactInfo& ci : s.world.contacts())
        points += std::size_t(ci.point_count);
    BOOST_TEST(c.touching == s.world.contacts().size());
    BOOST_TEST(c.contact_points == points);

    // One stack's top box gone: 9 bodies and shapes, 8 of them movable and awake, 5 touching
    // pairs (10 points), still 5 islands (the stack's bottom box alone).
    s.world.destroy_body(s.stack_boxes[1]);
    const WorldCounters d = s.world.counters();
    BOOST_TEST(d.bodies == 9u);
    BOOST_TEST(d.shapes == 9u);
    BOOST_TEST(d.awake_bodies == 8u);
    BOOST_TEST(d.touching == 5u);
    BOOST_TEST(d.contact_points == 10u);
    BOOST_TEST(d.islands == 5u);
}

// Oracle: hand count with sleeping on: after three seconds the stacks have been at rest for
// longer than time_to_sleep (0.5 s) and sleep, while the ball and the joined pair still fall:
// 3 bodies awake; the sleeping stacks' contacts still touch (6 pairs) and no manifold with a
// moving body is solved (0 packs).
BOOST_AUTO_TEST_CASE(counters_with_sleeping, *utf::label("internals")) {
    KnownScene s(WorldDef{.enable_sleep = true});
    for (int k = 0; k < 180; ++k)
        s.world.step(dt);
    for (const BodyId b : s.stack_boxes)
        BOOST_TEST_REQUIRE(!s.world.is_awake(b));
    const WorldCounters c = s.world.counters();
    BOOST_TEST(c.awake_bodies == 3u);
    BOOST_TEST(c.touching == 6u);
    BOOST_TEST(c.islands == 5u);
    BOOST_TEST(c.solver_packs == 0u);
}

BOOST_AUTO_TEST_SUITE_END()
