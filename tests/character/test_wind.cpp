// World::apply_wind (DD45) against closed forms: one step's drag and lift on a disc and a box
// face-on (F = 1/2 rho h w |u| (C_d u + C_l u_perp)), and a disc released in a uniform wind
// approaching the wind's speed as quadratic drag's closed form says; WrongKind and the input
// rules; a sleeping body left alone unless woken.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "tamias2d/errors.hpp"
#include "tamias2d/world.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;

namespace {

constexpr double rho = 1.225; // kg m^-3, air (DD45)
constexpr double depth = 1.0; // m (DD45)

World still_world() {
    return World(WorldDef{.gravity = {0.0, 0.0}});
}

} // namespace

BOOST_AUTO_TEST_SUITE(wind_dd45)

// Oracle: DD45 by hand for one step from rest: a disc of radius a shows the wind its diameter,
// u = W, F = 1/2 rho h 2a |W| (C_d W + C_l W_perp); after one step of dt, v = F dt / m (the
// force constant over the step, IM1). A box 2 m x 1 m face-on to a wind along x shows 1 m.
BOOST_AUTO_TEST_CASE(one_step_force, *utf::label("DD45")) {
    World w = still_world();
    const double a = 0.5;
    const BodyId disc = w.create_body({});
    const ShapeId ds = w.create_shape(disc, circle_shape(a, Material{.density = 2.0}));
    const BodyId box = w.create_body(BodyDef{.position = {5.0, 0.0}});
    const ShapeId bs = w.create_shape(box, box_shape(2.0, 1.0));
    const Vec2d W{3.0, -4.0}; // |W| = 5
    const double cd = 0.8, cl = 0.3, dt = 0.01;
    w.apply_wind(ds, W, cd, cl);
    w.apply_wind(bs, {6.0, 0.0}, 1.0, 0.0);
    w.step(dt);
    const double k = 0.5 * rho * depth * 2.0 * a * 5.0;
    const Vec2d F{k * (cd * W.x - cl * W.y), k * (cd * W.y + cl * W.x)};
    const Vec2d v = w.velocity(disc);
    const double m = w.mass(disc);
    BOOST_TEST(std::abs(v.x - F.x * dt / m) <= 1e-14);
    BOOST_TEST(std::abs(v.y - F.y * dt / m) <= 1e-14);
    BOOST_TEST(std::abs(w.angular_velocity(disc)) <= 1e-15); // at the centroid: no torque
    const double Fb = 0.5 * rho * depth * 1.0 * 6.0 * 6.0;
    BOOST_TEST(std::abs(w.velocity(box).x - Fb * dt / w.mass(box)) <= 1e-14);
    BOOST_TEST(std::abs(w.velocity(box).y) <= 1e-15);
}

// Oracle: quadratic drag's closed form. A disc of mass m at rest in a uniform wind W (no
// gravity): du/dt = -k u^2 for u = W - v, k = rho h C_d 2a / (2 m), so v(t) = W - W / (1 + k W
// t): it approaches the wind's speed and never passes it. With the force held over each step
// (explicit in u), the step's error is k^2 u^3 dt^2 at most (the next term of the exact
// u / (1 + k u dt)); the map contracts, so after time t the error is at most t k^2 W^3 dt.
BOOST_AUTO_TEST_CASE(approaches_the_wind_speed, *utf::label("DD45")) {
    World w = still_world();
    const double a = 0.25;
    const BodyId disc = w.create_body({});
    const ShapeId s = w.create_shape(disc, circle_shape(a, Material{.density = 4.0}));
    const double W = 8.0, cd = 1.0, dt = 1.0 / 240.0;
    const double k = rho * depth * cd * 2.0 * a / (2.0 * w.mass(disc));
    double t = 0.0;
    for (int n = 1; n <= 2400; ++n) {
        w.apply_wind(s, {W, 0.0}, cd, 0.0);
        w.step(dt);
        t = n * dt;
        const double exact = W - W / (1.0 + k * W * t);
        const double v = w.velocity(disc).x;
        BOOST_TEST(std::abs(v - exact) <= t * k * k * W * W * W * dt);
        BOOST_TEST(v < W);
    }
    // Ten seconds in, it moves at a good part of the wind's speed (k W t is about 30 here).
    BOOST_TEST(w.velocity(disc).x > 0.9 * W);
}

