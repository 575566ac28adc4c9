// Manifold reuse (WorldDef::manifold_reuse_distance, src/tamias2d/collision/manifold_reuse.hpp):
// a touching contact keeps its manifold while its bodies drift less than d against each other,
// each point's separation exact for the two material points it pairs, the point midway between
// them; beyond d the manifold is computed afresh.
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "tamias2d/world.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;

namespace {

constexpr double dt = 1.0 / 60.0;

/// A unit box gliding over a static floor (top face y = 0) without gravity or friction, apart
/// from it by `gap` and moving by `step` each step (its velocity keeps it from the floor, so no
/// impulse acts and it moves uniformly).
struct Glide {
    World world;
    BodyId box;
    Glide(double reuse, double gap, Vec2d step)
        : world(WorldDef{.gravity = {0.0, 0.0}, .manifold_reuse_distance = reuse}) {
        BodyDef floor;
        floor.type = BodyType::static_body;
        floor.position = {0.0, -0.5};
        world.create_shape(world.create_body(floor), box_shape(20.0, 1.0));
        BodyDef b;
        b.position = {0.0, 0.5 + gap};
        b.linear_velocity = step / dt;
        box = world.create_body(b);
        world.create_shape(box, box_shape(1.0, 1.0));
    }
};

} // namespace

BOOST_AUTO_TEST_SUITE(manifold_reuse)

// Oracle: closed-form geometry of a unit box over a floor, and the reuse rule as stated in
// WorldDef::manifold_reuse_distance. A fresh manifold of a box parallel to the floor holds its
// two bottom corners' points midway to the floor: (x -+ 0.5, s / 2), s = y - 0.5, the box's
// height over the floor. A reused one pairs the floor's material point of then, (xb -+ 0.5,
// sb / 2), with the box's, carried by the box's displacement since then (dx, dy): the reported
// point is midway, (xb -+ 0.5 + dx / 2, sb / 2 + dy / 2), and the separation exactly s. Reuse
// holds while |(dx, dy)| <= d (the box does not turn).
BOOST_AUTO_TEST_CASE(a_drift_within_the_distance_keeps_the_manifold_beyond_it_renews_it,
                     *utf::label("R7")) {
    const double d = 0.005;
    const Vec2d step{0.3 * d * 0.8, 0.3 * d * 0.6}; // 0.3 d a step, rising
    Glide g(d, 0.002, step);
    Vec2d basis{};
    int reused = 0, renewed = 0;
    for (int n = 0; n < 12; ++n) {
        const Vec2d at = g.world.position(g.box); // the pose this step's narrow phase sees
        g.world.step(dt);
        BOOST_TEST_REQUIRE(g.world.contacts().size() == 1u);
        const ContactInfo& c = g.world.contacts()[0];
        BOOST_TEST_REQUIRE(c.point_count == 2);
        const double s = at.y - 0.5;
        const bool fresh = n == 0 || std::hypot(at.x - basis.x, at.y - basis.y) > d;
        if (fresh)
            basis = at;
        (fresh ? renewed : reused) += 1;
        const Vec2d drift = at - basis;
        BOOST_TEST_CONTEXT("step " << n << (fresh ? " (fresh)" : " (reused)")) {
            for (int j = 0; j < 2; ++j) {
                const ContactPointInfo& p = c.points[j];
                const double corner = p.point.x < at.x - drift.x / 2 ? -0.5 : 0.5;
                BOOST_TEST(std::abs(p.separation - s) < 1e-12);
                BOOST_TEST(std::abs(p.point.x - (basis.x + corner + drift.x / 2)) < 1e-12);
                BOOST_TEST(std::abs(p.point.y - ((basis.y - 0.5) / 2 + drift.y / 2)) < 1e-12);
            }
        }
    }
    // 0.3 d a step: three reuses after each renewal.
    BOOST_TEST(renewed == 3);
    BOOST_TEST(reused == 9);
}

