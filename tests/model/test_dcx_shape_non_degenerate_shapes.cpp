// DCX_shape's signed polygon area (the shoelace formula summed as a fan), checked against hand
// values: rectangles and right triangles whose areas are products of their sides.
#include <boost/test/unit_test.hpp>

#include <vector>

#include "tamias2d/model/dcx_shape_non_degenerate_shapes.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d::units;
using tamias2d::Vec2d;
namespace dcx_shape = tamias2d::model::dcx_shape;

BOOST_AUTO_TEST_SUITE(dcx_shape_non_degenerate_shapes)

// Oracle: hand values. The right triangle with legs 2 m along x and 3 m along y has area 3 m^2,
// positive counter-clockwise (b = (0, 3) lies counter-clockwise of a = (2, 0), A4), negative the
// other way round; collinear legs have none.
BOOST_AUTO_TEST_CASE(triangle_area_is_half_the_cross_product, *utf::label("DCX_shape")) {
    const auto a = vec_from_values<Length>(2.0, 0.0);
    const auto b = vec_from_values<Length>(0.0, 3.0);
    BOOST_TEST(dcx_shape::triangle_area(a, b).value() == 3.0);
    BOOST_TEST(dcx_shape::triangle_area(b, a).value() == -3.0);
    BOOST_TEST(dcx_shape::triangle_area(a, 2.0 * a).value() == 0.0);
}

// Oracle: hand values. A 4 m x 2.5 m rectangle has 10 m^2, a right triangle with legs 4 m and
// 3 m has 6 m^2 (counter-clockwise: positive; clockwise: negative), also 1e6 m from the origin
// (every coordinate exact in binary, so the fan's differences are exact and the area is too),
// and a regular-ish hexagon made of a 2 x 2 square and two triangles of base 2, height 1: 6 m^2.
BOOST_AUTO_TEST_CASE(polygon_area_hand_values, *utf::label("DCX_shape")) {
    const std::vector<Vec2d> rectangle = {{0.0, 0.0}, {4.0, 0.0}, {4.0, 2.5}, {0.0, 2.5}};
    BOOST_TEST(dcx_shape::polygon_area(rectangle.data(), rectangle.size()).value() == 10.0);
    const std::vector<Vec2d> ccw = {{1e6, 1e6}, {1e6 + 4.0, 1e6}, {1e6, 1e6 + 3.0}};
    BOOST_TEST(dcx_shape::polygon_area(ccw.data(), ccw.size()).value() == 6.0);
    const std::vector<Vec2d> cw = {ccw[0], ccw[2], ccw[1]};
    BOOST_TEST(dcx_shape::polygon_area(cw.data(), cw.size()).value() == -6.0);
    const std::vector<Vec2d> hexagon = {{0.0, 0.0}, {2.0, 0.0}, {3.0, 1.0},
                                        {2.0, 2.0}, {0.0, 2.0}, {-1.0, 1.0}};
    BOOST_TEST(dcx_shape::polygon_area(hexagon.data(), hexagon.size()).value() == 6.0);
}

BOOST_AUTO_TEST_SUITE_END()
