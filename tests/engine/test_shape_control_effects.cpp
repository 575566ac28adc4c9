// Run-time changes of a shape (World's shape_control calls) against independent oracles:
// Coulomb friction's deceleration mu g, restitution's rebound e v (DD12), the closed-form mass
// and inertia of the new density or geometry (DD1, DD14, DD30), a body resting on its new
// outline at the closed-form height, the broad phase finding the grown shape, and a sensor's
// events as DD28 defines them.
#include <boost/test/unit_test.hpp>

#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "tamias2d/world.hpp"

namespace utf = boost::unit_test;
namespace tt = boost::test_tools;
using namespace tamias2d;

namespace {

constexpr double dt = 1.0 / 240.0, g = 10.0;

WorldDef plain_world() {
    WorldDef d;
    d.gravity = {0.0, -g};
    d.enable_sleep = false;
    return d;
}

/// A static ground 40 m x 1 m whose top is y = 0.
ShapeId add_ground(World& w, Material m = {}) {
    BodyDef bd;
    bd.type = BodyType::static_body;
    bd.position = {0.0, -0.5};
    const BodyId ground = w.create_body(bd);
    return w.create_shape(ground, box_shape(40.0, 1.0, m));
}

bool ended(const World& w, ShapeId a, ShapeId b) {
    for (const ContactEvent& e : w.contact_end_events())
        if ((e.shape_a == a && e.shape_b == b) || (e.shape_a == b && e.shape_b == a))
            return true;
    return false;
}

} // namespace

BOOST_AUTO_TEST_SUITE(shape_control_effects)

// Oracle: Coulomb's law (LC2) in closed form. A box sliding on level ground with the combined
// coefficient mu (DD42's default: the geometric mean of the two shapes') decelerates at mu g.
// Frictionless at first (the box's coefficient 0), it keeps its speed; set to 0.25 against the
// ground's 1, mu = 0.5, and the speed drops by 0.5 g t.
BOOST_AUTO_TEST_CASE(friction_set_while_sliding_decelerates_at_mu_g,
                     *utf::label("LC2") * utf::label("DD42")) {
    World w(plain_world());
    add_ground(w, Material{1.0, 0.0, 1.0});
    BodyDef bd;
    bd.position = {-10.0, 0.25};
    bd.linear_velocity = {6.0, 0.0};
    bd.fixed_rotation = true;
    const BodyId box = w.create_body(bd);
    const ShapeId s = w.create_shape(box, box_shape(0.5, 0.5, Material{1.0, 0.0, 0.0}));
    for (int k = 0; k < 120; ++k)
        w.step(dt);
    BOOST_TEST(w.velocity(box).x == 6.0, tt::tolerance(1e-9));
    w.set_friction(s, 0.25);
    BOOST_TEST(w.friction(s) == 0.25);
    const double v0 = w.velocity(box).x;
    const int n = 240; // 1 s: the speed drops by 5 m s^-1, not to zero
    for (int k = 0; k < n; ++k)
        w.step(dt);
    const double drop = std::sqrt(0.25 * 1.0) * g * n * dt;
    BOOST_TEST(v0 - w.velocity(box).x == drop, tt::tolerance(0.01));
}

// Oracle: DD12's rebound, v_after = e v_before, for a disc falling on a static floor whose
// restitution is raised from 0 to 0.5 while the disc falls (the pair's restitution is DD42's
// default, the larger of the two: 0.5).
BOOST_AUTO_TEST_CASE(restitution_set_in_flight_gives_the_rebound_e_v,
                     *utf::label("DD12") * utf::label("DD42")) {
    World w(plain_world());
    const ShapeId floor = add_ground(w);
    BodyDef bd;
    bd.position = {0.0, 2.0};
    bd.fixed_rotation = true;
    const BodyId ball = w.create_body(bd);
    w.create_shape(ball, circle_shape(0.25));
    w.step(dt);
    w.set_restitution(floor, 0.5);
    BOOST_TEST(w.restitution(floor) == 0.5);
    double before = 0.0, after = 0.0;
    for (int k = 0; k < 480; ++k) {
        const double v = w.velocity(ball).y;
        w.step(dt);
        if (v < 0.0 && w.velocity(ball).y > 0.0) {
            before = v;
            after = w.velocity(ball).y;
            break;
        }
    }
    BOOST_TEST_REQUIRE(before < -5.0); // it fell about 1.75 m
    BOOST_TEST(after == -0.5 * before, tt::tolerance(0.03));
}

