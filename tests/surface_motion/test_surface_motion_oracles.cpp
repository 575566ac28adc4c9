// Surface motion (DD46 rolling resistance, DD47 tangent speed) against closed forms: a ball
// rolling to rest on flat ground and down a slope, a ball resting on a slope shallower than
// the resistance angle, a box carried by a conveyor belt, and a belt without friction.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <cstdint>

#include "tamias2d/world.hpp"

using namespace tamias2d;
namespace utf = boost::unit_test;

namespace {

constexpr double dt = 1.0 / 60.0;
constexpr double h = dt / 4.0; // the substep (WorldDef::substeps = 4)
constexpr double g = 9.81;

/// A circle of radius r rolling down a static slope of angle theta (0: flat ground) along
/// d = (cos theta, -sin theta), released rolling without slipping at v0 (omega = -v0 / r);
/// warm is WorldDef::enable_warm_starting; ball_first creates the ball before the ground, so
/// that the ball is the first body of their pair (a contact orders its shapes by creation);
/// a ground_radius above 0 makes the ground a capsule of that radius instead of a box, its top
/// through the origin as the box's; radius is the ball's.
struct Roll {
    World world;
    BodyId ball;
    ShapeId ball_shape;
    Vec2d d, p0;
    static constexpr double default_radius = 0.5;
    double r;
    Roll(double theta, double v0, double c_ball, double c_ground = 0.0, bool warm = true,
         bool ball_first = false, double ground_radius = 0.0, double radius = default_radius)
        : world(
              WorldDef{.gravity = {0.0, -g}, .enable_warm_starting = warm, .enable_sleep = false}),
          r(radius) {
        d = {std::cos(theta), -std::sin(theta)};
        const Vec2d n{std::sin(theta), std::cos(theta)}; // the slope's upward normal
        const auto make_ground = [&] {
            const double depth = ground_radius > 0.0 ? ground_radius : 0.5;
            BodyDef gd;
            gd.type = BodyType::static_body;
            gd.position = {-depth * n.x, -depth * n.y}; // top face through the origin
            gd.angle = -theta;
            Material mg{1.0, 0.0, 0.9};
            mg.rolling_resistance = c_ground;
            const BodyId ground = world.create_body(gd);
            if (ground_radius > 0.0)
                world.create_shape(ground,
                                   capsule_shape({-200.0, 0.0}, {200.0, 0.0}, ground_radius, mg));
            else
                world.create_shape(ground, box_shape(400.0, 1.0, mg));
        };
        if (!ball_first)
            make_ground();
        BodyDef bd;
        bd.position = {r * n.x, r * n.y};
        bd.linear_velocity = {v0 * d.x, v0 * d.y};
        bd.angular_velocity = -v0 / r;
        ball = world.create_body(bd);
        Material mb{1.0, 0.0, 0.9};
        mb.rolling_resistance = c_ball;
        ball_shape = world.create_shape(ball, circle_shape(r, mb));
        if (ball_first)
            make_ground();
        p0 = world.position(ball);
    }
    double along() const {
        const Vec2d p = world.position(ball);
        return (p.x - p0.x) * d.x + (p.y - p0.y) * d.y;
    }
    double speed_along() const {
        const Vec2d v = world.velocity(ball);
        return v.x * d.x + v.y * d.y;
    }
    /// Steps until the ball no longer moves down the slope (at most `seconds`): the distance.
    double distance_to_rest(double seconds) {
        for (int i = 0; i < int(seconds / dt) && speed_along() > 0.0; ++i)
            world.step(dt);
        BOOST_TEST(speed_along() <= 1e-6); // it stopped
        return along();
    }
};

/// The closed form of DD46 (the note of srs/data_definitions.yaml): a solid disc (I = m r^2 / 2)
/// rolling without slipping has kinetic energy (1/2) m v^2 + (1/2) I (v / r)^2 = (3/4) m v^2.
/// The resistance is a torque c r N, N = m g cos(theta), against the rolling; over the rolled
/// angle s / r it takes c N s, while gravity gives m g sin(theta) s: the ball stops after
/// s = (3/4) v0^2 / (g (c cos(theta) - sin(theta))).
double stopping_distance(double v0, double c, double theta) {
    return 0.75 * v0 * v0 / (g * (c * std::cos(theta) - std::sin(theta)));
}

/// The integration's error on a constant deceleration: the substeps' positions use the
/// velocity at the end of each substep (IM1), which cuts the travel short by half a substep's
/// travel at v0, and the stop is seen at a step's end, at most one step's travel at the last
/// speed (below the deceleration times dt): v0 h / 2 + a dt^2 <= v0 h for the cases below.
double integration_bound(double v0) {
    return v0 * h;
}

} // namespace

