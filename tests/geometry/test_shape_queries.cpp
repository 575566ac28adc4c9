// Queries on placed shapes: bounding boxes (IM4's rectangles), point containment (T5's
// "p in A") and ray casts.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "tamias2d/geometry/shape_aabb.hpp"
#include "tamias2d/geometry/shape_factory.hpp"
#include "tamias2d/geometry/shape_queries.hpp"
#include "tamias2d/model/t5_collision_detection.hpp"

namespace utf = boost::unit_test;
namespace tt = boost::test_tools;
using namespace tamias2d;
namespace t5 = tamias2d::model::t5;
using tamias2d::units::Length;

namespace {

Vec2d placed(const Transform& xf, Vec2d v) {
    return {xf.q.c * v.x - xf.q.s * v.y + xf.p.x, xf.q.s * v.x + xf.q.c * v.y + xf.p.y};
}

std::vector<units::Vec2<Length>> world_polygon(const Polygon& p, const Transform& xf) {
    std::vector<units::Vec2<Length>> out;
    for (int i = 0; i < p.count; ++i) {
        const Vec2d w = placed(xf, p.vertices[i]);
        out.push_back(units::vec_from_values<Length>(w.x, w.y));
    }
    return out;
}

} // namespace

BOOST_AUTO_TEST_SUITE(shape_queries)

// Oracle: the definition of the tight box: the box of a placed polygon is the min/max of its placed
// vertices; of a circle, centre +- radius.
BOOST_AUTO_TEST_CASE(aabb_encloses_tightly, *utf::label("IM4")) {
    const Polygon tri = make_polygon(std::vector<Vec2d>{{0, 0}, {2, 0}, {0, 1}});
    const Transform xf{{1.0, -1.0}, Rot::from_angle(std::numbers::pi / 2)};
    const Aabb b = compute_aabb(to_geometry(tri), xf);
    // Rotated by 90 degrees: (0,0)->(1,-1), (2,0)->(1,1), (0,1)->(0,-1).
    BOOST_TEST(b.min_x == 0.0, tt::tolerance(1e-15));
    BOOST_TEST(b.max_x == 1.0, tt::tolerance(1e-15));
    BOOST_TEST(b.min_y == -1.0, tt::tolerance(1e-15));
    BOOST_TEST(b.max_y == 1.0, tt::tolerance(1e-15));
    const Aabb c = compute_aabb(to_geometry(make_circle(0.5, {1.0, 0.0})), xf);
    BOOST_TEST(c.min_x == 0.5, tt::tolerance(1e-15));
    BOOST_TEST(c.max_y == 0.5, tt::tolerance(1e-15)); // centre (1, 0) -> (1, 0)
}

// Oracle: T5's containment predicates (model::t5::contains, the cross-product form) on random
// points, for a quadrilateral and for an octagon (the most vertices a polygon holds) whose
// centroid lies off its body's origin.
BOOST_AUTO_TEST_CASE(test_point_matches_t5, *utf::label("T5")) {
    std::mt19937_64 rng(31);
    std::uniform_real_distribution<double> u(-2.0, 2.0);
    std::vector<Vec2d> octagon;
    for (int i = 0; i < max_polygon_vertices; ++i) {
        const double a = 2.0 * std::numbers::pi * i / max_polygon_vertices;
        octagon.push_back({0.6 + 0.9 * std::cos(a), -0.4 + 0.9 * std::sin(a)});
    }
    const Polygon polys[] = {
        make_polygon(std::vector<Vec2d>{{-1, -0.5}, {1, -0.7}, {1.2, 0.4}, {0, 1}}),
        make_polygon(octagon)};
    BOOST_TEST_REQUIRE(polys[1].count == max_polygon_vertices);
    const Circle circ = make_circle(0.8, {0.3, -0.2});
    for (const Polygon& poly : polys) {
        int inside = 0;
        for (int k = 0; k < 5000; ++k) {
            const Transform xf{{u(rng) * 0.2, u(rng) * 0.2}, Rot::from_angle(u(rng))};
            const Vec2d p{u(rng), u(rng)};
            const auto wp = world_polygon(poly, xf);
            const bool in_poly =
                t5::contains(t5::ConvexPolygon(wp), units::vec_from_values<Length>(p.x, p.y));
            BOOST_TEST(test_point(to_geometry(poly), xf, p) == in_poly);
            const Vec2d c = placed(xf, circ.center);
            const t5::Disc disc{units::vec_from_values<Length>(c.x, c.y), Length::from_value(0.8)};
            BOOST_TEST(test_point(to_geometry(circ), xf, p) ==
                       t5::contains(disc, units::vec_from_values<Length>(p.x, p.y)));
            inside += in_poly;
        }
        BOOST_TEST(inside > 500);
    }
}

