// Motion locks (DD39), mass data changed at run time (DD41), the per-body sleep threshold and
// wake_touching: their effects against closed forms and the rules they state, and their strong
// guarantee (a refused call leaves state_hash() unchanged).
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <vector>

#include "tamias2d/errors.hpp"
#include "tamias2d/world.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;

namespace {

constexpr double dt = 1.0 / 60.0;
constexpr int substeps = 4;
constexpr double h = dt / substeps;

double rel_err(double got, double want) {
    return std::abs(got - want) / std::max(1.0, std::abs(want));
}

/// A static slope through the origin, falling at `theta` (rad) to the right: its surface is the
/// line y = -x tan(theta), its upward normal (sin theta, cos theta).
BodyId slope(World& w, double theta, Material m) {
    BodyDef d;
    d.type = BodyType::static_body;
    d.angle = -theta;
    // A 2 m thick box turned by -theta, its top face through the origin: its centre 1 m below
    // the origin along the normal.
    d.position = {-std::sin(theta), -std::cos(theta)};
    const BodyId id = w.create_body(d);
    w.create_shape(id, box_shape(200.0, 2.0, m));
    return id;
}

} // namespace

BOOST_AUTO_TEST_SUITE(body_control_mass)

// ----------------------------------------------------------------------------- DD39

// Oracle: closed forms on an incline of theta = 30 degrees with friction mu = 0.5. A disc free
// to turn rolls without slipping (mu >= tan(theta) / 3): a = g sin(theta) / (1 + I / (m r^2))
// = 2/3 g sin(theta). Its rotation locked (DD39), it slides: a = g (sin(theta) - mu
// cos(theta)), a fifth of that, and does not turn at all. Measured as the change of speed along the
// slope over 1 s of steady motion.
BOOST_AUTO_TEST_CASE(a_disc_with_its_rotation_locked_slides_instead_of_rolling,
                     *utf::label("DD39") * utf::label("LC2")) {
    const double theta = std::numbers::pi / 6.0, mu = 0.5, g = 10.0;
    for (const bool locked : {false, true}) {
        World w(WorldDef{.gravity = {0.0, -g}});
        slope(w, theta, Material{1.0, 0.0, mu});
        // The disc of radius 0.5 resting on the surface at x = 0 (the surface normal there is
        // (sin theta, cos theta)).
        const double r = 0.5;
        BodyDef d;
        d.position = {r * std::sin(theta), r * std::cos(theta)};
        const BodyId disc = w.create_body(d);
        w.create_shape(disc, circle_shape(r, Material{1.0, 0.0, mu}));
        if (locked)
            w.set_fixed_rotation(disc, true);
        BOOST_TEST(w.fixed_rotation(disc) == locked);
        const double angle0 = w.orientation(disc);
        for (int i = 0; i < 30; ++i)
            w.step(dt);
        // The surface y = -x tan(theta) falls to the right: down it is (cos theta, -sin theta).
        const Vec2d along{std::cos(theta), -std::sin(theta)};
        const auto speed = [&] {
            return w.velocity(disc).x * along.x + w.velocity(disc).y * along.y;
        };
        const double v1 = speed();
        for (int i = 0; i < 60; ++i) {
            w.step(dt);
            if (locked) {
                BOOST_TEST_REQUIRE(w.angular_velocity(disc) == 0.0);
                BOOST_TEST_REQUIRE(w.orientation(disc) == angle0);
            }
        }
        const double a = (speed() - v1) / 1.0;
        const double want = locked ? g * (std::sin(theta) - mu * std::cos(theta))
                                   : (2.0 / 3.0) * g * std::sin(theta);
        BOOST_TEST(std::abs(a - want) / want < 0.01,
                   "locked " << locked << ": a = " << a << ", closed form " << want);
    }
}

