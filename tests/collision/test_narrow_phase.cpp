// Narrow phase: contact manifolds for circle and polygon pairs (T5, A4, A5, LC1).
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>
#include <random>
#include <set>

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

/// Support gap along n: min over B of n.x minus max over A of n.x (positive: n separates).
double support_gap(const Geometry& a, const Transform& xa, const Geometry& b, const Transform& xb,
                   Vec2d n) {
    auto extent = [&](const Geometry& g, const Transform& x, double sign) {
        if (g.type == ShapeType::circle)
            return sign * oracle::dotp(n, oracle::world_point(x, g.circle.center)) +
                   g.circle.radius;
        double m = -INFINITY;
        for (const Vec2d& v : oracle::world_vertices(g.polygon, x))
            m = std::max(m, sign * oracle::dotp(n, v));
        return m;
    };
    return -extent(b, xb, -1.0) - extent(a, xa, 1.0);
}

bool same_bits(Vec2d a, Vec2d b) {
    return std::memcmp(&a.x, &b.x, sizeof(double)) == 0 &&
           std::memcmp(&a.y, &b.y, sizeof(double)) == 0;
}

} // namespace

BOOST_AUTO_TEST_SUITE(narrow_phase)

// Oracle: A4 convention stated in docs/collision.md: n is a unit vector from A into B; for
// axis-aligned layouts the expected normal is the axis from A's side to B's.
BOOST_AUTO_TEST_CASE(normal_points_from_a_into_b, *utf::label("A4")) {
    const Geometry box = to_geometry(make_box(0.5, 0.5));
    const Geometry ball = to_geometry(make_circle(0.5));
    const struct {
        const Geometry& a;
        const Geometry& b;
    } pairs[] = {{box, box}, {box, ball}, {ball, box}, {ball, ball}};
    const Vec2d dirs[] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
    for (const auto& pr : pairs)
        for (const Vec2d d : dirs) {
            const Transform xa = at(2.0, -1.0);
            const Transform xb = at(2.0 + 0.9 * d.x, -1.0 + 0.9 * d.y);
            const Manifold m = collide(pr.a, pr.b, input(xa, xb));
            BOOST_TEST_REQUIRE(m.count >= 1);
            BOOST_TEST(m.normal.x == d.x, tt::tolerance(1e-12));
            BOOST_TEST(m.normal.y == d.y, tt::tolerance(1e-12));
            // Swapping the roles reverses the normal.
            const Manifold r = collide(pr.b, pr.a, input(xb, xa));
            BOOST_TEST(r.normal.x == -d.x, tt::tolerance(1e-12));
            BOOST_TEST(r.normal.y == -d.y, tt::tolerance(1e-12));
        }
}

// Oracle: A4's convention as a property on random penetrating pairs: n separates A then B
// better than -n does (the
// support gap along n exceeds the one along -n), and |n| = 1.
BOOST_AUTO_TEST_CASE(normal_direction_random, *utf::label("A4")) {
    std::mt19937_64 rng(7);
    int checked = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        const Geometry a = oracle::random_shape(rng);
        const Geometry b = oracle::random_shape(rng);
        const Transform xa = oracle::random_transform(rng, 0.6);
        const Transform xb = oracle::random_transform(rng, 0.6);
        const Manifold m = collide(a, b, input(xa, xb, 0.02));
        if (m.count == 0)
            continue;
        ++checked;
        BOOST_TEST(oracle::len(m.normal) == 1.0, tt::tolerance(1e-12));
        BOOST_TEST(support_gap(a, xa, b, xb, m.normal) > support_gap(a, xa, b, xb, -m.normal));
    }
    BOOST_TEST(checked > 1500);
}

