// DD28 (a sensor's overlap) checked against its statement (srs/data_definitions.yaml): the pair
// overlaps when its least separation is below zero, so touching at a point, or a speculative
// point ahead of contact, is no overlap, and a pair without points overlaps nowhere.
#include <boost/test/unit_test.hpp>

#include <limits>

#include "tamias2d/model/dd28_sensor_overlap.hpp"

namespace utf = boost::unit_test;
namespace dd28 = tamias2d::model::dd28;
using tamias2d::units::Length;

BOOST_AUTO_TEST_SUITE(dd28_sensor_overlap)

// Oracle: min_k s_k < 0 evaluated by hand on both sides of zero: the smallest negative double
// overlaps, zero (either sign) does not, nor the smallest positive one, nor a speculative point
// 1 cm or 1 m ahead; with no point there is no separation to compare, hence no overlap.
BOOST_AUTO_TEST_CASE(a_pair_overlaps_exactly_when_its_least_separation_is_negative,
                     *utf::label("DD28")) {
    const double tiny = std::numeric_limits<double>::denorm_min();
    for (const int points : {1, 2}) {
        BOOST_TEST_CONTEXT(points << " points") {
            BOOST_TEST(dd28::overlapping(points, Length::from_value(-0.25)));
            BOOST_TEST(dd28::overlapping(points, Length::from_value(-tiny)));
            BOOST_TEST(!dd28::overlapping(points, Length::from_value(0.0)));
            BOOST_TEST(!dd28::overlapping(points, Length::from_value(-0.0)));
            BOOST_TEST(!dd28::overlapping(points, Length::from_value(tiny)));
            BOOST_TEST(!dd28::overlapping(points, Length::from_value(0.01)));
            BOOST_TEST(!dd28::overlapping(points, Length::from_value(1.0)));
        }
    }
    BOOST_TEST(!dd28::overlapping(0, Length::from_value(-0.25)));
}

BOOST_AUTO_TEST_SUITE_END()