// Oracle: DD39's projection and IM1's free fall: under gravity (3, -10), a box locked along x
// keeps its x to the bit while it falls (y per IM1 from rest), lands on a 30-degree slope
// whose contact pushes it sideways, and is struck sideways; unlocked, the slope moves it.
BOOST_AUTO_TEST_CASE(a_linear_lock_holds_its_axis_exactly,
                     *utf::label("DD39") * utf::label("IM1")) {
    World w(WorldDef{.gravity = {3.0, -10.0}});
    slope(w, std::numbers::pi / 6.0, Material{1.0, 0.0, 0.0});
    BodyDef d;
    d.position = {0.0, 5.0};
    const BodyId b = w.create_body(d);
    w.create_shape(b, circle_shape(0.5));
    w.set_motion_locks(b, MotionLocks{.linear_x = true});
    BOOST_TEST((w.motion_locks(b) == MotionLocks{true, false, false}));
    for (int n = 1; n <= 20; ++n) { // 4.5 m to fall takes ~0.95 s: free for 20 steps
        w.step(dt);
        BOOST_TEST_REQUIRE(w.position(b).x == 0.0);
        BOOST_TEST_REQUIRE(w.velocity(b).x == 0.0);
        const int k = n * substeps;
        BOOST_TEST_REQUIRE(rel_err(w.position(b).y, 5.0 - 10.0 * h * h * k * (k + 1) / 2.0) <
                           1e-12);
    }
    for (int n = 0; n < 120; ++n)
        w.step(dt);
    w.apply_impulse(b, {50.0, 0.0}, w.position(b));
    BOOST_TEST(rel_err(w.velocity(b).x, 50.0 / w.mass(b)) < 1e-14); // the impulse acts (DD10)
    for (int n = 0; n < 30; ++n)
        w.step(dt);
    BOOST_TEST(w.position(b).x == 0.0); // but the lock holds x
    BOOST_TEST(w.velocity(b).x == 0.0);
    BOOST_TEST(std::abs(w.position(b).y - 0.5 / std::cos(std::numbers::pi / 6.0)) < 0.02);
    // Unlocked, the frictionless slope and gravity's x move it.
    w.set_motion_locks(b, MotionLocks{});
    for (int n = 0; n < 30; ++n)
        w.step(dt);
    BOOST_TEST(w.position(b).x > 0.1);
}

// Oracle: the rule: a lock set now stops its motion now (DD39), and the angular lock's inertia
// (DD14) returns when it is lifted.
BOOST_AUTO_TEST_CASE(locks_stop_their_motion_at_once, *utf::label("DD39") * utf::label("DD14")) {
    World w(WorldDef{.gravity = {0.0, 0.0}});
    const BodyId b = w.create_body(BodyDef{.linear_velocity = {1.0, 2.0}, .angular_velocity = 3.0});
    w.create_shape(b, box_shape(2.0, 1.0, Material{1.5, 0.0, 0.0}));
    const double inertia = 3.0 * (4.0 + 1.0) / 12.0;
    BOOST_TEST(w.inertia(b) == inertia, boost::test_tools::tolerance(1e-15));
    w.set_motion_locks(b, MotionLocks{.linear_y = true, .angular = true});
    BOOST_TEST(w.velocity(b).x == 1.0);
    BOOST_TEST(w.velocity(b).y == 0.0);
    BOOST_TEST(w.angular_velocity(b) == 0.0);
    w.apply_torque(b, 10.0);
    w.step(dt);
    BOOST_TEST(w.angular_velocity(b) == 0.0);
    w.set_motion_locks(b, MotionLocks{});
    BOOST_TEST(w.inertia(b) == inertia, boost::test_tools::tolerance(1e-15));
    w.apply_torque(b, 10.0);
    w.step(dt);
    // One step of alpha = tau / I, its torque held over the step (IM2).
    BOOST_TEST(w.angular_velocity(b) == 10.0 / inertia * dt, boost::test_tools::tolerance(1e-12));
    const std::uint64_t before = w.state_hash();
    BOOST_CHECK_THROW(w.set_motion_locks(BodyId{7, 7}, MotionLocks{}), InvalidHandle);
    BOOST_TEST(w.state_hash() == before);
}