BOOST_AUTO_TEST_SUITE(surface_motion_oracles)

// Oracle: closed form (stopping_distance above): on flat ground a ball of c = 0.05 at 3 m/s
// stops after 3 v0^2 / (4 c g) = 13.76 m, within the integration bound; the ground's own
// coefficient 0 mixes to the ball's (max), and the ball stops alike when it is the pair's first
// body. The distance does not depend on the radius: a ball of 2 m (I = 8 pi kg m^2, so that
// 1 / I is below 1) stops there too. With warm starting off (each step's resistance then
// starts from none) it slows at the same rate. Without resistance the ball still rolls on.
BOOST_AUTO_TEST_CASE(ball_rolls_to_rest_on_flat_ground, *utf::label("DD46")) {
    const double v0 = 3.0, c = 0.05;
    Roll roll(0.0, v0, c);
    const double s = roll.distance_to_rest(12.0);
    BOOST_TEST_MESSAGE("flat ground: " << s << " m, closed form " << stopping_distance(v0, c, 0.0));
    BOOST_TEST(std::abs(s - stopping_distance(v0, c, 0.0)) <= integration_bound(v0));
    // The mixed coefficient is the larger: the same ball of 0 on a ground of 0.05.
    Roll swapped(0.0, v0, 0.0, c);
    BOOST_TEST(std::abs(swapped.distance_to_rest(12.0) - s) <= integration_bound(v0));
    // The ball as the pair's first body: DD46 reads the relative spin omega_b - omega_a.
    Roll first(0.0, v0, c, 0.0, true, true);
    BOOST_TEST(std::abs(first.distance_to_rest(12.0) - s) <= integration_bound(v0));
    Roll big(0.0, v0, c, 0.0, true, false, 0.0, 2.0);
    BOOST_TEST(std::abs(big.distance_to_rest(12.0) - stopping_distance(v0, c, 0.0)) <=
               integration_bound(v0));
    // Warm starting off: the same deceleration, (2/3) c g (the torque c r m g on I + m r^2 =
    // (3/2) m r^2), read as the speed after 4 s, within one step's change of speed.
    Roll cold(0.0, v0, c, 0.0, false);
    for (int i = 0; i < 240; ++i)
        cold.world.step(dt);
    const double a = 2.0 / 3.0 * c * g;
    BOOST_TEST(std::abs(cold.speed_along() - (v0 - a * 240 * dt)) <= a * dt);
    Roll free(0.0, v0, 0.0);
    for (int i = 0; i < 300; ++i)
        free.world.step(dt);
    BOOST_TEST(free.speed_along() > 0.99 * v0); // nothing else slows a rolling ball
}

// Oracle: closed form of DD46 with its lever, the larger rolling radius: a ball of radius r on
// the flat top of a capsule of radius R > r is resisted by the torque c R N, which takes
// c R N s / r over the rolled angle s / r, so it stops after (3/4) v0^2 r / (c R g), r / R of
// its distance on a box (lever r). Here 3 m/s, c = 0.05, R = 0.75: 9.17 m, within the
// integration bound.
BOOST_AUTO_TEST_CASE(a_capsule_gives_its_radius_as_the_lever, *utf::label("DD46")) {
    const double v0 = 3.0, c = 0.05, R = 0.75;
    Roll roll(0.0, v0, c, 0.0, true, false, R);
    const double s = roll.distance_to_rest(12.0);
    const double closed = stopping_distance(v0, c, 0.0) * Roll::default_radius / R;
    BOOST_TEST_MESSAGE("on a capsule: " << s << " m, closed form " << closed);
    BOOST_TEST(std::abs(s - closed) <= integration_bound(v0));
}

// Oracle: closed form (stopping_distance above): down a slope of 0.1 rad a ball of c = 0.2 at
// 2 m/s stops after (3/4) v0^2 / (g (c cos(theta) - sin(theta))) = 3.08 m.
BOOST_AUTO_TEST_CASE(ball_rolls_to_rest_down_a_slope, *utf::label("DD46")) {
    const double v0 = 2.0, c = 0.2, theta = 0.1;
    Roll roll(theta, v0, c);
    const double s = roll.distance_to_rest(6.0);
    BOOST_TEST_MESSAGE("slope: " << s << " m, closed form " << stopping_distance(v0, c, theta));
    BOOST_TEST(std::abs(s - stopping_distance(v0, c, theta)) <= integration_bound(v0));
}

