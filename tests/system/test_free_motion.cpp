// System test cases TC1-TC7 (R5, IM1): translation of free bodies with no force, constant forces,
// gravity and projectiles, over the whole history, against closed forms. Every case also runs
// the reversed direction and a non-zero vertical velocity.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <numbers>
#include <vector>

#include "system/system_support.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;
using namespace tamias2d::system_test;

namespace {

/// Round-off bound for norm-relative errors of quantities the scheme reproduces exactly
/// (a few thousand additions at 1e-16 each).
constexpr double exact_rel = 1e-12;

struct Expected {
    BodyId id;
    Vec2d p0, v0, a; ///< centre of mass, its velocity, the constant acceleration g + F / m
};

/// Steps the world and checks every body at every step against
///  * the scheme's exact discrete solution p_n = p0 + v0 t + a t^2/2 + a h t/2, v_n = v0 + a t
///    (norm-relative error over the history at round-off), and
///  * the continuous solution p(t) = p0 + v0 t + a t^2/2 within the scheme's known first-order
///    error bound |p_n - p(t_n)| <= |a| h t_n / 2, pointwise and as a history norm.
void check_constant_acceleration(World& world, const std::vector<Expected>& bodies, double dt,
                                 int steps) {
    const double h = dt / world.settings().substeps;
    History discrete, velocity, continuous;
    double bound2 = 0.0, ref2 = 0.0;
    bool within = true;
    for (int n = 1; n <= steps; ++n) {
        world.step(dt);
        const double t = n * dt;
        for (const Expected& e : bodies) {
            const BodyState s = world.state(e.id);
            discrete.add(s.position, discrete_position(e.p0, e.v0, e.a, t, h));
            velocity.add(s.velocity, e.v0 + t * e.a);
            const Vec2d pc = continuous_position(e.p0, e.v0, e.a, t);
            continuous.add(s.position, pc);
            const double bound = 0.5 * norm(e.a) * h * t;
            bound2 += bound * bound;
            ref2 += pc.x * pc.x + pc.y * pc.y;
            within =
                within && norm(s.position - pc) <= bound * (1.0 + 1e-9) + 1e-12 * (1.0 + norm(pc));
        }
    }
    BOOST_TEST(discrete.rel_error() < exact_rel);
    BOOST_TEST(velocity.rel_error() < exact_rel);
    BOOST_TEST(within, "pointwise |p - p(t)| <= |a| h t / 2 at every step");
    const double rel_bound = std::sqrt(bound2 / ref2);
    BOOST_TEST(continuous.rel_error() <= rel_bound * (1.0 + 1e-9) + exact_rel);
    BOOST_TEST_MESSAGE("history: discrete rel " << discrete.rel_error() << ", continuous rel "
                                                << continuous.rel_error() << " (bound " << rel_bound
                                                << ")");
}

} // namespace

BOOST_AUTO_TEST_SUITE(system_free_motion)

// Oracle: closed form of IM1 with a = 0 (Newton's first law): p(t) = p0 + v0 t, v(t) = v0 (the
// displacement v dt of every step, DD3, summed); the scheme is exact for it, so the whole
// history must agree to round-off.
BOOST_AUTO_TEST_CASE(TC1_translation_without_force, *utf::label("R1") * utf::label("R2") *
                                                        utf::label("R5") * utf::label("IM1") *
                                                        utf::label("DD3")) {
    World world(WorldDef{.gravity = {0.0, 0.0}});
    std::vector<Expected> bodies;
    // Right, left (reversed), and with non-zero vertical velocity up and down; rows 50 m apart.
    const Vec2d velocities[] = {{3.0, 0.0}, {-3.0, 0.0}, {2.0, 1.5}, {-2.0, -1.5}, {0.0, 4.0}};
    for (int i = 0; i < 5; ++i) {
        const Vec2d p0{1.0, 50.0 * i};
        const Vec2d v = velocities[i];
        const BodyId b = (i % 2 == 0) ? add_circle(world, p0, v, 0.5, 2.0)
                                      : add_box(world, p0, v, 1.0, 0.5, 3.0);
        bodies.push_back({b, p0, v, {0.0, 0.0}});
    }
    check_constant_acceleration(world, bodies, 1.0 / 60.0, 600);
    for (const Expected& e : bodies) {
        BOOST_TEST(world.velocity(e.id).x == e.v0.x);
        BOOST_TEST(world.velocity(e.id).y == e.v0.y);
        BOOST_TEST(world.angular_velocity(e.id) == 0.0);
    }
}

