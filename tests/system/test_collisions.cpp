// System test cases TC10-TC11 (R7, R8, IM3): a head-on elastic collision of unequal masses and
// impulses against a static body, over the whole history, against closed forms. Every case also
// runs the reversed direction and a non-zero velocity along the contact surface.
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "system/system_support.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;
using namespace tamias2d::system_test;

namespace {

double kinetic(double m, Vec2d v) {
    return 0.5 * m * (v.x * v.x + v.y * v.y);
}

struct Pair {
    double x1, v1, x2, v2; ///< centres on the x axis and their x velocities
    double vy;             ///< common vertical velocity (along the contact surface)
    bool boxes;            ///< false: circles r = 0.5 and 1; true: boxes 1 x 1 and 2 x 2
};

/// A head-on, centred collision of m1 = 1 kg with m2 = 100 kg, C_R = 1, no gravity.
/// Oracle: the 1-D elastic collision closed form (GD1 + conservation of kinetic energy):
///   v1' = ((m1 - m2) v1 + 2 m2 v2) / (m1 + m2),  v2' = ((m2 - m1) v2 + 2 m1 v1) / (m1 + m2),
/// the vertical velocity unchanged (frictionless, A6), and the continuous history
///   x_i(t) = x_i0 + v_i t before t_c = gap / closing speed, x_i(t_c) + v_i' (t - t_c) after,
/// which the engine follows within |v_i' - v_i| dt (the collision is resolved in the step that
/// contains t_c, so its timing is known to one step).
void check_pair(const Pair& c) {
    const double m1 = 1.0, m2 = 100.0;
    World world(WorldDef{.gravity = {0.0, 0.0}});
    BodyId b1, b2;
    double contact_distance;
    if (c.boxes) {
        b1 = add_box(world, {c.x1, 0.0}, {c.v1, c.vy}, 1.0, 1.0, m1, 1.0);
        b2 = add_box(world, {c.x2, 0.0}, {c.v2, c.vy}, 2.0, 2.0, m2 / 4.0, 1.0);
        contact_distance = 1.5;
    } else {
        b1 = add_circle(world, {c.x1, 0.0}, {c.v1, c.vy}, 0.5, m1, 1.0);
        b2 = add_circle(world, {c.x2, 0.0}, {c.v2, c.vy}, 1.0, m2, 1.0);
        contact_distance = 1.5;
    }
    BOOST_TEST(std::abs(world.mass(b1) - m1) < 1e-12);
    BOOST_TEST(std::abs(world.mass(b2) - m2) < 1e-10);
    const double w1 = ((m1 - m2) * c.v1 + 2.0 * m2 * c.v2) / (m1 + m2);
    const double w2 = ((m2 - m1) * c.v2 + 2.0 * m1 * c.v1) / (m1 + m2);
    const double gap = std::abs(c.x2 - c.x1) - contact_distance;
    const double closing = (c.x2 > c.x1) ? c.v1 - c.v2 : c.v2 - c.v1;
    BOOST_TEST_REQUIRE(closing > 0.0);
    const double tc = gap / closing;

    const Vec2d P0 = m1 * Vec2d{c.v1, c.vy} + m2 * Vec2d{c.v2, c.vy};
    const double E0 = kinetic(m1, {c.v1, c.vy}) + kinetic(m2, {c.v2, c.vy});
    const double dt = 1.0 / 60.0;
    const double y_at = 0.0;
    // Contacts are created within the speculative distance: a pair closing faster than that per
    // step is first seen overlapping, by at most closing dt - speculative distance; the slop is
    // tolerated on top (no continuous collision between dynamic bodies, as in Box2D v3).
    const double max_overlap = std::max(0.0, closing * dt - world.settings().speculative_distance) +
                               world.settings().linear_slop + 1e-12;
    History hist;
    double bound2 = 0.0, ref2 = 0.0;
    bool within = true, momentum = true, separated = true;
    for (int n = 1; n <= int(std::ceil(2.0 * tc / dt)) + 30; ++n) {
        world.step(dt);
        const double t = n * dt;
        const auto exact = [&](double x0, double v, double w) {
            return t <= tc ? x0 + v * t : x0 + v * tc + w * (t - tc);
        };
        const Vec2d e1{exact(c.x1, c.v1, w1), y_at + c.vy * t};
        const Vec2d e2{exact(c.x2, c.v2, w2), y_at + c.vy * t};
        const Vec2d p1 = world.position(b1), p2 = world.position(b2);
        hist.add(p1, e1);
        hist.add(p2, e2);
        const double bd1 = std::abs(w1 - c.v1) * dt, bd2 = std::abs(w2 - c.v2) * dt;
        within = within && norm(p1 - e1) <= bd1 + 1e-9 && norm(p2 - e2) <= bd2 + 1e-9;
        bound2 += bd1 * bd1 + bd2 * bd2;
        ref2 += e1.x * e1.x + e1.y * e1.y + e2.x * e2.x + e2.y * e2.y;
        // GD1 at every step: no external impulse acts on the pair.
        const Vec2d P = world.linear_momentum();
        momentum = momentum && norm(P - P0) <= 1e-12 * (norm(P0) + m1 * std::abs(c.v1));
        separated = separated && std::abs(p2.x - p1.x) >= contact_distance - max_overlap;
    }
    BOOST_TEST(momentum, "GD1: total momentum constant at every step");
    BOOST_TEST(within, "|p_i - p_i(t)| <= |v_i' - v_i| dt at every step");
    BOOST_TEST(hist.rel_error() <= std::sqrt(bound2 / ref2) + 1e-12);
    BOOST_TEST(separated, "overlap never beyond closing dt - speculative distance + slop");
    const Vec2d u1 = world.velocity(b1), u2 = world.velocity(b2);
    BOOST_TEST(std::abs(u1.x - w1) <= 1e-9 * std::abs(c.v1 - c.v2));
    BOOST_TEST(std::abs(u2.x - w2) <= 1e-9 * std::abs(c.v1 - c.v2));
    BOOST_TEST(std::abs(u1.y - c.vy) <= 1e-12);
    BOOST_TEST(std::abs(u2.y - c.vy) <= 1e-12);
    BOOST_TEST(std::abs(world.angular_velocity(b1)) <= 1e-9);
    BOOST_TEST(std::abs(world.angular_velocity(b2)) <= 1e-9);
    const double E1 = kinetic(m1, u1) + kinetic(m2, u2);
    BOOST_TEST(std::abs(E1 - E0) <= 1e-9 * E0, "kinetic energy conserved (C_R = 1)");
    BOOST_TEST(std::abs(world.kinetic_energy() - E1) <= 1e-12 * E0);
    BOOST_TEST_MESSAGE("pair: v1' = " << u1.x << " (closed form " << w1 << "), v2' = " << u2.x
                                      << " (" << w2 << "), history rel error " << hist.rel_error());
}

} // namespace