// Oracle: T5, model::t5::collided_at: every penetrating contact point lies in both shapes
// grown by half its penetration (it is midway between the two surfaces); shapes that share a
// point (brute-force distance 0) give a contact; shapes farther apart than the margin none.
BOOST_AUTO_TEST_CASE(contact_points_satisfy_t5, *utf::label("T5")) {
    std::mt19937_64 rng(2024);
    int penetrating = 0, separated = 0;
    for (int trial = 0; trial < 4000; ++trial) {
        const Geometry a = oracle::random_shape(rng);
        const Geometry b = oracle::random_shape(rng);
        const Transform xa = oracle::random_transform(rng, 1.0);
        const Transform xb = oracle::random_transform(rng, 1.0);
        const double margin = trial % 2 == 0 ? 0.0 : 0.1;
        const Manifold m = collide(a, b, input(xa, xb, margin));
        const double d = oracle::distance(a, xa, b, xb);
        if (d == 0.0) {
            ++penetrating;
            BOOST_TEST_REQUIRE(m.count >= 1);
            double deepest = INFINITY;
            for (int i = 0; i < m.count; ++i)
                deepest = std::min(deepest, m.points[i].separation);
            BOOST_TEST(deepest <= 1e-12);
        }
        if (d > margin) {
            ++separated;
            BOOST_TEST(m.count == 0);
        }
        for (int i = 0; i < m.count; ++i) {
            const ManifoldPoint& mp = m.points[i];
            BOOST_TEST(mp.separation < margin);
            if (mp.separation < 0.0)
                BOOST_TEST(oracle::collided_at_within(a, xa, b, xb, mp.point,
                                                      0.5 * -mp.separation + 1e-9));
            // Anchors are relative to the centres of mass given in the input.
            BOOST_TEST(mp.anchor_a.x == mp.point.x - xa.p.x, tt::tolerance(1e-12));
            BOOST_TEST(mp.anchor_b.y == mp.point.y - xb.p.y, tt::tolerance(1e-12));
        }
    }
    BOOST_TEST(penetrating > 1000);
    BOOST_TEST(separated > 500);
}

// Oracle: the stated rule of speculative contacts (docs/collision.md): a gap g is reported
// with separation g
// while g < margin, and not at all beyond.
BOOST_AUTO_TEST_CASE(speculative_margin, *utf::label("T5")) {
    const Geometry box = to_geometry(make_box(0.5, 0.5));
    const Geometry ball = to_geometry(make_circle(0.5));
    for (const Geometry* g : {&box, &ball}) {
        const Manifold near = collide(box, *g, input(at(0, 0), at(1.03, 0), 0.05));
        BOOST_TEST_REQUIRE(near.count >= 1);
        BOOST_TEST(near.points[0].separation == 0.03, tt::tolerance(1e-9));
        const Manifold far = collide(box, *g, input(at(0, 0), at(1.06, 0), 0.05));
        BOOST_TEST(far.count == 0);
    }
    // Corner to corner across a diagonal gap: one point, separation the true vertex gap.
    const Manifold corner = collide(box, box, input(at(0, 0), at(1.02, 1.02), 0.05));
    BOOST_TEST_REQUIRE(corner.count == 1);
    BOOST_TEST(corner.points[0].separation == 0.02 * std::sqrt(2.0), tt::tolerance(1e-9));
    BOOST_TEST(corner.normal.x == std::sqrt(0.5), tt::tolerance(1e-12));
    BOOST_TEST(corner.normal.y == std::sqrt(0.5), tt::tolerance(1e-12));
    // The same layout with a gap whose diagonal exceeds the margin: nothing.
    const Manifold none = collide(box, box, input(at(0, 0), at(1.04, 1.04), 0.05));
    BOOST_TEST(none.count == 0);
}

// Oracle: geometry of two aligned unit boxes 0.03 m apart (finding O3): the gap is the face
// separation along x, the faces overlap over y in [-0.5, 0.5], so the speculative manifold has
// two points, at y = -0.5 and 0.5, each 0.03 m apart, normal +x (A4), not a single corner point.
BOOST_AUTO_TEST_CASE(parallel_faces_apart_give_two_points, *utf::label("LC1") * utf::label("T5")) {
    const Geometry box = to_geometry(make_box(0.5, 0.5));
    for (const double dy : {0.0, 0.2}) { // exactly aligned, and offset along the faces
        const Manifold m = collide(box, box, input(at(0, 0), at(1.03, dy), 0.05));
        BOOST_TEST_REQUIRE(m.count == 2);
        BOOST_TEST(m.normal.x == 1.0);
        BOOST_TEST(m.normal.y == 0.0);
        std::set<double> ys;
        for (int i = 0; i < 2; ++i) {
            BOOST_TEST(m.points[i].separation == 0.03, tt::tolerance(1e-9));
            ys.insert(m.points[i].point.y);
        }
        BOOST_TEST(*ys.begin() == -0.5 + dy, tt::tolerance(1e-12));
        BOOST_TEST(*ys.rbegin() == 0.5, tt::tolerance(1e-12));
    }
}

