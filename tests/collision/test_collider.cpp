// Colliders (the narrow phase's per-shape records) and the separating axis test they feed (T5,
// LC1).
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <cstring>
#include <random>

#include "oracles.hpp"
#include "tamias2d/collision/collider.hpp"
#include "tamias2d/collision/narrow_phase.hpp"
#include "tamias2d/geometry/shape_aabb.hpp"

namespace utf = boost::unit_test;
namespace tt = boost::test_tools;
using namespace tamias2d;

namespace {

bool same_bits(double a, double b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

bool same_bits(const Manifold& a, const Manifold& b) {
    auto vec = [](Vec2d u, Vec2d v) { return same_bits(u.x, v.x) && same_bits(u.y, v.y); };
    if (a.count != b.count || !vec(a.normal, b.normal))
        return false;
    for (int j = 0; j < 2; ++j) {
        const ManifoldPoint& p = a.points[j];
        const ManifoldPoint& q = b.points[j];
        if (!vec(p.point, q.point) || !vec(p.anchor_a, q.anchor_a) ||
            !vec(p.anchor_b, q.anchor_b) || !same_bits(p.separation, q.separation) ||
            !(p.id == q.id))
            return false;
    }
    return true;
}

/// A random convex polygon from the oracle's shapes (boxes and hulls, no circles).
Geometry random_polygon(std::mt19937_64& rng) {
    for (;;) {
        Geometry g = oracle::random_shape(rng);
        if (g.type == ShapeType::polygon)
            return g;
    }
}

/// Plain separating axis test in the world frame: for every face of either polygon, the least
/// signed distance of the other polygon's vertices from the face's line; the largest of these.
struct Sat {
    double best = -INFINITY;
    std::vector<std::pair<Vec2d, double>> faces; ///< outward world normal from A into B, separation
};

Sat plain_sat(const Geometry& a, const Transform& xa, const Geometry& b, const Transform& xb) {
    const std::vector<Vec2d> A = oracle::world_vertices(a.polygon, xa);
    const std::vector<Vec2d> B = oracle::world_vertices(b.polygon, xb);
    Sat sat;
    auto faces_of = [&](const std::vector<Vec2d>& ref, const std::vector<Vec2d>& other,
                        double sign) {
        for (std::size_t i = 0; i < ref.size(); ++i) {
            const Vec2d p = ref[i], q = ref[(i + 1) % ref.size()];
            const double l = oracle::len({q.x - p.x, q.y - p.y});
            const Vec2d n{(q.y - p.y) / l, -(q.x - p.x) / l}; // CCW polygon: edge turned clockwise
            double s = INFINITY;
            for (const Vec2d& v : other)
                s = std::min(s, oracle::dotp(n, {v.x - p.x, v.y - p.y}));
            sat.faces.push_back({{sign * n.x, sign * n.y}, s});
            sat.best = std::max(sat.best, s);
        }
    };
    faces_of(A, B, 1.0);
    faces_of(B, A, -1.0);
    return sat;
}

/// Largest vertex distance from the centroid, vertex by vertex.
double plain_radius(const Polygon& p) {
    double r = 0.0;
    for (int i = 0; i < p.count; ++i)
        r = std::max(r,
                     oracle::len({p.vertices[i].x - p.centroid.x, p.vertices[i].y - p.centroid.y}));
    return r;
}

} // namespace

BOOST_AUTO_TEST_SUITE(collider)

// Oracle: the polygon itself (its vertex and normal arrays, bit for bit), the closed form
// sqrt(hx^2 + hy^2) for a centred box's radius, and the vertex-by-vertex largest distance
// from the centroid for hulls.
BOOST_AUTO_TEST_CASE(collider_keeps_the_polygon, *utf::label("T5")) {
    const Collider box = make_collider(make_box(0.3, 0.4));
    BOOST_TEST((box.type == ShapeType::polygon));
    BOOST_TEST(box.count == 4);
    BOOST_TEST(box.radius == 0.5, tt::tolerance(1e-15));

    std::mt19937_64 rng(11);
    for (int trial = 0; trial < 200; ++trial) {
        const Polygon p = random_polygon(rng).polygon;
        const Collider k = make_collider(p);
        BOOST_TEST_REQUIRE(k.count == p.count);
        BOOST_TEST(same_bits(k.center.x, p.centroid.x));
        BOOST_TEST(same_bits(k.center.y, p.centroid.y));
        BOOST_TEST(k.radius == plain_radius(p), tt::tolerance(1e-14));
        for (int i = 0; i < max_polygon_vertices; ++i) {
            const int from = i < p.count ? i : 0; // lanes past the count repeat vertex 0
            BOOST_TEST(same_bits(k.vertex(i).x, p.vertices[from].x));
            BOOST_TEST(same_bits(k.vertex(i).y, p.vertices[from].y));
            BOOST_TEST(same_bits(k.normal(i).x, p.normals[from].x));
            BOOST_TEST(same_bits(k.normal(i).y, p.normals[from].y));
        }
    }
    const Collider ball = make_collider(make_circle(0.7, {0.1, -0.2}));
    BOOST_TEST((ball.type == ShapeType::circle));
    BOOST_TEST(ball.radius == 0.7);
    BOOST_TEST(ball.center.x == 0.1);
    BOOST_TEST(ball.center.y == -0.2);
}

// Oracle: a plain separating axis test written in the test (world frame, every face against
// every vertex, no early exit). Polygons that the best axis separates by the margin or more
// give no contact; a two-point (face) contact's normal is the normal of a face whose separation
// is within the reference-face hysteresis (1e-3 of the smaller polygon's radius) of the best.
BOOST_AUTO_TEST_CASE(reference_face_is_a_best_separating_axis,
                     *utf::label("T5") * utf::label("LC1")) {
    std::mt19937_64 rng(31);
    int apart = 0, faces = 0;
    for (int trial = 0; trial < 6000; ++trial) {
        const Geometry a = random_polygon(rng);
        const Geometry b = trial % 3 == 0 ? a : random_polygon(rng);
        const Transform xa = oracle::random_transform(rng, 0.7);
        const Transform xb = oracle::random_transform(rng, 0.7);
        const double margin = trial % 2 == 0 ? 0.0 : 0.05;
        const Manifold m = collide(a, b, {xa, xa.p, xb, xb.p, margin});
        const Sat sat = plain_sat(a, xa, b, xb);
        if (sat.best >= margin + 1e-9) {
            ++apart;
            BOOST_TEST(m.count == 0);
        }
        if (m.count != 2)
            continue;
        ++faces;
        const double tol = 1e-3 * std::min(plain_radius(a.polygon), plain_radius(b.polygon));
        double chosen = -INFINITY;
        for (const auto& [n, s] : sat.faces) {
            if (std::abs(n.x - m.normal.x) < 1e-9 && std::abs(n.y - m.normal.y) < 1e-9)
                chosen = std::max(chosen, s);
        }
        BOOST_TEST(chosen >= sat.best - tol - 1e-9);
    }
    BOOST_TEST(apart > 500);
    BOOST_TEST(faces > 500);
}

// Oracle: a new manifold (the by-value form, zero-initialised). A contact's manifold is updated
// in place from whatever it held: one manifold reused across random pairs of circles and
// polygons, poses and margins must come out bit for bit as a new one each time, including the
// slots past its count.
BOOST_AUTO_TEST_CASE(in_place_update_matches_a_new_manifold, *utf::label("internals")) {
    std::mt19937_64 rng(47);
    Manifold reused;
    int with_points = 0, shrunk = 0;
    for (int trial = 0; trial < 5000; ++trial) {
        const Geometry a = oracle::random_shape(rng);
        const Geometry b = oracle::random_shape(rng);
        const Transform xa = oracle::random_transform(rng, 0.6);
        const Transform xb = oracle::random_transform(rng, 0.6);
        const CollideInput in{xa, xa.p, xb, {xb.p.x + 0.1, xb.p.y}, trial % 2 == 0 ? 0.0 : 0.05};
        const int before = reused.count;
        collide(make_collider(a), make_collider(b), in, reused);
        const Manifold fresh = collide(a, b, in);
        BOOST_TEST(same_bits(reused, fresh));
        with_points += fresh.count > 0;
        shrunk += fresh.count < before;
    }
    BOOST_TEST(with_points > 1000);
    BOOST_TEST(shrunk > 500);
}

// Oracle: compute_aabb of the geometry the collider was made from (the definition of the tight
// box, IM4's rectangle): the collider's box must be the same bits, for circles and polygons in
// random poses, since the broad phase now reads it instead.
BOOST_AUTO_TEST_CASE(collider_box_is_the_geometry_box, *utf::label("IM4") * utf::label("T5")) {
    std::mt19937_64 rng(31);
    for (int i = 0; i < 20000; ++i) {
        const Geometry g = oracle::random_shape(rng);
        const Transform xf = oracle::random_transform(rng, 1000.0);
        const Aabb want = compute_aabb(g, xf);
        const Aabb got = compute_aabb(make_collider(g), xf);
        BOOST_TEST_REQUIRE((same_bits(got.min_x, want.min_x) && same_bits(got.min_y, want.min_y) &&
                            same_bits(got.max_x, want.max_x) && same_bits(got.max_y, want.max_y)));
    }
}

// Oracle: the geometry's own world box (compute_aabb on the Geometry, vertex by vertex) and
// the containment of IM4's boxes. The header-only bound may say "not sure" but never "inside"
// wrongly: boxes around the tight one, each side moved by up to 2 % of the size either way
// (exactly tight included), at random poses up to 1000 m out.
BOOST_AUTO_TEST_CASE(surely_inside_never_errs, *utf::label("IM4")) {
    std::mt19937_64 rng(47);
    std::uniform_real_distribution<double> shift(-0.02, 0.02);
    int claimed = 0;
    for (int i = 0; i < 40000; ++i) {
        const Geometry g = oracle::random_shape(rng);
        const Transform xf = oracle::random_transform(rng, 1000.0);
        const Aabb tight = compute_aabb(g, xf);
        const double size = std::max(tight.max_x - tight.min_x, tight.max_y - tight.min_y);
        Aabb box = tight;
        if (i % 4 != 0) { // every fourth: exactly tight
            box.min_x += size * shift(rng);
            box.min_y += size * shift(rng);
            box.max_x += size * shift(rng);
            box.max_y += size * shift(rng);
        }
        const bool sure = surely_inside(make_collider(g), xf, box);
        claimed += sure ? 1 : 0;
        BOOST_TEST_REQUIRE((!sure || contains(box, tight)));
    }
    BOOST_TEST(claimed > 0);
}

// Oracle: the bound's construction: an unrotated box's bound is the box itself (plus a slack
// of 1e-9 of the coordinates), so a fat box 0.1 m wider on each side, the broad phase's margin,
// is decided without the vertices at 1000 m out.
BOOST_AUTO_TEST_CASE(surely_inside_decides_the_resting_case, *utf::label("internals")) {
    const Collider box = make_collider(make_box(0.25, 0.25));
    for (const double x : {0.0, 1.5, -999.0, 1000.0}) {
        const Transform xf{{x, 0.25}, Rot::from_angle(0.0)};
        BOOST_TEST(surely_inside(box, xf, inflated(compute_aabb(box, xf), 0.1)));
        BOOST_TEST(!surely_inside(box, xf, inflated(compute_aabb(box, xf), -0.01)));
    }
}

BOOST_AUTO_TEST_SUITE_END()
