// The wide contact solver (four manifolds per pack, grouped by ConstraintGraph's levels) against
// the sequential Gauss-Seidel pass in creation order that it must reproduce bit for bit (NFR1's
// speed must not change IM3's results).
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <set>
#include <vector>

#include "support/contact_manager_access.hpp"
#include "support/random_contacts.hpp"
#include "support/sequential_pass.hpp"
#include "support/wide_solver_access.hpp"
#include "tamias2d/dynamics/constraint_graph.hpp"
#include "tamias2d/dynamics/contacts/contact_iteration.hpp"
#include "tamias2d/dynamics/contacts/contact_manager.hpp"
#include "tamias2d/dynamics/contacts/restitution.hpp"
#include "tamias2d/dynamics/contacts/wide_contact_solver.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;

namespace {

using test::check_same_pass;
using test::creation_order;
using test::iteration_settings;
using test::random_scene;
using test::Scene;
using test::sequential_passes;

/// Lane l of a pack, by value (a reference cannot bind to a vector element).
double lane(const Wide& w, int l) {
    return w[l];
}

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
        sequential_passes(seq, creation_order(scene));

        Scene wide = scene;
        WideContactSolver solver;
        test::load(solver, wide.constraints, wide.bodies);
        for (int pass = 0; pass < 3; ++pass) {
            solver.warm_start(wide.bodies);
            solver.solve(wide.bodies, st, true);
            solver.solve(wide.bodies, st, false);
        }
        test::store(solver, wide.constraints);

        check_same_pass(wide, seq);
        for (const ContactConstraint& c : scene.constraints)
            compared += c.count;
    }
    BOOST_TEST(compared > 1000);
    BOOST_TEST_MESSAGE("wide solver: " << compared << " points equal to the sequential pass"
                                       << " ("
                                       << (WideContactSolver::instruction_set()
                                               ? WideContactSolver::instruction_set()
                                               : "baseline")
                                       << ")");
}

// Oracle: the same sequential pass. The packs' path groups only order manifolds within a level,
// which commute, so packs kept from an earlier colouring whose groups differ (colour keeps them
// while at most 1 in regroup_share manifolds changed group) must give the same numbers too:
// the solver is first loaded with some two-point manifolds' separations negated (apart <->
// touching), then with the scene itself.
BOOST_AUTO_TEST_CASE(kept_packs_reproduce_the_sequential_pass, *utf::label("internals")) {
    const ContactSolverSettings st = iteration_settings();
    int regrouped = 0; // seeds whose kept packs differ from the scene's own
    for (std::uint32_t seed = 1; seed <= 40; ++seed) {
        const Scene scene = random_scene(seed, 3 + int(seed % 17), 16 + int(seed * 7 % 90));

        Scene seq = scene;
        sequential_passes(seq, creation_order(scene), 1);

        Scene earlier = scene;
        std::size_t flipped = 0;
        for (ContactConstraint& c : earlier.constraints) {
            if (c.count != 2 ||
                (flipped + 1) * ConstraintGraph::regroup_share > earlier.constraints.size())
                continue;
            for (ContactConstraintPoint& p : c.points)
                p.base_separation = -p.base_separation;
            ++flipped;
        }
        Scene wide = scene;
        WideContactSolver solver;
        test::load(solver, earlier.constraints, earlier.bodies);
        const std::vector<ConstraintGraph::Pack> before(solver.graph().packs().begin(),
                                                        solver.graph().packs().end());
        test::load(solver, wide.constraints, wide.bodies);
        const std::vector<ConstraintGraph::Pack> after(solver.graph().packs().begin(),
                                                       solver.graph().packs().end());
        BOOST_TEST(after == before); // kept, so this is the case under test
        WideContactSolver afresh;
        test::load(afresh, scene.constraints, scene.bodies);
        regrouped += !std::equal(after.begin(), after.end(), afresh.graph().packs().begin(),
                                 afresh.graph().packs().end());
        solver.warm_start(wide.bodies);
        solver.solve(wide.bodies, st, true);
        solver.solve(wide.bodies, st, false);
        test::store(solver, wide.constraints);

        check_same_pass(wide, seq);
    }
    BOOST_TEST(regrouped > 20);
    BOOST_TEST_MESSAGE("kept packs: " << regrouped << " of 40 scenes' differ from their own packs");
}