// Oracle: statics: at rest on a slope of angle theta the resistance must hold the torque of
// the friction that keeps the ball from sliding, r m g sin(theta), and can give up to
// c r m g cos(theta): with tan(theta) = 0.1 < c = 0.2 the ball stays (over 3 s it moves less
// than a millimetre), while with c = 0.05 < tan(theta) it rolls away, accelerating at
// (2/3) g sin(theta) less the resistance's c g cos(theta) (2/3): about 0.5 m in 2 s.
BOOST_AUTO_TEST_CASE(ball_stays_on_a_slope_shallower_than_the_resistance_angle,
                     *utf::label("DD46")) {
    const double theta = std::atan(0.1);
    Roll stays(theta, 0.0, 0.2);
    for (int i = 0; i < 180; ++i)
        stays.world.step(dt);
    BOOST_TEST_MESSAGE("held on the slope: moved " << stays.along() << " m in 3 s");
    BOOST_TEST(std::abs(stays.along()) < 1e-3);
    Roll rolls(theta, 0.0, 0.05);
    for (int i = 0; i < 120; ++i)
        rolls.world.step(dt);
    const double a = (2.0 / 3.0) * g * (std::sin(theta) - 0.05 * std::cos(theta));
    const double expected = 0.5 * a * 2.0 * 2.0;
    BOOST_TEST(std::abs(rolls.along() - expected) <= 0.1 * expected);
}

namespace {

/// A 1 m box set at rest on a static belt (a 100 m x 1 m box, top face y = 0) of tangent
/// speed v and friction mu; `belt_first`: the belt's shape is created first (shape a of the
/// contact) or second.
struct Belt {
    World world{WorldDef{.gravity = {0.0, -g}, .enable_sleep = false}};
    BodyId box;
    Belt(double v, double mu, bool belt_first = true) {
        Material belt_m{1.0, 0.0, mu};
        belt_m.tangent_speed = v;
        BodyDef gd;
        gd.type = BodyType::static_body;
        gd.position = {0.0, -0.5};
        BodyDef bd;
        bd.position = {0.0, 0.5};
        if (belt_first) {
            world.create_shape(world.create_body(gd), box_shape(100.0, 1.0, belt_m));
            box = world.create_body(bd);
            world.create_shape(box, box_shape(1.0, 1.0, Material{1.0, 0.0, mu}));
        } else {
            box = world.create_body(bd);
            world.create_shape(box, box_shape(1.0, 1.0, Material{1.0, 0.0, mu}));
            world.create_shape(world.create_body(gd), box_shape(100.0, 1.0, belt_m));
        }
    }
};

} // namespace

// Oracle: closed form: friction mu m g drags the box towards the belt's speed v, so it
// accelerates at mu g (velocity mu g t) until t* = v / (mu g), having gone v^2 / (2 mu g), and
// then rides at v: x(t) = v t - v^2 / (2 mu g). With mu = 0.5 and v = 2 m/s, t* = 0.408 s.
// Each substep gives the box at most mu g h of speed, and it starts from the first substep's
// end: the velocity is within mu g h of the closed form, the position within v h.
BOOST_AUTO_TEST_CASE(box_on_a_conveyor_reaches_the_belt_speed_at_the_friction_limit,
                     *utf::label("DD47")) {
    const double v = 2.0, mu = 0.5;
    const double t_star = v / (mu * g);
    for (const bool belt_first : {true, false}) {
        Belt belt(v, mu, belt_first);
        double t = 0.0;
        for (int i = 0; i < 90; ++i) {
            belt.world.step(dt);
            t += dt;
            const double expected_v = std::min(mu * g * t, v);
            BOOST_TEST(std::abs(belt.world.velocity(belt.box).x - expected_v) <= mu * g * h);
        }
        const double expected_x = v * t - v * v / (2.0 * mu * g);
        BOOST_TEST(t > t_star);
        BOOST_TEST_MESSAGE("belt: x " << belt.world.position(belt.box).x << " m, closed form "
                                      << expected_x);
        BOOST_TEST(std::abs(belt.world.position(belt.box).x - expected_x) <= v * h);
    }
}

// Oracle: DD47 with mu = 0: friction's bound mu lambda_n is 0, so a belt without friction
// exerts no tangential impulse and the box resting on it never moves sideways (exactly).
BOOST_AUTO_TEST_CASE(tangent_speed_without_friction_does_nothing, *utf::label("DD47")) {
    Belt belt(5.0, 0.0);
    for (int i = 0; i < 120; ++i)
        belt.world.step(dt);
    BOOST_TEST(belt.world.velocity(belt.box).x == 0.0);
    BOOST_TEST(belt.world.position(belt.box).x == 0.0);
}

BOOST_AUTO_TEST_SUITE_END()