BOOST_AUTO_TEST_SUITE(system_collisions)

// Oracle: 1-D elastic collision closed form (see check_pair) and GD1: circles of 1 kg and
// 100 kg, C_R = 1, centred head-on; light into heavy, reversed (from the right into a heavy body
// moving right), heavy into light, and with a common vertical velocity.
BOOST_AUTO_TEST_CASE(TC10_elastic_collision_of_unequal_masses,
                     *utf::label("R7") * utf::label("R8") * utf::label("IM3") * utf::label("GD1") *
                         utf::label("DD8") * utf::label("DD12")) {
    check_pair({-3.0, 4.0, 0.0, 0.0, 0.0, false});
    check_pair({3.0, -4.0, 0.0, 0.5, 0.0, false});
    check_pair({3.0, 0.0, 0.0, 2.0, 0.0, false});
    check_pair({-3.0, 4.0, 0.0, 0.0, 1.5, false});
    check_pair({3.0, -4.0, 0.0, -0.5, -1.5, false});
}

// Oracle: as TC10 with boxes 1 x 1 m (1 kg) and 2 x 2 m (100 kg) meeting face to face: the
// contact has two points (edge-edge, LC1), solved together; symmetric, so no spin arises.
BOOST_AUTO_TEST_CASE(TC10b_elastic_collision_of_unequal_boxes_face_to_face,
                     *utf::label("R7") * utf::label("R8") * utf::label("IM3") * utf::label("GD1") *
                         utf::label("DD12") * utf::label("LC1")) {
    check_pair({-3.0, 4.0, 0.0, 0.0, 0.0, true});
    check_pair({3.0, -4.0, 0.0, 0.5, 0.0, true});
    check_pair({-3.0, 4.0, 0.0, 0.0, 1.5, true});
}