// Oracle: the level rule itself, checked pack by pack: every constraint is in exactly one lane,
// no moving body appears twice in a pack, and two constraints on one moving body are solved in
// creation order.
BOOST_AUTO_TEST_CASE(levels_separate_bodies_and_keep_their_order) {
    for (std::uint32_t seed = 100; seed < 120; ++seed) {
        const Scene scene = random_scene(seed, 4 + int(seed % 13), 60);
        std::vector<GraphEdge> edges;
        for (const ContactConstraint& c : scene.constraints)
            edges.push_back(test::prepared_edge(c));
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

// Oracle: the rule for keeping packs and regions, with a fresh graph as the colouring of given
// inputs. A graph coloured before gives the packs of the last inputs it coloured while the
// manifolds' bodies and the number of regions stay and at most 1 in regroup_share manifolds
// changed group since; otherwise those of the new inputs, in the regions drawn at the last
// change of bodies.
BOOST_AUTO_TEST_CASE(packs_are_kept_only_while_the_bodies_and_most_groups_stay) {
    using Packs = std::vector<ConstraintGraph::Pack>;
    const auto fresh = [](const std::vector<GraphEdge>& edges, std::uint32_t regions,
                          const std::vector<double>& cut) {
        ConstraintGraph g;
        g.colour(edges, 30, regions, cut);
        return Packs(g.packs().begin(), g.packs().end());
    };
    std::mt19937 rng(7);
    std::uniform_int_distribution<std::uint32_t> body(0, 29);
    std::vector<GraphEdge> start;
    while (start.size() < 160) {
        const std::uint32_t a = body(rng), b = body(rng);
        if (a != b)
            start.push_back({a, b, PathGroup(rng() % path_groups)});
    }
    const std::size_t few = start.size() / ConstraintGraph::regroup_share;
    const auto regrouped = [&](std::size_t count) {
        std::vector<GraphEdge> e = start;
        for (std::size_t i = 0; i < count; ++i)
            e[i].group = PathGroup((std::uint32_t(e[i].group) + 1) % path_groups);
        return e;
    };
    std::vector<double> cut(30);
    for (std::size_t i = 0; i < cut.size(); ++i)
        cut[i] = double(i % 10);
    for (const std::uint32_t regions : {1u, 2u}) {
        ConstraintGraph g;
        const auto packs = [&] { return Packs(g.packs().begin(), g.packs().end()); };
        g.colour(start, 30, regions, cut);
        BOOST_TEST((packs() == fresh(start, regions, cut)));
        // A few regrouped: the packs of `start`, which here differ from the new inputs' own.
        g.colour(regrouped(few), 30, regions, cut);
        BOOST_TEST((packs() == fresh(start, regions, cut)));
        BOOST_TEST((packs() != fresh(regrouped(few), regions, cut)));
        // One more: coloured afresh.
        g.colour(regrouped(few + 1), 30, regions, cut);
        BOOST_TEST((packs() == fresh(regrouped(few + 1), regions, cut)));
        // A body changed.
        std::vector<GraphEdge> moved = regrouped(few + 1);
        moved[40].body_b = moved[40].body_a == 29 ? 28 : 29;
        g.colour(moved, 30, regions, cut);
        BOOST_TEST((packs() == fresh(moved, regions, cut)));
        // One region more or less.
        g.colour(moved, 30, 3 - regions, cut);
        BOOST_TEST((packs() == fresh(moved, 3 - regions, cut)));
        g.colour(moved, 30, regions, cut);
        BOOST_TEST((packs() == fresh(moved, regions, cut)));
    }
    // The same edges with bodies moved across a region's bound: each manifold keeps its region
    // (the regions are drawn when the manifolds change), and the packs are kept; a body changed,
    // and they are drawn at the new places.
    ConstraintGraph g;
    g.colour(start, 30, 2, cut);
    std::vector<double> across = cut;
    for (std::size_t i = 0; i < across.size(); ++i)
        if (across[i] < 1.0)
            across[i] = 9.5;
    BOOST_TEST((fresh(start, 2, across) != fresh(start, 2, cut)));
    g.colour(start, 30, 2, across);
    BOOST_TEST((Packs(g.packs().begin(), g.packs().end()) == fresh(start, 2, cut)));
    g.colour(regrouped(few + 1), 30, 2, across); // recoloured in the regions drawn at `cut`
    BOOST_TEST((Packs(g.packs().begin(), g.packs().end()) == fresh(regrouped(few + 1), 2, cut)));
    std::vector<GraphEdge> moved = start;
    moved[40].body_b = moved[40].body_a == 29 ? 28 : 29;
    g.colour(moved, 30, 2, across);
    BOOST_TEST((Packs(g.packs().begin(), g.packs().end()) == fresh(moved, 2, across)));
}

// Oracle: the lane filled through a ContactConstraint (ContactManager::unprepared_constraint,
// then set_input_lane from it, which test::load uses and the IM7 tests above check against the
// sequential pass). The world's path fills the lane from the contact directly; every field of
// the lane must come out the same, over one- and two-point manifolds, filled over a lane that
// held another manifold before.
BOOST_AUTO_TEST_CASE(a_lane_from_the_contact_is_the_lane_from_its_constraint) {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    ContactManager contacts;
    for (int k = 0; k < 12; ++k) {
        Contact c;
        c.friction = 0.5 + 0.5 * u(rng);
        c.manifold.normal = {std::cos(3.0 * u(rng)), std::sin(3.0 * u(rng))};
        c.manifold.count = 1 + k % 2;
        for (int j = 0; j < c.manifold.count; ++j) {
            ManifoldPoint& p = c.manifold.points[j];
            p.anchor_a = {u(rng), u(rng)};
            p.anchor_b = {u(rng), u(rng)};
            p.separation = 0.01 * u(rng);
        }
        const double n0 = u(rng), n1 = u(rng), t0 = u(rng), t1 = u(rng); // (in draw order)
        ContactManagerAccess::add(contacts, c, {{n0, n1}, {t0, t1}});
    }
    WideManifoldInput staged, direct;
    for (std::uint32_t k = 0; k < 12; ++k) {
        const int l = int(k % wide_lanes);
        const GraphEdge edge{k + 1, k % 3 == 0 ? 0u : k + 2, PathGroup::point_by_point};
        const std::uint32_t slot = k % 4 == 0 ? WideContactSolver::no_slot : k;
        ContactConstraint cc;
        contacts.unprepared_constraint(cc, edge, k);
        set_input_lane(staged, l, cc, slot);
        set_input_lane(direct, l, edge, k, contacts.contacts()[k], contacts.warm_impulses()[k],
                       slot);
        BOOST_TEST(direct.body_a[l] == staged.body_a[l]);
        BOOST_TEST(direct.body_b[l] == staged.body_b[l]);
        BOOST_TEST(direct.contact[l] == staged.contact[l]);
        BOOST_TEST(direct.restitution_slot[l] == staged.restitution_slot[l]);
        BOOST_TEST(direct.count[l] == staged.count[l]);
        BOOST_TEST(lane(direct.normal.x, l) == lane(staged.normal.x, l));
        BOOST_TEST(lane(direct.normal.y, l) == lane(staged.normal.y, l));
        BOOST_TEST(lane(direct.friction, l) == lane(staged.friction, l));
        for (int j = 0; j < 2; ++j) {
            BOOST_TEST(lane(direct.r_a[j].x, l) == lane(staged.r_a[j].x, l));
            BOOST_TEST(lane(direct.r_a[j].y, l) == lane(staged.r_a[j].y, l));
            BOOST_TEST(lane(direct.r_b[j].x, l) == lane(staged.r_b[j].x, l));
            BOOST_TEST(lane(direct.r_b[j].y, l) == lane(staged.r_b[j].y, l));
            BOOST_TEST(lane(direct.separation[j], l) == lane(staged.separation[j], l));
            BOOST_TEST(lane(direct.normal_impulse[j], l) == lane(staged.normal_impulse[j], l));
            BOOST_TEST(lane(direct.tangent_impulse[j], l) == lane(staged.tangent_impulse[j], l));
        }
    }
}

BOOST_AUTO_TEST_SUITE_END()
