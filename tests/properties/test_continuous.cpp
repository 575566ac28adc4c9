// Continuous collision (DD29, R7): fast bodies never pass through a thin static wall.
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>
#include <optional>
#include <random>
#include <utility>
#include <vector>

#include "tamias2d/world.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;

namespace {

constexpr double dt = 1.0 / 60.0;
constexpr int steps = 10;

struct Shot {
    bool circle;
    double a, b; ///< m: the circle's radius, or the box's width and height
    double angle, speed, heading, lead, y;
};

Shot random_shot(std::mt19937_64& rng, bool circle) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    Shot s{};
    s.circle = circle;
    s.a = circle ? 0.01 + 0.49 * u(rng) : 0.02 + 0.98 * u(rng);
    s.b = 0.02 + 0.98 * u(rng);
    s.angle = 6.3 * u(rng);
    s.speed = 1.0 + 1999.0 * u(rng);  // m/s
    s.heading = (u(rng) - 0.5) * 1.5; // rad, within about 43 degrees of the wall's normal
    s.lead = 0.2 + 2.3 * u(rng);      // steps of travel between the body and the wall
    s.y = 2.0 * u(rng) - 1.0;
    return s;
}

/// A world without gravity holding `obstacle`, if any, on a static body at the origin.
World weightless_world(const std::optional<ShapeDef>& obstacle) {
    World world(WorldDef{.gravity = {0.0, 0.0}});
    if (obstacle)
        world.create_shape(world.create_body({.type = BodyType::static_body}), *obstacle);
    return world;
}

struct Outcome {
    bool crossed = false; ///< the centre was past the wall's mid-plane after some step
    BodyState end{};
};

/// A wall 1 cm thick (x in [-0.005, 0.005], 1 km tall, static) and one body fired at it
/// from the left; whether its centre ever got to the right of the wall's mid-plane.
Outcome fire(const Shot& s, bool continuous) {
    WorldDef def;
    def.enable_continuous = continuous;
    World world(def);
    BodyDef wall;
    wall.type = BodyType::static_body;
    world.create_shape(world.create_body(wall), box_shape(0.01, 1000.0));
    BodyDef shot;
    const double size = s.circle ? s.a : 0.5 * std::hypot(s.a, s.b);
    shot.position = {-0.005 - size - s.lead * s.speed * dt * std::cos(s.heading), s.y};
    shot.angle = s.angle;
    shot.linear_velocity = {s.speed * std::cos(s.heading), s.speed * std::sin(s.heading)};
    const BodyId body = world.create_body(shot);
    world.create_shape(body, s.circle ? circle_shape(s.a) : box_shape(s.a, s.b));
    Outcome out;
    for (int k = 0; k < steps; ++k) {
        world.step(dt);
        out.crossed = out.crossed || world.position(body).x > 0.0;
    }
    out.end = world.state(body);
    return out;
}

// 10000 shots each way: a fraction of a second in Release, a few seconds under ASan.
constexpr int shots = 10000;

/// What a shot meets: the static 1 cm box wall above, a static zero-thickness segment or chain
/// edge on x = 0 (the chain's collision side facing the shots), or a free plank 1 cm x 1 km
/// of 10 t (dynamic, no gravity).
enum class Target { segment, chain, plank };

ShapeDef projectile(const Shot& s, int kind) {
    switch (kind) {
    case 0:
        return box_shape(s.a, s.b);
    case 1:
        return circle_shape(s.a);
    default: // a capsule along the body's x axis, s.b long, radius s.a / 2
        return capsule_shape({-0.5 * s.b, 0.0}, {0.5 * s.b, 0.0}, 0.5 * s.a);
    }
}