// Oracle: geometry and the soft contact's design (WorldDef defaults: an overdamped spring,
// damping ratio 10, whose slow time constant 2 zeta / omega is 0.11 s at 30 Hz): two circles
// created overlapping by 0.1 m at rest, no gravity, are pushed apart to within the linear slop
// (plus 1 mm) after 1 s. Regression test for a defect found during V&V (docs/verification.md):
// a solver separation offset by the distance between the anchors made an overlap look like a gap.
BOOST_AUTO_TEST_CASE(overlapping_circles_are_pushed_apart, *utf::label("R8") * utf::label("IM3")) {
    World world(WorldDef{.gravity = {0.0, 0.0}});
    const BodyId a = add_circle(world, {0.0, 0.0}, {0.0, 0.0}, 0.5, 1.0);
    const BodyId b = add_circle(world, {1.4, 0.0}, {0.0, 0.0}, 1.0, 1.0);
    for (int n = 0; n < 60; ++n)
        world.step(1.0 / 60.0);
    const double overlap = 1.5 - norm(world.position(b) - world.position(a));
    BOOST_TEST(overlap <= world.settings().linear_slop + 1e-3);
    BOOST_TEST(norm(world.linear_momentum()) <= 1e-12);
}

namespace {

struct Bounce {
    Vec2d p0, v0;  ///< ball centre and velocity
    Vec2d wall_c;  ///< static box centre
    Vec2d wall_sz; ///< static box size
    Vec2d n;       ///< unit normal of the wall face the ball hits (pointing at the ball)
};

/// A ball (circle r = 0.5, m = 2 kg, C_R = e) hits a static box (C_R = 0; the engine combines
/// restitution by the maximum) with no gravity.
/// Oracle: DD12 with a static body: the normal velocity reverses and scales by C_R,
/// v_n' = -C_R v_n, the tangential velocity is unchanged (A6); DD8 with 1/m_B = 0 and
/// r x n = 0 (centred hit): j = m (1 + C_R) |v_n|, equal to m |dv| (DD10).
void check_bounce(const Bounce& c, double e) {
    World world(WorldDef{.gravity = {0.0, 0.0}});
    BodyDef wd;
    wd.type = BodyType::static_body;
    wd.position = c.wall_c;
    const BodyId wall = world.create_body(wd);
    world.create_shape(wall, box_shape(c.wall_sz.x, c.wall_sz.y));
    const double m = 2.0;
    const BodyId ball = add_circle(world, c.p0, c.v0, 0.5, m, e);
    const double vn = dot(c.v0, c.n); // < 0: approaching
    BOOST_TEST_REQUIRE(vn < 0.0);
    const Vec2d vt = c.v0 - vn * c.n;
    const Vec2d v_after = vt + (-e * vn) * c.n;
    // Distance from the ball's centre to the wall face along n, at contact 0.5.
    const Vec2d face_point = c.wall_c + Vec2d{0.5 * c.wall_sz.x * c.n.x, 0.5 * c.wall_sz.y * c.n.y};
    const double gap = dot(c.p0 - face_point, c.n) - 0.5;
    const double tc = gap / -vn;
    const double dt = 1.0 / 60.0;
    History hist;
    bool within = true;
    int hits = 0;
    double impulse = 0.0;
    for (int n = 1; n <= int(std::ceil(2.0 * tc / dt)) + 20; ++n) {
        world.step(dt);
        const double t = n * dt;
        const Vec2d exact = t <= tc ? c.p0 + t * c.v0 : c.p0 + tc * c.v0 + (t - tc) * v_after;
        const Vec2d p = world.position(ball);
        hist.add(p, exact);
        within = within && norm(p - exact) <= norm(v_after - c.v0) * dt + 1e-9;
        for (const ContactInfo& ci : world.contacts()) {
            if (ci.points[0].normal_impulse > 0.0) {
                ++hits;
                impulse = ci.points[0].normal_impulse;
            }
        }
    }
    const Vec2d v = world.velocity(ball);
    const double speed = norm(c.v0);
    BOOST_TEST(hits == 1, "one impulsive contact step");
    BOOST_TEST(std::abs(dot(v, c.n) - (-e * vn)) <= 1e-9 * speed, "DD12: v_n' = -C_R v_n");
    BOOST_TEST(norm((v - dot(v, c.n) * c.n) - vt) <= 1e-12 * speed, "tangential velocity kept");
    BOOST_TEST(std::abs(impulse - m * (1.0 + e) * -vn) <= 1e-9 * m * speed, "DD8 impulse");
    BOOST_TEST(std::abs(impulse - m * norm(v - c.v0)) <= 1e-9 * m * speed, "DD10: J = m |dv|");
    BOOST_TEST(std::abs(world.angular_velocity(ball)) <= 1e-12);
    BOOST_TEST(within, "|p - p(t)| <= |v' - v| dt at every step");
    BOOST_TEST_MESSAGE("bounce C_R = " << e << ": v_n' = " << dot(v, c.n) << ", j = " << impulse
                                       << ", history rel error " << hist.rel_error());
}

} // namespace

