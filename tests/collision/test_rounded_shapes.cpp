// Narrow phase for capsules and segments against every shape kind (T5, A4, A5, LC1), and
// chain edges' one-sided, ghost-free contacts (DD31).
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <random>

#include "oracles.hpp"
#include "support/collide_input.hpp"
#include "tamias2d/collision/narrow_phase.hpp"
#include "tamias2d/geometry/shape_factory.hpp"

namespace utf = boost::unit_test;
namespace tt = boost::test_tools;
using namespace tamias2d;
using tamias2d::test::at;
using tamias2d::test::input;

namespace {

double deepest(const Manifold& m) {
    double d = INFINITY;
    for (int i = 0; i < m.count; ++i)
        d = std::min(d, m.points[i].separation);
    return d;
}

Geometry capsule(Vec2d a, Vec2d b, double r) {
    return to_geometry(make_capsule(a, b, r));
}

/// Chain edge p1 -> p2 between ghosts g1 and g2 (collides on the right of p1 -> p2).
Geometry edge(Vec2d g1, Vec2d p1, Vec2d p2, Vec2d g2) {
    return to_geometry(ChainSegment{g1, p1, p2, g2});
}

} // namespace

BOOST_AUTO_TEST_SUITE(rounded_shapes)

// Oracle: brute-force distance between the shapes' cores less their radii (oracles.hpp, all
// vertex-edge pairs, no library code): capsules and segments against circles, boxes, hulls,
// capsules and segments at random poses. Overlapping shapes give a contact whose deepest point
// is not apart; shapes farther apart than the margin none; a speculative contact reports the
// true gap as its deepest separation; every penetrating point lies in both shapes grown by half its
// penetration (T5: it is midway between the surfaces); the normal is a unit vector.
BOOST_AUTO_TEST_CASE(contacts_agree_with_brute_force_distance, *utf::label("T5")) {
    std::mt19937_64 rng(7);
    int overlapping = 0, apart = 0, speculative = 0;
    double worst_understatement = 0.0;
    for (int trial = 0; trial < 6000; ++trial) {
        const Geometry a = oracle::random_rounded_shape(rng);
        const Geometry b =
            trial % 3 == 0 ? oracle::random_rounded_shape(rng) : oracle::random_shape(rng);
        const Transform xa = oracle::random_transform(rng, 1.0);
        const Transform xb = oracle::random_transform(rng, 1.0);
        const double margin = trial % 2 == 0 ? 0.0 : 0.1;
        // Both orders: the pair's manifold must not depend on which shape is A.
        for (int order = 0; order < 2; ++order) {
            const Geometry& p = order == 0 ? a : b;
            const Geometry& q = order == 0 ? b : a;
            const Transform& xp = order == 0 ? xa : xb;
            const Transform& xq = order == 0 ? xb : xa;
            const Manifold m = collide(p, q, input(xp, xq, margin));
            const double d = oracle::rounded_distance(p, xp, q, xq);
            BOOST_TEST_CONTEXT("trial " << trial << " order " << order << " distance " << d) {
                if (d == 0.0) {
                    ++overlapping;
                    BOOST_TEST_REQUIRE(m.count >= 1);
                    BOOST_TEST(deepest(m) <= 1e-12);
                } else if (d >= margin) {
                    ++apart;
                    BOOST_TEST(m.count == 0);
                } else if (m.count > 0) {
                    ++speculative;
                    BOOST_TEST(deepest(m) == d, tt::tolerance(1e-9));
                    worst_understatement = std::max(worst_understatement, d - deepest(m));
                }
                if (m.count > 0)
                    BOOST_TEST(std::hypot(m.normal.x, m.normal.y) == 1.0, tt::tolerance(1e-12));
                for (int i = 0; i < m.count; ++i) {
                    const ManifoldPoint& mp = m.points[i];
                    BOOST_TEST(mp.separation < margin);
                    if (mp.separation < 0.0) {
                        const double half = 0.5 * -mp.separation + 1e-9;
                        BOOST_TEST(oracle::within(p, xp, mp.point, half));
                        BOOST_TEST(oracle::within(q, xq, mp.point, half));
                    }
                }
            }
        }
    }
    BOOST_TEST_MESSAGE("rounded pairs: " << overlapping << " overlapping, " << apart << " apart, "
                                         << speculative
                                         << " speculative; largest understatement of a gap "
                                         << worst_understatement << " m");
    BOOST_TEST(overlapping > 2000);
    BOOST_TEST(apart > 1000);
}