// Oracle: hand geometry of LC1 (edge-to-edge): a box resting face down on a wider box
// touches along a
// segment; the manifold has two points, at its ends, midway through the overlap.
BOOST_AUTO_TEST_CASE(edge_edge_gives_two_points, *utf::label("LC1")) {
    const Geometry ground = to_geometry(make_box(5.0, 0.5));
    const Geometry box = to_geometry(make_box(0.5, 0.25));
    const Manifold m = collide(ground, box, input(at(0, 0), at(1.0, 0.74)));
    BOOST_TEST_REQUIRE(m.count == 2);
    BOOST_TEST(m.normal.x == 0.0);
    BOOST_TEST(m.normal.y == 1.0);
    std::set<double> xs;
    for (int i = 0; i < 2; ++i) {
        BOOST_TEST(m.points[i].separation == -0.01, tt::tolerance(1e-9));
        BOOST_TEST(m.points[i].point.y == 0.495, tt::tolerance(1e-12));
        xs.insert(m.points[i].point.x);
    }
    BOOST_TEST((xs == std::set<double>{0.5, 1.5}));
    BOOST_TEST(m.points[0].id.key() != m.points[1].id.key());
}

// Oracle: hand geometry of LC1 with clipping: a box overhanging the ground's corner touches
// only over the
// overlap [4.5, 5]; the clip point sits at the ground's corner x = 5.
BOOST_AUTO_TEST_CASE(edge_edge_clipped_at_corner, *utf::label("LC1")) {
    const Geometry ground = to_geometry(make_box(5.0, 0.5));
    const Geometry box = to_geometry(make_box(0.5, 0.25));
    const Manifold m = collide(box, ground, input(at(5.0, 0.74), at(0, 0)));
    BOOST_TEST_REQUIRE(m.count == 2);
    BOOST_TEST(m.normal.y == -1.0); // from the box (A) down into the ground (B)
    std::set<double> xs;
    for (int i = 0; i < 2; ++i)
        xs.insert(m.points[i].point.x);
    BOOST_TEST(*xs.begin() == 4.5, tt::tolerance(1e-12));
    BOOST_TEST(*xs.rbegin() == 5.0, tt::tolerance(1e-12));
}

// Oracle: hand geometry of A5 (vertex-to-edge): a box turned 45 degrees pokes one corner
// 0.01 m into a face;
// one point, midway between the corner and the face, separation -0.01, ids vertex-face.
BOOST_AUTO_TEST_CASE(vertex_edge_gives_one_point, *utf::label("A5") * utf::label("LC1")) {
    const Geometry ground = to_geometry(make_box(5.0, 0.5));
    const Geometry box = to_geometry(make_box(0.5, 0.5));
    const double h = 0.5 * std::sqrt(2.0); // centre to corner
    const Transform xb = at(0.3, 0.5 + h - 0.01, std::numbers::pi / 4);
    for (const double margin : {0.0, 0.1}) {
        const Manifold m = collide(ground, box, input(at(0, 0), xb, margin));
        BOOST_TEST_REQUIRE(m.count == 1);
        BOOST_TEST(m.normal.y == 1.0, tt::tolerance(1e-12));
        const ManifoldPoint& p = m.points[0];
        BOOST_TEST(p.separation == -0.01, tt::tolerance(1e-9));
        BOOST_TEST(p.point.x == 0.3, tt::tolerance(1e-9));
        BOOST_TEST(p.point.y == 0.495, tt::tolerance(1e-9));
        BOOST_TEST(p.id.type_a == 1); // ground face
        BOOST_TEST(p.id.type_b == 0); // box vertex
    }
}

