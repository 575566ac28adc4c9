// Shape construction: boxes, circles, convex hulls, and the rejection of degenerate shapes
// with the offending field named (DCX_shape, DCX_finite).
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "tamias2d/errors.hpp"
#include "tamias2d/geometry/mass_properties.hpp"
#include "tamias2d/geometry/shape_factory.hpp"

namespace utf = boost::unit_test;
namespace tt = boost::test_tools;
using namespace tamias2d;

namespace {

double cross2(Vec2d a, Vec2d b) {
    return a.x * b.y - a.y * b.x;
}

/// Runs f, expecting a ValidationError on `field` for `constraint`; returns its what().
template <class F>
std::string expect_rejected(F f, const std::string& field, const std::string& constraint) {
    try {
        f();
    } catch (const ValidationError& e) {
        BOOST_TEST(e.field == field);
        BOOST_TEST(e.constraint == constraint);
        return e.what();
    }
    BOOST_ERROR("accepted, expected rejection of " + field);
    return {};
}

/// Brute-force extreme points: p is a hull vertex iff it lies in no closed triangle of three
/// other points (O(n^4); exact for points in general position).
std::vector<Vec2d> brute_force_extreme(const std::vector<Vec2d>& pts) {
    std::vector<Vec2d> out;
    const std::size_t n = pts.size();
    for (std::size_t p = 0; p < n; ++p) {
        bool inside = false;
        for (std::size_t i = 0; i < n && !inside; ++i)
            for (std::size_t j = i + 1; j < n && !inside; ++j)
                for (std::size_t k = j + 1; k < n && !inside; ++k) {
                    if (p == i || p == j || p == k)
                        continue;
                    const double d1 = cross2(pts[j] - pts[i], pts[p] - pts[i]);
                    const double d2 = cross2(pts[k] - pts[j], pts[p] - pts[j]);
                    const double d3 = cross2(pts[i] - pts[k], pts[p] - pts[k]);
                    const bool neg = d1 < 0 || d2 < 0 || d3 < 0;
                    const bool pos = d1 > 0 || d2 > 0 || d3 > 0;
                    inside = !(neg && pos);
                }
        if (!inside)
            out.push_back(pts[p]);
    }
    return out;
}

bool same_point(Vec2d a, Vec2d b) {
    return a.x == b.x && a.y == b.y;
}

} // namespace

BOOST_AUTO_TEST_SUITE(shape_factory)

// Oracle: the definition of a box: corners at centre +- half extents, CCW, outward normals.
BOOST_AUTO_TEST_CASE(box_is_exact, *utf::label("DCX_shape")) {
    const Polygon p = make_box(2.0, 1.0, {1.0, 1.0});
    BOOST_TEST(p.count == 4);
    const Vec2d expected[4] = {{-1.0, 0.0}, {3.0, 0.0}, {3.0, 2.0}, {-1.0, 2.0}};
    const Vec2d normals[4] = {{0.0, -1.0}, {1.0, 0.0}, {0.0, 1.0}, {-1.0, 0.0}};
    for (int i = 0; i < 4; ++i) {
        BOOST_TEST(same_point(p.vertices[i], expected[i]));
        BOOST_TEST(same_point(p.normals[i], normals[i]));
    }
    BOOST_TEST(same_point(p.centroid, Vec2d{1.0, 1.0}));
    BOOST_CHECK_NO_THROW(validate(p));
}

// Oracle: SRS data constraints: sizes > 0 and finite; the error names field and constraint.
BOOST_AUTO_TEST_CASE(degenerate_sizes_rejected, *utf::label("DCX_shape")) {
    const std::string msg =
        expect_rejected([] { (void)make_circle(-1.0); }, "shape.radius", "DCX_shape");
    BOOST_TEST(msg == "shape.radius = -1: must be > 0 (DCX_shape)");
    expect_rejected([] { (void)make_circle(0.0); }, "shape.radius", "DCX_shape");
    expect_rejected([] { (void)make_box(0.0, 1.0); }, "shape.half_width", "DCX_shape");
    expect_rejected([] { (void)make_box(1.0, -3.0); }, "shape.half_height", "DCX_shape");
    Circle c{{0.0, 0.0}, -0.5};
    expect_rejected([&] { validate(c); }, "shape.radius", "DCX_shape");
}

// Oracle: SRS data constraints: no NaN or infinity enters the world.
BOOST_AUTO_TEST_CASE(non_finite_rejected, *utf::label("DCX_finite")) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    expect_rejected([&] { (void)make_circle(nan); }, "shape.radius", "DCX_finite");
    expect_rejected([&] { (void)make_circle(inf); }, "shape.radius", "DCX_finite");
    expect_rejected([&] { (void)make_circle(1.0, {nan, 0.0}); }, "shape.center.x", "DCX_finite");
    expect_rejected([&] { (void)make_box(1.0, 1.0, {}, inf); }, "shape.angle", "DCX_finite");
    const std::vector<Vec2d> pts{{0.0, 0.0}, {1.0, 0.0}, {1.0, inf}};
    const std::string msg =
        expect_rejected([&] { (void)make_polygon(pts); }, "polygon.points[2].y", "DCX_finite");
    BOOST_TEST(msg == "polygon.points[2].y = inf: must be finite (DCX_finite)");
}