// Oracle: closed-form geometry of a unit box turning in place over a floor (top face y = 0),
// and the reuse rule. A fresh manifold of the tilted box holds its two bottom corners q_j:
// separation q_j.y, point (q_j.x, q_j.y / 2). A reused one pairs the floor's point of then, p_j,
// with the box's material point that coincided with it, carried by the box's turn since then
// about its centre c: b_j = c + R(phi - phi_b) (p_j - c); reported: midway, separation
// s_j + (b_j - p_j).y. The floor does not move, so the rule reduces to the turn: reuse while
// 2 sin(|phi - phi_b| / 2) max_j |p_j - c| <= d.
BOOST_AUTO_TEST_CASE(a_turn_within_the_distance_keeps_the_manifold_beyond_it_renews_it,
                     *utf::label("R7")) {
    const double d = 0.005;
    World world(WorldDef{.gravity = {0.0, 0.0}, .manifold_reuse_distance = d});
    BodyDef floor;
    floor.type = BodyType::static_body;
    floor.position = {0.0, -0.5};
    world.create_shape(world.create_body(floor), box_shape(20.0, 1.0));
    BodyDef bd;
    bd.position = {0.0, 0.51}; // both bottom corners within the speculative 0.02 m throughout
    bd.angular_velocity = 0.3 * d / 0.72 * 60.0; // turns a 0.72 m arm by 0.3 d a step
    const BodyId box = world.create_body(bd);
    world.create_shape(box, box_shape(1.0, 1.0));
    const auto corners = [](Vec2d c, double phi) {
        const double cs = std::cos(phi), sn = std::sin(phi);
        std::array<Vec2d, 2> q{};
        for (int j = 0; j < 2; ++j) {
            const double lx = j == 0 ? -0.5 : 0.5, ly = -0.5;
            q[std::size_t(j)] = {c.x + cs * lx - sn * ly, c.y + sn * lx + cs * ly};
        }
        return q;
    };
    std::array<Vec2d, 2> p{}; // the floor's points of the basis
    std::array<double, 2> s{};
    double phi_b = 0.0;
    int reused = 0, renewed = 0;
    for (int n = 0; n < 8; ++n) {
        const Vec2d c = world.position(box);
        const double phi = world.orientation(box); // small and positive here
        world.step(dt);
        BOOST_TEST_REQUIRE(world.contacts().size() == 1u);
        const ContactInfo& info = world.contacts()[0];
        BOOST_TEST_REQUIRE(info.point_count == 2);
        double arm = 0.0;
        for (const Vec2d& q : p)
            arm = std::max(arm, std::hypot(q.x - c.x, q.y - c.y));
        const bool fresh = n == 0 || 2.0 * std::sin(std::abs(phi - phi_b) / 2.0) * arm > d;
        if (fresh) {
            const auto q = corners(c, phi);
            for (int j = 0; j < 2; ++j) {
                p[std::size_t(j)] = {q[std::size_t(j)].x, q[std::size_t(j)].y / 2.0};
                s[std::size_t(j)] = q[std::size_t(j)].y;
            }
            phi_b = phi;
        }
        (fresh ? renewed : reused) += 1;
        const double cs = std::cos(phi - phi_b), sn = std::sin(phi - phi_b);
        BOOST_TEST_CONTEXT("step " << n << (fresh ? " (fresh)" : " (reused)")) {
            for (int j = 0; j < 2; ++j) {
                const Vec2d pj = p[std::size_t(j)], r{pj.x - c.x, pj.y - c.y};
                const Vec2d b{c.x + cs * r.x - sn * r.y, c.y + sn * r.x + cs * r.y};
                const ContactPointInfo& got = info.points[0].point.x < info.points[1].point.x
                                                  ? info.points[j]
                                                  : info.points[1 - j];
                BOOST_TEST(std::abs(got.separation - (s[std::size_t(j)] + b.y - pj.y)) < 1e-12);
                BOOST_TEST(std::abs(got.point.x - 0.5 * (pj.x + b.x)) < 1e-12);
                BOOST_TEST(std::abs(got.point.y - 0.5 * (pj.y + b.y)) < 1e-12);
            }
        }
    }
    BOOST_TEST(renewed == 2); // steps 0 and 4
    BOOST_TEST(reused == 6);
}

