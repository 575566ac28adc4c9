// Surface motion (DD46, DD47) in the world: equal results on 1 to 4 workers, a snapshot's
// continuation, a removed contact's rolling impulse kept from the others and a scene file's round
// trip with the values, and the run-time setters' refusals (the world unchanged) and their values.
#include <boost/test/unit_test.hpp>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "support/pyramid.hpp"
#include "tamias2d/errors.hpp"
#include "tamias2d/io/scene.hpp"
#include "tamias2d/io/scene_from_world.hpp"
#include "tamias2d/world.hpp"

using namespace tamias2d;
namespace utf = boost::unit_test;

namespace {

constexpr double dt = 1.0 / 60.0;

/// A small pyramid on a moving belt, and balls that resist rolling dropped beside it.
void belt_and_balls(World& w) {
    test::build_pyramid(w, 6);
    for (const BodyId b : w.bodies())
        for (const ShapeId s : w.shapes(b))
            if (w.type(b) == BodyType::static_body) {
                w.set_friction(s, 0.6);
                w.set_tangent_speed(s, 1.5);
            }
    for (int k = 0; k < 6; ++k) {
        BodyDef d;
        d.position = {4.0 + 1.1 * k, 1.0 + 0.7 * k};
        d.angular_velocity = -3.0;
        const BodyId ball = w.create_body(d);
        Material m{.friction = 0.6};
        m.rolling_resistance = 0.05 * (k + 1);
        w.create_shape(ball, k % 2 == 0 ? circle_shape(0.3, m)
                                        : capsule_shape({-0.2, 0.0}, {0.2, 0.0}, 0.25, m));
    }
}

/// Four balls (r = 0.5 m) rolling without slipping along a static floor, each at its own
/// speed and with its own rolling resistance (DD46), friction 0.6; the first only when
/// `with_first`. Returns the balls made, in order.
std::vector<BodyId> rolling_balls(World& w, bool with_first) {
    BodyDef fd;
    fd.type = BodyType::static_body;
    fd.position = {40.0, -0.5};
    w.create_shape(w.create_body(fd), box_shape(100.0, 1.0, Material{.friction = 0.6}));
    std::vector<BodyId> balls;
    for (int k = with_first ? 0 : 1; k < 4; ++k) {
        BodyDef d;
        d.position = {3.0 * k, 0.5};
        d.linear_velocity = {1.0 + 0.5 * k, 0.0};
        d.angular_velocity = -d.linear_velocity.x / 0.5;
        balls.push_back(w.create_body(d));
        Material m{.friction = 0.6};
        m.rolling_resistance = 0.02 * (k + 1);
        w.create_shape(balls.back(), circle_shape(0.5, m));
    }
    return balls;
}

/// The bits of a body's pose and velocities.
std::vector<std::uint64_t> motion_bits(const World& w, BodyId b) {
    const double v[] = {w.position(b).x, w.position(b).y, w.orientation(b),
                        w.velocity(b).x, w.velocity(b).y, w.angular_velocity(b)};
    std::vector<std::uint64_t> out;
    for (const double x : v)
        out.push_back(std::bit_cast<std::uint64_t>(x));
    return out;
}

} // namespace

BOOST_AUTO_TEST_SUITE(surface_motion_workers, *utf::label("determinism"))

// Oracle: the determinism requirement: the same world with belts and rolling resistance gives
// the same state hash on 1, 2, 3 and 4 workers, step by step; and the surface motion changes the
// run (the hash differs from the same world with both values set back to 0).
BOOST_AUTO_TEST_CASE(equal_on_one_to_four_workers) {
    std::vector<std::uint64_t> reference;
    for (int workers = 1; workers <= 4; ++workers) {
        World w{WorldDef{.workers = workers}};
        belt_and_balls(w);
        for (int i = 0; i < 150; ++i) {
            w.step(dt);
            if (workers == 1)
                reference.push_back(w.state_hash());
            else
                BOOST_TEST_REQUIRE(w.state_hash() == reference[std::size_t(i)]);
        }
    }
    World still{WorldDef{}};
    belt_and_balls(still);
    for (const BodyId b : still.bodies())
        for (const ShapeId s : still.shapes(b)) {
            still.set_tangent_speed(s, 0.0);
            still.set_rolling_resistance(s, 0.0);
        }
    for (int i = 0; i < 150; ++i)
        still.step(dt);
    BOOST_TEST(still.state_hash() != reference.back());
}

