// R5, R6 (IM1, IM2): motion under no load, constant force and constant torque, over the whole
// history, against closed forms.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <vector>

#include "tamias2d/units/angle.hpp"
#include "tamias2d/world.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;

namespace {

/// A 2 x 1 box of density 1.5: m = 3 kg, I = m (w^2 + h^2) / 12 = 1.25 kg m^2.
BodyId make_box_body(World& world, BodyDef def) {
    const BodyId b = world.create_body(def);
    world.create_shape(b, box_shape(2.0, 1.0, Material{1.5, 0.0, 0.0}));
    return b;
}

double rel_err(double got, double want) {
    return std::abs(got - want) / std::max(1.0, std::abs(want));
}

} // namespace

BOOST_AUTO_TEST_SUITE(motion)

// Oracle: closed form p(t) = p0 + v0 t, phi(t) = phi0 + omega0 t (no force: IM1, IM2 with
// a = alpha = 0 are solved exactly by any consistent scheme). Also with sleeping on and a slow
// glide (0.3 m/s, 0.02 rad/s: above the linear sleep tolerance, below the angular one): a body
// that moves is never put to sleep, so it follows the same closed form.
BOOST_AUTO_TEST_CASE(free_flight_is_exact,
                     *utf::label("R5") * utf::label("R6") * utf::label("IM1") * utf::label("IM2")) {
    struct Case {
        bool sleep;
        Vec2d v;
        double w;
    };
    for (const Case c : {Case{false, {3.0, -0.5}, -0.7}, Case{true, {0.3, -0.2}, 0.02}}) {
        World world(WorldDef{.gravity = {0.0, 0.0}, .enable_sleep = c.sleep});
        BodyDef def;
        def.position = {1.0, -2.0};
        def.linear_velocity = c.v;
        def.angular_velocity = c.w;
        def.angle = 0.3;
        const BodyId b = make_box_body(world, def);
        const double dt = 1.0 / 60.0;
        for (int n = 1; n <= 600; ++n) {
            world.step(dt);
            const double t = n * dt;
            const BodyState s = world.state(b);
            BOOST_TEST(rel_err(s.position.x, 1.0 + c.v.x * t) < 1e-12);
            BOOST_TEST(rel_err(s.position.y, -2.0 + c.v.y * t) < 1e-12);
            BOOST_TEST(s.velocity.x == c.v.x);
            BOOST_TEST(s.velocity.y == c.v.y);
            BOOST_TEST(rel_err(s.orientation, units::wrap_orientation(0.3 + c.w * t)) < 1e-12);
            BOOST_TEST(s.angular_velocity == c.w);
        }
    }
}

// Oracle: IM1 and IM2 with a constant load and no gravity: v(t) = (F / m) t and
// omega(t) = (tau / I) t, exact in the scheme. Each body carries one load component alone, of
// exactly 1 N or 1 N m, given at creation (BodyDef), so that every component is applied on its
// own whatever the others are.
BOOST_AUTO_TEST_CASE(a_single_unit_load_is_applied, *utf::label("IM1") * utf::label("IM2")) {
    World world(WorldDef{.gravity = {0.0, 0.0}});
    BodyDef def;
    def.force = {1.0, 0.0};
    const BodyId fx = make_box_body(world, def);
    def.force = {0.0, 1.0};
    def.position = {10.0, 0.0};
    const BodyId fy = make_box_body(world, def);
    def.force = {0.0, 0.0};
    def.torque = 1.0;
    def.position = {20.0, 0.0};
    const BodyId tz = make_box_body(world, def);
    const double m = 3.0, inertia = 1.25, dt = 1.0 / 60.0;
    for (int n = 1; n <= 30; ++n) {
        world.step(dt);
        const double t = n * dt;
        BOOST_TEST(rel_err(world.velocity(fx).x, t / m) < 1e-12);
        BOOST_TEST(world.velocity(fx).y == 0.0);
        BOOST_TEST(rel_err(world.velocity(fy).y, t / m) < 1e-12);
        BOOST_TEST(world.velocity(fy).x == 0.0);
        BOOST_TEST(rel_err(world.angular_velocity(tz), t / inertia) < 1e-12);
    }
}

