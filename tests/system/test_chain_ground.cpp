// Chain ground (DD31): a body sliding over the joints between a chain's edges meets no bump.
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include "tamias2d/world.hpp"

namespace utf = boost::unit_test;
namespace tt = boost::test_tools;
using namespace tamias2d;

namespace {

constexpr double dt = 1.0 / 60.0;
constexpr int edges = 100;    // 1 m each, from x = 0 to x = 100
constexpr double speed = 5.0; // m/s to the right

struct Slide {
    double max_vy = 0.0;  ///< m/s, largest |vertical velocity| over the run
    double max_dvx = 0.0; ///< m/s, largest |vx - speed|
    double max_w = 0.0;   ///< rad/s, largest |angular velocity|
    double max_dy = 0.0;  ///< m, largest |height - resting height|
    double end_x = 0.0;   ///< m
};

enum class Kind { box, circle, capsule };

const char* name(Kind k) {
    return k == Kind::box ? "box" : k == Kind::circle ? "circle" : "capsule";
}

/// A frictionless box, circle or lying capsule resting on the ground and sliding right at
/// `speed` until it nears the far end; the ground is a chain, or `edges` separate 1 m boxes.
Slide slide(bool chain, Kind kind) {
    World world;
    BodyDef ground;
    ground.type = BodyType::static_body;
    const BodyId g = world.create_body(ground);
    if (chain) {
        // Listed right to left: each edge's collision side (its right) is up.
        std::vector<Vec2d> points;
        for (int i = edges; i >= 0; --i)
            points.push_back({double(i), 0.0});
        world.create_chain(g, chain_shapes(points, false));
    } else {
        for (int i = 0; i < edges; ++i)
            world.create_shape(g, box_shape(1.0, 1.0, {}, {i + 0.5, -0.5}));
    }
    BodyDef def;
    def.position = {1.0, kind == Kind::circle ? 0.3 : 0.25};
    def.linear_velocity = {speed, 0.0};
    const BodyId body = world.create_body(def);
    world.create_shape(body, kind == Kind::box      ? box_shape(0.5, 0.5)
                             : kind == Kind::circle ? circle_shape(0.3)
                                                    : capsule_shape({-0.4, 0.0}, {0.4, 0.0}, 0.25));
    const double rest = def.position.y;
    Slide out;
    const int steps = int((edges - 3.0) / (speed * dt));
    for (int k = 0; k < steps; ++k) {
        world.step(dt);
        const BodyState s = world.state(body);
        out.max_vy = std::max(out.max_vy, std::abs(s.velocity.y));
        out.max_dvx = std::max(out.max_dvx, std::abs(s.velocity.x - speed));
        out.max_w = std::max(out.max_w, std::abs(s.angular_velocity));
        out.max_dy = std::max(out.max_dy, std::abs(s.position.y - rest));
        out.end_x = s.position.x;
    }
    return out;
}

/// A ball of radius r thrown straight up at v0 from 1 m below a flat chain (normal up) at
/// height `ledge`, under the default gravity, for `steps` steps: its highest point, the largest
/// gap between its height and free flight's in IM1's discrete closed form while it rises, and
/// its last state.
struct Throw {
    double highest = -INFINITY, worst = 0.0;
    BodyState end{};
};

Throw throw_up(double ledge, double v0, double r, int steps) {
    World world;
    BodyDef ground;
    ground.type = BodyType::static_body;
    const BodyId g = world.create_body(ground);
    const Vec2d points[] = {{10.0, ledge}, {0.0, ledge}, {-10.0, ledge}};
    world.create_chain(g, chain_shapes(points, false));
    BodyDef def;
    def.position = {0.5, ledge - 1.0};
    def.linear_velocity = {0.0, v0};
    const BodyId ball = world.create_body(def);
    world.create_shape(ball, circle_shape(r));
    Throw t;
    for (int k = 1; k <= steps; ++k) {
        world.step(dt);
        const double y = world.state(ball).position.y;
        t.highest = std::max(t.highest, y);
        const double h = dt / WorldDef{}.substeps, n = double(k * WorldDef{}.substeps);
        if (world.state(ball).velocity.y > 0.0) // rising: free flight, through the chain too
            t.worst = std::max(t.worst, std::abs(y - (ledge - 1.0 + v0 * n * h -
                                                      9.81 * h * h * n * (n + 1.0) / 2.0)));
    }
    t.end = world.state(ball);
    return t;
}

/// Where a disc (radius 0.5 m, no gravity) shot along the line of a chain's edges from 3 m
/// before its end, at 10 m a step, is after one step; `above` (m) lifts its start off the line.
Vec2d shot_along_the_line(double above) {
    World world(WorldDef{.gravity = {0.0, 0.0}});
    const BodyId g = world.create_body(BodyDef{.type = BodyType::static_body});
    // Listed right to left, from (10, 0) to (0, 0): each edge's collision side is up.
    std::vector<Vec2d> points;
    for (int i = 10; i >= 0; --i)
        points.push_back({double(i), 0.0});
    world.create_chain(g, chain_shapes(points, false));
    const BodyId disc =
        world.create_body(BodyDef{.position = {-3.0, above}, .linear_velocity = {10.0 / dt, 0.0}});
    world.create_shape(disc, circle_shape(0.5));
    world.step(dt);
    return world.position(disc);
}

} // namespace