/// Fires one projectile of `kind` at `target`; whether its centre ever got past the target's
/// mid-plane (the plank's centre, as it is pushed).
bool crosses(const Shot& s, int kind, Target target, bool continuous, bool bullet) {
    WorldDef def;
    def.enable_continuous = continuous;
    if (target == Target::plank)
        def.gravity = {0.0, 0.0};
    World world(def);
    BodyDef wall;
    wall.type = target == Target::plank ? BodyType::dynamic : BodyType::static_body;
    const BodyId w = world.create_body(wall);
    if (target == Target::segment)
        world.create_shape(w, segment_shape({0.0, -500.0}, {0.0, 500.0}));
    else if (target == Target::chain) // listed downwards: the right of the direction is -x
        world.create_chain(w, chain_shapes(std::vector<Vec2d>{{0.0, 500.0}, {0.0, -500.0}}, false));
    else
        world.create_shape(w, box_shape(0.01, 1000.0, Material{1000.0, 0.0, 0.0}));
    BodyDef shot;
    const double size = kind == 1 ? s.a : 0.5 * std::hypot(s.a, s.b);
    shot.position = {-0.005 - size - s.lead * s.speed * dt * std::cos(s.heading), s.y};
    shot.angle = s.angle;
    shot.linear_velocity = {s.speed * std::cos(s.heading), s.speed * std::sin(s.heading)};
    shot.bullet = bullet;
    const BodyId body = world.create_body(shot);
    world.create_shape(body, projectile(s, kind));
    for (int k = 0; k < steps; ++k) {
        world.step(dt);
        if (world.position(body).x > world.position(w).x)
            return true;
    }
    return false;
}

} // namespace

BOOST_AUTO_TEST_SUITE(continuous_suite)

// Oracle: the wall's geometry: a body fired from its left side ends every step with its centre
// left of the wall's mid-plane. Boxes and circles of random size and orientation, at 1 to
// 2000 m/s, within about 43 degrees of the wall's normal. With continuous collision off the
// same shots must pass through it at least once (so that this test can fail).
BOOST_AUTO_TEST_CASE(no_tunnelling_through_thin_wall, *utf::label("DD29") * utf::label("R7")) {
    std::mt19937_64 rng(2024);
    int crossed_on = 0, crossed_off = 0;
    for (int k = 0; k < shots; ++k) {
        const Shot s = random_shot(rng, k % 2 == 1);
        const bool on = fire(s, true).crossed;
        if (on)
            BOOST_TEST_MESSAGE("tunnelled: shot " << k << (s.circle ? " circle " : " box ") << s.a
                                                  << " x " << s.b << " at " << s.speed << " m/s");
        crossed_on += on;
        crossed_off += fire(s, false).crossed;
    }
    BOOST_TEST_MESSAGE("thin wall: " << shots << " shots, through it with continuous collision "
                                     << crossed_on << ", without " << crossed_off);
    BOOST_TEST(crossed_on == 0);
    BOOST_TEST(crossed_off > 0);
}

// Oracle: the targets' geometry, as above: boxes, circles and capsules fired from the left at
// 1 to 2000 m/s never end a step with their centre past a static wall of zero thickness (a
// two-sided segment, or a chain edge facing them, DD31), and a body marked bullet never past a
// free dynamic plank 1 cm thick. Without continuous collision (or without the bullet mark,
// for the plank) the same shots pass through at least once, so the test can fail.
BOOST_AUTO_TEST_CASE(no_tunnelling_through_segments_chains_and_planks,
                     *utf::label("DD29") * utf::label("R7")) {
    std::mt19937_64 rng(77);
    for (const Target target : {Target::segment, Target::chain, Target::plank}) {
        int on = 0, off = 0;
        const int n = 1500;
        for (int k = 0; k < n; ++k) {
            const int kind = k % 3;
            const Shot s = random_shot(rng, kind == 1);
            const bool plank = target == Target::plank;
            on += crosses(s, kind, target, true, plank);
            off += plank ? crosses(s, kind, target, true, false)
                         : crosses(s, kind, target, false, false);
        }
        const char* name = target == Target::segment ? "segment"
                           : target == Target::chain ? "chain edge"
                                                     : "dynamic plank (bullets)";
        BOOST_TEST_MESSAGE(name << ": " << n << " shots, through it " << on << " with the pass, "
                                << off << " without");
        BOOST_TEST_CONTEXT(name) {
            BOOST_TEST(on == 0);
            BOOST_TEST(off > 0);
        }
    }
}

