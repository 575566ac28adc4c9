// R8, IM3, DD8: collision response in the SRS regime (A5 vertex-edge, A6 no friction, A7 no
// joints) against IM3's closed form, and exact elastic face contact (LC1).
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <numbers>

#include "tamias2d/world.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;

namespace {

double rel(double got, double want) {
    return std::abs(got - want) / std::max(std::abs(want), 1e-300);
}

double cross2(Vec2d a, Vec2d b) {
    return a.x * b.y - a.y * b.x;
}

} // namespace

BOOST_AUTO_TEST_SUITE(collision_response)

// Oracle: IM3's closed form, evaluated here from the SRS text (not through the engine):
// j = -(1 + C_R) v^AB.n / ((1/m_A + 1/m_B) + (r_AP x n)^2 / I_A + (r_BP x n)^2 / I_B) (DD8),
// v_A' = v_A + j n / m_A, v_B' = v_B - j n / m_B, omega_A' = omega_A + (r_AP x j n) / I_A,
// omega_B' = omega_B - (r_BP x j n) / I_B (B takes the reaction -j n, T2), with v^AB the
// velocity of A's point P relative to B's (DD11), each by Chasles' theorem (DD9); A is a unit
// square turned 45 degrees whose lowest vertex P touches the top face of a 4 x 1 box B
// off-centre, so n = (0, 1) points from B into A.
BOOST_AUTO_TEST_CASE(vertex_edge_matches_im3_closed_form,
                     *utf::label("IM3") * utf::label("R8") * utf::label("DD8") * utf::label("A5") *
                         utf::label("A6") * utf::label("A7") * utf::label("T2") *
                         utf::label("DD9") * utf::label("DD11")) {
    for (const double c_r : {0.0, 0.4, 1.0}) {
        World world(WorldDef{.gravity = {0.0, 0.0}});
        const double half_diag = std::sqrt(0.5);
        // B: 4 x 1 box, density 2 (m_B = 8, I_B = 8 (16 + 1) / 12), top face at y = 0.5.
        BodyDef bd;
        bd.linear_velocity = {0.25, 0.5};
        bd.angular_velocity = 0.1;
        const BodyId b = world.create_body(bd);
        world.create_shape(b, box_shape(4.0, 1.0, Material{2.0, c_r, 0.0}));
        // A: unit square (m_A = 1, I_A = 1/6) rotated 45 deg, vertex at (0.7, 0.5).
        BodyDef ad;
        ad.position = {0.7, 0.5 + half_diag};
        ad.angle = std::numbers::pi / 4.0;
        ad.linear_velocity = {0.3, -2.0};
        ad.angular_velocity = 0.6;
        const BodyId a = world.create_body(ad);
        world.create_shape(a, box_shape(1.0, 1.0, Material{1.0, c_r, 0.0}));

        const double mA = 1.0, IA = 1.0 / 6.0, mB = 8.0, IB = 8.0 * 17.0 / 12.0;
        BOOST_TEST(rel(world.inertia(b), IB) < 1e-14);
        const Vec2d P{0.7, 0.5}, n{0.0, 1.0};
        const Vec2d rAP = P - ad.position, rBP = P - Vec2d{0.0, 0.0};
        // DD9 + DD11: velocity of A's point P relative to B's point P.
        const Vec2d vAP = ad.linear_velocity + ad.angular_velocity * Vec2d{-rAP.y, rAP.x};
        const Vec2d vBP = bd.linear_velocity + bd.angular_velocity * Vec2d{-rBP.y, rBP.x};
        const double vn = dot(vAP - vBP, n);
        BOOST_TEST_REQUIRE(vn < 0.0);
        const double j = -(1.0 + c_r) * vn /
                         ((1.0 / mA + 1.0 / mB) + std::pow(cross2(rAP, n), 2) / IA +
                          std::pow(cross2(rBP, n), 2) / IB);

        world.step(1.0 / 60.0);

        BOOST_TEST_REQUIRE(world.contacts().size() == 1u);
        BOOST_TEST(world.contacts()[0].point_count == 1); // A5: one vertex-edge point
        const Vec2d vA = world.velocity(a), vB = world.velocity(b);
        BOOST_TEST(rel(vA.x, ad.linear_velocity.x + j * n.x / mA) < 1e-9);
        BOOST_TEST(rel(vA.y, ad.linear_velocity.y + j * n.y / mA) < 1e-9);
        BOOST_TEST(rel(vB.x, bd.linear_velocity.x - j * n.x / mB) < 1e-9);
        BOOST_TEST(rel(vB.y, bd.linear_velocity.y - j * n.y / mB) < 1e-9);
        BOOST_TEST(rel(world.angular_velocity(a), ad.angular_velocity + cross2(rAP, j * n) / IA) <
                   1e-9);
        BOOST_TEST(rel(world.angular_velocity(b), bd.angular_velocity - cross2(rBP, j * n) / IB) <
                   1e-9);
        BOOST_TEST(rel(world.contacts()[0].points[0].normal_impulse, j) < 1e-9);
    }
}