// Oracle: DD39's angular lock, "nothing turns it": an angular velocity set on a locked body is
// ignored (as Box2D v3's b2Body_SetAngularVelocity does), so the body keeps its orientation
// through the next steps and its kinetic energy is its translation's alone (DD15: 1/2 m v^2,
// 3 kg at (1, 2) m/s: 7.5 J). Lifted, the lock lets the same call turn it.
BOOST_AUTO_TEST_CASE(a_set_angular_velocity_does_not_turn_a_locked_body,
                     *utf::label("DD39") * utf::label("DD15")) {
    World w(WorldDef{.gravity = {0.0, 0.0}});
    const BodyId b = w.create_body(
        BodyDef{.angle = 0.25, .linear_velocity = {1.0, 2.0}, .fixed_rotation = true});
    w.create_shape(b, box_shape(2.0, 1.0, Material{1.5, 0.0, 0.0}));
    w.set_angular_velocity(b, 3.0);
    BOOST_TEST(w.angular_velocity(b) == 0.0);
    for (int i = 0; i < 10; ++i)
        w.step(dt);
    BOOST_TEST(w.orientation(b) == 0.25);
    BOOST_TEST(w.kinetic_energy() == 7.5, boost::test_tools::tolerance(1e-14));
    w.set_fixed_rotation(b, false);
    w.set_angular_velocity(b, 3.0);
    BOOST_TEST(w.angular_velocity(b) == 3.0);
}

// Oracle: DD39's angular lock, "nothing turns it", which acts on dynamic bodies: a kinematic
// body keeps the turn it is given (R2) though its definition locks its rotation. Made dynamic,
// the lock holds it: no angular velocity, its orientation kept through the next steps, and its
// kinetic energy its translation's alone (DD15: 3 kg at (1, 2) m/s, 7.5 J).
BOOST_AUTO_TEST_CASE(a_turning_kinematic_body_made_dynamic_under_a_lock_stops_turning,
                     *utf::label("DD39") * utf::label("DD15")) {
    World w(WorldDef{.gravity = {0.0, 0.0}});
    const BodyId b = w.create_body(BodyDef{.type = BodyType::kinematic,
                                           .linear_velocity = {1.0, 2.0},
                                           .angular_velocity = 3.0,
                                           .fixed_rotation = true});
    w.create_shape(b, box_shape(2.0, 1.0, Material{1.5, 0.0, 0.0}));
    w.step(dt);
    BOOST_TEST(w.angular_velocity(b) == 3.0);
    BOOST_TEST(w.orientation(b) == 3.0 * dt, boost::test_tools::tolerance(1e-12));
    w.set_body_type(b, BodyType::dynamic);
    BOOST_TEST(w.angular_velocity(b) == 0.0);
    const double held = w.orientation(b);
    for (int i = 0; i < 10; ++i)
        w.step(dt);
    BOOST_TEST(w.orientation(b) == held);
    BOOST_TEST(w.kinetic_energy() == 7.5, boost::test_tools::tolerance(1e-14));
}