// Oracle: DD12/DD8/DD10 closed forms for a ball against a static body (see check_bounce), for
// C_R = 0, 0.3, 0.5, 0.8, 1: falling on the ground (straight and with either horizontal
// velocity), reversed (rising into a ceiling) and sideways into a wall with a vertical velocity.
BOOST_AUTO_TEST_CASE(TC11_impulse_against_a_static_body,
                     *utf::label("R7") * utf::label("R8") * utf::label("IM3") * utf::label("DD8") *
                         utf::label("DD10") * utf::label("DD12")) {
    const Bounce ground_straight{{0.0, 3.0}, {0.0, -5.0}, {0.0, -0.5}, {40.0, 1.0}, {0.0, 1.0}};
    const Bounce ground_right{{0.0, 3.0}, {1.5, -5.0}, {0.0, -0.5}, {40.0, 1.0}, {0.0, 1.0}};
    const Bounce ground_left{{0.0, 3.0}, {-1.5, -5.0}, {0.0, -0.5}, {40.0, 1.0}, {0.0, 1.0}};
    const Bounce ceiling{{0.0, 7.0}, {1.0, 5.0}, {0.0, 10.5}, {40.0, 1.0}, {0.0, -1.0}};
    const Bounce wall{{7.0, 0.0}, {5.0, 1.0}, {10.5, 0.0}, {1.0, 40.0}, {-1.0, 0.0}};
    for (const double e : {0.0, 0.3, 0.5, 0.8, 1.0}) {
        for (const Bounce& c : {ground_straight, ground_right, ground_left, ceiling, wall}) {
            BOOST_TEST_CONTEXT("C_R = " << e << ", v0 = (" << c.v0.x << ", " << c.v0.y << ")") {
                check_bounce(c, e);
            }
        }
    }
}