// Oracle: conservation laws for a 1-D elastic collision of equal masses (GD1 and kinetic
// energy DD15): the bodies exchange velocities exactly; by symmetry no spin arises. Box2D v3
// fails this (sequential points leave spin and lose energy), see docs/design.md. The impulses
// the contact reports are the momentum exchanged (Newton's second law).
BOOST_AUTO_TEST_CASE(equal_boxes_face_to_face_swap_velocities,
                     *utf::label("R8") * utf::label("LC1") * utf::label("GD1") *
                         utf::label("DD15") * utf::label("DD12")) {
    World world(WorldDef{.gravity = {0.0, 0.0}});
    const Material elastic{1.0, 1.0, 0.0};
    BodyDef left;
    left.position = {-0.5, 0.0};
    left.linear_velocity = {3.0, 0.0};
    BodyDef right;
    right.position = {0.5, 0.0};
    right.linear_velocity = {-1.0, 0.0};
    const BodyId a = world.create_body(left);
    world.create_shape(a, box_shape(1.0, 1.0, elastic));
    const BodyId b = world.create_body(right);
    world.create_shape(b, box_shape(1.0, 1.0, elastic));
    const double e0 = world.kinetic_energy();
    world.step(1.0 / 60.0);
    BOOST_TEST_REQUIRE(world.contacts().size() == 1u);
    const ContactInfo& c = world.contacts()[0];
    BOOST_TEST(c.point_count == 2); // LC1: edge-edge gives two points
    // The impulses reported are the momentum each box took (Newton's second law: 1 kg from
    // 3 to -1 m/s, 4 N s along the normal, split evenly by symmetry), and without friction
    // none along the tangent (Coulomb's |P_t| <= mu P_n with mu = 0).
    BOOST_TEST(c.points[0].normal_impulse + c.points[1].normal_impulse == 4.0,
               boost::test_tools::tolerance(1e-9));
    BOOST_TEST(c.points[0].normal_impulse == c.points[1].normal_impulse,
               boost::test_tools::tolerance(1e-9));
    BOOST_TEST(c.points[0].tangent_impulse == 0.0);
    BOOST_TEST(c.points[1].tangent_impulse == 0.0);
    BOOST_TEST(std::abs(world.velocity(a).x - (-1.0)) < 1e-9);
    BOOST_TEST(std::abs(world.velocity(b).x - 3.0) < 1e-9);
    BOOST_TEST(std::abs(world.velocity(a).y) < 1e-9);
    BOOST_TEST(std::abs(world.angular_velocity(a)) < 1e-9);
    BOOST_TEST(std::abs(world.angular_velocity(b)) < 1e-9);
    BOOST_TEST(std::abs(world.kinetic_energy() - e0) < 1e-9 * e0);
    // And they keep flying apart, untouched, afterwards.
    for (int i = 0; i < 60; ++i)
        world.step(1.0 / 60.0);
    BOOST_TEST(std::abs(world.velocity(a).x - (-1.0)) < 1e-9);
    BOOST_TEST(std::abs(world.kinetic_energy() - e0) < 1e-9 * e0);
}

// Oracle: DD12 measured on the outcome: a ball dropped on static ground with C_R = e leaves
// with -e times its impact normal velocity; momentum is not conserved (static body) but the
// restitution law is.
BOOST_AUTO_TEST_CASE(impulse_against_static_body_obeys_restitution,
                     *utf::label("R8") * utf::label("DD12") * utf::label("IM3")) {
    for (const double e : {0.0, 0.5, 0.9}) {
        World world(WorldDef{.gravity = {0.0, 0.0}});
        BodyDef gd;
        gd.type = BodyType::static_body;
        const BodyId ground = world.create_body(gd);
        world.create_shape(ground, box_shape(10.0, 1.0, Material{1.0, e, 0.0}));
        BodyDef bd;
        bd.position = {0.0, 0.5 + 0.25};
        bd.linear_velocity = {0.0, -4.0};
        const BodyId ball = world.create_body(bd);
        world.create_shape(ball, circle_shape(0.25, Material{1.0, e, 0.0}));
        world.step(1.0 / 60.0);
        BOOST_TEST(std::abs(world.velocity(ball).y - 4.0 * e) < 1e-9);
        BOOST_TEST(std::abs(world.angular_velocity(ball)) < 1e-12);
        BOOST_TEST(world.velocity(ground).y == 0.0);
    }
}