// Oracle: geometry: a capsule (core from x = -1 to 1, radius 0.25) lying 0.02 m above a box's
// top face has two contact points (LC1) under its two end discs, each 0.02 m apart, normal
// +y from the box into the capsule (A4); tilted, it touches with one end only (A5).
BOOST_AUTO_TEST_CASE(capsule_lying_on_a_box, *utf::label("LC1") * utf::label("A5")) {
    const Geometry box = to_geometry(make_box(2.0, 0.5));
    const Geometry cap = capsule({-1.0, 0.0}, {1.0, 0.0}, 0.25);
    const Manifold flat = collide(box, cap, input(at(0, 0), at(0.3, 0.77), 0.05));
    BOOST_TEST_REQUIRE(flat.count == 2);
    BOOST_TEST(flat.normal.x == 0.0, tt::tolerance(1e-15));
    BOOST_TEST(flat.normal.y == 1.0);
    for (int i = 0; i < 2; ++i) {
        BOOST_TEST(flat.points[i].separation == 0.02, tt::tolerance(1e-9));
        BOOST_TEST(std::abs(flat.points[i].point.x - 0.3) == 1.0, tt::tolerance(1e-9));
        BOOST_TEST(flat.points[i].point.y == 0.51, tt::tolerance(1e-9)); // midway
    }
    const Manifold tilted = collide(box, cap, input(at(0, 0), at(0.0, 0.95, 0.3), 0.05));
    BOOST_TEST_REQUIRE(tilted.count == 1);
    // Lower end disc: centre at y = 0.95 - sin(0.3), bottom 0.25 below it.
    BOOST_TEST(tilted.points[0].separation == 0.95 - std::sin(0.3) - 0.25 - 0.5,
               tt::tolerance(1e-9));
}

// Oracle: closed forms for circle against segment and capsule: the gap is the distance from
// the centre to the core segment less both radii; in an end's region the normal runs from the
// end's centre to the circle's.
BOOST_AUTO_TEST_CASE(circle_against_segment_and_capsule, *utf::label("T5") * utf::label("A4")) {
    const Geometry seg = to_geometry(make_segment({-1.0, 0.0}, {1.0, 0.0}));
    const Geometry cap = capsule({-1.0, 0.0}, {1.0, 0.0}, 0.1);
    const Geometry ball = to_geometry(make_circle(0.3));
    for (double side : {1.0, -1.0}) { // a segment is two-sided
        const Manifold m = collide(seg, ball, input(at(0, 0), at(0.4, side * 0.32), 0.05));
        BOOST_TEST_REQUIRE(m.count == 1);
        BOOST_TEST(m.points[0].separation == 0.02, tt::tolerance(1e-9));
        BOOST_TEST(m.normal.y == side);
    }
    const Manifold end = collide(cap, ball, input(at(0, 0), at(1.3, 0.3), 0.1));
    BOOST_TEST_REQUIRE(end.count == 1);
    const double gap = std::hypot(0.3, 0.3) - 0.1 - 0.3;
    BOOST_TEST(end.points[0].separation == gap, tt::tolerance(1e-9));
    BOOST_TEST(end.normal.x == std::sqrt(0.5), tt::tolerance(1e-12));
    BOOST_TEST(end.normal.y == std::sqrt(0.5), tt::tolerance(1e-12));
    // Reversed roles: the same contact with the normal reversed (A4: from A into B).
    const Manifold rev = collide(ball, cap, input(at(1.3, 0.3), at(0, 0), 0.1));
    BOOST_TEST_REQUIRE(rev.count == 1);
    BOOST_TEST(rev.points[0].separation == gap, tt::tolerance(1e-12));
    BOOST_TEST(rev.normal.x == -end.normal.x, tt::tolerance(1e-12));
}