// Oracle: DD12 under gravity: a ball dropped from rest 2 m above the ground rebounds with
// C_R times the normal speed it had at the start of the impact step (the engine's pre-solve
// velocity), which is within 2 g dt of the free-fall speed sqrt(2 g H) (the impact is resolved
// in a step starting at most one step, plus the scheme's O(h) lag, before the true impact).
BOOST_AUTO_TEST_CASE(TC11b_bounce_under_gravity, *utf::label("R8") * utf::label("IM3") *
                                                     utf::label("DD12") * utf::label("GD2")) {
    const double g = 9.81, H = 2.0, dt = 1.0 / 60.0;
    for (const double e : {0.3, 0.8, 1.0}) {
        World world(WorldDef{.gravity = {0.0, -g}});
        BodyDef gd;
        gd.type = BodyType::static_body;
        gd.position = {0.0, -0.5};
        const BodyId ground = world.create_body(gd);
        world.create_shape(ground, box_shape(40.0, 1.0));
        const BodyId ball = add_circle(world, {0.0, H + 0.5}, {0.0, 0.0}, 0.5, 2.0, e);
        double v_impact = 0.0, v_rebound = 0.0;
        for (int n = 0; n < 200 && v_rebound == 0.0; ++n) {
            const double before = world.velocity(ball).y;
            world.step(dt);
            for (const ContactInfo& ci : world.contacts()) {
                if (ci.points[0].normal_impulse > 0.0) {
                    v_impact = before;
                    v_rebound = world.velocity(ball).y;
                }
            }
        }
        BOOST_TEST_REQUIRE(v_impact < 0.0);
        BOOST_TEST(std::abs(v_rebound - (-e * v_impact)) <= 1e-9 * std::abs(v_impact));
        BOOST_TEST(std::abs(-v_impact - std::sqrt(2.0 * g * H)) <= 2.0 * g * dt);
        BOOST_TEST_MESSAGE("drop C_R = " << e << ": impact " << v_impact << " m/s (closed form "
                                         << -std::sqrt(2.0 * g * H) << "), rebound " << v_rebound);
    }
}

// Oracle: DD12 with the world's restitution threshold (WorldDef::restitution_threshold:
// restitution applies only to bodies approaching faster than it). An elastic ball (C_R = 1)
// dropped 2 m under a 4 m/s threshold lands at about 6.3 m/s and rebounds at C_R times its
// impact speed, as above; dropped 0.2 m (about 2 m/s) it does not rebound: after the impact
// step it neither leaves the ground nor moves up faster than the contact's push (0.1 m/s).
BOOST_AUTO_TEST_CASE(a_ball_slower_than_the_restitution_threshold_does_not_bounce,
                     *utf::label("DD12")) {
    const double g = 9.81, dt = 1.0 / 60.0;
    for (const double H : {2.0, 0.2}) {
        BOOST_TEST_CONTEXT("dropped from " << H << " m") {
            WorldDef def{.gravity = {0.0, -g}};
            def.restitution_threshold = 4.0;
            World world(def);
            BodyDef gd;
            gd.type = BodyType::static_body;
            gd.position = {0.0, -0.5};
            world.create_shape(world.create_body(gd), box_shape(40.0, 1.0));
            const BodyId ball = add_circle(world, {0.0, H + 0.5}, {0.0, 0.0}, 0.5, 2.0, 1.0);
            double v_impact = 0.0, v_after = 0.0;
            for (int n = 0; n < 200 && v_impact == 0.0; ++n) {
                const double before = world.velocity(ball).y;
                world.step(dt);
                for (const ContactInfo& ci : world.contacts())
                    if (ci.points[0].normal_impulse > 0.0) {
                        v_impact = before;
                        v_after = world.velocity(ball).y;
                    }
            }
            BOOST_TEST_REQUIRE(v_impact < 0.0);
            BOOST_TEST_MESSAGE("impact " << v_impact << " m/s, after " << v_after << " m/s");
            if (H > 1.0) {
                BOOST_TEST(-v_impact > def.restitution_threshold);
                BOOST_TEST(std::abs(v_after + v_impact) <= 1e-9 * std::abs(v_impact));
            } else {
                BOOST_TEST(-v_impact < def.restitution_threshold);
                BOOST_TEST(v_after <= 0.1);
                double highest = world.position(ball).y;
                for (int n = 0; n < 30; ++n) {
                    world.step(dt);
                    highest = std::max(highest, world.position(ball).y);
                }
                BOOST_TEST(highest <= 0.5 + 0.01); // the ball's centre stays at its radius
            }
        }
    }
}

BOOST_AUTO_TEST_SUITE_END()
