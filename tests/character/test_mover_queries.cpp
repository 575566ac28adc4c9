// World::collide_mover and World::cast_mover against closed forms on boxes, a wall and a chain:
// the planes' normals, offsets and points, the cast's fraction of first contact; what they
// leave out (sensors, the back of a chain, an excluded body, shapes beyond reach); and that
// they are queries: the world's state hash is the same before and after, and a refused call
// throws naming the field.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <limits>
#include <vector>

#include "tamias2d/errors.hpp"
#include "tamias2d/world.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;

namespace {

constexpr double r = 0.3; // m, the mover's radius

/// A vertical capsule mover whose core runs from (x, y) up 1 m.
Capsule mover_at(double x, double y) {
    return Capsule{{x, y}, {x, y + 1.0}, r};
}

/// A static floor whose top is y = 0.5 (a 20 m x 1 m box at the origin) and a wall whose left
/// face is x = 3 (a 1 m x 6 m box centred at (3.5, 3)).
struct Level {
    World world{WorldDef{.gravity = {0.0, -10.0}}};
    BodyId ground = world.create_body(BodyDef{.type = BodyType::static_body});
    ShapeId floor = world.create_shape(ground, box_shape(20.0, 1.0));
    BodyId wall_body =
        world.create_body(BodyDef{.type = BodyType::static_body, .position = {3.5, 3.0}});
    ShapeId wall = world.create_shape(wall_body, box_shape(1.0, 6.0));
};

} // namespace

BOOST_AUTO_TEST_SUITE(mover_queries)

// Oracle: closed form, the level's geometry. The distance from the core's lower end (x, y) to
// the floor's top is y - 0.5, so the
// floor's plane has normal (0, 1), offset r - (y - 0.5) and point (x, 0.5), reported while
// y - 0.5 <= r + the speculative distance (0.02 m), none beyond; the wall's plane has normal
// (-1, 0) and offset r - (3 - x). To rounding: a normal from points a few metres from the
// origin over a gap of 0.25 m is good to a few ulps of 3 m over 0.25 m, 1e-14.
BOOST_AUTO_TEST_CASE(planes_of_floor_and_wall, *utf::label("DD34")) {
    Level l;
    const std::uint64_t before = l.world.state_hash();
    {
        const auto planes = l.world.collide_mover(mover_at(1.0, 0.75));
        BOOST_TEST_REQUIRE(planes.size() == 1u);
        BOOST_TEST((planes[0].shape == l.floor));
        BOOST_TEST((planes[0].body == l.ground));
        BOOST_TEST(std::abs(planes[0].plane.normal.x) <= 1e-15);
        BOOST_TEST(std::abs(planes[0].plane.normal.y - 1.0) <= 1e-15);
        BOOST_TEST(std::abs(planes[0].plane.offset - 0.05) <= 1e-15);
        BOOST_TEST(std::abs(planes[0].point.x - 1.0) <= 1e-12);
        BOOST_TEST(std::abs(planes[0].point.y - 0.5) <= 1e-15);
        BOOST_TEST(std::isinf(planes[0].plane.push_limit));
    }
    {
        const auto planes = l.world.collide_mover(mover_at(2.75, 0.81));
        BOOST_TEST_REQUIRE(planes.size() == 2u); // the floor (nearly touching) and the wall
        BOOST_TEST(std::abs(planes[0].plane.offset - (r - 0.31)) <= 1e-14);
        BOOST_TEST((planes[1].shape == l.wall));
        BOOST_TEST(std::abs(planes[1].plane.normal.x + 1.0) <= 1e-14);
        BOOST_TEST(std::abs(planes[1].plane.normal.y) <= 1e-14);
        BOOST_TEST(std::abs(planes[1].plane.offset - (r - 0.25)) <= 1e-14);
    }
    BOOST_TEST(l.world.collide_mover(mover_at(1.0, 0.9)).empty()); // 0.1 m beyond reach
    BOOST_TEST(l.world.state_hash() == before);
}

// Oracle: closed form, the level's geometry. A mover whose core ends 1.5 m above the floor's
// top, cast down 3 m, first touches
// when the core's end is r above it: at f* = (1.5 - r) / 3. The cast leaves a gap of at most
// its tolerance tau (World::cast_tolerance), so f is in [f* - tau / 3, f*]. Cast right from
// x = 1 by 3 m, it meets the wall at f* = (3 - r - 1) / 3.
BOOST_AUTO_TEST_CASE(cast_fraction, *utf::label("DD29")) {
    Level l;
    const std::uint64_t before = l.world.state_hash();
    Geometry g;
    g.type = ShapeType::capsule;
    g.capsule = mover_at(1.0, 2.0);
    const double down = l.world.cast_mover(mover_at(1.0, 2.0), {0.0, -3.0});
    const double f_down = (1.5 - r) / 3.0;
    const double tau_down = World::cast_tolerance(g, {0.0, -3.0});
    BOOST_TEST(down <= f_down);
    BOOST_TEST(down >= f_down - tau_down / 3.0);
    const double right = l.world.cast_mover(mover_at(1.0, 2.0), {3.0, 0.0});
    const double f_right = (3.0 - r - 1.0) / 3.0;
    BOOST_TEST(right <= f_right);
    BOOST_TEST(right >= f_right - World::cast_tolerance(g, {3.0, 0.0}) / 3.0);
    // Free of everything: the whole translation.
    BOOST_TEST(l.world.cast_mover(mover_at(-5.0, 2.0), {-3.0, 1.0}) == 1.0);
    BOOST_TEST(l.world.state_hash() == before);
}

