// Mass properties (DD1 centre of mass, DD14 moment of inertia) of boxes, discs, triangles and
// a compound L-shape, against textbook closed forms.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <numbers>
#include <vector>

#include "tamias2d/errors.hpp"
#include "tamias2d/geometry/mass_properties.hpp"
#include "tamias2d/geometry/shape_factory.hpp"

namespace utf = boost::unit_test;
namespace tt = boost::test_tools;
using namespace tamias2d;

BOOST_AUTO_TEST_SUITE(mass_properties)

// Oracle: textbook rectangle, m = rho w h (its area w h, DCX_shape's, times the density),
// I = m (w^2 + h^2) / 12 about the centroid.
BOOST_AUTO_TEST_CASE(box_matches_closed_form,
                     *utf::label("DD14") * utf::label("DD1") * utf::label("DCX_shape")) {
    const double rho = 3.0, w = 2.0, h = 1.0;
    const MassData d = compute_mass(make_box(w / 2, h / 2), rho);
    const double m = rho * w * h;
    BOOST_TEST(d.mass == m, tt::tolerance(1e-15));
    BOOST_TEST(d.inertia == m * (w * w + h * h) / 12.0, tt::tolerance(1e-14));
    BOOST_TEST(std::abs(d.center.x) < 1e-15);
    BOOST_TEST(std::abs(d.center.y) < 1e-15);
}

// Oracle: the same textbook rectangle; rotation and offset do not change I about the centre.
BOOST_AUTO_TEST_CASE(rotated_offset_box, *utf::label("DD14") * utf::label("DD1")) {
    const double rho = 0.5, w = 4.0, h = 0.5;
    const Vec2d c{10.0, -7.0};
    const MassData d = compute_mass(make_box(w / 2, h / 2, c, 0.7), rho);
    const double m = rho * w * h;
    BOOST_TEST(d.mass == m, tt::tolerance(1e-13));
    BOOST_TEST(d.inertia == m * (w * w + h * h) / 12.0, tt::tolerance(1e-12));
    BOOST_TEST(d.center.x == c.x, tt::tolerance(1e-13));
    BOOST_TEST(d.center.y == c.y, tt::tolerance(1e-13));
}

// Oracle: textbook disc, m = rho pi r^2, I = m r^2 / 2.
BOOST_AUTO_TEST_CASE(disc_matches_closed_form, *utf::label("DD14")) {
    const double rho = 1.5, r = 2.0;
    const MassData d = compute_mass(make_circle(r, {1.0, 2.0}), rho);
    const double m = rho * std::numbers::pi * r * r;
    BOOST_TEST(d.mass == m, tt::tolerance(1e-15));
    BOOST_TEST(d.inertia == m * r * r / 2.0, tt::tolerance(1e-15));
    BOOST_TEST(d.center.x == 1.0);
    BOOST_TEST(d.center.y == 2.0);
}

// Oracle: right triangle with legs a, b: centroid at (a/3, b/3), area ab/2 (DCX_shape's, so
// m = rho ab/2), polar moment about the centroid m (a^2 + b^2) / 18 (textbook table of area
// moments).
BOOST_AUTO_TEST_CASE(right_triangle,
                     *utf::label("DD14") * utf::label("DD1") * utf::label("DCX_shape")) {
    const double a = 3.0, b = 2.0, rho = 2.0;
    const std::vector<Vec2d> pts{{0.0, 0.0}, {a, 0.0}, {0.0, b}};
    const Polygon t = make_polygon(pts);
    const MassData d = compute_mass(t, rho);
    const double m = rho * a * b / 2.0;
    BOOST_TEST(d.mass == m, tt::tolerance(1e-15));
    BOOST_TEST(d.center.x == a / 3.0, tt::tolerance(1e-15));
    BOOST_TEST(d.center.y == b / 3.0, tt::tolerance(1e-15));
    BOOST_TEST(t.centroid.x == a / 3.0, tt::tolerance(1e-15));
    BOOST_TEST(t.centroid.y == b / 3.0, tt::tolerance(1e-15));
    BOOST_TEST(d.inertia == m * (a * a + b * b) / 18.0, tt::tolerance(1e-14));
}