// Oracle: DD29's sweep: a body stopped at its time of impact t in [0, 1] is put at
// p_0 + t Delta p and phi_0 + t Delta phi, on its way, not past it nor behind where it started.
// Spinning boxes (5 to 50 rad/s either way) fired at the thin wall: in every step no contact
// acted in (the spin unchanged), the turn is w dt, or a part t of it of the same sign when the
// step ended at a time of impact; and such stops do happen. At such a stop the box's leading
// corner is within DD29's band of the wall, [s*, s* + s*/4] (s* = 5 mm): conservative
// advancement never passes s* and stops at its first iterate within the band (each of these
// stops is reached within its 30 advances).
BOOST_AUTO_TEST_CASE(a_stopped_spinning_body_turns_part_of_its_way, *utf::label("DD29")) {
    constexpr double s_star = 0.005; // max(linear_slop 0, speculative_distance 0.02 / 4)
    std::mt19937_64 rng(77);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    int stopped = 0;
    for (int k = 0; k < 500; ++k) {
        Shot s = random_shot(rng, false);
        WorldDef def;
        def.gravity = {0.0, 0.0};
        World world(def);
        BodyDef wall;
        wall.type = BodyType::static_body;
        world.create_shape(world.create_body(wall), box_shape(0.01, 1000.0));
        BodyDef shot;
        const double size = 0.5 * std::hypot(s.a, s.b);
        shot.position = {-0.005 - size - s.lead * s.speed * dt * std::cos(s.heading), s.y};
        shot.angle = s.angle;
        shot.linear_velocity = {s.speed * std::cos(s.heading), s.speed * std::sin(s.heading)};
        shot.angular_velocity = (k % 2 == 0 ? 1.0 : -1.0) * (5.0 + 45.0 * u(rng));
        const BodyId body = world.create_body(shot);
        world.create_shape(body, box_shape(s.a, s.b));
        for (int step = 0; step < steps; ++step) {
            const double a0 = world.state(body).orientation;
            const double w0 = world.angular_velocity(body);
            world.step(dt);
            const double w1 = world.angular_velocity(body);
            if (w1 != w0)
                break; // a contact acted: the substeps turned it at varying speeds
            double turn = world.state(body).orientation - a0; // unwrapped into (-pi, pi]
            turn -= 2.0 * std::numbers::pi * std::round(turn / (2.0 * std::numbers::pi));
            const double full = w1 * dt;
            BOOST_TEST(turn * full >= -1e-12 * std::abs(full), "shot " << k << " step " << step);
            BOOST_TEST(std::abs(turn) <= std::abs(full) * (1.0 + 1e-9) + 1e-12,
                       "shot " << k << " step " << step);
            if (std::abs(turn) >= std::abs(full) * (1.0 - 1e-6))
                continue;
            ++stopped;
            // Stopped at a time of impact: its leading corner within the band [s*, 1.25 s*]
            // of the wall's face (x = -0.005).
            const BodyState st = world.state(body);
            const double c = std::cos(st.orientation), sn = std::sin(st.orientation);
            double front = -std::numeric_limits<double>::infinity();
            for (const double sx : {-0.5, 0.5})
                for (const double sy : {-0.5, 0.5})
                    front = std::max(front, st.position.x + c * sx * s.a - sn * sy * s.b);
            const double gap = -0.005 - front;
            BOOST_TEST(gap >= s_star * (1.0 - 1e-9), "shot " << k << " step " << step);
            BOOST_TEST(gap <= 1.25 * s_star, "shot " << k << " step " << step);
        }
    }
    BOOST_TEST_MESSAGE("spinning shots: " << stopped << " steps ended at a time of impact");
    BOOST_TEST(stopped > 100);
}