// Oracle: the definition of a convex hull (DCX_shape): three non-collinear points, some area,
// and at most 8 vertices.
BOOST_AUTO_TEST_CASE(degenerate_polygons_rejected, *utf::label("DCX_shape")) {
    const std::vector<Vec2d> two{{0.0, 0.0}, {1.0, 0.0}};
    expect_rejected([&] { (void)make_polygon(two); }, "polygon.points.size", "DCX_shape");
    const std::vector<Vec2d> same{{1.0, 1.0}, {1.0, 1.0}, {1.0, 1.0}};
    expect_rejected([&] { (void)make_polygon(same); }, "polygon.extent", "DCX_shape");
    const std::vector<Vec2d> line{{0.0, 0.0}, {1.0, 1.0}, {2.0, 2.0}, {0.5, 0.5}};
    expect_rejected([&] { (void)make_polygon(line); }, "polygon.hull_count", "DCX_shape");
    // A sliver 1e-8 m thick over 1 m: below the welding tolerance, so no area.
    const std::vector<Vec2d> sliver{{0.0, 0.0}, {1.0, 0.0}, {0.5, 1e-8}};
    expect_rejected([&] { (void)make_polygon(sliver); }, "polygon.area", "DCX_shape");
    std::vector<Vec2d> nonagon;
    for (int i = 0; i < 9; ++i)
        nonagon.push_back(
            {std::cos(i * 2.0 * std::numbers::pi / 9), std::sin(i * 2.0 * std::numbers::pi / 9)});
    const std::string msg =
        expect_rejected([&] { (void)make_polygon(nonagon); }, "polygon.hull_count", "DCX_shape");
    BOOST_TEST(msg == "polygon.hull_count = 9: must be <= 8 (DCX_shape)");
    Polygon clockwise = make_box(1.0, 1.0);
    std::reverse(clockwise.vertices.begin(), clockwise.vertices.begin() + 4);
    BOOST_CHECK_THROW(validate(clockwise), ValidationError);
}

// Oracle: the definition of the hull: duplicates and points on edges add no vertex.
BOOST_AUTO_TEST_CASE(duplicates_and_collinear_removed, *utf::label("DCX_shape")) {
    const std::vector<Vec2d> pts{{0.0, 0.0}, {1.0, 0.0}, {2.0, 0.0},  {2.0, 0.0},
                                 {2.0, 1.0}, {2.0, 2.0}, {1.0, 2.0},  {0.0, 2.0},
                                 {0.0, 1.0}, {1.0, 1.0}, {0.0, 1e-9}, {2.0 + 1e-9, 2.0}};
    const Polygon p = make_polygon(pts);
    BOOST_TEST(p.count == 4);
    BOOST_TEST(area(p) == 4.0, tt::tolerance(1e-8));
    BOOST_CHECK_NO_THROW(validate(p));
}

// Oracle: brute-force hull (a point is a vertex iff it is in no triangle of other points);
// every input point lies inside the hull.
BOOST_AUTO_TEST_CASE(random_clouds_vs_brute_force, *utf::label("DCX_shape")) {
    std::mt19937_64 rng(20240611);
    std::uniform_real_distribution<double> u(-3.0, 3.0);
    std::uniform_int_distribution<int> count(3, 14);
    int built = 0, too_many = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        std::vector<Vec2d> pts(static_cast<std::size_t>(count(rng)));
        for (Vec2d& v : pts)
            v = {u(rng), u(rng)};
        const std::vector<Vec2d> extreme = brute_force_extreme(pts);
        if (extreme.size() > std::size_t(max_polygon_vertices)) {
            BOOST_CHECK_THROW((void)make_polygon(pts), ValidationError);
            ++too_many;
            continue;
        }
        const Polygon p = make_polygon(pts);
        ++built;
        BOOST_TEST_REQUIRE(std::size_t(p.count) == extreme.size());
        for (int i = 0; i < p.count; ++i) {
            const bool found = std::any_of(extreme.begin(), extreme.end(),
                                           [&](Vec2d e) { return same_point(e, p.vertices[i]); });
            BOOST_TEST(found);
        }
        for (const Vec2d& q : pts)
            for (int i = 0; i < p.count; ++i)
                BOOST_TEST(cross2(p.vertices[(i + 1) % p.count] - p.vertices[i],
                                  q - p.vertices[i]) >= -1e-12);
        BOOST_CHECK_NO_THROW(validate(p));
        const MassData d = compute_mass(p, 1.0);
        BOOST_TEST(p.centroid.x == d.center.x);
        BOOST_TEST(p.centroid.y == d.center.y);
    }
    BOOST_TEST(built > 1000);
    BOOST_TEST(too_many > 0);
}

BOOST_AUTO_TEST_SUITE_END()
