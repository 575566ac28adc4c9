// T5 (collision detection: A and B have collided when some point p lies in both), checked
// against analytic point-in-shape predicates.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <vector>

#include "tamias2d/model/t5_collision_detection.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d::units;
namespace t5 = tamias2d::model::t5;

namespace {
Vec2<Length> L2(double x, double y) {
    return vec_from_values<Length>(x, y);
}
// Unit square [0, 1]^2 and the diamond |x| + |y| <= 1, counter-clockwise (A4).
const Vec2<Length> unit_square[] = {L2(0, 0), L2(1, 0), L2(1, 1), L2(0, 1)};
const Vec2<Length> diamond[] = {L2(1, 0), L2(0, 1), L2(-1, 0), L2(0, -1)};
} // namespace

BOOST_AUTO_TEST_SUITE(t5_collision_detection)

// Oracle: hand derivation for the unit square: interior, exterior, and the closed boundary
// (edge midpoints and vertices belong to the square; the cross products are exact there).
BOOST_AUTO_TEST_CASE(square_contains_hand_points, *utf::label("T5")) {
    BOOST_TEST(t5::contains(unit_square, L2(0.5, 0.5)));
    BOOST_TEST(t5::contains(unit_square, L2(1.0, 0.5)));
    BOOST_TEST(t5::contains(unit_square, L2(0.0, 0.0)));
    BOOST_TEST(t5::contains(unit_square, L2(1.0, 1.0)));
    BOOST_TEST(!t5::contains(unit_square, L2(1.5, 0.5)));
    BOOST_TEST(!t5::contains(unit_square, L2(0.5, -0.25)));
    BOOST_TEST(!t5::contains(unit_square, L2(-1e-9, 0.5)));
}

// Oracle: the same hand points for the form the engine stores (vertices with outward unit edge
// normals): the closed boundary, edge midpoints and vertices, belongs to the square.
BOOST_AUTO_TEST_CASE(square_with_normals_contains_its_boundary, *utf::label("T5")) {
    const tamias2d::Vec2d v[] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    const tamias2d::Vec2d n[] = {{0, -1}, {1, 0}, {0, 1}, {-1, 0}};
    for (const tamias2d::Vec2d p :
         {tamias2d::Vec2d{0.5, 0.5}, tamias2d::Vec2d{1.0, 0.5}, tamias2d::Vec2d{0.5, 0.0},
          tamias2d::Vec2d{0.0, 0.0}, tamias2d::Vec2d{1.0, 1.0}})
        BOOST_TEST(t5::contains(v, n, 4, p), "(" << p.x << ", " << p.y << ")");
    for (const tamias2d::Vec2d p :
         {tamias2d::Vec2d{1.5, 0.5}, tamias2d::Vec2d{0.5, -0.25}, tamias2d::Vec2d{-1e-9, 0.5}})
        BOOST_TEST(!t5::contains(v, n, 4, p), "(" << p.x << ", " << p.y << ")");
}

// Oracle: analytic predicate |x| + |y| <= 1 for the diamond, on a grid of step 1/8 over
// [-1.5, 1.5]^2. Every coordinate is a multiple of 1/8, so both the analytic sum and the
// polygon's cross products are exact in binary and boundary points agree exactly.
BOOST_AUTO_TEST_CASE(diamond_matches_analytic_predicate, *utf::label("T5")) {
    int inside = 0;
    for (int i = -12; i <= 12; ++i)
        for (int k = -12; k <= 12; ++k) {
            const double x = i / 8.0;
            const double y = k / 8.0;
            const bool expected = std::abs(x) + std::abs(y) <= 1.0;
            BOOST_TEST(t5::contains(diamond, L2(x, y)) == expected,
                       "at (" << x << ", " << y << ")");
            inside += expected ? 1 : 0;
        }
    BOOST_TEST(inside == 2 * 8 * 8 + 2 * 8 + 1); // lattice points in |i| + |k| <= 8: 145
}

// Oracle: analytic predicate |p - c|^2 <= R^2 by hand: for a disc of radius 5 m at (1, 1), the
// point (4, 5) is at distance 5 (3-4-5 triangle: on the closed boundary), (1, 1) is the centre,
// (6.5, 1) is 5.5 m away.
BOOST_AUTO_TEST_CASE(disc_contains_hand_points, *utf::label("T5")) {
    const t5::Disc d{L2(1.0, 1.0), 5.0 * metre};
    BOOST_TEST(t5::contains(d, L2(1.0, 1.0)));
    BOOST_TEST(t5::contains(d, L2(4.0, 5.0)));
    BOOST_TEST(t5::contains(d, L2(1.0, -4.0)));
    BOOST_TEST(!t5::contains(d, L2(6.5, 1.0)));
    BOOST_TEST(!t5::contains(d, L2(4.5, 5.0)));
}

// Oracle: analytic cases of T5. Unit square and diamond overlap in the region x, y >= 0,
// x + y <= 1 (and the square's edges): (0.25, 0.25) lies in both, (0.75, 0.75) only in the
// square, (-0.5, 0) only in the diamond. A square [3, 4]^2 shares no point with the diamond:
// no grid point may lie in both. A disc of radius 0.5 at (1.5, 0.5) touches the unit square
// at exactly (1, 0.5), a witness point of contact.
BOOST_AUTO_TEST_CASE(collided_at_analytic_cases, *utf::label("T5")) {
    BOOST_TEST(t5::collided_at(unit_square, diamond, L2(0.25, 0.25)));
    BOOST_TEST(!t5::collided_at(unit_square, diamond, L2(0.75, 0.75)));
    BOOST_TEST(!t5::collided_at(unit_square, diamond, L2(-0.5, 0.0)));
    const Vec2<Length> far_square[] = {L2(3, 3), L2(4, 3), L2(4, 4), L2(3, 4)};
    int both = 0;
    for (int i = -16; i <= 40; ++i)
        for (int k = -16; k <= 40; ++k)
            both += t5::collided_at(far_square, diamond, L2(i / 8.0, k / 8.0)) ? 1 : 0;
    BOOST_TEST(both == 0);
    const t5::Disc d{L2(1.5, 0.5), 0.5 * metre};
    BOOST_TEST(t5::collided_at(unit_square, d, L2(1.0, 0.5)));
    BOOST_TEST(t5::collided_at(d, unit_square, L2(1.0, 0.5)));
    BOOST_TEST(!t5::collided_at(unit_square, d, L2(1.0, 0.75)));
}

// Oracle: the definition of a polygon: fewer than three vertices enclose no area, so nothing
// is contained (hand case: a segment and the empty polygon).
BOOST_AUTO_TEST_CASE(degenerate_polygon_contains_nothing, *utf::label("T5")) {
    const Vec2<Length> segment[] = {L2(0, 0), L2(1, 0)};
    BOOST_TEST(!t5::contains(segment, L2(0.5, 0.0)));
    BOOST_TEST(!t5::contains(t5::ConvexPolygon{}, L2(0.0, 0.0)));
}

BOOST_AUTO_TEST_SUITE_END()