// Oracle: the geometry of the turn. A body that does not translate but turns is swept when
// the farthest point of its shapes from its centre of mass may travel farther than the
// speculative distance in the step (DD29's motion bound, the reach measured from the centre of
// mass). Its one shape, a disc of 5 cm, sits 2 m from its centre of mass (set_mass_data puts
// the centre 1 m on the other side of the body's origin), and it turns at 20 rad/s: the disc
// swings 0.67 m a step, across a static segment 0.25 m away; and at 60 rad/s, a turn of exactly
// 1 rad a step (four substeps of 0.25 rad). Its centre never ends a step past the segment's
// line; without continuous collision it does (so the test can fail). The scene is built along
// y and again turned a quarter turn, along x. Where the pass stops the body, as after any step,
// it stays one rigid frame: its centre of mass is its origin plus its turned local centre, and
// its disc sits at its origin plus the disc's turned offset (the body's definition).
BOOST_AUTO_TEST_CASE(a_turning_body_is_swept_from_its_centre_of_mass, *utf::label("DD29")) {
    const auto swing = [](bool continuous, bool turned, double spin) {
        // The scene's points, turned a quarter turn counter-clockwise when asked.
        const auto at = [turned](double x, double y) {
            return turned ? Vec2d{-y, x} : Vec2d{x, y};
        };
        WorldDef def;
        def.enable_continuous = continuous;
        def.gravity = {0.0, 0.0};
        World world(def);
        BodyDef wall;
        wall.type = BodyType::static_body;
        world.create_shape(world.create_body(wall), segment_shape(at(-0.3, 0.5), at(-0.3, 1.5)));
        const BodyId body = world.create_body(BodyDef{});
        const ShapeId disc = world.create_shape(body, circle_shape(0.05, {}, at(0.0, 1.0)));
        world.set_mass_data(body,
                            BodyMassData{.mass = 1.0, .center = at(0.0, -1.0), .inertia = 1.0});
        world.set_velocity(body, {0.0, 0.0});
        world.set_angular_velocity(body, spin); // counter-clockwise: towards the segment
        bool crossed = false;
        for (int k = 0; k < 10; ++k) {
            world.step(dt);
            const Aabb box = world.shape_aabb(disc);
            const Vec2d c{0.5 * (box.min_x + box.max_x), 0.5 * (box.min_y + box.max_y)};
            crossed = crossed || (turned ? c.y : c.x) < -0.3; // the unturned scene's x
            const Vec2d o = world.origin(body), p = world.position(body);
            const double q = world.orientation(body), cq = std::cos(q), sq = std::sin(q);
            const auto turn = [&](Vec2d v) {
                return Vec2d{cq * v.x - sq * v.y, sq * v.x + cq * v.y};
            };
            const Vec2d lc = turn(world.local_center(body)), offset = turn(at(0.0, 1.0));
            BOOST_TEST(std::hypot(o.x + lc.x - p.x, o.y + lc.y - p.y) <= 1e-12, "step " << k);
            BOOST_TEST(std::hypot(o.x + offset.x - c.x, o.y + offset.y - c.y) <= 1e-12,
                       "step " << k);
        }
        return crossed;
    };
    for (const double spin : {20.0, 60.0})
        for (const bool turned : {false, true}) {
            BOOST_TEST(!swing(true, turned, spin), (turned ? "along x, " : "along y, ") << spin);
            BOOST_TEST(swing(false, turned, spin), (turned ? "along x, " : "along y, ") << spin);
        }
}

