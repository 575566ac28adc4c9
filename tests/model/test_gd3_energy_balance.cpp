// GD3's bound on a step's energy rise, checked against a hand evaluation of its equation.
#include <boost/test/unit_test.hpp>

#include <vector>

#include "tamias2d/model/gd3_energy_balance.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d::units;
namespace gd3 = tamias2d::model::gd3;

BOOST_AUTO_TEST_SUITE(gd3_energy_balance)

// Oracle: GD3's equation by hand. One point overlapping by 0.01 m with m_eff = 2 kg, omega =
// 10 s^-1: m_eff omega^2 x^2 / 2 = 0.01 J; the lift M |g| x = 5 x 10 x 0.01 = 0.5 J; a point
// 0.02 m apart adds nothing; the allowance 1e-12 (|3| + |-7| + 5 x 10 x 25) = 1.26e-9 J.
BOOST_AUTO_TEST_CASE(bound_by_hand, *utf::label("GD3")) {
    const std::vector<gd3::ContactPoint> points = {{0.01 * metre, 2.0 * kilogram},
                                                   {-0.02 * metre, 1.0 * kilogram}};
    const Energy bound =
        gd3::step_energy_bound(points, 10.0 / second, 5.0 * kilogram,
                               10.0 * metre / (second * second), 3.0 * joule, -7.0 * joule);
    BOOST_TEST(bound.value() == 0.51 + 1.26e-9, boost::test_tools::tolerance(1e-13));
    const Energy none =
        gd3::step_energy_bound({}, 10.0 / second, 5.0 * kilogram, 10.0 * metre / (second * second),
                               0.0 * joule, 0.0 * joule);
    BOOST_TEST(none.value() == 1250e-12, boost::test_tools::tolerance(1e-13));
}

BOOST_AUTO_TEST_SUITE_END()