// Oracle: closed forms: a ray along x hits the unit box's face x = -0.5 at fraction
// (x0 - (-0.5)) / |d|... and a circle at the near root of |o + t d - c| = r.
BOOST_AUTO_TEST_CASE(ray_cast_closed_forms, *utf::label("T5")) {
    const Geometry box = to_geometry(make_box(0.5, 0.5));
    const Transform id{};
    const auto h = ray_cast(box, id, {-2.0, 0.1}, {4.0, 0.0});
    BOOST_TEST_REQUIRE(h.has_value());
    BOOST_TEST(h->fraction == 1.5 / 4.0, tt::tolerance(1e-15));
    BOOST_TEST(h->point.x == -0.5, tt::tolerance(1e-15));
    BOOST_TEST(h->normal.x == -1.0);
    BOOST_TEST(!ray_cast(box, id, {-2.0, 0.1}, {1.0, 0.0}).has_value()); // too short
    BOOST_TEST(!ray_cast(box, id, {0.0, 0.0}, {4.0, 0.0}).has_value());  // starts inside
    BOOST_TEST(!ray_cast(box, id, {-2.0, 0.6}, {4.0, 0.0}).has_value()); // misses
    const Geometry ball = to_geometry(make_circle(1.0));
    const Transform xf{{3.0, 4.0}, Rot::from_angle(0.3)};
    const auto c = ray_cast(ball, xf, {0.0, 0.0}, {6.0, 8.0});
    BOOST_TEST_REQUIRE(c.has_value());
    BOOST_TEST(c->fraction == 4.0 / 10.0, tt::tolerance(1e-14));
    BOOST_TEST(c->normal.x == -0.6, tt::tolerance(1e-14));
    BOOST_TEST(c->normal.y == -0.8, tt::tolerance(1e-14));
}