// Oracle: closed-form geometry of two boxes turning together in free space, and the reuse rule.
// A 2 x 0.5 plank and a unit box 5 mm above it spin at one rate with the velocities of one rigid
// body (to first order: the integrator moves them along straight lines, so they part by
// 1e-4 m over the test), so their relative pose barely changes and only the turn can renew the
// manifold. A fresh manifold's normal is the plank's up face normal, (-sin phi, cos phi); a
// reused one keeps the normal of its basis. Reuse holds while 2 sin(|phi - phi_b| / 2) times
// the longest moment arm, the box's centre to its bottom corners |(0.5, 0.5 + g / 2)|, is <= d.
BOOST_AUTO_TEST_CASE(a_turn_of_both_bodies_renews_the_normal, *utf::label("R7")) {
    const double d = 0.005, g = 0.005;
    World world(WorldDef{.gravity = {0.0, 0.0}, .manifold_reuse_distance = d});
    const double arm = std::hypot(0.5, 0.5 + g / 2.0);
    const double omega = 0.3 * d / arm / dt;       // the arm turns by 0.3 d a step
    const double com_y = (0.0 + (0.75 + g)) / 2.0; // equal masses (1 kg each)
    BodyDef pd;
    pd.angular_velocity = omega;
    pd.linear_velocity = {omega * com_y, 0.0}; // omega x (c - com)
    const BodyId plank = world.create_body(pd);
    world.create_shape(plank, box_shape(2.0, 0.5));
    BodyDef bd;
    bd.position = {0.0, 0.75 + g};
    bd.angular_velocity = omega;
    bd.linear_velocity = {-omega * (0.75 + g - com_y), 0.0};
    const BodyId box = world.create_body(bd);
    world.create_shape(box, box_shape(1.0, 1.0));
    double phi_b = 0.0;
    int reused = 0, renewed = 0;
    for (int n = 0; n < 8; ++n) {
        const double phi = world.orientation(plank); // small and positive here
        BOOST_TEST_REQUIRE(std::abs(world.orientation(box) - phi) < 1e-12);
        world.step(dt);
        BOOST_TEST_REQUIRE(world.contacts().size() == 1u);
        const ContactInfo& info = world.contacts()[0];
        const bool fresh = n == 0 || 2.0 * std::sin(std::abs(phi - phi_b) / 2.0) * arm > d;
        if (fresh)
            phi_b = phi;
        (fresh ? renewed : reused) += 1;
        BOOST_TEST_CONTEXT("step " << n << (fresh ? " (fresh)" : " (reused)")) {
            BOOST_TEST(std::abs(info.normal.x + std::sin(phi_b)) < 1e-12);
            BOOST_TEST(std::abs(info.normal.y - std::cos(phi_b)) < 1e-12);
        }
    }
    BOOST_TEST(renewed == 2); // steps 0 and 4
    BOOST_TEST(reused == 6);
}

// Oracle: the same closed form with d = 0: every manifold is fresh, its points at the corners.
BOOST_AUTO_TEST_CASE(distance_zero_computes_every_manifold_afresh, *utf::label("R7")) {
    Glide g(0.0, 0.002, {0.0015, 0.0});
    for (int n = 0; n < 6; ++n) {
        const Vec2d at = g.world.position(g.box);
        g.world.step(dt);
        BOOST_TEST_REQUIRE(g.world.contacts().size() == 1u);
        const ContactInfo& c = g.world.contacts()[0];
        BOOST_TEST_REQUIRE(c.point_count == 2);
        for (int j = 0; j < 2; ++j) {
            const double corner = c.points[j].point.x < at.x ? -0.5 : 0.5;
            BOOST_TEST(std::abs(c.points[j].point.x - (at.x + corner)) < 1e-12);
            BOOST_TEST(std::abs(c.points[j].separation - (at.y - 0.5)) < 1e-12);
        }
    }
}

BOOST_AUTO_TEST_SUITE_END()
