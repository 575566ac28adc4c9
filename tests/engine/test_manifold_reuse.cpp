// Manifold reuse (WorldDef::manifold_reuse_distance, src/tamias2d/collision/manifold_reuse.hpp):
// a touching contact keeps its manifold while its bodies drift less than d against each other,
// each point's separation exact for the two material points it pairs, the point midway between
// them; beyond d the manifold is computed afresh.
#include <boost/test/unit_test.hpp>

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