// Oracle: DD1 and DD14's closed forms for a box, m = rho w h and I = m (w^2 + h^2) / 12: the
// new density counts at once with the mass update, and only at the next update without it.
BOOST_AUTO_TEST_CASE(density_gives_the_closed_form_mass, *utf::label("DD1") * utf::label("DD14")) {
    World w(plain_world());
    const BodyId b = w.create_body(BodyDef{});
    const ShapeId s = w.create_shape(b, box_shape(2.0, 0.5));
    w.set_density(s, 3.0);
    BOOST_TEST(w.density(s) == 3.0);
    BOOST_TEST(w.mass(b) == 3.0 * 2.0 * 0.5, tt::tolerance(1e-14));
    BOOST_TEST(w.inertia(b) == 3.0 * (4.0 + 0.25) / 12.0, tt::tolerance(1e-14));
    w.set_density(s, 5.0, false);
    BOOST_TEST(w.density(s) == 5.0);
    BOOST_TEST(w.mass(b) == 3.0, tt::tolerance(1e-14)); // not yet
    w.set_density(s, 5.0, true);
    BOOST_TEST(w.mass(b) == 5.0, tt::tolerance(1e-14));
}

// Oracle: the closed forms of each new outline: a circle's m = rho pi r^2, I = m r^2 / 2 (about
// its centre, which is the body's centre of mass); a capsule's DD30 (rectangle 2 r L plus a
// disc pi r^2, I = rho (2 r L (L^2 + 4 r^2) / 12 + pi r^2 (r^2 / 2 + L^2 / 4) + 4/3 r^3 L))
// with L = 1, r = 0.5; a box polygon's; a segment has no area (the shapeless default mass,
// 1 kg).
BOOST_AUTO_TEST_CASE(geometry_gives_the_closed_form_mass,
                     *utf::label("DD1") * utf::label("DD14") * utf::label("DD30")) {
    World w(plain_world());
    const BodyId b = w.create_body(BodyDef{});
    const ShapeId s = w.create_shape(b, box_shape(1.0, 1.0, Material{2.0, 0.0, 0.0}));
    w.set_circle(s, Circle{{0.0, 0.0}, 0.5});
    const double pi = std::numbers::pi;
    BOOST_TEST(w.mass(b) == 2.0 * pi * 0.25, tt::tolerance(1e-14));
    BOOST_TEST(w.inertia(b) == 2.0 * pi * 0.25 * 0.25 / 2.0, tt::tolerance(1e-14));
    BOOST_TEST((w.shape_geometry(s).type == ShapeType::circle));
    BOOST_TEST(w.shape_geometry(s).circle.radius == 0.5);

    w.set_capsule(s, Capsule{{-0.5, 0.0}, {0.5, 0.0}, 0.5});
    const double r = 0.5, L = 1.0;
    const double m = 2.0 * (2.0 * r * L + pi * r * r);
    const double I = 2.0 * (2.0 * r * L * (L * L + 4.0 * r * r) / 12.0 +
                            pi * r * r * (r * r / 2.0 + L * L / 4.0) + 4.0 / 3.0 * r * r * r * L);
    BOOST_TEST(w.mass(b) == m, tt::tolerance(1e-13));
    BOOST_TEST(w.inertia(b) == I, tt::tolerance(1e-13));

    w.set_polygon(s, box_shape(3.0, 1.0).geometry.polygon);
    BOOST_TEST(w.mass(b) == 2.0 * 3.0, tt::tolerance(1e-14));
    BOOST_TEST(w.inertia(b) == 6.0 * (9.0 + 1.0) / 12.0, tt::tolerance(1e-14));

    w.set_segment(s, Segment{{-1.0, 0.0}, {1.0, 0.0}});
    BOOST_TEST(w.mass(b) == 1.0);
    BOOST_TEST((w.shape_geometry(s).type == ShapeType::segment));
}