// Oracle: a uniform rectangle's moment of inertia in closed form, m (w^2 + h^2) / 12, and R2's
// rule for a given mass: it replaces the shapes' mass and keeps their distribution. A 2 m x 1 m
// box of density 1 (2 kg, 5/6 kg m^2) given a mass of 6 kg has 6 * 5 / 12 = 2.5 kg m^2, as the
// same box of density 3 has; given a moment of inertia as well, it has that one. Boxes of 1 kg
// and of 0.5 kg (1 m x 1 m, 1 m x 0.5 m) given 6 kg have 6 (w^2 + h^2) / 12 too: the rule holds
// whatever the shapes' own mass.
BOOST_AUTO_TEST_CASE(a_given_mass_scales_the_shapes_moment_of_inertia, *utf::label("R2")) {
    World w(WorldDef{.gravity = {0.0, 0.0}});
    for (const auto& [width, height] :
         {std::pair{2.0, 1.0}, std::pair{1.0, 1.0}, std::pair{1.0, 0.5}}) {
        BOOST_TEST_CONTEXT(width << " m x " << height << " m") {
            const BodyId given = w.create_body(BodyDef{.mass = 6.0});
            w.create_shape(given, box_shape(width, height));
            BOOST_TEST(w.mass(given) == 6.0);
            BOOST_TEST(w.inertia(given) == 6.0 * (width * width + height * height) / 12.0,
                       boost::test_tools::tolerance(1e-14));
        }
    }
    const BodyId dense = w.create_body(BodyDef{});
    w.create_shape(dense, box_shape(2.0, 1.0, Material{3.0, 0.0, 0.6}));
    BOOST_TEST(w.mass(dense) == 6.0, boost::test_tools::tolerance(1e-14));
    BOOST_TEST(w.inertia(dense) == 2.5, boost::test_tools::tolerance(1e-14));
    const BodyId both = w.create_body(BodyDef{.mass = 6.0, .inertia = 4.0});
    w.create_shape(both, box_shape(2.0, 1.0));
    BOOST_TEST(w.inertia(both) == 4.0);
}

// Oracle: DD15, 1/2 m v^2 + 1/2 I omega^2, for a dynamic body without shapes: a point of the
// default mass (1 kg) and no moment of inertia (I = 0), moving at 3 m/s and turning at 2 rad/s,
// carries 4.5 J, its translation's alone, before and after a step.
BOOST_AUTO_TEST_CASE(a_turning_point_mass_carries_only_its_translations_energy,
                     *utf::label("DD15")) {
    World w(WorldDef{.gravity = {0.0, 0.0}});
    const BodyId b = w.create_body(BodyDef{.linear_velocity = {3.0, 0.0}, .angular_velocity = 2.0});
    BOOST_TEST_REQUIRE(w.mass(b) == 1.0);
    BOOST_TEST_REQUIRE(w.inertia(b) == 0.0);
    BOOST_TEST(w.kinetic_energy() == 4.5);
    w.step(dt);
    BOOST_TEST(w.angular_velocity(b) == 2.0);
    BOOST_TEST(w.kinetic_energy() == 4.5);
}

// ----------------------------------------------------------------------------- DD41

