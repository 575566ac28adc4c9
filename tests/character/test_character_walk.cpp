// A capsule character moved by the mover's calls (collide_mover, solve_planes, cast_mover,
// clip_vector) and set_target_transform: up a straight slope, where each step's displacement
// is the closed form's (the target's part along the slope), and across the terrain scene's
// ground from x = -20 m into the wall at x = 30 m, where it never tunnels (never below the
// ground's polyline or beyond the wall), never sinks (its core's distance to the ground, by a
// segment-to-segment distance written here, never below the radius less a stated tolerance)
// and stops at the wall. The mover's queries leave the world's state untouched.
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "tamias2d/io/scene.hpp"
#include "tamias2d/plane_solver.hpp"
#include "tamias2d/world.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;
using tamias2d::io::build_world;
using tamias2d::io::load_scene;
using tamias2d::io::Scene;
using tamias2d::io::SceneBody;

namespace {

constexpr double radius = 0.3; // m
constexpr double height = 1.0; // m, the core's length
constexpr double walk_speed = 4.0;
constexpr double dt = 1.0 / 60.0;

Capsule capsule_at(Vec2d p) {
    return {p, {p.x, p.y + height}, radius};
}

double cross2(Vec2d a, Vec2d b) {
    return a.x * b.y - a.y * b.x;
}

/// The distance from point p to segment a-b.
double point_segment(Vec2d p, Vec2d a, Vec2d b) {
    const Vec2d e = b - a;
    const double t = std::clamp(dot(p - a, e) / dot(e, e), 0.0, 1.0);
    const Vec2d q = a + t * e;
    return std::hypot(p.x - q.x, p.y - q.y);
}

/// The distance between segments p1-p2 and q1-q2 (0 when they cross): the least of the four
/// endpoint-to-segment distances otherwise.
double segment_segment(Vec2d p1, Vec2d p2, Vec2d q1, Vec2d q2) {
    const double d1 = cross2(p2 - p1, q1 - p1), d2 = cross2(p2 - p1, q2 - p1);
    const double d3 = cross2(q2 - q1, p1 - q1), d4 = cross2(q2 - q1, p2 - q1);
    if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
        return 0.0;
    return std::min({point_segment(p1, q1, q2), point_segment(p2, q1, q2),
                     point_segment(q1, p1, p2), point_segment(q2, p1, p2)});
}

struct Character {
    BodyId body;
    Vec2d position; // m, the lower end of the core
    Vec2d velocity; // m s^-1
    Vec2d last_target{};
};

/// One step, as apps/examples/character.cpp takes it. Returns the last pass's planes.
std::vector<CollisionPlane> walk(World& world, Character& c, const QueryFilter& filter,
                                 double speed) {
    c.velocity.x = speed;
    c.velocity += dt * world.gravity();
    const Vec2d target = c.position + dt * c.velocity;
    c.last_target = target - c.position;
    std::vector<CollisionPlane> planes;
    for (int pass = 0; pass < 5; ++pass) {
        planes.clear();
        const std::uint64_t before = world.state_hash();
        for (const MoverPlane& p : world.collide_mover(capsule_at(c.position), filter))
            planes.push_back(p.plane);
        const Vec2d wanted = solve_planes(target - c.position, planes).translation;
        const double fraction = world.cast_mover(capsule_at(c.position), wanted, filter);
        BOOST_TEST_REQUIRE(world.state_hash() == before); // queries: nothing changed
        const Vec2d moved = fraction * wanted;
        c.position += moved;
        if (std::hypot(moved.x, moved.y) < 1e-6)
            break;
    }
    c.velocity = clip_vector(c.velocity, planes);
    world.set_target_transform(c.body, c.position, 0.0, dt);
    world.step(dt);
    return planes;
}

Character make_character(World& w, Vec2d at) {
    Character c;
    c.position = at;
    c.body = w.create_body({.type = BodyType::kinematic, .position = at});
    w.create_shape(c.body, capsule_shape({0.0, 0.0}, {0.0, height}, radius));
    return c;
}

} // namespace

BOOST_AUTO_TEST_SUITE(character_walk)