// Oracle: closed form of IM1 with constant a = F / m (T1), F = (+6, 0) N on m = 3 kg (box
// 2 x 1 m of density 1.5 kg/m^2, m checked by hand): a = (2, 0) m/s^2, from rest and with a
// non-zero vertical velocity; v(t) = v0 + a t (the change a dt of every step, DD4, summed).
BOOST_AUTO_TEST_CASE(TC2_constant_force_to_the_right, *utf::label("R2") * utf::label("R5") *
                                                          utf::label("IM1") * utf::label("T1") *
                                                          utf::label("DD4")) {
    World world(WorldDef{.gravity = {0.0, 0.0}});
    std::vector<Expected> bodies;
    const Vec2d starts[] = {{0.0, 0.0}, {1.0, 0.5}, {-1.0, -2.0}};
    double y = 0.0;
    for (const Vec2d v : starts) {
        BodyDef def;
        def.position = {0.0, y};
        def.linear_velocity = v;
        def.force = {6.0, 0.0};
        const BodyId b = world.create_body(def);
        world.create_shape(b, box_shape(2.0, 1.0, Material{1.5, 0.0, 0.0}));
        BOOST_TEST(world.mass(b) == 3.0);
        bodies.push_back({b, def.position, v, {2.0, 0.0}});
        y += 100.0;
    }
    check_constant_acceleration(world, bodies, 1.0 / 60.0, 300);
}

// Oracle: as TC2 with the force reversed, F = (-6, 0) N: a = (-2, 0) m/s^2; one body starts
// moving right (it stops at t = v0 / 2 and comes back), one with a vertical velocity.
BOOST_AUTO_TEST_CASE(TC3_constant_force_to_the_left,
                     *utf::label("R2") * utf::label("R5") * utf::label("IM1") * utf::label("T1")) {
    World world(WorldDef{.gravity = {0.0, 0.0}});
    std::vector<Expected> bodies;
    const Vec2d starts[] = {{0.0, 0.0}, {3.0, 0.0}, {0.5, -1.25}};
    double y = 0.0;
    for (const Vec2d v : starts) {
        BodyDef def;
        def.position = {5.0, y};
        def.linear_velocity = v;
        def.force = {-6.0, 0.0};
        const BodyId b = world.create_body(def);
        world.create_shape(b, box_shape(2.0, 1.0, Material{1.5, 0.0, 0.0}));
        BOOST_TEST(world.mass(b) == 3.0);
        bodies.push_back({b, def.position, v, {-2.0, 0.0}});
        y += 100.0;
    }
    check_constant_acceleration(world, bodies, 1.0 / 60.0, 300);
    // The body launched right at 3 m/s turns round at t = 1.5 s: now moving left.
    BOOST_TEST(world.velocity(bodies[1].id).x < 0.0);
}

// Oracle: GD2 and IM1: every body falls with a = g whatever its mass (0.5 kg to 40 kg, boxes
// and circles), p(t) = p0 + v0 t + g t^2 / 2; bodies 20 m apart never meet.
BOOST_AUTO_TEST_CASE(TC4_free_fall_of_several_bodies,
                     *utf::label("GD2") * utf::label("IM1") * utf::label("R5") * utf::label("T1")) {
    const Vec2d g{0.0, -9.81};
    World world(WorldDef{.gravity = g});
    std::vector<Expected> bodies;
    const Vec2d starts[] = {{0.0, 0.0}, {1.0, 0.0}, {-1.0, 2.0}, {0.0, -3.0}, {0.5, 8.0}};
    const double masses[] = {0.5, 3.0, 40.0, 7.0, 1.0};
    for (int i = 0; i < 5; ++i) {
        const Vec2d p0{20.0 * i, 100.0};
        const BodyId b = (i % 2 == 0) ? add_circle(world, p0, starts[i], 0.5, masses[i])
                                      : add_box(world, p0, starts[i], 1.0, 1.0, masses[i]);
        BOOST_TEST(std::abs(world.mass(b) - masses[i]) < 1e-12 * masses[i]);
        bodies.push_back({b, p0, starts[i], g});
    }
    check_constant_acceleration(world, bodies, 1.0 / 60.0, 240);
}

