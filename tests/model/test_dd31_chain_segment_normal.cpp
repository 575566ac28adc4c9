// DD31 (the admissible contact normals of a chain edge) at the edges of its arcs. The SRS
// states non-strict inequalities with a tolerance of 0.01: a normal exactly that far beyond an
// arc's end is still admissible, and the next double beyond it is not. The edge's normal is
// (0, 1) and its neighbours' are axis-aligned, so every cross product below is computed exactly
// and lands on the tolerance itself.
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

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

V at(double angle) {
    return {std::cos(angle), std::sin(angle)};
}

/// The angle from a to b counter-clockwise, in [0, 2 pi).
double turn(double a, double b) {
    const double d = std::fmod(b - a, 2.0 * std::numbers::pi);
    return d < 0.0 ? d + 2.0 * std::numbers::pi : d;
}

/// The angle between a direction and the arc from angle `from` counter-clockwise to `to`.
double off_arc(double angle, double from, double to) {
    if (turn(from, angle) <= turn(from, to))
        return 0.0;
    return std::min(std::min(turn(angle, from), turn(from, angle)),
                    std::min(turn(angle, to), turn(to, angle)));
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

// Oracle: DD31's statement in angles (turns measured with fmod, not the module's cross
// products): N is admissible exactly when it lies within asin(0.01) (the tolerance's angle) of
// n_k or of a convex vertex's arc, the arc from n_{k-1} to n_k (start
// vertex) or from n_k to n_{k+1} (end vertex), each less than a half turn. Every pair of
// vertices from concave to barely and fully convex, with N all round the circle; directions
// within 1e-9 rad of the tolerance's angle are left out (rounding decides them). The back of
// the edge, -n_k, lies a half turn from n_k and is never admissible at these vertices.
BOOST_AUTO_TEST_CASE(every_normal_within_the_tolerance_of_an_arc_and_no_other_is_admissible,
                     *utf::label("DD31")) {
    const double pi = std::numbers::pi, reach = std::asin(tolerance);
    const double up_angle = pi / 2.0;
    // The vertex's turn: negative concave, 0 flat, positive convex (barely: below the angle).
    const double turns[] = {-2.0,        -0.3,        0.0, 1e-4, 0.5 * reach, reach,
                            1.5 * reach, 2.5 * reach, 0.3, 1.5,  3.0};
    int checked = 0, wrong = 0;
    for (const double start : turns) {
        for (const double end : turns) {
            const V n_prev = at(up_angle - start), n_next = at(up_angle + end);
            for (int i = 0; i < 7200; ++i) {
                const double angle = 2.0 * pi * i / 7200.0 + 1e-3;
                double off = off_arc(angle, up_angle, up_angle);
                if (start > 0.0)
                    off = std::min(off, off_arc(angle, up_angle - start, up_angle));
                if (end > 0.0)
                    off = std::min(off, off_arc(angle, up_angle, up_angle + end));
                if (std::abs(off - reach) < 1e-9)
                    continue;
                ++checked;
                if (dd31::admissible(n_prev, up, n_next, at(angle), tolerance) != (off <= reach))
                    ++wrong;
            }
            BOOST_TEST(!dd31::admissible(n_prev, up, n_next, V{0.0, -1.0}, tolerance),
                       "-n_k at the turns " << start << ", " << end);
        }
    }
    BOOST_TEST(checked > 800000);
    BOOST_TEST(wrong == 0);
}

BOOST_AUTO_TEST_SUITE_END()