// Oracle: geometry. A box 1 m high resting on the floor is made a circle of radius 0.2 m: its
// old contact ends at once, and it settles with its centre at y = 0.2 (the radius above the
// floor's top). Made a circle of radius 1.5 m, it overlaps the floor and is pushed out to rest
// at y = 1.5; a query of a box beyond the old outline but inside the new one finds it (its
// broad-phase box was moved).
BOOST_AUTO_TEST_CASE(new_outline_rests_at_its_closed_form_height,
                     *utf::label("R3") * utf::label("R7") * utf::label("IM4")) {
    World w(plain_world());
    const ShapeId floor = add_ground(w);
    BodyDef bd;
    bd.position = {0.0, 0.5};
    bd.fixed_rotation = true;
    const BodyId body = w.create_body(bd);
    const ShapeId s = w.create_shape(body, box_shape(1.0, 1.0));
    for (int k = 0; k < 240; ++k)
        w.step(dt);
    BOOST_TEST(w.origin(body).y == 0.5, tt::tolerance(0.01));
    w.set_circle(s, Circle{{0.0, 0.0}, 0.2});
    BOOST_TEST(ended(w, floor, s));
    for (int k = 0; k < 480; ++k)
        w.step(dt);
    BOOST_TEST(w.origin(body).y == 0.2, tt::tolerance(0.01));
    BOOST_TEST(std::abs(w.velocity(body).y) < 1e-3);

    const Aabb beyond{1.0, 0.5, 1.2, 0.7}; // inside a 1.5 m disc at (0, 0.2), outside 0.2 m
    BOOST_TEST(w.query_aabb(beyond).empty());
    w.set_circle(s, Circle{{0.0, 0.0}, 1.5});
    const std::vector<ShapeId> found = w.query_aabb(beyond);
    BOOST_TEST_REQUIRE(found.size() == 1u);
    BOOST_TEST((found[0] == s));
    for (int k = 0; k < 960; ++k)
        w.step(dt);
    BOOST_TEST(w.origin(body).y == 1.5, tt::tolerance(0.01));
    BOOST_TEST(std::abs(w.velocity(body).y) < 1e-3);
}

// Oracle: DD28's definitions and free fall. A disc resting on a solid box: the box made a
// sensor, the pair's contact ends at once, the disc falls freely into it (y = y0 - g t^2 / 2,
// no force from a sensor) and the next step reports it entering; made solid again, the overlap
// ends at once (a sensor end event) and contacts begin from the next step.
BOOST_AUTO_TEST_CASE(sensor_flag_switches_contacts_and_overlaps,
                     *utf::label("DD28") * utf::label("IM1")) {
    WorldDef def = plain_world();
    World w(def);
    BodyDef pd;
    pd.type = BodyType::static_body;
    const BodyId post = w.create_body(pd);
    const ShapeId block = w.create_shape(post, box_shape(2.0, 2.0)); // top at y = 1
    BodyDef bd;
    bd.position = {0.0, 1.25};
    bd.fixed_rotation = true;
    const BodyId disc = w.create_body(bd);
    const ShapeId ds = w.create_shape(disc, circle_shape(0.25));
    for (int k = 0; k < 240; ++k)
        w.step(dt);
    const double y0 = w.origin(disc).y;
    BOOST_TEST(y0 == 1.25, tt::tolerance(0.01));
    w.set_sensor(block, true);
    BOOST_TEST(w.is_sensor(block));
    BOOST_TEST(ended(w, block, ds));
    w.set_velocity(disc, {0.0, 0.0});
    const int n = 12;
    bool entered = false;
    for (int k = 0; k < n; ++k) {
        w.step(dt);
        for (const SensorEvent& e : w.sensor_begin_events())
            entered = entered || (e.sensor == block && e.visitor == ds);
    }
    BOOST_TEST(entered);
    const double t = n * dt;
    // The soft step's symplectic Euler: y0 - g h^2 (N (N + 1) / 2) for N substeps of h.
    const double h = dt / def.substeps;
    const int substeps = n * def.substeps;
    BOOST_TEST(w.origin(disc).y == y0 - g * h * h * substeps * (substeps + 1) / 2.0,
               tt::tolerance(1e-9));
    BOOST_TEST(w.velocity(disc).y == -g * t, tt::tolerance(1e-9));

    w.set_sensor(block, false);
    BOOST_TEST(!w.is_sensor(block));
    bool left = false;
    for (const SensorEvent& e : w.sensor_end_events())
        left = left || (e.sensor == block && e.visitor == ds);
    BOOST_TEST(left);
    w.step(dt);
    bool began = false;
    for (const ContactEvent& e : w.contact_begin_events())
        began = began || ((e.shape_a == block && e.shape_b == ds) ||
                          (e.shape_a == ds && e.shape_b == block));
    BOOST_TEST(began);
}

BOOST_AUTO_TEST_SUITE_END()
