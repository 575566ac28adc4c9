// The choice between a two-point manifold's block solve and its sequential one (prepare_block,
// contact_preparation.hpp) at the bounds on K's condition, where a K built from exact binary
// numbers puts k11^2 exactly on bound * det. The solves themselves are tests/model's (IM7) and
// the restitution pass's.
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "tamias2d/dynamics/contacts/contact_preparation.hpp"
#include "tamias2d/dynamics/solver_body.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;

namespace {

/// K of two points on one body against a static one: the body's inverse mass `inv_m`, inverse
/// inertia 1, the first point's normal moment arm 0 and the second's `arm`. Then k11 = inv_m,
/// k12 = inv_m, k22 = inv_m + arm^2 and det = inv_m arm^2, each exact in binary for the values
/// below (integers under 2^53).
preparation::PreparedBlock<double> block_of(double inv_m, double arm) {
    SolverBody fixed, body;
    body.inv_m = inv_m;
    body.inv_I = 1.0;
    return preparation::prepare_block(fixed, body, 0.0, 0.0, 0.0, arm);
}

} // namespace

BOOST_AUTO_TEST_SUITE(contact_preparation)

// Oracle: the rule stated beside the bounds, the block only where k11^2 < bound * det,
// strictly, as Box2D 2.4's b2ContactSolver tests its condition; and closed-form K of one body
// on a static one (DD8 generalised to two points: k_ij = 1/m + (r_i x n)(r_j x n) / I). With
// inv_m = bound and arm 1, k11^2 = bound^2 = bound * det exactly: the iterations' block is
// refused there and taken a little inside it; with inv_m = 1e6 the restitution pass's bound
// alike (its inverse then zero).
BOOST_AUTO_TEST_CASE(a_condition_exactly_on_a_bound_is_solved_point_by_point,
                     *utf::label("internals")) {
    const double bound = preparation::max_condition_number;
    const auto on = block_of(bound, 1.0);
    BOOST_TEST(on.k11 == bound);
    BOOST_TEST(on.k12 == bound);
    BOOST_TEST(on.k22 == bound + 1.0);
    BOOST_TEST(on.k11 * on.k11 == bound * (on.k11 * on.k22 - on.k12 * on.k12));
    BOOST_TEST(bool(on.invertible));
    BOOST_TEST(!bool(on.use_block));
    const auto inside = block_of(bound, 1.0 + std::ldexp(1.0, -20));
    BOOST_TEST(bool(inside.use_block));

    const double restitution_bound = preparation::max_restitution_condition_number;
    const auto on_r = block_of(restitution_bound, 1.0);
    BOOST_TEST(on_r.k11 * on_r.k11 ==
               restitution_bound * (on_r.k11 * on_r.k22 - on_r.k12 * on_r.k12));
    BOOST_TEST(!bool(on_r.invertible));
    BOOST_TEST(!bool(on_r.use_block));
    BOOST_TEST(on_r.inv_k11 == 0.0);
    BOOST_TEST(on_r.inv_k12 == 0.0);
    BOOST_TEST(on_r.inv_k22 == 0.0);
    const auto inside_r = block_of(restitution_bound, 1.0 + std::ldexp(1.0, -20));
    BOOST_TEST(bool(inside_r.invertible));
    BOOST_TEST(!bool(inside_r.use_block));
    // Its inverse, against K's closed-form inverse [k22 -k12; -k12 k11] / det.
    const double det = inside_r.k11 * inside_r.k22 - inside_r.k12 * inside_r.k12;
    BOOST_TEST(inside_r.inv_k11 == inside_r.k22 / det, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(inside_r.inv_k12 == -inside_r.k12 / det, boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_SUITE_END()