// Oracle: symmetry: equal boxes meeting face to face head-on touch symmetrically about the
// line of centres (exactly, so a head-on impulse applies no torque).
BOOST_AUTO_TEST_CASE(head_on_points_symmetric, *utf::label("LC1") * utf::label("A4")) {
    const Geometry box = to_geometry(make_box(0.5, 0.3));
    for (const double y : {0.0, 0.1, 0.3, -12.7, 1234.567}) {
        const Manifold m = collide(box, box, input(at(-3.1, y), at(-2.1 - 0.013, y), 0.05));
        BOOST_TEST_REQUIRE(m.count == 2);
        BOOST_TEST(m.points[0].point.x == m.points[1].point.x);
        BOOST_TEST(m.points[0].point.y - y == -(m.points[1].point.y - y), tt::tolerance(1e-12));
        BOOST_TEST(m.points[0].anchor_a.x == m.points[1].anchor_a.x);
        BOOST_TEST(m.points[0].anchor_a.y == -m.points[1].anchor_a.y);
        BOOST_TEST(m.points[0].anchor_b.y == -m.points[1].anchor_b.y);
        BOOST_TEST(m.points[0].separation == m.points[1].separation);
    }
    // Rotated line of centres: symmetric to round-off.
    const double phi = 0.7;
    const Vec2d u{std::cos(phi), std::sin(phi)};
    const Manifold m =
        collide(box, box, input(at(1, 2, phi), at(1 + 0.99 * u.x, 2 + 0.99 * u.y, phi)));
    BOOST_TEST_REQUIRE(m.count == 2);
    const double c0 = oracle::cross(u, m.points[0].anchor_a);
    const double c1 = oracle::cross(u, m.points[1].anchor_a);
    BOOST_TEST(c0 + c1 == 0.0, tt::tolerance(1e-12));
}

// Oracle: warm-starting contract: feature ids of a resting box do not change under small
// motion and tilt, and the reference face does not flip (normal stays up).
BOOST_AUTO_TEST_CASE(resting_box_ids_stable, *utf::label("internals")) {
    const Geometry box = to_geometry(make_box(0.5, 0.5));
    std::mt19937_64 rng(99);
    std::uniform_real_distribution<double> jitter(-1e-4, 1e-4);
    std::set<std::uint32_t> first;
    for (int step = 0; step < 1000; ++step) {
        // Equal boxes stacked: the two faces' SAT separations tie up to the tilt.
        const Transform xb = at(0.2 + jitter(rng), 1.0 - 0.005 + jitter(rng), jitter(rng));
        const Manifold m = collide(box, box, input(at(0, 0, jitter(rng)), xb, 0.02));
        BOOST_TEST_REQUIRE(m.count == 2);
        BOOST_TEST(m.normal.y > 0.999);
        std::set<std::uint32_t> ids{m.points[0].id.key(), m.points[1].id.key()};
        if (step == 0)
            first = ids;
        BOOST_TEST((ids == first));
    }
}

// Oracle: closed forms for circles: separation |c_b - c_a| - r_a - r_b, point midway between
// the surfaces on the line of centres.
BOOST_AUTO_TEST_CASE(circles_closed_form, *utf::label("T5") * utf::label("A4")) {
    const Circle a = make_circle(1.0, {0.5, 0.0});
    const Circle b = make_circle(0.5);
    const Manifold m = collide_circles(a, b, {at(0, 0), {0, 0}, at(1.5, 1.2), {1.5, 1.2}, 0.1});
    BOOST_TEST_REQUIRE(m.count == 1);
    const double d = std::hypot(1.0, 1.2);
    BOOST_TEST(m.points[0].separation == d - 1.5, tt::tolerance(1e-12));
    BOOST_TEST(m.normal.x == 1.0 / d, tt::tolerance(1e-12));
    const double s = 1.0 + 0.5 * (d - 1.5); // from A's centre along n
    BOOST_TEST(m.points[0].point.x == 0.5 + s / d, tt::tolerance(1e-12));
    BOOST_TEST(m.points[0].point.y == s * 1.2 / d, tt::tolerance(1e-12));
    BOOST_TEST(m.points[0].anchor_b.x == m.points[0].point.x - 1.5, tt::tolerance(1e-12));
}