// Oracle: DD12 acts on an impact, so a ball that has not reached the ground keeps its velocity
// (Newton's first law: no gravity on it, gravity scale 0). An elastic ball drifts down at
// 0.3 m/s through the speculative band (0.02 m) while boxes rest on the same ground, their
// manifolds pushing each step in the solver's packs beside the ball's. In every step that
// starts with the ball farther from the ground than it travels (0.005 m), its velocity is
// exactly what it was; in the step in which it reaches the ground it leaves at +0.3 m/s
// (C_R = 1). A box that rested on the ground since the first step is destroyed in the step in
// which the ball comes within the band, so that the ball's manifold takes a place in the packs
// that a pushing manifold held in the step before (the pack slots are reused from step to step).
BOOST_AUTO_TEST_CASE(a_ball_bounces_only_in_the_step_it_reaches_the_ground,
                     *utf::label("DD12") * utf::label("IM3")) {
    World world(WorldDef{.gravity = {0.0, -10.0}, .enable_sleep = false});
    BodyDef gd;
    gd.type = BodyType::static_body;
    world.create_shape(world.create_body(gd), box_shape(40.0, 1.0, {}, {0.0, -0.5}));
    const auto box_at = [&](double x) {
        BodyDef b;
        b.position = {x, 0.5};
        const BodyId id = world.create_body(b);
        world.create_shape(id, box_shape(1.0, 1.0));
        return id;
    };
    const BodyId first = box_at(-12.0);
    const double radius = 0.25, speed = 0.3, dt = 1.0 / 60.0;
    BodyDef bd;
    bd.position = {-15.0, 5.0}; // far from everything until it is put in place
    bd.gravity_scale = 0.0;
    const BodyId ball = world.create_body(bd);
    world.create_shape(ball, circle_shape(radius, Material{1.0, 1.0, 0.0}));
    for (int k = 0; k < 12; ++k)
        box_at(-10.0 + 2.0 * k);
    for (int k = 0; k < 30; ++k) // the boxes settle
        world.step(dt);
    world.set_transform(ball, {-15.0, radius + 0.0525}, 0.0);
    world.set_velocity(ball, {0.0, -speed});
    int bounced_at = -1, reached_at = -1;
    bool destroyed = false;
    for (int k = 0; k < 20 && bounced_at < 0; ++k) {
        const double gap = world.origin(ball).y - radius;
        if (!destroyed && gap < world.settings().speculative_distance) {
            world.destroy_body(first);
            destroyed = true;
        }
        if (reached_at < 0 && gap <= speed * dt)
            reached_at = k;
        world.step(dt);
        const double vy = world.velocity(ball).y;
        if (vy != -speed) {
            bounced_at = k;
            BOOST_TEST(std::abs(vy - speed) < 1e-9);
        }
    }
    BOOST_TEST(destroyed);
    BOOST_TEST(reached_at > 0);
    BOOST_TEST(bounced_at == reached_at);
}

// Oracle: GD1, conservation of momentum: an isolated pair of unequal bodies (1 kg vs 100 kg,
// C_R = 1) colliding off-centre keeps its total momentum and, being elastic, its kinetic energy.
BOOST_AUTO_TEST_CASE(unequal_masses_conserve_momentum_and_energy,
                     *utf::label("GD1") * utf::label("R8") * utf::label("DD15")) {
    World world(WorldDef{.gravity = {0.0, 0.0}});
    BodyDef light;
    light.position = {-2.0, 0.3};
    light.linear_velocity = {5.0, 0.0};
    const BodyId a = world.create_body(light);
    world.create_shape(a, circle_shape(0.5, Material{1.0 / (std::numbers::pi * 0.25), 1.0, 0.0}));
    BodyDef heavy;
    heavy.position = {1.0, 0.0};
    const BodyId b = world.create_body(heavy);
    world.create_shape(b, box_shape(2.0, 2.0, Material{25.0, 1.0, 0.0}));
    BOOST_TEST(rel(world.mass(a), 1.0) < 1e-14);
    BOOST_TEST(world.mass(b) == 100.0);
    const Vec2d p0 = world.linear_momentum();
    const double e0 = world.kinetic_energy();
    for (int i = 0; i < 120; ++i)
        world.step(1.0 / 60.0);
    BOOST_TEST(world.velocity(a).x < 0.0); // it bounced
    const Vec2d p1 = world.linear_momentum();
    BOOST_TEST(std::abs(p1.x - p0.x) < 1e-12 * std::abs(p0.x));
    BOOST_TEST(std::abs(p1.y - p0.y) < 1e-12 * std::abs(p0.x));
    BOOST_TEST(std::abs(world.kinetic_energy() - e0) < 1e-9 * e0);
}