// Oracle: DD29's interpolation of the velocities to the time of impact, v_0 + t (v_1 - v_0) and
// w_0 + t (w_1 - w_0), with v_1, w_1 and the unobstructed end position x_1 taken from a twin world
// without the wall, and t read from where the body stopped on its straight path,
// t = (x - x_0) / (x_1 - x_0). Linear and angular damping (DD17, DD18) change both velocities
// within the step, so keeping the end velocities at the earlier pose would show. A disc: its turn
// does not change where it meets the wall. It starts 1 m from the wall, beyond the speculative
// distance, so no contact acts in the step.
BOOST_AUTO_TEST_CASE(a_stopped_body_keeps_the_velocities_of_its_time_of_impact,
                     *utf::label("DD29")) {
    const auto shot = [](bool wall) {
        World world = weightless_world(wall ? box_shape(0.01, 10.0) : std::optional<ShapeDef>{});
        BodyDef disc;
        disc.position = {-0.005 - 0.1 - 1.0, 0.0};
        disc.linear_velocity = {100.0, 0.0};
        disc.angular_velocity = 30.0;
        disc.linear_damping = 2.0;
        disc.angular_damping = 3.0;
        const BodyId body = world.create_body(disc);
        world.create_shape(body, circle_shape(0.1));
        const BodyState start = world.state(body);
        world.step(dt);
        return std::pair{start, world.state(body)};
    };
    const auto [start, stopped] = shot(true);
    const BodyState free = shot(false).second;
    const double t = (stopped.position.x - start.position.x) / (free.position.x - start.position.x);
    BOOST_TEST_REQUIRE(t > 0.3); // stopped well inside the step: the pass acted
    BOOST_TEST_REQUIRE(t < 0.9);
    const auto near = [](double a, double b) { return std::abs(a - b) <= 1e-12 * std::abs(b); };
    const double v = start.velocity.x + t * (free.velocity.x - start.velocity.x);
    const double w = start.angular_velocity + t * (free.angular_velocity - start.angular_velocity);
    BOOST_TEST(near(stopped.velocity.x, v), stopped.velocity.x << " against " << v);
    BOOST_TEST(stopped.velocity.y == 0.0);
    BOOST_TEST(near(stopped.angular_velocity, w), stopped.angular_velocity << " against " << w);
}

// Oracle: DD29's rule and its closed form for straight motion along the line of centres. The
// pass acts only where a shape's core (a disc of a quarter of its radius, for a disc) would come
// within s* of a static shape; the body is then put where its whole shape's conservative
// advancement first lands within s* + s*/4, which for this motion is at s* exactly. A disc of
// 1 cm at 30 m/s ends its step delta beyond its unobstructed end x_1 (from a twin world without
// the pebble) short of a static pebble of 0.5 mm. With linear slop 5 cm and speculative distance
// 1 mm, s* = 5 cm and the pebble's box in the broad phase is fattened by 1 mm only, so the
// swept box's own margin decides whether the pebble is met.
//   delta = 5.1 cm: the core would end 4.8 cm from the pebble, inside s*: stopped at s*.
//   delta = 5.5 cm: the core would end 5.2 cm away; the disc itself would end 4.45 cm away,
//   inside s*, but the pass does not act: it ends at x_1.
BOOST_AUTO_TEST_CASE(the_pass_acts_where_a_core_comes_within_the_target_separation,
                     *utf::label("DD29")) {
    constexpr double radius = 0.01, pebble = 0.0005, target = 0.05;
    const auto end_x = [](double pebble_x) {
        WorldDef def;
        def.gravity = {0.0, 0.0};
        def.linear_slop = target;
        def.speculative_distance = 0.001;
        World world(def);
        if (pebble_x > 0.0) {
            BodyDef p;
            p.type = BodyType::static_body;
            p.position = {pebble_x, 0.0};
            world.create_shape(world.create_body(p), circle_shape(pebble));
        }
        BodyDef disc;
        disc.linear_velocity = {30.0, 0.0};
        const BodyId body = world.create_body(disc);
        world.create_shape(body, circle_shape(radius));
        world.step(dt);
        return world.position(body).x;
    };
    const double x1 = end_x(0.0); // no pebble
    BOOST_TEST_REQUIRE(x1 > 0.4);
    const double stopped_for = x1 + 0.051;
    BOOST_TEST(std::abs(stopped_for - pebble - radius - end_x(stopped_for) - target) <= 1e-12);
    BOOST_TEST(end_x(x1 + 0.055) == x1);
}

