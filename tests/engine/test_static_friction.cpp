// Coulomb's law on an incline (LC2), in the frame of the incline: a level ground under gravity
// turned by the incline's angle theta. A box whose combined coefficient mu exceeds tan(theta)
// stays at rest; one whose mu is below it slides with the closed-form acceleration
// g (sin(theta) - mu cos(theta)). Both with the manifolds reused and computed afresh each step.
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "tamias2d/world.hpp"

namespace utf = boost::unit_test;
namespace tt = boost::test_tools;
using namespace tamias2d;

namespace {

constexpr double dt = 1.0 / 60.0, g = 9.81;

struct Incline {
    World world;
    BodyId box;
    /// A 1 m box of friction mu on a ground of friction mu (combined: mu), at rest on the
    /// incline of angle theta (radians); reuse is WorldDef::manifold_reuse_distance.
    Incline(double theta, double mu, double reuse)
        : world(WorldDef{.gravity = {g * std::sin(theta), -g * std::cos(theta)},
                         .manifold_reuse_distance = reuse}) {
        BodyDef gd;
        gd.type = BodyType::static_body;
        world.create_shape(world.create_body(gd),
                           box_shape(400.0, 1.0, Material{1.0, 0.0, mu}, {0.0, -0.5}));
        BodyDef bd;
        bd.position = {0.0, 0.5};
        box = world.create_body(bd);
        world.create_shape(box, box_shape(1.0, 1.0, Material{1.0, 0.0, mu}));
    }
};

} // namespace

BOOST_AUTO_TEST_SUITE(static_friction)

// Oracle: Coulomb's law, statics: with mu = 0.6 > tan(theta) for theta of 10, 20 and 25 degrees
// the friction the box needs, m g sin(theta), is within mu m g cos(theta), so the box stays at
// rest. "At rest" is taken as a game would see it: after a second of settling, its speed along
// the incline stays under 1 micrometre per second for ten seconds, and it moves less than
// 1 micrometre. Manifolds computed afresh each step (reuse 0) carry their friction impulses
// over by their points' features, as the reused ones do; without that, each step's friction
// starts from zero and the box ends each step sliding at about 1e-3 m/s.
BOOST_AUTO_TEST_CASE(a_box_steeper_than_its_friction_allows_stays_at_rest, *utf::label("LC2")) {
    for (const double reuse : {0.0, 0.005}) {
        for (const double degrees : {10.0, 20.0, 25.0}) {
            BOOST_TEST_CONTEXT("reuse " << reuse << " m, theta " << degrees << " degrees") {
                Incline s(degrees * std::numbers::pi / 180.0, 0.6, reuse);
                for (int k = 0; k < 60; ++k)
                    s.world.step(dt);
                const Vec2d start = s.world.origin(s.box);
                double fastest = 0.0;
                for (int k = 0; k < 600; ++k) {
                    s.world.step(dt);
                    fastest = std::max(fastest, std::abs(s.world.velocity(s.box).x));
                }
                const Vec2d end = s.world.origin(s.box);
                BOOST_TEST(fastest < 1e-6);
                BOOST_TEST(std::hypot(end.x - start.x, end.y - start.y) < 1e-6);
            }
        }
    }
}

// Oracle: Coulomb's law, kinetic friction: with mu = 0.3 < tan(25 degrees) the box slides down
// the incline with acceleration g (sin(theta) - mu cos(theta)) (1.478 m/s^2), without tipping
// (tan(theta) < 1, the box's half width over its half height: it turns by less than 0.01 rad).
// Its speed gained over one second, after a second of sliding, is that acceleration to within
// 1 %: the positive control of the test above (the same scene slides when Coulomb's law says it
// must).
BOOST_AUTO_TEST_CASE(a_box_below_its_friction_angle_slides_at_the_closed_form_rate,
                     *utf::label("LC2")) {
    const double theta = 25.0 * std::numbers::pi / 180.0, mu = 0.3;
    const double a = g * (std::sin(theta) - mu * std::cos(theta));
    for (const double reuse : {0.0, 0.005}) {
        BOOST_TEST_CONTEXT("reuse " << reuse << " m") {
            Incline s(theta, mu, reuse);
            for (int k = 0; k < 60; ++k)
                s.world.step(dt);
            const double v0 = s.world.velocity(s.box).x;
            for (int k = 0; k < 60; ++k)
                s.world.step(dt);
            BOOST_TEST(s.world.velocity(s.box).x - v0 == a * 1.0, tt::tolerance(0.01));
            BOOST_TEST(std::abs(std::sin(s.world.orientation(s.box))) < 0.01);
        }
    }
}

BOOST_AUTO_TEST_SUITE_END()