// Oracle: DD41's closed form. A 2 x 1 box (3 kg) moving at v = (1, 2) and turning at omega =
// 3 rad/s without gravity gets mass 6 kg, centre (0.5, 0) in its frame and inertia 4: its new
// centre is at origin + R(phi) (0.5, 0) and moves at v + omega x d (d = R(phi) (0.5, 0)); omega
// stays; the momentum becomes 6 (v + omega x d), not 3 v (GD1 gives no rule for it).
BOOST_AUTO_TEST_CASE(mass_data_changed_mid_flight_keeps_the_rigid_motion,
                     *utf::label("DD41") * utf::label("DD9") * utf::label("GD1")) {
    World w(WorldDef{.gravity = {0.0, 0.0}});
    const BodyId b = w.create_body(
        BodyDef{.angle = 0.3, .linear_velocity = {1.0, 2.0}, .angular_velocity = 3.0});
    w.create_shape(b, box_shape(2.0, 1.0, Material{1.5, 0.0, 0.0}));
    for (int i = 0; i < 7; ++i)
        w.step(dt);
    const Vec2d v = w.velocity(b);
    const double omega = w.angular_velocity(b);
    const double phi = w.orientation(b);
    const Vec2d origin = w.origin(b);
    w.set_mass_data(b, BodyMassData{6.0, {0.5, 0.0}, 4.0});
    const Vec2d d{0.5 * std::cos(phi), 0.5 * std::sin(phi)};
    BOOST_TEST(w.mass(b) == 6.0);
    BOOST_TEST(w.inertia(b) == 4.0);
    BOOST_TEST(w.local_center(b).x == 0.5);
    BOOST_TEST(w.origin(b).x == origin.x);
    BOOST_TEST(w.origin(b).y == origin.y);
    BOOST_TEST(rel_err(w.position(b).x, origin.x + d.x) < 1e-14);
    BOOST_TEST(rel_err(w.position(b).y, origin.y + d.y) < 1e-14);
    BOOST_TEST(rel_err(w.velocity(b).x, v.x - omega * d.y) < 1e-14);
    BOOST_TEST(rel_err(w.velocity(b).y, v.y + omega * d.x) < 1e-14);
    BOOST_TEST(w.angular_velocity(b) == omega);
    BOOST_TEST(rel_err(w.linear_momentum().y, 6.0 * (v.y + omega * d.x)) < 1e-14);
    const BodyMassData md = w.mass_data(b);
    BOOST_TEST(md.mass == 6.0);
    BOOST_TEST(md.inertia == 4.0);
    // Free flight goes on from there (IM1, IM2 with no load).
    const Vec2d p = w.position(b);
    const Vec2d v2 = w.velocity(b);
    w.step(dt);
    BOOST_TEST(rel_err(w.position(b).x, p.x + v2.x * dt) < 1e-13);
    // reset_mass_data: the shapes' again (DD1, DD14), the centre back at the origin.
    w.reset_mass_data(b);
    BOOST_TEST(w.mass(b) == 3.0);
    BOOST_TEST(w.inertia(b) == 1.25, boost::test_tools::tolerance(1e-15));
    BOOST_TEST(w.local_center(b).x == 0.0);
}

// Oracle: DD41's closed form where the centre moves along one axis only: a body at angle 0
// moving at v = (1, 2) and turning at omega = 3 rad/s is given its centre at (0.5, 0), then at
// (0, 0.5), then at (1, 0), then at (0, 1) in its frame: the new centre moves at
// v + omega x d, (1, 3.5), (-0.5, 2), (1, 5) and (-2, 2).
BOOST_AUTO_TEST_CASE(a_centre_moved_along_one_axis_takes_the_rigid_velocity,
                     *utf::label("DD41") * utf::label("DD9")) {
    struct Case {
        Vec2d center, velocity;
    };
    for (const Case& c : {Case{{0.5, 0.0}, {1.0, 3.5}}, Case{{0.0, 0.5}, {-0.5, 2.0}},
                          Case{{1.0, 0.0}, {1.0, 5.0}}, Case{{0.0, 1.0}, {-2.0, 2.0}}}) {
        World w(WorldDef{.gravity = {0.0, 0.0}});
        const BodyId b =
            w.create_body(BodyDef{.linear_velocity = {1.0, 2.0}, .angular_velocity = 3.0});
        w.create_shape(b, box_shape(2.0, 1.0));
        w.set_mass_data(b, BodyMassData{6.0, c.center, 4.0});
        BOOST_TEST(w.velocity(b).x == c.velocity.x, "centre " << c.center.x << ", " << c.center.y);
        BOOST_TEST(w.velocity(b).y == c.velocity.y, "centre " << c.center.x << ", " << c.center.y);
        BOOST_TEST(w.angular_velocity(b) == 3.0);
    }
}