// Oracle: closed forms for a capsule (core x in [-1, 1], radius 0.5), placed turned and moved:
// a ray straight down onto its side enters at 0.5 above the core; one along its axis at the end
// disc's tip; one 0.3 off the axis on the end disc where x = 1 + sqrt(0.25 - 0.09) = 1.4, with
// the normal (0.8, 0.6); containment is distance to the core at most the radius. A segment is
// hit from either side, a chain edge only from its collision side (its right, DD31); neither
// contains a point.
BOOST_AUTO_TEST_CASE(capsule_segment_and_chain_queries, *utf::label("T5") * utf::label("DD31")) {
    const Geometry cap = to_geometry(make_capsule({-1.0, 0.0}, {1.0, 0.0}, 0.5));
    const Transform xf{{2.0, -1.0}, Rot::from_angle(0.7)};
    const Rot q = xf.q;
    auto world = [&](Vec2d v) { return placed(xf, v); };
    auto dir = [&](Vec2d v) { return Vec2d{q.c * v.x - q.s * v.y, q.s * v.x + q.c * v.y}; };
    const auto side = ray_cast(cap, xf, world({0.2, 3.0}), dir({0.0, -4.0}));
    BOOST_TEST_REQUIRE(side.has_value());
    BOOST_TEST(side->fraction == 2.5 / 4.0, tt::tolerance(1e-13));
    BOOST_TEST(side->normal.x == dir({0.0, 1.0}).x, tt::tolerance(1e-13));
    const auto tip = ray_cast(cap, xf, world({3.0, 0.0}), dir({-4.0, 0.0}));
    BOOST_TEST_REQUIRE(tip.has_value());
    BOOST_TEST(tip->fraction == 1.5 / 4.0, tt::tolerance(1e-13));
    const auto off = ray_cast(cap, xf, world({3.0, 0.3}), dir({-4.0, 0.0}));
    BOOST_TEST_REQUIRE(off.has_value());
    BOOST_TEST(off->fraction == 1.6 / 4.0, tt::tolerance(1e-13));
    BOOST_TEST(off->normal.x == dir({0.8, 0.6}).x, tt::tolerance(1e-12));
    BOOST_TEST(off->normal.y == dir({0.8, 0.6}).y, tt::tolerance(1e-12));
    BOOST_TEST(!ray_cast(cap, xf, world({0.0, 0.2}), dir({0.0, 4.0})).has_value());  // inside
    BOOST_TEST(!ray_cast(cap, xf, world({3.0, 0.6}), dir({-6.0, 0.0})).has_value()); // misses
    BOOST_TEST(test_point(cap, xf, world({1.3, 0.3})));   // 0.42 from the core's end
    BOOST_TEST(!test_point(cap, xf, world({1.4, 0.4})));  // 0.57 from it
    BOOST_TEST(test_point(cap, xf, world({-0.7, -0.5}))); // on the side

    const Geometry seg = to_geometry(make_segment({-1.0, 0.0}, {1.0, 0.0}));
    for (const double from : {2.0, -2.0}) {
        const auto h = ray_cast(seg, Transform{}, {0.5, from}, {0.0, -2.0 * from});
        BOOST_TEST_REQUIRE(h.has_value());
        BOOST_TEST(h->fraction == 0.5);
        BOOST_TEST(h->normal.y == (from > 0.0 ? 1.0 : -1.0));
    }
    const Geometry edge =
        to_geometry(ChainSegment{{2.0, 0.0}, {1.0, 0.0}, {-1.0, 0.0}, {-2.0, 0.0}});
    const auto above = ray_cast(edge, Transform{}, {0.5, 2.0}, {0.0, -4.0});
    BOOST_TEST_REQUIRE(above.has_value());
    BOOST_TEST(above->normal.y == 1.0);
    BOOST_TEST(!ray_cast(edge, Transform{}, {0.5, -2.0}, {0.0, 4.0}).has_value()); // from behind
    BOOST_TEST(!test_point(seg, Transform{}, {0.0, 0.0}));
    BOOST_TEST(!test_point(edge, Transform{}, {0.0, 0.0}));
}

// Oracle: T5 containment along the ray: random rays that hit end on the boundary (just
// inside after, just outside before), and rays that miss never pass through the shape.
BOOST_AUTO_TEST_CASE(ray_cast_random_consistent, *utf::label("T5")) {
    std::mt19937_64 rng(37);
    std::uniform_real_distribution<double> u(-3.0, 3.0);
    const Geometry shapes[] = {
        to_geometry(make_polygon(std::vector<Vec2d>{{-1, -0.5}, {1, -0.7}, {1.2, 0.4}, {0, 1}})),
        to_geometry(make_circle(0.9, {0.2, 0.1}))};
    int hits = 0;
    for (int k = 0; k < 4000; ++k) {
        const Geometry& g = shapes[k % 2];
        const Transform xf{{u(rng) * 0.1, u(rng) * 0.1}, Rot::from_angle(u(rng))};
        const Vec2d o{u(rng), u(rng)};
        const Vec2d d{2 * u(rng), 2 * u(rng)};
        if (test_point(g, xf, o))
            continue; // starts inside: no hit by contract
        const auto h = ray_cast(g, xf, o, d);
        if (h) {
            ++hits;
            BOOST_TEST(h->fraction >= 0.0);
            BOOST_TEST(h->fraction <= 1.0);
            BOOST_TEST(std::hypot(h->normal.x, h->normal.y) == 1.0, tt::tolerance(1e-12));
            const double e = 1e-7;
            BOOST_TEST(test_point(g, xf, h->point + e * h->normal) == false);
            BOOST_TEST(test_point(g, xf, h->point - e * h->normal) == true);
            // The ray enters: it moves against the outward normal.
            BOOST_TEST(h->normal.x * d.x + h->normal.y * d.y < 0.0);
        } else {
            for (int s = 0; s <= 200; ++s)
                BOOST_TEST(!test_point(g, xf, o + (s / 200.0) * d));
        }
    }
    BOOST_TEST(hits > 500);
}

BOOST_AUTO_TEST_SUITE_END()