// Oracle: IM1 with T1 and GD2 per body: a_i = g + F_i / m_i for bodies of different masses and
// forces (masses from the densities, checked by hand), including a force that beats gravity.
BOOST_AUTO_TEST_CASE(TC5_free_bodies_with_different_masses_and_forces,
                     *utf::label("R2") * utf::label("R5") * utf::label("IM1") * utf::label("T1") *
                         utf::label("GD2")) {
    const Vec2d g{0.0, -9.81};
    World world(WorldDef{.gravity = g});
    struct Spec {
        double w, h, density; // m = w h density
        Vec2d force, v0;
    };
    const Spec specs[] = {{1.0, 1.0, 2.0, {10.0, 0.0}, {0.0, 0.0}},
                          {0.5, 1.0, 1.0, {-3.0, 20.0}, {1.0, 0.0}},
                          {2.0, 1.0, 5.0, {0.0, -5.0}, {-2.0, 3.0}},
                          {1.0, 2.0, 0.25, {-1.0, 4.905}, {0.0, -1.0}}};
    std::vector<Expected> bodies;
    int i = 0;
    for (const Spec& s : specs) {
        BodyDef def;
        def.position = {30.0 * i++, 0.0};
        def.linear_velocity = s.v0;
        def.force = s.force;
        const BodyId b = world.create_body(def);
        world.create_shape(b, box_shape(s.w, s.h, Material{s.density, 0.0, 0.0}));
        const double m = s.w * s.h * s.density;
        BOOST_TEST(std::abs(world.mass(b) - m) < 1e-14 * m);
        bodies.push_back({b, def.position, s.v0, g + (1.0 / m) * s.force});
    }
    check_constant_acceleration(world, bodies, 1.0 / 60.0, 300);
}

namespace {

/// A projectile launched from the origin at `speed` and `degrees` (measured from +x) under
/// g = 9.81 m/s^2; checks the flight history and the range R = v^2 sin(2 theta) / g.
void check_projectile(double speed, double degrees) {
    const double g = 9.81;
    const double theta = degrees * std::numbers::pi / 180.0;
    const Vec2d v0{speed * std::cos(theta), speed * std::sin(theta)};
    const double flight = 2.0 * v0.y / g;
    const double dt = 1.0 / 60.0;
    const int steps = int(std::ceil(flight / dt)) + 2;
    {
        World world(WorldDef{.gravity = {0.0, -g}});
        const BodyId b = add_circle(world, {0.0, 0.0}, v0, 0.1, 1.0);
        check_constant_acceleration(world, {{b, {0.0, 0.0}, v0, {0.0, -g}}}, dt, steps);
    }
    // The range: where the trajectory comes back to y = 0, interpolated linearly between steps.
    World world(WorldDef{.gravity = {0.0, -g}});
    const BodyId b = add_circle(world, {0.0, 0.0}, v0, 0.1, 1.0);
    const double h = dt / world.settings().substeps;
    Vec2d prev = world.position(b);
    double range = std::nan("");
    for (int n = 1; n <= steps; ++n) {
        world.step(dt);
        const Vec2d p = world.position(b);
        if (n > 1 && prev.y >= 0.0 && p.y < 0.0) {
            range = prev.x + (p.x - prev.x) * prev.y / (prev.y - p.y);
            break;
        }
        prev = p;
    }
    const double R = speed * speed * std::sin(2.0 * theta) / g;
    // The scheme's discrete trajectory y_n = v_y t - g t^2/2 - g h t/2 lands at t = 2 v_y / g - h:
    // range R - v_x h. Linear interpolation between steps adds at most v_x g dt^2 / (8 v_y).
    const double interp = std::abs(v0.x) * g * dt * dt / (8.0 * v0.y);
    BOOST_TEST(std::abs(range - (R - v0.x * h)) <= interp * (1.0 + 1e-9) + 1e-12);
    BOOST_TEST(std::abs(range - R) <= std::abs(v0.x) * h + interp + 1e-12);
    BOOST_TEST_MESSAGE("projectile " << degrees << " deg: range " << range << " m, closed form "
                                     << R << " m");
}

} // namespace

// Oracle: projectile closed form (IM1 with a = g, GD2): x = v cos(theta) t,
// y = v sin(theta) t - g t^2 / 2, range R = v^2 sin(2 theta) / g; at 45 degrees and mirrored
// (135 degrees, launched to the left).
BOOST_AUTO_TEST_CASE(TC6_projectile_at_45_degrees,
                     *utf::label("R5") * utf::label("IM1") * utf::label("GD2") * utf::label("T1")) {
    check_projectile(20.0, 45.0);
    check_projectile(20.0, 135.0);
    check_projectile(7.5, 45.0);
}

// Oracle: as TC6 at 60 degrees and mirrored (120 degrees).
BOOST_AUTO_TEST_CASE(TC7_projectile_at_60_degrees,
                     *utf::label("R5") * utf::label("IM1") * utf::label("GD2") * utf::label("T1")) {
    check_projectile(20.0, 60.0);
    check_projectile(20.0, 120.0);
    check_projectile(7.5, 60.0);
}

BOOST_AUTO_TEST_SUITE_END()