// Oracle: regular n-gon of circumradius R: I = m R^2 (1 + 2 cos^2(pi/n)) / 6 (textbook);
// for n = 6 this is 5 m R^2 / 12.
BOOST_AUTO_TEST_CASE(regular_hexagon, *utf::label("DD14") * utf::label("DD1")) {
    const double R = 1.5;
    std::vector<Vec2d> pts;
    for (int i = 0; i < 6; ++i)
        pts.push_back({5.0 + R * std::cos(i * std::numbers::pi / 3),
                       -2.0 + R * std::sin(i * std::numbers::pi / 3)});
    const MassData d = compute_mass(make_polygon(pts), 1.0);
    const double m = 3.0 * std::sqrt(3.0) / 2.0 * R * R;
    BOOST_TEST(d.mass == m, tt::tolerance(1e-14));
    BOOST_TEST(d.inertia == 5.0 * m * R * R / 12.0, tt::tolerance(1e-13));
    BOOST_TEST(d.center.x == 5.0, tt::tolerance(1e-14));
    BOOST_TEST(d.center.y == -2.0, tt::tolerance(1e-14));
}

// Oracle: hand derivation for an L of a 1x2 and a 1x1 block (density 1): masses 2 and 1,
// centre (5/6, 5/6), I = 2 (1 + 4)/12 + 2 (5/36) + 1 (1 + 1)/12 + 1 (20/36) = 11/6 kg m^2.
BOOST_AUTO_TEST_CASE(l_shape_combination, *utf::label("DD14") * utf::label("DD1")) {
    const MassData parts[2] = {compute_mass(make_box(0.5, 1.0, {0.5, 1.0}), 1.0),
                               compute_mass(make_box(0.5, 0.5, {1.5, 0.5}), 1.0)};
    const MassData d = combine(parts);
    BOOST_TEST(d.mass == 3.0, tt::tolerance(1e-15));
    BOOST_TEST(d.center.x == 5.0 / 6.0, tt::tolerance(1e-15));
    BOOST_TEST(d.center.y == 5.0 / 6.0, tt::tolerance(1e-15));
    BOOST_TEST(d.inertia == 11.0 / 6.0, tt::tolerance(1e-14));
}

// Oracle: textbook rectangle: two 1x1 halves of a 2x1 box combine to the 2x1 box's
// m (w^2 + h^2) / 12 about its centre.
BOOST_AUTO_TEST_CASE(halves_combine_to_whole, *utf::label("DD14") * utf::label("DD1")) {
    const MassData parts[2] = {compute_mass(make_box(0.5, 0.5, {-0.5, 0.0}), 2.0),
                               compute_mass(make_box(0.5, 0.5, {0.5, 0.0}), 2.0)};
    const MassData d = combine(parts);
    BOOST_TEST(d.mass == 4.0, tt::tolerance(1e-15));
    BOOST_TEST(d.inertia == 4.0 * (4.0 + 1.0) / 12.0, tt::tolerance(1e-14));
    BOOST_TEST(std::abs(d.center.x) < 1e-15);
}

// Oracle: SRS Table 1, m >= 0: a negative or non-finite density is rejected and named.
BOOST_AUTO_TEST_CASE(bad_density_rejected, *utf::label("DCX_density")) {
    const Polygon box = make_box(1.0, 1.0);
    try {
        (void)compute_mass(box, -2.0);
        BOOST_FAIL("negative density accepted");
    } catch (const ValidationError& e) {
        BOOST_TEST(e.field == "shape.density");
        BOOST_TEST(e.value == -2.0);
        BOOST_TEST(e.constraint == "DCX_density");
    }
    BOOST_CHECK_THROW((void)compute_mass(make_circle(1.0), std::nan("")), ValidationError);
}

// Oracle: DD1 with uniform weights: a massless (density 0) shape still reports its
// geometric centroid, so callers can place it; mass and inertia are zero.
BOOST_AUTO_TEST_CASE(zero_density_geometric_centre, *utf::label("DD1")) {
    const MassData z = compute_mass(make_box(1.0, 1.0, {2.0, 3.0}), 0.0);
    BOOST_TEST(z.mass == 0.0);
    BOOST_TEST(z.inertia == 0.0);
    BOOST_TEST(z.center.x == 2.0, tt::tolerance(1e-15));
}

BOOST_AUTO_TEST_SUITE_END()
