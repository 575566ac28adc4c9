// Continuous collision (DD29, R7): fast bodies never pass through a thin static wall.
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>

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

// Oracle: determinism (same inputs, same bits): a shot the pass acts on, fired twice.
BOOST_AUTO_TEST_CASE(continuous_deterministic, *utf::label("DD29") * utf::label("R7")) {
    const Shot s{false, 0.05, 0.8, 0.3, 1500.0, 0.2, 1.3, 0.1};
    const BodyState a = fire(s, true).end, b = fire(s, true).end;
    BOOST_TEST(std::memcmp(&a, &b, sizeof a) == 0);
}

BOOST_AUTO_TEST_SUITE_END()