// Oracle: the snapshot's promise: a world restored from a snapshot taken mid-run, on 1 and on 4
// workers, continues with the same state hash at every step as the world it was taken from (the
// materials and the rolling impulses carried between steps are in it).
BOOST_AUTO_TEST_CASE(snapshot_continues_with_the_same_bits) {
    World w{WorldDef{}};
    belt_and_balls(w);
    for (int i = 0; i < 40; ++i)
        w.step(dt);
    const std::vector<std::byte> bytes = w.snapshot();
    std::vector<std::uint64_t> expected;
    for (int i = 0; i < 40; ++i) {
        w.step(dt);
        expected.push_back(w.state_hash());
    }
    for (const int workers : {1, 4}) {
        World r = World::from_snapshot(bytes, workers);
        for (int i = 0; i < 40; ++i) {
            r.step(dt);
            BOOST_TEST_REQUIRE(r.state_hash() == expected[std::size_t(i)]);
        }
    }
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(surface_motion_removal, *utf::label("determinism"))

// Oracle: the locality of the contact solve: contacts that share no body are solved apart, so
// a ball's motion does not depend on another ball's contact. Once the first ball is destroyed
// (its contact removed while the others roll on, each with the rolling impulse it carries into
// the next step), the other three move bit for bit as in a world that never held it.
BOOST_AUTO_TEST_CASE(a_removed_contact_leaves_the_others_rolling_as_without_it) {
    World w{WorldDef{}}, without{WorldDef{}};
    const std::vector<BodyId> balls = rolling_balls(w, true);
    const std::vector<BodyId> others = rolling_balls(without, false);
    for (int i = 0; i < 60; ++i) {
        if (i == 20)
            w.destroy_body(balls[0]);
        w.step(dt);
        without.step(dt);
        for (std::size_t k = 0; k < others.size(); ++k)
            BOOST_TEST_REQUIRE(motion_bits(w, balls[k + 1]) == motion_bits(without, others[k]),
                               "step " << i << ", ball " << k + 1);
    }
    // The balls still roll and resist it: the resistance is at work when the contact goes.
    for (std::size_t k = 0; k < others.size(); ++k) {
        BOOST_TEST(without.angular_velocity(others[k]) < 0.0);
        BOOST_TEST(without.velocity(others[k]).x < 1.0 + 0.5 * double(k + 1));
    }
}

BOOST_AUTO_TEST_SUITE_END()

BOOST_AUTO_TEST_SUITE(surface_motion_values, *utf::label("reliability"))

// Oracle: the setters' contract (docs/user-guide.md, "Surface motion"): a value that is not
// finite, a negative rolling resistance and a speed beyond the supported range are refused with
// ValidationError naming the field and the constraint, the world's state hash unchanged; an
// accepted value is returned by the getter; a stale handle is refused.
BOOST_AUTO_TEST_CASE(setters_refuse_bad_values_and_change_nothing) {
    World w{WorldDef{}};
    belt_and_balls(w);
    w.step(dt);
    const ShapeId s = w.shapes(w.bodies().back()).front();
    const std::uint64_t before = w.state_hash();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    for (const double bad : {-0.1, nan, inf, -inf}) {
        try {
            w.set_rolling_resistance(s, bad);
            BOOST_ERROR("rolling resistance " << bad << " accepted");
        } catch (const ValidationError& e) {
            BOOST_TEST(e.field == "rolling_resistance");
            BOOST_TEST((e.constraint == "DD46" || e.constraint == "DCX_finite"));
        }
        BOOST_TEST(w.state_hash() == before);
    }
    for (const double bad : {nan, inf, -inf, 1e300}) {
        try {
            w.set_tangent_speed(s, bad);
            BOOST_ERROR("tangent speed " << bad << " accepted");
        } catch (const ValidationError& e) {
            BOOST_TEST(e.field == "tangent_speed");
            BOOST_TEST((e.constraint == "DCX_range" || e.constraint == "DCX_finite"));
        }
        BOOST_TEST(w.state_hash() == before);
    }
    ShapeDef bad_def = circle_shape(0.5);
    bad_def.material.rolling_resistance = -1.0;
    BOOST_CHECK_THROW(w.create_shape(w.bodies().back(), bad_def), ValidationError);
    BOOST_TEST(w.state_hash() == before);
    w.set_rolling_resistance(s, 0.25);
    w.set_tangent_speed(s, -3.5);
    BOOST_TEST(w.rolling_resistance(s) == 0.25);
    BOOST_TEST(w.tangent_speed(s) == -3.5);
    BOOST_TEST(w.state_hash() != before); // in the hash when not 0
    const std::uint64_t set = w.state_hash();
    w.set_tangent_speed(s, -3.5); // the same value: no bit changes
    BOOST_TEST(w.state_hash() == set);
    w.destroy_shape(s);
    BOOST_CHECK_THROW(w.set_rolling_resistance(s, 0.1), InvalidHandle);
    BOOST_CHECK_THROW(w.tangent_speed(s), InvalidHandle);
}

// Oracle: the scene format (docs/scene-format.md): a world with surface motion written as a
// scene and read back has the same values on every shape; a material without them is written
// without the keys, as before.
BOOST_AUTO_TEST_CASE(scene_round_trip_keeps_the_values) {
    World w{WorldDef{}};
    belt_and_balls(w);
    const std::string json = io::scene_to_json(io::scene_from_world(w));
    BOOST_TEST(json.find("\"tangent_speed\"") != std::string::npos);
    BOOST_TEST(json.find("\"rolling_resistance\"") != std::string::npos);
    const io::Scene scene = io::parse_scene(json);
    World r{WorldDef{}};
    io::build_world(scene, r);
    std::vector<double> a, b;
    for (const World* x : {&w, &r})
        for (const BodyId body : x->bodies())
            for (const ShapeId s : x->shapes(body)) {
                auto& out = x == &w ? a : b;
                out.push_back(x->rolling_resistance(s));
                out.push_back(x->tangent_speed(s));
            }
    BOOST_TEST(a == b, boost::test_tools::per_element());
    World plain{WorldDef{}};
    test::build_pyramid(plain, 3);
    const std::string plain_json = io::scene_to_json(io::scene_from_world(plain));
    BOOST_TEST(plain_json.find("rolling_resistance") == std::string::npos);
    BOOST_TEST(plain_json.find("tangent_speed") == std::string::npos);
}

BOOST_AUTO_TEST_SUITE_END()