// Oracle: geometry: two parallel capsules (radius 0.2) whose cores are 0.43 m apart and overlap
// over 1.5 m along their axes touch along that overlap: two points (LC1) 0.03 m apart; crossed
// at right angles through their middles, the least move that parts them is along either axis,
// by half a core (1 m) plus both radii: a penetration of 1.4 m.
BOOST_AUTO_TEST_CASE(capsule_pairs, *utf::label("LC1") * utf::label("T5")) {
    const Geometry cap = capsule({-1.0, 0.0}, {1.0, 0.0}, 0.2);
    const Manifold side = collide(cap, cap, input(at(0, 0), at(0.5, 0.43), 0.05));
    BOOST_TEST_REQUIRE(side.count == 2);
    for (int i = 0; i < 2; ++i)
        BOOST_TEST(side.points[i].separation == 0.03, tt::tolerance(1e-9));
    const Manifold crossed =
        collide(cap, cap, input(at(0, 0), at(0, 0, 0.5 * std::numbers::pi), 0.05));
    BOOST_TEST_REQUIRE(crossed.count >= 1);
    BOOST_TEST(deepest(crossed) == -1.4, tt::tolerance(1e-9));
    // End to end along one line: one point on the axis, the gap between the end discs.
    const Manifold ends = collide(cap, cap, input(at(0, 0), at(2.45, 0.0), 0.1));
    BOOST_TEST_REQUIRE(ends.count == 1);
    BOOST_TEST(ends.points[0].separation == 0.05, tt::tolerance(1e-9));
    BOOST_TEST(ends.normal.x == 1.0, tt::tolerance(1e-12));
}

// Oracle: hand geometry of DD31's one-sidedness: a chain edge running right to left (normal +y)
// meets a circle above it and not one whose centre is below its line, which passes through from
// behind.
BOOST_AUTO_TEST_CASE(chain_edge_is_one_sided, *utf::label("DD31")) {
    const Geometry e = edge({2.0, 0.0}, {1.0, 0.0}, {-1.0, 0.0}, {-2.0, 0.0});
    const Geometry ball = to_geometry(make_circle(0.3));
    const Manifold above = collide(e, ball, input(at(0, 0), at(0.2, 0.28), 0.05));
    BOOST_TEST_REQUIRE(above.count == 1);
    BOOST_TEST(above.normal.y == 1.0, tt::tolerance(1e-12));
    BOOST_TEST(above.points[0].separation == -0.02, tt::tolerance(1e-9));
    const Manifold below = collide(e, ball, input(at(0, 0), at(0.2, -0.1), 0.05));
    BOOST_TEST(below.count == 0);
    // Reversed roles: the same, with the normal reversed.
    const Manifold rev = collide(ball, e, input(at(0.2, 0.28), at(0, 0), 0.05));
    BOOST_TEST_REQUIRE(rev.count == 1);
    BOOST_TEST(rev.normal.y == -1.0, tt::tolerance(1e-12));
}