// Oracle: DD10, J = m dv and r x J = I d omega (impulse-momentum), and Coulomb's law for a
// sliding contact. Two boxes of different mass slide on static ground, one made before the
// ground (the first body of its contact) and one after (the second): the impulses each contact
// reports, J_i = jn_i n + jt_i t (t = (n.y, -n.x), acting on the second body, minus on the
// first), are its own box's momentum change beyond gravity's, their moments about the box's
// centre at the step's start its angular momentum change; as it slides the whole step,
// |sum jt| = mu sum jn, and friction opposes the slip.
BOOST_AUTO_TEST_CASE(reported_friction_impulse_is_the_momentum_change, *utf::label("DD10")) {
    const double mu = 0.5, dt = 1.0 / 60.0, g = 10.0;
    World world(WorldDef{.gravity = {0.0, -g}});
    BodyId boxes[2];
    const auto add_box = [&](int k) {
        BodyDef bd;
        bd.position = {-5.0 + 10.0 * k, 1.0}; // resting on the ground's top face, y = 0.5
        boxes[k] = world.create_body(bd);
        world.create_shape(boxes[k], box_shape(1.0, 1.0, Material{1.0 + 2.0 * k, 0.0, mu}));
    };
    add_box(0);
    BodyDef gd;
    gd.type = BodyType::static_body;
    const BodyId ground = world.create_body(gd);
    world.create_shape(ground, box_shape(40.0, 1.0, Material{1.0, 0.0, mu}));
    add_box(1);
    BOOST_TEST_REQUIRE(world.mass(boxes[0]) == 1.0);
    BOOST_TEST_REQUIRE(world.mass(boxes[1]) == 3.0);
    for (int i = 0; i < 30; ++i) // settle: the contacts and their impulses established
        world.step(dt);
    for (const BodyId box : boxes)
        world.set_velocity(box, {3.0, world.velocity(box).y});
    bool first_side = false, second_side = false;
    for (int i = 0; i < 5; ++i) {
        Vec2d v0[2], c0[2];
        double w0[2];
        for (int k = 0; k < 2; ++k) {
            v0[k] = world.velocity(boxes[k]);
            w0[k] = world.angular_velocity(boxes[k]);
            c0[k] = world.position(boxes[k]);
        }
        world.step(dt);
        BOOST_TEST_REQUIRE(world.contacts().size() == 2u);
        for (int k = 0; k < 2; ++k) {
            const double m = world.mass(boxes[k]), inertia = world.inertia(boxes[k]);
            const Vec2d v1 = world.velocity(boxes[k]);
            const ContactInfo* found = nullptr;
            for (const ContactInfo& c : world.contacts())
                if (c.body_a == boxes[k] || c.body_b == boxes[k])
                    found = &c;
            BOOST_TEST_REQUIRE(found != nullptr);
            const ContactInfo& c = *found;
            BOOST_TEST_REQUIRE(c.point_count == 2); // face on face
            const double side = c.body_b == boxes[k] ? 1.0 : -1.0;
            (side > 0.0 ? second_side : first_side) = true;
            const Vec2d n = c.normal, t{n.y, -n.x};
            double jt = 0.0, jn = 0.0, jx = 0.0, jy = 0.0, moment = 0.0;
            for (int p = 0; p < c.point_count; ++p) {
                const ContactPointInfo& q = c.points[p];
                const Vec2d j{side * (q.normal_impulse * n.x + q.tangent_impulse * t.x),
                              side * (q.normal_impulse * n.y + q.tangent_impulse * t.y)};
                const Vec2d r = q.point - c0[k];
                jt += q.tangent_impulse;
                jn += q.normal_impulse;
                jx += j.x;
                jy += j.y;
                moment += r.x * j.y - r.y * j.x;
            }
            BOOST_TEST(v1.x > 0.0); // still sliding: the friction bound holds all step
            BOOST_TEST(std::abs(m * (v1.x - v0[k].x) - jx) < 1e-9 * jn);
            BOOST_TEST(std::abs(m * (v1.y - v0[k].y) + m * g * dt - jy) < 1e-9 * jn);
            BOOST_TEST(std::abs(inertia * (world.angular_velocity(boxes[k]) - w0[k]) - moment) <
                       1e-9 * jn);
            BOOST_TEST(rel(std::abs(jt), mu * jn) < 1e-9);
            BOOST_TEST(side * jt * (t.x * v0[k].x + t.y * v0[k].y) < 0.0); // against the slip
        }
    }
    BOOST_TEST((first_side && second_side)); // both sides of a contact were boxes
}

BOOST_AUTO_TEST_SUITE_END()