// Oracle: closed forms of IM1 with constant a = g + F/m: v(t) = v0 + a t (the scheme is exact in
// v), and the semi-implicit Euler scheme's exact discrete solution
// p_n = p0 + v0 t + a t^2 / 2 + a h t / 2 (h = substep), i.e. the continuous
// p(t) = p0 + v0 t + a t^2 / 2 with its known first-order error a h t / 2.
BOOST_AUTO_TEST_CASE(constant_force_history, *utf::label("R5") * utf::label("IM1") *
                                                 utf::label("GD2") * utf::label("T1") *
                                                 utf::label("GS1")) {
    const Vec2d g{0.0, -9.81};
    World world(WorldDef{.gravity = g});
    BodyDef def;
    def.position = {0.0, 100.0};
    def.linear_velocity = {-2.0, 4.0};
    def.force = {6.0, 1.5}; // N, on m = 3 kg: a = g + (2, 0.5)
    const BodyId b = make_box_body(world, def);
    BOOST_TEST(world.mass(b) == 3.0);
    const Vec2d a{g.x + 2.0, g.y + 0.5};
    const double dt = 1.0 / 60.0;
    const double h = dt / world.settings().substeps;
    for (int n = 1; n <= 300; ++n) {
        world.step(dt);
        const double t = n * dt;
        const BodyState s = world.state(b);
        BOOST_TEST(rel_err(s.velocity.x, -2.0 + a.x * t) < 1e-12);
        BOOST_TEST(rel_err(s.velocity.y, 4.0 + a.y * t) < 1e-12);
        BOOST_TEST(rel_err(s.position.x, -2.0 * t + 0.5 * a.x * t * t + 0.5 * a.x * h * t) < 1e-12);
        BOOST_TEST(rel_err(s.position.y, 100.0 + 4.0 * t + 0.5 * a.y * t * t + 0.5 * a.y * h * t) <
                   1e-12);
        // First-order convergence to the continuous solution: the error is a h t / 2.
        BOOST_TEST(std::abs(s.position.y - (100.0 + 4.0 * t + 0.5 * a.y * t * t)) <=
                   0.5 * std::abs(a.y) * h * t * (1.0 + 1e-9));
    }
}

// Oracle: closed form of IM2 with constant alpha = tau / I (T4): omega(t) = omega0 + alpha t,
// phi_n = phi0 + omega0 t + alpha t^2 / 2 + alpha h t / 2 (semi-implicit Euler, exact discrete
// solution), wrapped to [0, 2 pi) (SRS Table 2).
BOOST_AUTO_TEST_CASE(constant_torque_history, *utf::label("R6") * utf::label("IM2") *
                                                  utf::label("T4") * utf::label("DCO_phi") *
                                                  utf::label("GS2")) {
    World world(WorldDef{.gravity = {0.0, 0.0}});
    BodyDef def;
    def.angular_velocity = 0.5;
    def.torque = -2.5; // N m on I = 1.25 kg m^2: alpha = -2 rad s^-2
    const BodyId b = make_box_body(world, def);
    BOOST_TEST(std::abs(world.inertia(b) - 1.25) < 1e-14);
    const double alpha = -2.5 / world.inertia(b);
    const double dt = 1.0 / 60.0;
    const double h = dt / world.settings().substeps;
    for (int n = 1; n <= 300; ++n) {
        world.step(dt);
        const double t = n * dt;
        const BodyState s = world.state(b);
        BOOST_TEST(rel_err(s.angular_velocity, 0.5 + alpha * t) < 1e-12);
        const double phi = 0.5 * t + 0.5 * alpha * t * t + 0.5 * alpha * h * t;
        BOOST_TEST(std::abs(s.orientation - units::wrap_orientation(phi)) < 1e-11);
        BOOST_TEST(s.orientation >= 0.0);
        BOOST_TEST(s.orientation < 2.0 * M_PI);
        // The centre of mass does not move under a pure torque.
        BOOST_TEST(s.position.x == 0.0);
        BOOST_TEST(s.position.y == 0.0);
    }
}