// Oracle: hand geometry of DD31, the ghost corner: a box resting flat on a flat chain (edges
// meeting at x = 0) and straddling the joint, with less of it over the edge on the left than its
// penetration: two-sided, the left edge's bare end meets the box's side face and the separating
// axis test gives a horizontal normal (the "ghost" that catches a sliding body); as a chain edge
// its normal is the edge's own, +y, and its points lie on its own extent.
BOOST_AUTO_TEST_CASE(flat_joint_has_no_ghost_normal, *utf::label("DD31") * utf::label("T5")) {
    const Geometry box = to_geometry(make_box(0.5, 0.5));
    const Transform xb = at(0.495, 0.49); // left side 0.005 m past the joint, 0.01 m deep
    const Geometry two_sided = to_geometry(make_segment({0.0, 0.0}, {-1.0, 0.0}));
    const Manifold ghost = collide(two_sided, box, input(at(0, 0), xb, 0.05));
    BOOST_TEST_REQUIRE(ghost.count >= 1);
    BOOST_TEST(std::abs(ghost.normal.x) == 1.0, tt::tolerance(1e-12)); // the catch, shown
    const Geometry left = edge({1.0, 0.0}, {0.0, 0.0}, {-1.0, 0.0}, {-2.0, 0.0});
    const Manifold m = collide(left, box, input(at(0, 0), xb, 0.05));
    BOOST_TEST_REQUIRE(m.count >= 1);
    BOOST_TEST(m.normal.x == 0.0, tt::tolerance(1e-15));
    BOOST_TEST(m.normal.y == 1.0, tt::tolerance(1e-15));
    for (int i = 0; i < m.count; ++i) {
        BOOST_TEST(m.points[i].point.x <= 0.0 + 1e-12);
        BOOST_TEST(m.points[i].separation == -0.01, tt::tolerance(1e-9));
    }
}

// Oracle: hand geometry of DD31 at a convex vertex: a chain over a hilltop at the origin (edges
// sloping down both ways) gives a circle resting on the top the normal from the vertex to its
// centre, which lies between the two edges' normals (the vertex's arc), from either edge.
BOOST_AUTO_TEST_CASE(convex_vertex_keeps_its_arc, *utf::label("DD31")) {
    const Vec2d right{2.0, -0.5}, top{0.0, 0.0}, left{-2.0, -0.5};
    const Geometry ball = to_geometry(make_circle(0.3));
    const Transform xb = at(0.05, 0.29);
    const Vec2d expected{0.05 / std::hypot(0.05, 0.29), 0.29 / std::hypot(0.05, 0.29)};
    const Geometry edges[] = {edge({4.0, -1.0}, right, top, left),
                              edge(right, top, left, {-4.0, -1.0})};
    for (const Geometry& e : edges) {
        const Manifold m = collide(e, ball, input(at(0, 0), xb, 0.05));
        BOOST_TEST_REQUIRE(m.count == 1);
        BOOST_TEST(m.normal.x == expected.x, tt::tolerance(1e-9));
        BOOST_TEST(m.normal.y == expected.y, tt::tolerance(1e-9));
        BOOST_TEST(m.points[0].separation == std::hypot(0.05, 0.29) - 0.3, tt::tolerance(1e-9));
    }
}

// Oracle: hand geometry of DD31 and its one-sidedness. A wide triangle (centre 0.02 m in front
// of the edge, top 0.45 m above its line, apex 0.85 m below) overlaps the edge least along -y:
// two-sided, the separating axis test gives the back of the edge. DD31 admits no normal facing
// away from the edge's arcs, so the edge answers with its face, +y, whether the vertex before
// it is flat or convex by only 0.3 degrees (an arc narrower than the tolerance's angle).
BOOST_AUTO_TEST_CASE(a_barely_convex_vertex_admits_no_back_normal,
                     *utf::label("DD31") * utf::label("T5")) {
    const Vec2d corners[] = {
        {-2.0, 0.3 + 0.4 / 3.0}, {2.0, 0.3 + 0.4 / 3.0}, {0.0, -1.0 + 0.4 / 3.0}};
    const Geometry wedge = to_geometry(make_polygon(corners));
    const Transform xb = at(0.2, 0.02);
    const Geometry two_sided = to_geometry(make_segment({1.0, 0.0}, {-1.0, 0.0}));
    const Manifold back = collide(two_sided, wedge, input(at(0, 0), xb, 0.05));
    BOOST_TEST_REQUIRE(back.count >= 1);
    BOOST_TEST(back.normal.y == -1.0, tt::tolerance(1e-12)); // the back, shown
    for (const double drop : {0.0, 2.0 * std::tan(0.3 * std::numbers::pi / 180.0)}) {
        const Geometry e = edge({3.0, -drop}, {1.0, 0.0}, {-1.0, 0.0}, {-3.0, 0.0});
        const Manifold m = collide(e, wedge, input(at(0, 0), xb, 0.05));
        BOOST_TEST_REQUIRE(m.count >= 1);
        BOOST_TEST(m.normal.x == 0.0, tt::tolerance(1e-15));
        BOOST_TEST_INFO("the vertex's drop " << drop);
        BOOST_TEST(m.normal.y == 1.0, tt::tolerance(1e-15));
    }
}