// Oracle: the contract of cast_mover in world.hpp: shapes the mover already touches are passed
// over, so a mover resting on the floor (core's end r above its top) casts its whole translation
// (1.0) and can walk; collide_mover's one plane holds it up instead.
BOOST_AUTO_TEST_CASE(touching_shapes_are_passed_over, *utf::label("reliability")) {
    Level l;
    const Capsule resting = mover_at(0.0, 0.5 + r);
    BOOST_TEST(l.world.cast_mover(resting, {1.0, 0.0}) == 1.0);
    BOOST_TEST(l.world.collide_mover(resting).size() == 1u);
}

// Oracle: the contract of collide_mover and cast_mover in world.hpp and query_filter.hpp: a
// sensor, the back of a chain's edge (DD31: a chain drawn right to left collides from above
// only), a shape the core lies in, an excluded body and a category the mask leaves out give no
// plane and no hit, while the same shapes seen from the front or unfiltered do.
BOOST_AUTO_TEST_CASE(what_the_mover_does_not_see, *utf::label("reliability")) {
    World w(WorldDef{.gravity = {0.0, 0.0}});
    const BodyId ground = w.create_body(BodyDef{.type = BodyType::static_body});
    const std::vector<Vec2d> points{{10.0, 0.0}, {-10.0, 0.0}};
    w.create_chain(ground, chain_shapes(points, false));
    // Above the chain: a plane; below it (core's top 0.1 m under it): none, and a cast up
    // through it is free.
    BOOST_TEST(w.collide_mover(mover_at(0.0, 0.2)).size() == 1u);
    BOOST_TEST(w.collide_mover(mover_at(0.0, -1.1)).empty());
    BOOST_TEST(w.cast_mover(mover_at(0.0, -3.0), {0.0, 5.0}) == 1.0);
    // A sensor box around the mover: no plane, no hit.
    const BodyId zone =
        w.create_body(BodyDef{.type = BodyType::static_body, .position = {5.0, 5.0}});
    ShapeDef sensor = box_shape(2.0, 2.0);
    sensor.is_sensor = true;
    w.create_shape(zone, sensor);
    BOOST_TEST(w.collide_mover(mover_at(5.0, 4.5)).empty());
    // The mover's own body (a kinematic capsule) left out by exclude_body; a category the
    // filter's mask leaves out.
    const BodyId self =
        w.create_body(BodyDef{.type = BodyType::kinematic, .position = {-5.0, 3.0}});
    w.create_shape(self, capsule_shape({0.0, 0.0}, {0.0, 1.0}, r));
    const Capsule at_self{{-5.0, 3.0}, {-5.0, 4.0}, r};
    BOOST_TEST(w.collide_mover(at_self).empty()); // the core lies in the shape: no direction
    const Capsule beside{{-5.0 + 2.0 * r + 0.01, 3.0}, {-5.0 + 2.0 * r + 0.01, 4.0}, r};
    BOOST_TEST(w.collide_mover(beside).size() == 1u);
    BOOST_TEST(w.collide_mover(beside, QueryFilter{.exclude_body = self}).empty());
    BOOST_TEST(w.collide_mover(beside, QueryFilter{.mask_bits = 0x2}).empty());
    BOOST_TEST(w.cast_mover(Capsule{{-8.0, 3.0}, {-8.0, 4.0}, r}, {6.0, 0.0},
                            QueryFilter{.exclude_body = self}) == 1.0);
    BOOST_TEST(w.cast_mover(Capsule{{-8.0, 3.0}, {-8.0, 4.0}, r}, {6.0, 0.0}) < 1.0);
}

// Oracle: the contract of the callback form in world.hpp: a callback returning false stops it
// after the first plane; one returning true sees both planes (floor and wall) the level's
// geometry gives for that mover.
BOOST_AUTO_TEST_CASE(callback_form, *utf::label("reliability")) {
    Level l;
    int seen = 0;
    l.world.collide_mover(mover_at(2.75, 0.81), {}, [&](const MoverPlane&) {
        ++seen;
        return false;
    });
    BOOST_TEST(seen == 1);
    seen = 0;
    l.world.collide_mover(mover_at(2.75, 0.81), {}, [&](const MoverPlane&) {
        ++seen;
        return true;
    });
    BOOST_TEST(seen == 2);
}

// Oracle: the stated rules of the mover calls in world.hpp: a mover of negative radius or of a
// core of no length, or a non-finite input, throws ValidationError (a NaN translation naming
// translation.x), another world's exclude_body throws InvalidHandle, and the calls are queries:
// state_hash() is the same before and after.
BOOST_AUTO_TEST_CASE(refusals, *utf::label("reliability")) {
    Level l;
    const std::uint64_t before = l.world.state_hash();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    BOOST_CHECK_THROW(l.world.collide_mover(Capsule{{0.0, 0.0}, {0.0, 1.0}, -1.0}),
                      ValidationError);
    BOOST_CHECK_THROW(l.world.collide_mover(Capsule{{0.0, 0.0}, {0.0, 0.0}, 0.3}), ValidationError);
    BOOST_CHECK_THROW(l.world.cast_mover(mover_at(nan, 0.0), {1.0, 0.0}), ValidationError);
    try {
        l.world.cast_mover(mover_at(0.0, 2.0), {nan, 0.0});
        BOOST_FAIL("a NaN translation was accepted");
    } catch (const ValidationError& e) {
        BOOST_TEST(e.field == "translation.x");
    }
    World other;
    const BodyId foreign = other.create_body({});
    BOOST_CHECK_THROW(
        l.world.collide_mover(mover_at(0.0, 2.0), QueryFilter{.exclude_body = foreign}),
        InvalidHandle);
    BOOST_TEST(l.world.state_hash() == before);
}

BOOST_AUTO_TEST_SUITE_END()