// Oracle: the same closed form of IM2 (T4), omega(t) = omega0 + (tau / I) t, for the bodies of
// a world stepped on two workers and large enough (1100 boxes, 3 m apart) for the bodies to be
// prepared in blocks: every third box is turned by -2.5 N m, every third by +1.25 N m, the rest
// by none.
BOOST_AUTO_TEST_CASE(a_torque_turns_bodies_prepared_in_blocks_on_workers,
                     *utf::label("IM2") * utf::label("T4")) {
    World world(WorldDef{.gravity = {0.0, 0.0}, .workers = 2});
    std::vector<BodyId> ids;
    const double torques[] = {-2.5, 1.25, 0.0};
    for (int k = 0; k < 1100; ++k) {
        BodyDef def;
        def.position = {3.0 * (k % 40), 3.0 * (k / 40)};
        def.angular_velocity = 0.5;
        def.torque = torques[k % 3];
        ids.push_back(make_box_body(world, def));
    }
    const double dt = 1.0 / 60.0;
    for (int n = 1; n <= 30; ++n)
        world.step(dt);
    for (std::size_t k = 0; k < ids.size(); ++k) {
        const double alpha = torques[k % 3] / world.inertia(ids[k]);
        BOOST_TEST(rel_err(world.angular_velocity(ids[k]), 0.5 + alpha * 30 * dt) < 1e-12,
                   "box " << k);
    }
}

// Oracle: DD13 by hand. A force F = (0, 2) N at the world point (1, 0) m from the centre gives
// tau = r x F = 1 * 2 = 2 N m, so after one step of dt: omega = alpha dt = (2 / I) dt and
// v = (F / m) dt.
BOOST_AUTO_TEST_CASE(force_at_point_gives_torque, *utf::label("R2") * utf::label("DD13")) {
    World world(WorldDef{.gravity = {0.0, 0.0}});
    const BodyId b = make_box_body(world, {});
    world.apply_force(b, {0.0, 2.0}, {1.0, 0.0});
    const double dt = 0.1;
    world.step(dt);
    BOOST_TEST(rel_err(world.angular_velocity(b), 2.0 / 1.25 * dt) < 1e-14);
    BOOST_TEST(rel_err(world.velocity(b).y, 2.0 / 3.0 * dt) < 1e-14);
    // One-step forces do not persist.
    world.step(dt);
    BOOST_TEST(rel_err(world.angular_velocity(b), 2.0 / 1.25 * dt) < 1e-14);
}

// Oracle: IM1 and IM2 by hand, step by step: a load acts in every step taken while it is set
// (a one-step load in the next step only), giving dv = (F / m) dt and d omega = (tau / I) dt
// per step, and nothing without it. (The step skips an unloaded body's loads and masses: this
// switches the loads on and off, persistent and one-step, to show the skip never drops one.)
BOOST_AUTO_TEST_CASE(loads_switched_on_and_off,
                     *utf::label("R5") * utf::label("R6") * utf::label("IM1") * utf::label("IM2")) {
    World world(WorldDef{.gravity = {0.0, 0.0}});
    const BodyId b = make_box_body(world, {}); // m = 3 kg, I = 1.25 kg m^2
    const double dt = 0.1;
    world.step(dt);
    BOOST_TEST(world.velocity(b).x == 0.0);
    world.set_force(b, {6.0, 0.0}); // a = 2 m s^-2
    for (int n = 1; n <= 3; ++n) {
        world.step(dt);
        BOOST_TEST(rel_err(world.velocity(b).x, 2.0 * dt * n) < 1e-14);
    }
    world.set_force(b, {0.0, 0.0});
    for (int n = 0; n < 2; ++n) {
        world.step(dt);
        BOOST_TEST(rel_err(world.velocity(b).x, 6.0 * dt) < 1e-14);
    }
    world.apply_torque(b, 2.5); // alpha = 2 rad s^-2, this step only
    world.step(dt);
    BOOST_TEST(rel_err(world.angular_velocity(b), 2.0 * dt) < 1e-14);
    world.step(dt);
    BOOST_TEST(rel_err(world.angular_velocity(b), 2.0 * dt) < 1e-14);
    world.set_torque(b, -2.5); // alpha = -2 rad s^-2 from now on
    world.step(dt);
    world.step(dt);
    BOOST_TEST(std::abs(world.angular_velocity(b) - (2.0 * dt - 2.0 * 2.0 * dt)) < 1e-14);
    BOOST_TEST(rel_err(world.velocity(b).x, 6.0 * dt) < 1e-14);
}

