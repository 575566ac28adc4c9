// The oracle of the packed contact solves: IM7's iteration as a sequential Gauss-Seidel pass,
// one manifold after another (contact_iteration.hpp for one manifold at a time), and the check
// that a packed solve reproduced its numbers exactly.
#pragma once

#include <boost/test/unit_test.hpp>

#include <cstdint>
#include <numeric>
#include <vector>

#include "support/random_contacts.hpp"
#include "tamias2d/dynamics/contacts/contact_iteration.hpp"

namespace tamias2d::test {

/// The manifolds in creation order.
inline std::vector<std::uint32_t> creation_order(const Scene& s) {
    std::vector<std::uint32_t> order(s.constraints.size());
    std::iota(order.begin(), order.end(), 0u);
    return order;
}

/// `rounds` rounds of warm start, soft iteration and relax over the manifolds in `sequence`.
inline void sequential_passes(Scene& s, const std::vector<std::uint32_t>& sequence,
                              int rounds = 3) {
    const ContactSolverSettings st = iteration_settings();
    for (int round = 0; round < rounds; ++round) {
        for (std::uint32_t i : sequence) {
            ContactConstraint& c = s.constraints[i];
            iteration::warm_start(c, s.bodies[c.body_a], s.bodies[c.body_b]);
        }
        for (const bool bias : {true, false}) {
            for (std::uint32_t i : sequence) {
                ContactConstraint& c = s.constraints[i];
                iteration::solve(c, s.bodies[c.body_a], s.bodies[c.body_b], st, bias);
            }
        }
    }
}

/// Every body's velocities and every point's impulses of `packed` equal `sequential`'s.
inline void check_same_pass(const Scene& packed, const Scene& sequential) {
    for (std::size_t i = 0; i < sequential.bodies.size(); ++i) {
        BOOST_TEST(packed.bodies[i].v.x == sequential.bodies[i].v.x);
        BOOST_TEST(packed.bodies[i].v.y == sequential.bodies[i].v.y);
        BOOST_TEST(packed.bodies[i].w == sequential.bodies[i].w);
    }
    for (std::size_t i = 0; i < sequential.constraints.size(); ++i) {
        for (int j = 0; j < sequential.constraints[i].count; ++j) {
            const ContactConstraintPoint& a = packed.constraints[i].points[j];
            const ContactConstraintPoint& b = sequential.constraints[i].points[j];
            BOOST_TEST(a.normal_impulse == b.normal_impulse);
            BOOST_TEST(a.tangent_impulse == b.tangent_impulse);
            BOOST_TEST(a.max_normal_impulse == b.max_normal_impulse);
            BOOST_TEST(a.total_normal_impulse == b.total_normal_impulse);
            BOOST_TEST(a.total_tangent_impulse == b.total_tangent_impulse);
        }
    }
    BOOST_TEST(sequential.bodies[0].v.x == 0.0); // the static body never moves
}

} // namespace tamias2d::test
