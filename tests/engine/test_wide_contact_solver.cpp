// The wide contact solver (four manifolds per pack, grouped by ConstraintGraph's levels) against
// the sequential Gauss-Seidel pass in creation order that it must reproduce bit for bit (NFR1's
// speed must not change IM3's results).
#include <boost/test/unit_test.hpp>

#include <cstdint>
#include <set>
#include <vector>

#include "support/random_contacts.hpp"
#include "tamias2d/dynamics/constraint_graph.hpp"
#include "tamias2d/dynamics/contact_iteration.hpp"
#include "tamias2d/dynamics/restitution.hpp"
#include "tamias2d/dynamics/wide_contact_solver.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;

namespace {

using test::iteration_settings;
using test::random_scene;
using test::Scene;

} // namespace

BOOST_AUTO_TEST_SUITE(wide_contact_solver)

// Oracle: the definition of one soft-step iteration, a sequential Gauss-Seidel pass over the
// manifolds in creation order (contact_iteration.hpp instantiated for one manifold at a time,
// V = double). Constraints that share no moving body commute, so the packed, level-ordered
// solve must give the same numbers exactly; any lane mix-up, lost write or reordering of two
// manifolds on one body shows up as a difference. IM7: the packed solver is how the engine runs
// IM7's iteration, checked against IM7's order (the manifolds one after another in creation
// order); IM7's per-point equations are checked against closed forms elsewhere.
BOOST_AUTO_TEST_CASE(packs_reproduce_the_sequential_pass, *utf::label("IM7")) {
    const ContactSolverSettings st = iteration_settings();
    int compared = 0;
    for (std::uint32_t seed = 1; seed <= 40; ++seed) {
        const Scene scene = random_scene(seed, 3 + int(seed % 17), 5 + int(seed * 7 % 90));

        Scene seq = scene;
        for (int pass = 0; pass < 3; ++pass) {
            for (ContactConstraint& c : seq.constraints)
                iteration::warm_start(c, seq.bodies[c.body_a], seq.bodies[c.body_b]);
            for (bool bias : {true, false}) {
                for (ContactConstraint& c : seq.constraints)
                    iteration::solve(c, seq.bodies[c.body_a], seq.bodies[c.body_b], st, bias);
            }
        }

        Scene wide = scene;
        WideContactSolver solver;
        solver.load(wide.constraints, wide.bodies);
        for (int pass = 0; pass < 3; ++pass) {
            solver.warm_start(wide.bodies);
            solver.solve(wide.bodies, st, true);
            solver.solve(wide.bodies, st, false);
        }
        solver.store(wide.constraints);

        for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
            BOOST_TEST(wide.bodies[i].v.x == seq.bodies[i].v.x);
            BOOST_TEST(wide.bodies[i].v.y == seq.bodies[i].v.y);
            BOOST_TEST(wide.bodies[i].w == seq.bodies[i].w);
        }
        for (std::size_t i = 0; i < scene.constraints.size(); ++i) {
            for (int j = 0; j < scene.constraints[i].count; ++j) {
                const ContactConstraintPoint& a = wide.constraints[i].points[j];
                const ContactConstraintPoint& b = seq.constraints[i].points[j];
                BOOST_TEST(a.normal_impulse == b.normal_impulse);
                BOOST_TEST(a.tangent_impulse == b.tangent_impulse);
                BOOST_TEST(a.max_normal_impulse == b.max_normal_impulse);
                BOOST_TEST(a.total_normal_impulse == b.total_normal_impulse);
                BOOST_TEST(a.total_tangent_impulse == b.total_tangent_impulse);
                ++compared;
            }
        }
        BOOST_TEST(seq.bodies[0].v.x == 0.0); // the static body never moves
    }
    BOOST_TEST(compared > 1000);
    BOOST_TEST_MESSAGE("wide solver: " << compared << " points equal to the sequential pass"
                                       << " ("
                                       << (WideContactSolver::instruction_set()
                                               ? WideContactSolver::instruction_set()
                                               : "baseline")
                                       << ")");
}

// Oracle: the level rule itself, checked pack by pack: every constraint is in exactly one lane,
// no moving body appears twice in a pack, and two constraints on one moving body are solved in
// creation order.
BOOST_AUTO_TEST_CASE(levels_separate_bodies_and_keep_their_order) {
    for (std::uint32_t seed = 100; seed < 120; ++seed) {
        const Scene scene = random_scene(seed, 4 + int(seed % 13), 60);
        std::vector<GraphEdge> edges;
        for (const ContactConstraint& c : scene.constraints)
            edges.push_back({c.body_a, c.body_b, path_group(c.count, 0.0, 0.0, c.use_block)});
        ConstraintGraph graph;
        graph.colour(edges, scene.bodies.size());
        std::vector<int> position(scene.constraints.size(), -1);
        int next = 0;
        for (const ConstraintGraph::Pack& p : graph.packs()) {
            std::set<std::uint32_t> seen;
            for (std::uint32_t i : p) {
                if (i == ConstraintGraph::no_constraint)
                    continue;
                BOOST_TEST_REQUIRE(i < scene.constraints.size());
                BOOST_TEST(position[i] == -1);
                position[i] = next++;
                for (std::uint32_t body :
                     {scene.constraints[i].body_a, scene.constraints[i].body_b})
                    BOOST_TEST((body == 0 || seen.insert(body).second));
            }
        }
        BOOST_TEST(next == int(scene.constraints.size()));
        for (std::size_t i = 0; i < scene.constraints.size(); ++i) {
            for (std::size_t k = i + 1; k < scene.constraints.size(); ++k) {
                const ContactConstraint& a = scene.constraints[i];
                const ContactConstraint& b = scene.constraints[k];
                const bool share =
                    (a.body_a != 0 && (a.body_a == b.body_a || a.body_a == b.body_b)) ||
                    (a.body_b != 0 && (a.body_b == b.body_a || a.body_b == b.body_b));
                if (share)
                    BOOST_TEST(position[i] < position[k]);
            }
        }
    }
}

// Oracle: the packing rule worked by hand. Five manifolds on bodies 1-5 and the static body
// make level 1 (a full pack and one left over); in case A, three more each follow one manifold of
// the full pack, so they join the left-over one; in case B the first of two more follows the
// left-over manifold itself (body 5), so that pack closes with one lane.
BOOST_AUTO_TEST_CASE(packs_fill_across_levels) {
    using P = ConstraintGraph::Pack;
    constexpr std::uint32_t x = ConstraintGraph::no_constraint;
    const auto packs_of = [](std::vector<GraphEdge> edges) {
        ConstraintGraph graph;
        graph.colour(edges, 10);
        return std::vector<P>(graph.packs().begin(), graph.packs().end());
    };
    const std::vector<GraphEdge> level_one = {{1, 0}, {2, 0}, {3, 0}, {4, 0}, {5, 0}};
    std::vector<GraphEdge> a = level_one;
    a.insert(a.end(), {{1, 6}, {2, 7}, {3, 8}});
    const std::vector<P> expected_a = {{0, 1, 2, 3}, {4, 5, 6, 7}};
    BOOST_TEST(packs_of(a) == expected_a);
    std::vector<GraphEdge> b = level_one;
    b.insert(b.end(), {{5, 6}, {1, 7}});
    const std::vector<P> expected_b = {{0, 1, 2, 3}, {4, x, x, x}, {5, 6, x, x}};
    BOOST_TEST(packs_of(b) == expected_b);
}

BOOST_AUTO_TEST_SUITE_END()