// Oracle: DD10 J = m dv and r x J = I d omega by hand: J = (0, 3) N s at (0.5, 0) m from the
// centre on m = 3 kg, I = 1.25 kg m^2: dv = (0, 1) m/s, d omega = 1.5 / 1.25 rad/s.
BOOST_AUTO_TEST_CASE(impulse_at_point, *utf::label("R2") * utf::label("DD10")) {
    World world(WorldDef{.gravity = {0.0, 0.0}});
    const BodyId b = make_box_body(world, {});
    world.apply_impulse(b, {0.0, 3.0}, {0.5, 0.0});
    BOOST_TEST(rel_err(world.velocity(b).y, 1.0) < 1e-15);
    BOOST_TEST(world.velocity(b).x == 0.0);
    BOOST_TEST(rel_err(world.angular_velocity(b), 1.5 / 1.25) < 1e-14);
}

// Oracle: closed form for a load F(t) = (A sin(w t), 0) held constant over each step (the
// callback is sampled at step starts): v_n = sum_k A sin(w t_k) dt / m, exact for the scheme.
BOOST_AUTO_TEST_CASE(time_varying_load_is_sampled_per_step, *utf::label("R2") * utf::label("IM1")) {
    World world(WorldDef{.gravity = {0.0, 0.0}});
    BodyDef def;
    def.load = [](double t) { return Load{{4.0 * std::sin(3.0 * t), 0.0}, 0.0}; };
    const BodyId b = make_box_body(world, def);
    const double dt = 0.01;
    double v = 0.0;
    for (int n = 0; n < 200; ++n) {
        v += 4.0 * std::sin(3.0 * (n * dt)) / 3.0 * dt;
        world.step(dt);
        BOOST_TEST(std::abs(world.velocity(b).x - v) < 1e-13);
    }
}

// Oracle: closed form p(t) = p0 + v0 t (IM1 with a = 0) for every body of a world where some
// bodies have no shape (mass 1 kg by default): twelve bodies, every third shapeless, each
// gliding at its own velocity, all exact.
BOOST_AUTO_TEST_CASE(shapeless_bodies_among_others_fly_freely, *utf::label("IM1")) {
    World world(WorldDef{.gravity = {0.0, 0.0}});
    std::vector<BodyId> ids;
    for (int k = 0; k < 12; ++k) {
        BodyDef def;
        def.position = {10.0 * k, 0.0};
        def.linear_velocity = {0.5 + 0.25 * k, -0.1 * k};
        ids.push_back(k % 3 == 2 ? world.create_body(def) : make_box_body(world, def));
    }
    for (int n = 1; n <= 60; ++n) {
        world.step(1.0 / 60.0);
        const double t = n / 60.0;
        for (int k = 0; k < 12; ++k) {
            BOOST_TEST(rel_err(world.position(ids[k]).x, 10.0 * k + (0.5 + 0.25 * k) * t) < 1e-12);
            BOOST_TEST(rel_err(world.position(ids[k]).y, -0.1 * k * t) < 1e-12);
        }
    }
}