// Oracle: Voronoi regions of a box: a circle off the box's corner is pushed along the
// corner-to-centre direction; beside a face along the face normal.
BOOST_AUTO_TEST_CASE(polygon_circle_regions, *utf::label("T5") * utf::label("A4")) {
    const Polygon box = make_box(0.5, 0.5);
    const Circle ball = make_circle(0.25);
    const Manifold corner = collide_polygon_circle(box, ball, input(at(0, 0), at(0.6, 0.7)));
    BOOST_TEST_REQUIRE(corner.count == 1);
    const double d = std::hypot(0.1, 0.2);
    BOOST_TEST(corner.normal.x == 0.1 / d, tt::tolerance(1e-12));
    BOOST_TEST(corner.points[0].separation == d - 0.25, tt::tolerance(1e-12));
    const Manifold face = collide_polygon_circle(box, ball, input(at(0, 0), at(0.2, 0.7)));
    BOOST_TEST_REQUIRE(face.count == 1);
    BOOST_TEST(face.normal.y == 1.0);
    BOOST_TEST(face.points[0].separation == -0.05, tt::tolerance(1e-12));
    BOOST_TEST(face.points[0].point.y == 0.475, tt::tolerance(1e-12));
    // Centre inside the box: the nearest face wins.
    const Manifold deep = collide_polygon_circle(box, ball, input(at(0, 0), at(0.1, -0.4)));
    BOOST_TEST_REQUIRE(deep.count == 1);
    BOOST_TEST(deep.normal.y == -1.0);
    BOOST_TEST(deep.points[0].separation == -0.35, tt::tolerance(1e-12));
}

// Oracle: the narrow phase without the hint. A pair moving about randomly (apart, near,
// touching, overlapping) is collided twice per pose, once carrying its SeparationHint from pose
// to pose and once without: the manifolds must be identical, bit for bit, and the hint must have
// skipped the full test for some poses (otherwise this checks nothing).
BOOST_AUTO_TEST_CASE(separation_hint_changes_nothing, *utf::label("internals")) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const Vec2d triangle[] = {{0, 0}, {1, 0}, {0.2, 0.7}};
    const Geometry shapes[] = {to_geometry(make_box(0.5, 0.25)), to_geometry(make_box(0.3, 0.3)),
                               to_geometry(make_polygon(triangle))};
    int hinted_apart = 0, compared = 0;
    for (const Geometry& a : shapes) {
        for (const Geometry& b : shapes) {
            SeparationHint hint;
            Vec2d pb{1.2, 0.0};
            double angle_b = 0.0;
            for (int k = 0; k < 400; ++k) {
                pb = pb + 0.05 * Vec2d{u(rng), u(rng)};
                pb = {std::clamp(pb.x, -1.6, 1.6), std::clamp(pb.y, -1.6, 1.6)};
                angle_b += 0.1 * u(rng);
                const CollideInput in = input(at(0.1, -0.2, 0.3), at(pb.x, pb.y, angle_b), 0.05);
                const bool had_hint = hint.face >= 0;
                const Manifold with = collide(a, b, in, &hint);
                const Manifold without = collide(a, b, in);
                BOOST_TEST_REQUIRE(with.count == without.count);
                BOOST_TEST(same_bits(with.normal, without.normal));
                for (int j = 0; j < with.count; ++j) {
                    const ManifoldPoint& p = with.points[j];
                    const ManifoldPoint& q = without.points[j];
                    BOOST_TEST((same_bits(p.point, q.point) && same_bits(p.anchor_a, q.anchor_a) &&
                                same_bits(p.anchor_b, q.anchor_b) && p.id == q.id &&
                                std::memcmp(&p.separation, &q.separation, sizeof(double)) == 0));
                }
                hinted_apart += had_hint && with.count == 0 && hint.face >= 0;
                ++compared;
            }
        }
    }
    BOOST_TEST(hinted_apart > 100);
    BOOST_TEST_MESSAGE("separation hint: " << hinted_apart << " of " << compared
                                           << " poses rejected by the hinted face");
}

BOOST_AUTO_TEST_SUITE_END()
