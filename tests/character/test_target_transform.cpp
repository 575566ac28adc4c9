// World::set_target_transform (DD44) against its closed form: after one step of dt a kinematic
// body's origin is the target's and its orientation the target's (modulo 2 pi), reached by
// the shortest turn; WrongKind for other bodies; the strong guarantee; a repeated call changes
// no bit; the same result on 1 to 4 workers.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <limits>
#include <numbers>

#include "tamias2d/errors.hpp"
#include "tamias2d/world.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;

namespace {

constexpr double pi = std::numbers::pi;

/// The angle a - b brought into (-pi, pi].
double angle_gap(double a, double b) {
    return std::remainder(a - b, 2.0 * pi);
}

struct Platform {
    World world;
    BodyId body;
    explicit Platform(int workers = 1)
        : world(WorldDef{.gravity = {0.0, -10.0}, .workers = workers}) {
        body = world.create_body(
            BodyDef{.type = BodyType::kinematic, .position = {1.0, 2.0}, .angle = 0.2});
        // Off-centre shapes, so that the origin and the centre differ if the body has a centre.
        world.create_shape(body, box_shape(2.0, 0.5));
        world.create_shape(body, circle_shape(0.3, {}, {1.5, 0.4}));
    }
};

} // namespace

BOOST_AUTO_TEST_SUITE(target_transform_dd44)

// Oracle: closed form, the kinematics of constant velocity. A kinematic body keeps its velocity
// over a step (R2: no force moves it), so v = (c_t - c) / dt and omega = Delta / dt bring it to
// the target pose in one step: its origin equals the target (to rounding of the substeps' sums:
// 1e-12 m here) and its orientation equals the target modulo 2 pi. The target 2 pi - 0.3 from
// 0.2 is reached by turning -0.5 rad (written here), the shortest way, not +5.78 rad.
BOOST_AUTO_TEST_CASE(one_step_reaches_the_pose, *utf::label("DD44")) {
    Platform p;
    const double dt = 1.0 / 60.0;
    const Vec2d target{1.7, 1.6};
    const double angle = 2.0 * pi - 0.3;
    p.world.set_target_transform(p.body, target, angle, dt);
    BOOST_TEST(std::abs(p.world.angular_velocity(p.body) - (-0.5 / dt)) <= 1e-9);
    p.world.step(dt);
    const Vec2d o = p.world.origin(p.body);
    BOOST_TEST(std::abs(o.x - target.x) <= 1e-12);
    BOOST_TEST(std::abs(o.y - target.y) <= 1e-12);
    BOOST_TEST(std::abs(angle_gap(p.world.orientation(p.body), angle)) <= 1e-12);
    // A train of targets along a circle, each reached in its step.
    for (int k = 1; k <= 40; ++k) {
        const double phi = 0.15 * k;
        const Vec2d t{3.0 * std::cos(phi), 3.0 * std::sin(phi)};
        p.world.set_target_transform(p.body, t, phi + pi, dt);
        BOOST_TEST(std::abs(p.world.angular_velocity(p.body)) * dt <= pi + 1e-12);
        p.world.step(dt);
        const Vec2d at = p.world.origin(p.body);
        BOOST_TEST(std::hypot(at.x - t.x, at.y - t.y) <= 1e-12);
        BOOST_TEST(std::abs(angle_gap(p.world.orientation(p.body), phi + pi)) <= 1e-12);
    }
}

// Oracle: the stated rules of set_target_transform in world.hpp: WrongKind for a static or
// dynamic body, ValidationError naming the field for a non-finite origin, an angle out of range
// or dt outside [1e-12, 1e12], and the strong guarantee (state_hash() unchanged by the refusals).
BOOST_AUTO_TEST_CASE(refusals, *utf::label("reliability")) {
    Platform p;
    const BodyId ground = p.world.create_body(BodyDef{.type = BodyType::static_body});
    const BodyId ball = p.world.create_body(BodyDef{.position = {0.0, 5.0}});
    p.world.create_shape(ball, circle_shape(0.5));
    const std::uint64_t before = p.world.state_hash();
    BOOST_CHECK_THROW(p.world.set_target_transform(ground, {}, 0.0, 0.1), WrongKind);
    BOOST_CHECK_THROW(p.world.set_target_transform(ball, {}, 0.0, 0.1), WrongKind);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const auto field_of = [&](Vec2d o, double a, double dt) -> std::string {
        try {
            p.world.set_target_transform(p.body, o, a, dt);
        } catch (const ValidationError& e) {
            return e.field;
        }
        return "(none)";
    };
    BOOST_TEST(field_of({nan, 0.0}, 0.0, 0.1) == "origin.x");
    BOOST_TEST(field_of({}, 1e13, 0.1) == "angle");
    BOOST_TEST(field_of({}, 0.0, 0.0) == "dt");
    BOOST_TEST(field_of({}, 0.0, -1.0) == "dt");
    BOOST_TEST(p.world.state_hash() == before);
}

// Oracle: the stated rule of world.hpp (a call whose velocities are already those changes
// nothing), checked by bitwise equality with a second world: after 30 steps, the target renewed
// each step, the state hash is the same with one call per step or two.
BOOST_AUTO_TEST_CASE(same_value_twice, *utf::label("reliability")) {
    Platform once, twice;
    const double dt = 1.0 / 60.0;
    for (int k = 0; k < 30; ++k) {
        const Vec2d t{1.0 + 0.05 * k, 2.0};
        once.world.set_target_transform(once.body, t, 0.2 + 0.01 * k, dt);
        twice.world.set_target_transform(twice.body, t, 0.2 + 0.01 * k, dt);
        twice.world.set_target_transform(twice.body, t, 0.2 + 0.01 * k, dt);
        once.world.step(dt);
        twice.world.step(dt);
    }
    BOOST_TEST(once.world.state_hash() == twice.world.state_hash());
}

// Oracle: the determinism property of docs/user-guide.md (the worker count never decides the
// result): the same targets give the 1-worker world's state hash on 2 to 4 workers.
BOOST_AUTO_TEST_CASE(same_on_every_worker_count, *utf::label("determinism")) {
    std::uint64_t first = 0;
    for (int workers = 1; workers <= 4; ++workers) {
        Platform p(workers);
        for (int k = 0; k < 20; ++k) {
            p.world.set_target_transform(p.body, {0.1 * k, 2.0 - 0.05 * k}, 0.3 * k, 0.02);
            p.world.step(0.02);
        }
        if (workers == 1)
            first = p.world.state_hash();
        BOOST_TEST(p.world.state_hash() == first);
    }
}

BOOST_AUTO_TEST_SUITE_END()
