// The packed contact solver with surface motion (DD46, DD47) against the sequential pass it must
// reproduce bit for bit, as without (tests/engine/test_wide_contact_solver.cpp).
#include <boost/test/unit_test.hpp>

#include <cstdint>
#include <random>

#include "support/random_contacts.hpp"
#include "support/sequential_pass.hpp"
#include "support/wide_solver_access.hpp"
#include "tamias2d/dynamics/contacts/contact_iteration.hpp"
#include "tamias2d/dynamics/contacts/wide_contact_solver.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;

namespace {

/// `rounds` rounds of warm start, soft iteration and relax over the manifolds in creation order,
/// each with its own surface motion (ContactConstraint::surface).
void sequential_with_surfaces(test::Scene& s, int rounds = 3) {
    const ContactSolverSettings st = test::iteration_settings();
    for (int round = 0; round < rounds; ++round) {
        for (ContactConstraint& c : s.constraints)
            iteration::warm_start(c, s.bodies[c.body_a], s.bodies[c.body_b], &c.surface);
        for (const bool bias : {true, false})
            for (ContactConstraint& c : s.constraints)
                iteration::solve(c, s.bodies[c.body_a], s.bodies[c.body_b], st, bias, &c.surface);
    }
}

} // namespace

BOOST_AUTO_TEST_SUITE(surface_motion_solver, *utf::label("internals"))

// Oracle: the definition of one soft-step iteration with surface motion, a sequential
// Gauss-Seidel pass over the manifolds in creation order (contact_iteration.hpp for one
// manifold at a time, V = double, each with its tangent speed and rolling resistance): the
// packs, solved level by level four lanes at once, must give the same numbers exactly (bodies,
// point impulses and rolling impulses), and the surface motion must change them (against the
// same pass without it).
BOOST_AUTO_TEST_CASE(packs_with_surface_motion_reproduce_the_sequential_pass) {
    const ContactSolverSettings st = test::iteration_settings();
    int compared = 0, changed = 0;
    for (std::uint32_t seed = 1; seed <= 30; ++seed) {
        test::Scene scene = test::random_scene(seed, 3 + int(seed % 13), 5 + int(seed * 11 % 80));
        std::mt19937_64 rng(seed ^ 0x5eedu);
        std::uniform_real_distribution<double> speed(-2.0, 2.0), resistance(0.0, 0.3);
        for (ContactConstraint& c : scene.constraints)
            c.surface = {speed(rng), resistance(rng), 0.0};

        test::Scene seq = scene;
        sequential_with_surfaces(seq);
        test::Scene plain = scene;
        test::sequential_passes(plain, test::creation_order(scene));

        test::Scene wide = scene;
        WideContactSolver solver;
        test::load(solver, wide.constraints, wide.bodies);
        solver.use_surfaces(true);
        const auto order = solver.order();
        for (std::size_t p = 0; p < order.size(); ++p) {
            for (int l = 0; l < wide_lanes; ++l) {
                const std::uint32_t k = order[p][l];
                if (k == ConstraintGraph::no_constraint)
                    solver.set_surface_lane(p, l, 0.0, 0.0, 0.0);
                else
                    solver.set_surface_lane(p, l, wide.constraints[k].surface.tangent_speed,
                                            wide.constraints[k].surface.rolling_resistance, 0.0);
            }
        }
        for (int pass = 0; pass < 3; ++pass) {
            solver.warm_start(wide.bodies);
            solver.solve(wide.bodies, st, true);
            solver.solve(wide.bodies, st, false);
        }
        test::store(solver, wide.constraints);
        const auto surfaces = WideContactSolverAccess::surfaces(solver);
        for (std::size_t p = 0; p < order.size(); ++p)
            for (int l = 0; l < wide_lanes; ++l)
                if (order[p][l] != ConstraintGraph::no_constraint)
                    wide.constraints[order[p][l]].surface.rolling_impulse =
                        surfaces[p].rolling_impulse[l];

        test::check_same_pass(wide, seq);
        for (std::size_t i = 0; i < seq.constraints.size(); ++i) {
            BOOST_TEST(wide.constraints[i].surface.rolling_impulse ==
                       seq.constraints[i].surface.rolling_impulse);
            compared += seq.constraints[i].count;
        }
        for (std::size_t i = 1; i < seq.bodies.size(); ++i)
            if (seq.bodies[i].w != plain.bodies[i].w || seq.bodies[i].v.x != plain.bodies[i].v.x)
                ++changed;
    }
    BOOST_TEST(compared > 500);
    BOOST_TEST(changed > 50);
}

BOOST_AUTO_TEST_SUITE_END()
