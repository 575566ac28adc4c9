// DD31 (the admissible contact normals of a chain edge) at the edges of its arcs. The SRS
// states non-strict inequalities with a tolerance of 0.01: a normal exactly that far beyond an
// arc's end is still admissible, and the next double beyond it is not. The edge's normal is
// (0, 1) and its neighbours' are axis-aligned, so every cross product below is computed exactly
// and lands on the tolerance itself.
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "tamias2d/model/dd31_chain_segment_normal.hpp"

namespace utf = boost::unit_test;
namespace dd31 = tamias2d::model::dd31;
using V = tamias2d::units::Vec2<double>;

namespace {

constexpr double tolerance = 0.01; // DD31's, as the narrow phase passes it
const V up{0.0, 1.0};              // n_k
const double beyond = std::nextafter(tolerance, 1.0);

double other(double t) {
    return std::sqrt(1.0 - t * t);
}

} // namespace

BOOST_AUTO_TEST_SUITE(dd31_chain_segment_normal)

// Oracle: DD31's statement. At a flat vertex only n_k is admissible, within the tolerance:
// n_k x N <= 0.01 on the side of the end vertex, n_k x N >= -0.01 on the side of the start.
// N = (-t, s) gives n_k x N = t, N = (t, s) gives -t, exactly. -n_k is not n_k.
BOOST_AUTO_TEST_CASE(flat_vertices_admit_n_k_within_the_tolerance_inclusive, *utf::label("DD31")) {
    BOOST_TEST(dd31::admissible(up, up, up, up, tolerance));
    // Towards the end vertex (N turned counter-clockwise from n_k).
    BOOST_TEST(dd31::admissible(up, up, up, V{-tolerance, other(tolerance)}, tolerance));
    BOOST_TEST(!dd31::admissible(up, up, up, V{-beyond, other(beyond)}, tolerance));
    // Towards the start vertex (clockwise).
    BOOST_TEST(dd31::admissible(up, up, up, V{tolerance, other(tolerance)}, tolerance));
    BOOST_TEST(!dd31::admissible(up, up, up, V{beyond, other(beyond)}, tolerance));
    // The back of the edge is not n_k, though its cross product with n_k is as small: N =
    // (-t, -s) gives n_k x N = t, N = (t, -s) gives -t, both facing away.
    BOOST_TEST(!dd31::admissible(up, up, up, V{-tolerance, -other(tolerance)}, tolerance));
    BOOST_TEST(!dd31::admissible(up, up, up, V{tolerance, -other(tolerance)}, tolerance));
    BOOST_TEST(!dd31::admissible(up, up, up, V{0.0, -1.0}, tolerance));
}

// Oracle: DD31's statement. At a convex vertex the arc between the two edges' normals is
// admissible, within the tolerance past the neighbour's normal. End vertex: n_{k+1} = (-1, 0),
// N = (-s, -t) gives N x n_{k+1} = -t. Start vertex: n_{k-1} = (1, 0), N = (s, -t) gives
// n_{k-1} x N = -t. Both exactly.
BOOST_AUTO_TEST_CASE(convex_vertices_admit_their_arc_within_the_tolerance_inclusive,
                     *utf::label("DD31")) {
    const V left{-1.0, 0.0}, right{1.0, 0.0};
    BOOST_TEST(dd31::admissible(up, up, left, V{-other(tolerance), -tolerance}, tolerance));
    BOOST_TEST(!dd31::admissible(up, up, left, V{-other(beyond), -beyond}, tolerance));
    BOOST_TEST(dd31::admissible(right, up, up, V{other(tolerance), -tolerance}, tolerance));
    BOOST_TEST(!dd31::admissible(right, up, up, V{other(beyond), -beyond}, tolerance));
    // Inside the arcs, and the neighbour's own normal.
    BOOST_TEST(dd31::admissible(up, up, left, V{-std::sqrt(0.5), std::sqrt(0.5)}, tolerance));
    BOOST_TEST(dd31::admissible(up, up, left, left, tolerance));
    BOOST_TEST(dd31::admissible(right, up, up, right, tolerance));
}

BOOST_AUTO_TEST_SUITE_END()