// Oracle: IM1/IM2's closed forms p(t) = p0 + v0 t + g t^2/2 (+ the scheme's g h t / 2) and
// phi(t) = phi0 + omega0 t, and the ground's geometry (R7: no box's centre over the ground ever
// gets below its top face, as it would if a collision went undetected), for a world stepped on two
// workers: 1200 boxes (above the size from which the bodies' loops run in blocks) fall freely,
// then land in columns 30 high on the ground.
BOOST_AUTO_TEST_CASE(many_bodies_on_two_workers_fall_and_land,
                     *utf::label("IM1") * utf::label("IM2") * utf::label("R7")) {
    const double g = 9.81, dt = 1.0 / 60.0;
    World world(WorldDef{.gravity = {0.0, -g}, .workers = 2});
    BodyDef gd;
    gd.type = BodyType::static_body;
    world.create_shape(world.create_body(gd), box_shape(100.0, 1.0)); // top face at y = 0.5
    std::vector<BodyId> ids;
    std::vector<BodyDef> defs;
    for (int k = 0; k < 1200; ++k) {
        BodyDef def;
        def.position = {-30.0 + 1.5 * (k % 40), 20.0 + 1.5 * (k / 40)};
        // Spinning up to 12 rad/s (a turning box's fat box is refit from its vertices), and
        // every tenth thrown down at 25 m/s (swept by the continuous pass).
        def.linear_velocity = {0.01 * (k % 7), k % 10 == 0 ? -25.0 : 0.0};
        def.angular_velocity = 3.0 * (k % 5);
        ids.push_back(world.create_body(def));
        world.create_shape(ids.back(), box_shape(0.5, 0.5));
        defs.push_back(def);
    }
    const double h = dt / world.settings().substeps;
    for (int n = 1; n <= 30; ++n) { // 0.5 s: the lowest thrown box falls 13.7 m of its 19.5 m
        world.step(dt);
        const double t = n * dt;
        for (std::size_t k = 0; k < ids.size(); k += 5) {
            const BodyState s = world.state(ids[k]);
            BOOST_TEST(std::abs(s.position.x -
                                (defs[k].position.x + defs[k].linear_velocity.x * t)) < 1e-9);
            BOOST_TEST(std::abs(s.position.y - (defs[k].position.y + defs[k].linear_velocity.y * t -
                                                0.5 * g * t * t - 0.5 * g * h * t)) < 1e-9);
            BOOST_TEST(s.angular_velocity == defs[k].angular_velocity);
        }
    }
    for (int n = 0; n < 360; ++n) {
        world.step(dt);
        double lowest = 1e9;
        for (const BodyId id : ids) // over the ground (toppled columns scatter some beyond it)
            if (std::abs(world.position(id).x) < 49.5)
                lowest = std::min(lowest, world.position(id).y);
        BOOST_TEST(lowest > 0.5, "step " << n); // no centre below the face: none fell in
    }
}

// Oracle: BodyType's rule (body_def.hpp): a static body never moves, whatever velocities its
// input gives; it reports zero velocities and keeps its pose, while a kinematic body given the
// same input moves with it exactly (p = p0 + v t, phi = phi0 + omega t).
BOOST_AUTO_TEST_CASE(a_static_body_ignores_its_input_velocities, *utf::label("R2")) {
    World world(WorldDef{.gravity = {0.0, -9.81}});
    BodyDef def;
    def.position = {1.0, 2.0};
    def.angle = 0.25;
    def.linear_velocity = {3.0, -1.0};
    def.angular_velocity = 0.5;
    def.type = BodyType::static_body;
    const BodyId still = make_box_body(world, def);
    def.type = BodyType::kinematic;
    const BodyId moving = make_box_body(world, def);
    for (int n = 1; n <= 30; ++n) {
        world.step(1.0 / 60.0);
        const double t = n / 60.0;
        BOOST_TEST(world.velocity(still).x == 0.0);
        BOOST_TEST(world.velocity(still).y == 0.0);
        BOOST_TEST(world.angular_velocity(still) == 0.0);
        BOOST_TEST(world.position(still).x == 1.0);
        BOOST_TEST(world.position(still).y == 2.0);
        BOOST_TEST(world.orientation(still) == 0.25);
        BOOST_TEST(rel_err(world.position(moving).x, 1.0 + 3.0 * t) < 1e-12);
        BOOST_TEST(rel_err(world.orientation(moving), 0.25 + 0.5 * t) < 1e-12);
    }
}

// Oracle: DD1 and the parallel-axis theorem (DD14) by hand: two unit squares of density 1 at
// x = -1 and x = +2 (masses 1, 1): centre x = 0.5, I = 2 (1/6) + 1 (1.5^2) + 1 (1.5^2) = 4.8333.
BOOST_AUTO_TEST_CASE(compound_body_mass_properties,
                     *utf::label("R2") * utf::label("DD1") * utf::label("DD14")) {
    World world(WorldDef{});
    const BodyId b = world.create_body({});
    world.create_shape(b, box_shape(1.0, 1.0, Material{}, {-1.0, 0.0}));
    world.create_shape(b, box_shape(1.0, 1.0, Material{}, {2.0, 0.0}));
    BOOST_TEST(world.mass(b) == 2.0);
    BOOST_TEST(std::abs(world.local_center(b).x - 0.5) < 1e-15);
    BOOST_TEST(std::abs(world.inertia(b) - (2.0 / 6.0 + 2.0 * 2.25)) < 1e-13);
}

BOOST_AUTO_TEST_SUITE_END()