// Oracle: DD29's rule, "a hit when d is within s* + s*/4", where the core passes a static shape
// sideways. A disc of 1 m (its core 0.25 m) flies level at 360 m/s, in one step from 2 m left
// of a static box 1 m wide to 2 m right of it, its core passing over the box's top face at a
// height of m s* (s* = 5 mm, a quarter of the speculative distance); the whole disc sweeps
// through the box's upper part. Conservative advancement brings the core down to that height
// as it reaches the box's corner, and no nearer. Then the same with a box 2 m wide whose centre
// lies 0.6 m from its body's origin: its core is the disc of a quarter of its least
// centre-to-edge distance (1 m) about its centroid, the disc's core again.
//   m = 1.4: never within 1.25 s*: the pass does not act, and the body ends its step at the
//   twin world's unobstructed end (without the box), to the bit.
//   m = 1.1: within the band: the body is stopped at its whole shape's time of impact: the
//   disc's edge within [s*, 1.25 s*] of the box's corner, the box's leading face short of the
//   static box's.
BOOST_AUTO_TEST_CASE(a_core_passing_beside_a_shape_is_stopped_only_within_the_band,
                     *utf::label("DD29")) {
    constexpr double radius = 1.0, core = radius / 4.0, s_star = 0.005, offset = 0.6;
    const auto end = [&](double m, bool box, bool offset_box) {
        World world = weightless_world(box ? box_shape(1.0, 1.0) : std::optional<ShapeDef>{});
        BodyDef def; // the centroid starts 2 m left of the static box, m s* above its core's reach
        def.position = {-0.5 - radius - 2.0 - (offset_box ? offset : 0.0), 0.5 + core + m * s_star};
        def.linear_velocity = {360.0, 0.0};
        const BodyId body = world.create_body(def);
        world.create_shape(body, offset_box
                                     ? box_shape(2.0 * radius, 2.0 * radius, {}, {offset, 0.0})
                                     : circle_shape(radius));
        world.step(dt);
        return world.state(body);
    };
    for (const bool offset_box : {false, true}) {
        BOOST_TEST_CONTEXT((offset_box ? "the offset box" : "the disc")) {
            const BodyState beside = end(1.4, true, offset_box), free = end(1.4, false, offset_box);
            BOOST_TEST_REQUIRE(free.position.x > 0.5 + radius); // unobstructed, past the box
            BOOST_TEST(std::memcmp(&beside, &free, sizeof beside) == 0);
            const BodyState stopped = end(1.1, true, offset_box);
            if (offset_box) {
                BOOST_TEST(stopped.position.x + radius <= -0.5, "stopped short of the box");
                continue;
            }
            // The whole disc stops as it comes within s* of the box's corner (-0.5, 0.5), no
            // nearer and no farther than the iteration's own band.
            const double gap =
                std::hypot(stopped.position.x + 0.5, stopped.position.y - 0.5) - radius;
            BOOST_TEST(gap >= s_star, "stopped " << gap << " m from the corner");
            BOOST_TEST(gap <= 1.25 * s_star, "stopped " << gap << " m from the corner");
        }
    }
}

// Oracle: determinism (same inputs, same bits): a shot the pass acts on, fired twice.
BOOST_AUTO_TEST_CASE(continuous_deterministic, *utf::label("determinism")) {
    const Shot s{false, 0.05, 0.8, 0.3, 1500.0, 0.2, 1.3, 0.1};
    const BodyState a = fire(s, true).end, b = fire(s, true).end;
    BOOST_TEST(std::memcmp(&a, &b, sizeof a) == 0);
}

BOOST_AUTO_TEST_SUITE_END()