// Oracle: on a straight slope of angle alpha (tangent tau), a character pressing into it moves
// each step by the part of its target along the slope, (t . tau) tau (DD43's one-plane closed
// form), and stays at its radius from the slope's line (a gap within the speculative distance,
// 0.02 m). Walking up a 20 degree slope at 4 m/s under gravity: checked every step once it
// touches, to 1e-9 m (the solver's convergence) plus the cast's tolerance (World::
// cast_tolerance, 1e-6 of the cast's scale).
BOOST_AUTO_TEST_CASE(slides_along_a_slope, *utf::label("DD43")) {
    World w(WorldDef{.gravity = {0.0, -10.0}});
    const double a = 20.0 * std::acos(-1.0) / 180.0;
    const Vec2d tau{std::cos(a), std::sin(a)};
    const Vec2d n{-std::sin(a), std::cos(a)};
    const BodyId ground = w.create_body({.type = BodyType::static_body});
    w.create_shape(ground, segment_shape({-10.0, 0.0}, {40.0 * tau.x - 10.0, 40.0 * tau.y}));
    // The core's lower end r above the slope's line at x = 0.
    const Vec2d start = Vec2d{0.0, 10.0 * std::tan(a)} + radius * n;
    Character c = make_character(w, start);
    const QueryFilter filter{.exclude_body = c.body};
    const Vec2d l0{-10.0, 0.0}; // a point of the slope's line
    int touching = 0;
    for (int k = 0; k < 120; ++k) {
        const Vec2d before = c.position;
        walk(w, c, filter, walk_speed);
        const Vec2d t = c.last_target;
        const double s = dot(n, before - l0); // the core's lower end's height above the line
        const double gap = dot(n, c.position - l0) - radius;
        BOOST_TEST(gap >= -1e-9);
        BOOST_TEST(gap <= 0.02);
        const Geometry g{.type = ShapeType::capsule, .capsule = capsule_at({})};
        const double tol = 1e-9 + World::cast_tolerance(g, t);
        // Pressed into the slope (the target would end nearer than r): the move is the
        // target's part along the slope, and the part along n that puts it at r.
        const Vec2d expected = dot(n, t) < radius - s ? dot(t, tau) * tau + (radius - s) * n : t;
        if (dot(n, t) < radius - s)
            ++touching;
        const Vec2d moved = c.position - before;
        BOOST_TEST(std::hypot(moved.x - expected.x, moved.y - expected.y) <= tol);
    }
    BOOST_TEST(touching >= 100);
    // Up the slope: 120 steps at 4 m/s, less what gravity's drop takes along the slope.
    BOOST_TEST(c.position.x > start.x + 5.0);
}

// Oracle: the terrain scene's ground as a polyline (its chain's points, from the scene): the
// character's core never comes nearer to any of its segments than r less 1e-9 m, the plane
// solver's tolerance (never sinks: the planes are linear, so at a convex corner one pass may
// press in by up to s^2 / 2r for a move s, which the step's next pass undoes; checked after
// each step), never passes below the ground's line or beyond the wall at x = 30 m (never
// tunnels), reaches the valley and the hill, and stops r from the wall with its walking
// velocity clipped to 0 (to rounding: (v . n) n of v = 4 m/s is good to a few ulps, 1e-14).
BOOST_AUTO_TEST_CASE(walks_the_terrain, *utf::label("scene")) {
    Scene scene = load_scene(TAMIAS_EXAMPLE_SCENES "/terrain.json");
    std::erase_if(scene.bodies,
                  [](const SceneBody& b) { return b.def.type != BodyType::static_body; });
    std::vector<std::pair<Vec2d, Vec2d>> ground;
    for (const SceneBody& b : scene.bodies)
        if (b.def.name == "ground")
            for (const ShapeDef& s : b.shapes)
                ground.emplace_back(s.geometry.chain_segment.point1 + b.def.position,
                                    s.geometry.chain_segment.point2 + b.def.position);
    BOOST_TEST_REQUIRE(ground.size() == 15u);
    for (int workers : {1, 3}) {
        scene.world.workers = workers;
        World w(scene.world);
        build_world(scene, w);
        Character c = make_character(w, {-20.0, radius + 0.01});
        const QueryFilter filter{.exclude_body = c.body};
        double least_gap = std::numeric_limits<double>::infinity(), highest = -1e9, lowest = 1e9;
        for (int k = 0; k < 900; ++k) {
            walk(w, c, filter, walk_speed);
            const Vec2d top{c.position.x, c.position.y + height};
            for (const auto& [a, b] : ground)
                least_gap = std::min(least_gap, segment_segment(c.position, top, a, b) - radius);
            BOOST_TEST(c.position.x <= 30.0 - radius);
            highest = std::max(highest, c.position.y);
            lowest = std::min(lowest, c.position.y);
            const Vec2d o = w.origin(c.body);
            BOOST_TEST(std::hypot(o.x - c.position.x, o.y - c.position.y) <= 1e-9);
        }
        BOOST_TEST(least_gap >= -1e-9);
        BOOST_TEST(lowest < -1.5); // down in the valley (its floor at -2 m)
        BOOST_TEST(highest > 3.5); // over the hill (its top at 3.5 m)
        BOOST_TEST(c.position.x >= 30.0 - radius - 0.02);
        BOOST_TEST(std::abs(c.velocity.x) <= 1e-14);
        BOOST_TEST_MESSAGE("workers " << workers << ": least gap " << least_gap << " m");
    }
}

BOOST_AUTO_TEST_SUITE_END()
