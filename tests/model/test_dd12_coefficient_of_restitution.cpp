// DD12 (coefficient of restitution C_R = -(v_f^AB . n) / (v_i^AB . n)), checked by hand and
// against the textbook drop-and-rebound measurement C_R = sqrt(h_rebound / h_drop).
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "tamias2d/model/dd12_coefficient_of_restitution.hpp"

namespace utf = boost::unit_test;
namespace tt = boost::test_tools;
using namespace tamias2d::units;
namespace dd12 = tamias2d::model::dd12;

namespace {
const auto m_s = metre / second;
}

BOOST_AUTO_TEST_SUITE(dd12_coefficient_of_restitution)

// Oracle: hand derivation. Approaching at -2 m/s and separating at 1.6 m/s: C_R = 0.8 (the SRS
// typical value). Separating as fast as approaching: 1 (elastic); not separating: 0.
BOOST_AUTO_TEST_CASE(hand_values, *utf::label("DD12")) {
    BOOST_TEST(dd12::coefficient_of_restitution(1.6 * m_s, -2.0 * m_s).value() == 0.8,
               tt::tolerance(1e-15));
    BOOST_TEST(dd12::coefficient_of_restitution(2.0 * m_s, -2.0 * m_s).value() == 1.0);
    BOOST_TEST(dd12::coefficient_of_restitution(0.0 * m_s, -2.0 * m_s).value() == 0.0);
}

// Oracle: hand derivation of the solved form v_f . n = -C_R v_i . n: C_R = 0.8, v_i . n = -2.5
// gives 2.0 m/s; C_R = 0 gives 0 (bodies stay in contact). Both forms are inverse.
BOOST_AUTO_TEST_CASE(separating_velocity_and_inverse, *utf::label("DD12")) {
    BOOST_TEST(dd12::separating_normal_velocity(0.8, -2.5 * m_s).value() == 2.0,
               tt::tolerance(1e-15));
    BOOST_TEST(dd12::separating_normal_velocity(0.0, -2.5 * m_s).value() == 0.0);
    for (double e : {0.0, 0.25, 0.8, 1.0}) {
        const Velocity vf = dd12::separating_normal_velocity(e, -3.7 * m_s);
        BOOST_TEST(dd12::coefficient_of_restitution(vf, -3.7 * m_s).value() == e,
                   tt::tolerance(1e-15));
    }
}

// Oracle: textbook measurement. A ball dropped from h1 = 1 m hits the floor at
// v_i = -sqrt(2 g h1) and rebounds to h2 = 0.64 m, so it left at v_f = sqrt(2 g h2):
// C_R = sqrt(h2 / h1) = 0.8 (independent of g). Square roots and a division: 1e-15 relative.
BOOST_AUTO_TEST_CASE(drop_and_rebound_heights, *utf::label("DD12")) {
    const double g = 9.81;
    const Velocity vi = -std::sqrt(2.0 * g * 1.0) * m_s;
    const Velocity vf = std::sqrt(2.0 * g * 0.64) * m_s;
    BOOST_TEST(dd12::coefficient_of_restitution(vf, vi).value() == 0.8, tt::tolerance(1e-15));
}

BOOST_AUTO_TEST_SUITE_END()