// Oracle: brute-force distance (oracles.hpp) and DD31's one-sidedness: a chain edge whose
// ghosts make its ends right-angle convex corners (an open chain of one edge) admits every
// normal into the half-plane in front of it, so against any shape wholly in front of its line
// it is a segment: overlapping shapes touch, shapes apart by the margin do not, a speculative
// contact reports the true gap; against a shape whose centre is behind its line it never
// touches, whatever the overlap.
BOOST_AUTO_TEST_CASE(chain_edge_against_every_kind, *utf::label("DD31") * utf::label("T5")) {
    std::mt19937_64 rng(11);
    const std::vector<Vec2d> pts = {{1.0, 0.0}, {-1.0, 0.0}}; // normal +y
    const Geometry e = to_geometry(make_chain(pts, false)[0]);
    int in_front = 0, behind = 0, touching = 0;
    for (int trial = 0; trial < 4000; ++trial) {
        const Geometry b =
            trial % 2 == 0 ? oracle::random_shape(rng) : oracle::random_rounded_shape(rng);
        const Transform xb = oracle::random_transform(rng, 1.5);
        const double margin = 0.1;
        const oracle::Rounded r = oracle::rounded(b, xb);
        double lowest = INFINITY;
        for (const Vec2d& v : r.core)
            lowest = std::min(lowest, v.y);
        lowest -= r.radius;
        // The shape's centre: a polygon's area centroid (shoelace), else the core's midpoint.
        double cy = 0.0;
        if (r.core.size() >= 3) {
            double area2 = 0.0;
            for (std::size_t i = 0; i < r.core.size(); ++i) {
                const Vec2d p = r.core[i], q = r.core[(i + 1) % r.core.size()];
                const double c = p.x * q.y - q.x * p.y;
                area2 += c;
                cy += (p.y + q.y) * c;
            }
            cy /= 3.0 * area2;
        } else {
            for (const Vec2d& v : r.core)
                cy += v.y / double(r.core.size());
        }
        for (int order = 0; order < 2; ++order) {
            const Manifold m = order == 0 ? collide(e, b, input(at(0, 0), xb, margin))
                                          : collide(b, e, input(xb, at(0, 0), margin));
            BOOST_TEST_CONTEXT("trial " << trial << " order " << order) {
                if (cy < 0.0) { // the shape's centre behind the edge
                    ++behind;
                    BOOST_TEST(m.count == 0);
                } else if (lowest >= 0.0) { // wholly in front
                    ++in_front;
                    const double d = oracle::rounded_distance(e, at(0, 0), b, xb);
                    if (d >= margin)
                        BOOST_TEST(m.count == 0);
                    else {
                        ++touching;
                        BOOST_TEST_REQUIRE(m.count >= 1);
                        BOOST_TEST(deepest(m) == d, tt::tolerance(1e-9));
                    }
                }
            }
        }
    }
    BOOST_TEST_MESSAGE("chain edge: " << in_front << " in front (" << touching
                                      << " within the margin), " << behind << " behind");
    BOOST_TEST(touching > 100);
    BOOST_TEST(behind > 1000);
}

BOOST_AUTO_TEST_SUITE_END()