// Oracle: DD41's closed form under DD39's lock: a body locked along x, moving at v = (0, 2) and
// turning at omega = 3 rad/s, is given its centre at (0, 0.5) in its frame: the new centre's
// rigid velocity v + omega x d is (-1.5, 2), and the lock keeps its x at zero: (0, 2). Over the
// next steps the body's x does not move.
BOOST_AUTO_TEST_CASE(a_centre_moved_on_a_body_locked_along_x_keeps_x_still,
                     *utf::label("DD41") * utf::label("DD39")) {
    World w(WorldDef{.gravity = {0.0, 0.0}});
    const BodyId b = w.create_body(BodyDef{.linear_velocity = {0.0, 2.0}, .angular_velocity = 3.0});
    w.create_shape(b, box_shape(2.0, 1.0));
    w.set_motion_locks(b, MotionLocks{.linear_x = true});
    const double x = w.position(b).x;
    w.set_mass_data(b, BodyMassData{6.0, {0.0, 0.5}, 4.0});
    BOOST_TEST(w.velocity(b).x == 0.0);
    BOOST_TEST(w.velocity(b).y == 2.0);
    BOOST_TEST(w.angular_velocity(b) == 3.0);
    for (int n = 0; n < 10; ++n)
        w.step(dt);
    BOOST_TEST(w.position(b).x == x);
}

// Oracle: R4's strong guarantee and the rule that mass belongs to dynamic bodies (R2): the
// refusals name the field and constraint (DCI_m, DCI_I) or the handle (WrongKind), and change
// nothing; the same mass data changes no bit.
BOOST_AUTO_TEST_CASE(mass_data_refusals_change_nothing, *utf::label("R4")) {
    World w(WorldDef{.gravity = {0.0, -10.0}});
    const BodyId g = w.create_body(BodyDef{.type = BodyType::static_body, .name = "ground"});
    w.create_shape(g, box_shape(10.0, 1.0));
    const BodyId b = w.create_body(BodyDef{.position = {0.0, 2.0}});
    w.create_shape(b, box_shape(1.0, 1.0));
    const std::uint64_t before = w.state_hash();
    try {
        w.set_mass_data(g, BodyMassData{1.0, {}, 1.0});
        BOOST_ERROR("accepted");
    } catch (const WrongKind& e) {
        BOOST_TEST(e.subject == "body[0 'ground']");
        BOOST_TEST(e.call == "set_mass_data");
    }
    struct Bad {
        BodyMassData data;
        const char* field;
        const char* constraint;
    };
    for (const Bad& bad : {Bad{{0.0, {}, 1.0}, "mass_data.mass", "DCI_m"},
                           Bad{{-1.0, {}, 1.0}, "mass_data.mass", "DCI_m"},
                           Bad{{std::nan(""), {}, 1.0}, "mass_data.mass", "DCX_finite"},
                           Bad{{1.0, {}, 0.0}, "mass_data.inertia", "DCI_I"},
                           Bad{{1.0, {1e13, 0.0}, 1.0}, "mass_data.center.x", "DCX_range"}}) {
        try {
            w.set_mass_data(b, bad.data);
            BOOST_ERROR("accepted " << bad.field);
        } catch (const ValidationError& e) {
            BOOST_TEST(e.field == bad.field);
            BOOST_TEST(e.constraint == bad.constraint);
        }
    }
    BOOST_TEST(w.state_hash() == before);
    // The same mass data twice: no bit changes.
    World twin(WorldDef{.gravity = {0.0, -10.0}});
    const BodyId tg = twin.create_body(BodyDef{.type = BodyType::static_body, .name = "ground"});
    twin.create_shape(tg, box_shape(10.0, 1.0));
    const BodyId tb = twin.create_body(BodyDef{.position = {0.0, 2.0}});
    twin.create_shape(tb, box_shape(1.0, 1.0));
    w.set_mass_data(b, BodyMassData{2.0, {0.1, 0.0}, 0.5});
    twin.set_mass_data(tb, BodyMassData{2.0, {0.1, 0.0}, 0.5});
    for (int i = 0; i < 60; ++i) {
        w.set_mass_data(b, BodyMassData{2.0, {0.1, 0.0}, 0.5});
        w.step(dt);
        twin.step(dt);
        BOOST_TEST_REQUIRE(w.state_hash() == twin.state_hash());
    }
}

