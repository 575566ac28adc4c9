// DD32 through the engine: World places a body's points by the rotation of its orientation
// (model/dd32_rotation.hpp, called by math/vec2d.hpp's Rot). The module's own accuracy is
// tests/model/test_dd32_rotation.cpp's.
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "support/trig_reference.hpp"
#include "tamias2d/shape_def.hpp"
#include "tamias2d/world.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;
using tamias2d::test::LongSinCos;

BOOST_AUTO_TEST_SUITE(rotation_in_the_engine)

// Oracle: DD32's p = x + R(phi) p_B in long double (cos and sin at 1400 bits, rounded). A body
// whose centre of mass lies off its origin (a box centred at (1.5, -0.5) in the body frame) is
// placed at orientation phi: World::position, its centre of mass in the world, is the origin plus
// the counter-clockwise rotation of the local centre, to the roundings of the products and sums (4
// ulp of the largest term), for orientations up to 1e12 (DCX_range's input bound).
BOOST_AUTO_TEST_CASE(engine_places_a_body_point_by_the_rotation, *utf::label("DD32")) {
    for (double phi : {0.0, 0.3, -2.0, 3.9, 100.25, -1.0e6 + 0.7, 1.0e12}) {
        World world;
        BodyDef def;
        def.type = BodyType::dynamic;
        def.position = {2.0, 3.0};
        def.angle = phi;
        const BodyId body = world.create_body(def);
        world.create_shape(body, box_shape(0.5, 0.25, {}, {1.5, -0.5}));
        const Vec2d c = world.local_center(body);
        const LongSinCos r = test::multiprecision_sincos(phi);
        const long double x = 2.0L + r.cos * c.x - r.sin * c.y;
        const long double y = 3.0L + r.sin * c.x + r.cos * c.y;
        const Vec2d p = world.position(body);
        const double tolerance = 4.0 * std::ldexp(1.0, -52) * 3.0; // 4 ulp of |origin| <= 3
        BOOST_TEST(std::fabs(static_cast<long double>(p.x) - x) <= tolerance, "phi " << phi);
        BOOST_TEST(std::fabs(static_cast<long double>(p.y) - y) <= tolerance, "phi " << phi);
    }
}

BOOST_AUTO_TEST_SUITE_END()
