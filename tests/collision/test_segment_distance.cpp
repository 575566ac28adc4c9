// Closest points between segments (used by the polygon narrow phase to detect vertex-vertex
// approaches, T5's witness points when apart).
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <random>

#include "oracles.hpp"
#include "tamias2d/collision/segment_distance.hpp"

namespace utf = boost::unit_test;
namespace tt = boost::test_tools;
using namespace tamias2d;

BOOST_AUTO_TEST_SUITE(segment_distance_suite)

// Oracle: brute force over endpoints: in 2D, two segments that do not cross are closest at an
// endpoint of one of them,
// so the distance is the least of four point-segment distances (0 when they cross).
BOOST_AUTO_TEST_CASE(random_segments_vs_endpoint_oracle, *utf::label("T5")) {
    std::mt19937_64 rng(41);
    std::uniform_real_distribution<double> u(-2.0, 2.0);
    for (int k = 0; k < 20000; ++k) {
        const Vec2d p1{u(rng), u(rng)}, q1{u(rng), u(rng)}, p2{u(rng), u(rng)}, q2{u(rng), u(rng)};
        const SegmentDistance sd = segment_distance(p1, q1, p2, q2);
        const double want = oracle::segments_cross(p1, q1, p2, q2)
                                ? 0.0
                                : std::min({oracle::point_segment_distance(p1, p2, q2),
                                            oracle::point_segment_distance(q1, p2, q2),
                                            oracle::point_segment_distance(p2, p1, q1),
                                            oracle::point_segment_distance(q2, p1, q1)});
        BOOST_TEST(std::sqrt(sd.distance_squared) == want, tt::tolerance(1e-9));
        BOOST_TEST(sd.fraction1 >= 0.0);
        BOOST_TEST(sd.fraction1 <= 1.0);
        BOOST_TEST(sd.fraction2 >= 0.0);
        BOOST_TEST(sd.fraction2 <= 1.0);
    }
}

// Oracle: hand geometry: end to end along a line, and parallel overlapping segments.
BOOST_AUTO_TEST_CASE(vertex_and_parallel_cases, *utf::label("T5")) {
    const SegmentDistance ends = segment_distance({0, 0}, {1, 0}, {2, 1}, {3, 1});
    BOOST_TEST(ends.fraction1 == 1.0);
    BOOST_TEST(ends.fraction2 == 0.0);
    BOOST_TEST(ends.distance_squared == 2.0, tt::tolerance(1e-15));
    const SegmentDistance par = segment_distance({0, 0}, {2, 0}, {1, 0.5}, {3, 0.5});
    BOOST_TEST(par.distance_squared == 0.25, tt::tolerance(1e-15));
    BOOST_TEST(par.fraction1 > 0.0); // interior: an edge region, not two vertices
}

BOOST_AUTO_TEST_SUITE_END()