// ----------------------------------------------------------------------------- sleeping

// Oracle: the sleep rule (sleep.hpp) with the body's own threshold: a box gliding at 0.5 m/s on
// frictionless ground never rests under the world's 0.05 m/s, and falls asleep after
// time_to_sleep (0.5 s: within 31 steps) under its own 1 m/s.
BOOST_AUTO_TEST_CASE(a_bodys_sleep_threshold_replaces_the_worlds) {
    World w(WorldDef{.gravity = {0.0, -10.0}, .enable_sleep = true});
    const BodyId g = w.create_body(BodyDef{.type = BodyType::static_body, .position = {0.0, -0.5}});
    w.create_shape(g, box_shape(400.0, 1.0));
    const BodyId b = w.create_body(BodyDef{.position = {0.0, 0.5}, .linear_velocity = {0.5, 0.0}});
    w.create_shape(b, box_shape(1.0, 1.0));
    BOOST_TEST(w.sleep_threshold(b) == w.settings().linear_sleep_tolerance);
    for (int i = 0; i < 60; ++i)
        w.step(dt);
    BOOST_TEST(w.is_awake(b));
    BOOST_TEST(w.awake_body_count() == 1u);
    w.set_sleep_threshold(b, 1.0);
    BOOST_TEST(w.sleep_threshold(b) == 1.0);
    int steps = 0;
    while (w.is_awake(b) && steps < 100) {
        w.step(dt);
        ++steps;
    }
    BOOST_TEST(!w.is_awake(b));
    BOOST_TEST(steps <= 31);
    BOOST_TEST(w.awake_body_count() == 0u);
    const std::uint64_t before = w.state_hash();
    BOOST_CHECK_THROW(w.set_sleep_threshold(b, -1.0), ValidationError);
    BOOST_CHECK_THROW(w.set_sleep_threshold(b, std::nan("")), ValidationError);
    BOOST_TEST(w.state_hash() == before);
    // wake_touching: the ground's touching boxes wake (the rule of World::wake_touching).
    w.wake_touching(g);
    BOOST_TEST(w.is_awake(b));
}

// Oracle: the rule of World::wake_touching: it wakes the bodies touching the one named, and no
// other. Two boxes sleep, one on a platform and one on the ground (two static bodies): waking
// what touches the platform wakes the first box and leaves the second asleep; then waking what
// touches the ground wakes the second.
BOOST_AUTO_TEST_CASE(wake_touching_wakes_only_what_touches_the_body) {
    World w(WorldDef{.gravity = {0.0, -10.0}, .enable_sleep = true});
    const BodyId ground =
        w.create_body(BodyDef{.type = BodyType::static_body, .position = {0.0, -0.5}});
    w.create_shape(ground, box_shape(40.0, 1.0));
    const BodyId platform =
        w.create_body(BodyDef{.type = BodyType::static_body, .position = {10.0, 2.0}});
    w.create_shape(platform, box_shape(2.0, 1.0));
    const BodyId on_platform = w.create_body(BodyDef{.position = {10.0, 3.0}});
    w.create_shape(on_platform, box_shape(1.0, 1.0));
    const BodyId on_ground = w.create_body(BodyDef{.position = {-10.0, 0.5}});
    w.create_shape(on_ground, box_shape(1.0, 1.0));
    for (int i = 0; i < 200 && w.awake_body_count() > 0; ++i)
        w.step(dt);
    BOOST_TEST_REQUIRE(w.awake_body_count() == 0u);
    w.wake_touching(platform);
    BOOST_TEST(w.is_awake(on_platform));
    BOOST_TEST(!w.is_awake(on_ground));
    w.wake_touching(ground);
    BOOST_TEST(w.is_awake(on_ground));
}

BOOST_AUTO_TEST_SUITE_END()