// Oracle: the stated rules of apply_wind in world.hpp: WrongKind for a static or kinematic
// body's shape, ValidationError naming the field for a non-finite wind, a negative drag or a
// lift out of range, with state_hash() unchanged; DD45's force is zero in still air on a body at
// rest (hash unchanged); a sleeping body is left alone (hash unchanged) unless `wake` wakes it.
BOOST_AUTO_TEST_CASE(refusals_and_sleep, *utf::label("reliability")) {
    World w(WorldDef{.gravity = {0.0, 0.0}, .enable_sleep = true});
    const BodyId ground = w.create_body(BodyDef{.type = BodyType::static_body});
    const ShapeId gs = w.create_shape(ground, box_shape(1.0, 1.0));
    const BodyId lift = w.create_body(BodyDef{.type = BodyType::kinematic});
    const ShapeId ls = w.create_shape(lift, box_shape(1.0, 1.0));
    const BodyId ball = w.create_body(BodyDef{.position = {5.0, 0.0}});
    const ShapeId bs = w.create_shape(ball, circle_shape(0.5));
    const std::uint64_t before = w.state_hash();
    BOOST_CHECK_THROW(w.apply_wind(gs, {1.0, 0.0}, 1.0, 0.0), WrongKind);
    BOOST_CHECK_THROW(w.apply_wind(ls, {1.0, 0.0}, 1.0, 0.0), WrongKind);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const auto field_of = [&](Vec2d wind, double cd, double cl) -> std::string {
        try {
            w.apply_wind(bs, wind, cd, cl);
        } catch (const ValidationError& e) {
            return e.field;
        }
        return "(none)";
    };
    BOOST_TEST(field_of({nan, 0.0}, 1.0, 0.0) == "wind.x");
    BOOST_TEST(field_of({1.0, 0.0}, -1.0, 0.0) == "drag");
    BOOST_TEST(field_of({1.0, 0.0}, 1.0, 1e13) == "lift");
    BOOST_TEST(w.state_hash() == before);
    // Still air on a resting ball: no force, nothing changes.
    w.apply_wind(bs, {0.0, 0.0}, 1.0, 0.0);
    BOOST_TEST(w.state_hash() == before);
    // Let the ball fall asleep, then blow without waking: nothing changes.
    for (int i = 0; i < 200; ++i)
        w.step(1.0 / 60.0);
    BOOST_TEST_REQUIRE(w.awake_body_count() == 0u);
    const std::uint64_t asleep = w.state_hash();
    w.apply_wind(bs, {5.0, 0.0}, 1.0, 0.0, false);
    BOOST_TEST(w.state_hash() == asleep);
    w.apply_wind(bs, {5.0, 0.0}, 1.0, 0.0, true);
    BOOST_TEST(w.awake_body_count() == 1u);
}

// Oracle: the determinism property of docs/user-guide.md (the worker count never decides the
// result): a row of bodies of several shapes in a gusting wind, with gravity and a floor, gives
// the 1-worker world's state hash on 2 to 4 workers.
BOOST_AUTO_TEST_CASE(same_on_every_worker_count, *utf::label("determinism")) {
    std::uint64_t first = 0;
    for (int workers = 1; workers <= 4; ++workers) {
        World w(WorldDef{.gravity = {0.0, -10.0}, .workers = workers});
        const BodyId ground = w.create_body({.type = BodyType::static_body});
        w.create_shape(ground, box_shape(100.0, 1.0));
        std::vector<ShapeId> shapes;
        for (int k = 0; k < 12; ++k) {
            const BodyId b = w.create_body({.position = {2.0 * k - 12.0, 1.0 + 0.3 * k}});
            const ShapeDef d = k % 3 == 0   ? circle_shape(0.4)
                               : k % 3 == 1 ? box_shape(0.8, 0.5)
                                            : capsule_shape({-0.3, 0.0}, {0.3, 0.1}, 0.2);
            shapes.push_back(w.create_shape(b, d));
        }
        for (int n = 0; n < 120; ++n) {
            const Vec2d gust{6.0 + 3.0 * std::sin(0.1 * n), 1.0};
            for (const ShapeId s : shapes)
                w.apply_wind(s, gust, 1.1, 0.4);
            w.step(1.0 / 60.0);
        }
        if (workers == 1)
            first = w.state_hash();
        BOOST_TEST(w.state_hash() == first);
    }
}

BOOST_AUTO_TEST_SUITE_END()