BOOST_AUTO_TEST_SUITE(chain_ground)

// Oracle: the closed form of frictionless sliding on a horizontal plane under gravity: the
// velocity stays (5, 0) m/s, the height and the angle constant. A box, a circle and a capsule
// lying on its side cross 96 of
// the chain's joints: vertical and angular velocity stay zero to rounding, and the height
// within the soft contact's resting compliance (under the linear slop, millimetres). The same box
// on separate boxes, whose corners meet at each joint, is reported (not asserted): that bump is
// what chains remove.
BOOST_AUTO_TEST_CASE(box_slides_over_joints_without_a_bump,
                     *utf::label("DD31") * utf::label("R7")) {
    for (const Kind kind : {Kind::box, Kind::circle, Kind::capsule}) {
        const Slide s = slide(true, kind);
        BOOST_TEST_MESSAGE(name(kind) << " on a chain: |vy| <= " << s.max_vy << " m/s, |vx - 5| <= "
                                      << s.max_dvx << " m/s, |w| <= " << s.max_w
                                      << " rad/s, |dy| <= " << s.max_dy << " m");
        BOOST_TEST_CONTEXT(name(kind)) {
            BOOST_TEST(s.end_x > 95.0); // it crossed the joints
            BOOST_TEST(s.max_vy < 1e-9);
            BOOST_TEST(s.max_dvx < 1e-9);
            BOOST_TEST(s.max_dy < 5e-3);
            if (kind != Kind::circle)
                BOOST_TEST(s.max_w < 1e-9);
        }
    }
    const Slide boxes = slide(false, Kind::box);
    BOOST_TEST_MESSAGE("box on separate boxes: |vy| <= "
                       << boxes.max_vy << " m/s, |vx - 5| <= " << boxes.max_dvx << " m/s, |w| <= "
                       << boxes.max_w << " rad/s, end x " << boxes.end_x << " m");
}

// Oracle: DD31's one-sidedness under gravity: a ball thrown up at 10 m/s from 1 m below the
// chain passes through it: while it rises its height is free flight's, to rounding, in IM1's
// discrete closed form (semi-implicit Euler, n substeps of h: y = y0 + v0 n h - g h^2 n (n+1)/2),
// as if the chain were not there; then it lands on the chain from above and rests on its top.
BOOST_AUTO_TEST_CASE(thrown_up_through_a_chain_lands_on_it, *utf::label("DD31")) {
    const Throw t = throw_up(0.0, 10.0, 0.2, 240);
    BOOST_TEST(t.highest > 3.0); // it went through (from behind) to about 4.1 m
    BOOST_TEST(t.worst < 1e-12);
    BOOST_TEST(t.end.position.y == 0.2, tt::tolerance(0.05)); // resting on the top side
    BOOST_TEST(std::abs(t.end.velocity.y) < 1e-2);
}

// Oracle: as above, for a ledge raised 3 m and a small ball thrown up at 30 m/s, fast enough
// (0.5 m a step, ten radii) for the continuous pass to sweep it: the pass too lets a body that
// starts behind an edge through (DD31's one-sidedness, DD29), wherever the edge lies. Rising, the
// ball's height is free flight's to rounding (IM1's discrete closed form); it climbs far above
// the ledge, comes down on it from above at speed and is stopped on its top side.
BOOST_AUTO_TEST_CASE(thrown_up_fast_through_a_raised_chain_lands_on_it,
                     *utf::label("DD31") * utf::label("DD29")) {
    constexpr double ledge = 3.0, r = 0.05;
    const Throw t = throw_up(ledge, 30.0, r, 480);
    BOOST_TEST(t.highest > ledge + 40.0); // through the ledge from behind, to about 47.9 m
    BOOST_TEST(t.worst < 1e-11);
    BOOST_TEST(t.end.position.y == ledge + r, tt::tolerance(0.05)); // resting on the top side
    BOOST_TEST(std::abs(t.end.velocity.y) < 1e-2);
}

// Oracle: DD29's rule for chain edges (srs/data_definitions.yaml): only a body that starts
// behind an edge (strictly: on the side opposite its normal) is not swept against it. A disc
// whose centre starts exactly on the edges' line is not behind, so it is swept like one that
// starts a hair (1e-9 m) in front and stopped at the chain's end vertex (0, 0), within the
// speculative distance (0.02 m) of touching it; one that starts a hair behind passes (IM1's
// free flight: 10 m in the step, to x = 7).
BOOST_AUTO_TEST_CASE(a_fast_body_starting_on_the_edges_line_is_stopped_at_the_end,
                     *utf::label("DD29") * utf::label("DD31")) {
    const Vec2d on = shot_along_the_line(0.0);
    const Vec2d front = shot_along_the_line(1e-9);
    const Vec2d behind = shot_along_the_line(-1e-9);
    BOOST_TEST_MESSAGE("on the line: x " << on.x << ", in front: x " << front.x << ", behind: x "
                                         << behind.x);
    BOOST_TEST(front.x <= -0.5);
    BOOST_TEST(front.x >= -0.52);
    BOOST_TEST(on.x == front.x, tt::tolerance(1e-9));
    BOOST_TEST(behind.x == 7.0, tt::tolerance(1e-12));
}

BOOST_AUTO_TEST_SUITE_END()
