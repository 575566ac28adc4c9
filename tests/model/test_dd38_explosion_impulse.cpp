// DD38 (explosion impulse): the blast's strength s(d) in each of its cases and on their
// boundaries, and the shape's and the body's impulse magnitudes, by hand.
#include <boost/test/unit_test.hpp>

#include "tamias2d/model/dd38_explosion_impulse.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d::units;
namespace dd38 = tamias2d::model::dd38;

namespace {
double strength(double d, double r, double f) {
    return dd38::falloff_scale(d * metre, r * metre, f * metre).value();
}
} // namespace

BOOST_AUTO_TEST_SUITE(dd38_explosion_impulse)

// Oracle: DD38's cases as the SRS states them: s = 1 for d <= r; clamp((r + f - d) / f, 0, 1)
// for d > r and f > 0; 0 for d > r and f = 0. On the boundary d = r the first case holds: full
// strength, with or without a falloff, also where (r + f - d) / f rounds below 1 (r = 0.7 m,
// f = 0.1 m: 0.9999999999999998).
BOOST_AUTO_TEST_CASE(strength_in_each_case_and_on_its_boundaries, *utf::label("DD38")) {
    BOOST_TEST(strength(0.5, 1.0, 2.0) == 1.0);  // within the radius
    BOOST_TEST(strength(0.0, 0.0, 0.0) == 1.0);  // a point blast at its own centre
    BOOST_TEST(strength(1.0, 1.0, 0.0) == 1.0);  // on the radius, no falloff
    BOOST_TEST(strength(0.7, 0.7, 0.1) == 1.0);  // on the radius, with a falloff
    BOOST_TEST(strength(3.0, 2.0, 2.0) == 0.5);  // half way through the falloff
    BOOST_TEST(strength(4.0, 2.0, 2.0) == 0.0);  // at its end
    BOOST_TEST(strength(9.0, 2.0, 2.0) == 0.0);  // beyond it
    BOOST_TEST(strength(1.5, 1.0, 0.0) == 0.0);  // beyond the radius, no falloff
    BOOST_TEST(strength(1.5, 1.0, -0.0) == 0.0); // a falloff of -0 is none too
}

// Oracle: DD38's products by hand: J_shape = s j_w w = 0.5 * 2 N s/m * 3 m = 3 N s;
// J_body = s j_b = 0.5 * 4 N s = 2 N s.
BOOST_AUTO_TEST_CASE(impulses_scale_with_the_strength, *utf::label("DD38")) {
    const auto s = Dimensionless::from_value(0.5);
    BOOST_TEST(dd38::shape_impulse(s, 2.0 * newton * second / metre, 3.0 * metre).value() == 3.0);
    BOOST_TEST(dd38::body_impulse(s, 4.0 * newton * second).value() == 2.0);
}

BOOST_AUTO_TEST_SUITE_END()
