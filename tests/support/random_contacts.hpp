// Random contact manifolds between solver bodies, for the tests of the contact iterations and
// their orders (the wide solver, the colouring, the contact regions).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "support/wide_solver_access.hpp"
#include "tamias2d/dynamics/contacts/contact_constraint.hpp"
#include "tamias2d/dynamics/softness.hpp"
#include "tamias2d/dynamics/solver_body.hpp"
#include "tamias2d/dynamics/solver_settings.hpp"

namespace tamias2d::test {

struct Scene {
    std::vector<SolverBody> bodies; ///< 0 is the static body
    std::vector<ContactConstraint> constraints;
};

/// Random manifolds on a few bodies (many share a body, some the static body 0), with one or
/// two points, some frictionless, some speculative (positive separation), some penetrating.
inline Scene random_scene(std::uint32_t seed, int body_count, int constraint_count) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Scene s;
    s.bodies.assign(1, SolverBody{});
    for (int i = 1; i < body_count; ++i) {
        SolverBody b;
        b.v = {u(rng), u(rng)};
        b.w = u(rng);
        b.inv_m = 1.0 + 0.5 * u(rng);
        b.inv_I = 6.0 + 3.0 * u(rng);
        s.bodies.push_back(b);
    }
    std::uniform_int_distribution<std::uint32_t> body(0, std::uint32_t(body_count - 1));
    while (int(s.constraints.size()) < constraint_count) {
        ContactConstraint c;
        c.body_a = body(rng);
        c.body_b = body(rng);
        if (c.body_a == c.body_b || (c.body_a == 0 && c.body_b == 0))
            continue;
        const double angle = 3.2 * u(rng);
        c.normal = {std::cos(angle), std::sin(angle)};
        c.friction = u(rng) < -0.6 ? 0.0 : 0.6;
        c.count = u(rng) < -0.3 ? 1 : 2;
        for (int j = 0; j < c.count; ++j) {
            ContactConstraintPoint& p = c.points[j];
            p.r_a = {0.5 * u(rng), 0.5 * u(rng)};
            p.r_b = {0.5 * u(rng), 0.5 * u(rng)};
            p.base_separation = 0.02 * u(rng);
            p.normal_impulse = std::max(0.0, u(rng));
            p.tangent_impulse = 0.3 * u(rng);
        }
        s.constraints.push_back(c);
    }
    prepare_contacts(s.constraints, s.bodies);
    return s;
}

/// The iteration's settings the tests of its orders share: substeps of 1/240 s, a 30 Hz
/// contact spring, some slop and a restitution threshold.
inline ContactSolverSettings iteration_settings() {
    ContactSolverSettings st;
    st.inv_h = 240.0;
    st.softness = make_softness(30.0, 10.0, 1.0 / 240.0);
    st.linear_slop = 0.005;
    st.push_max_velocity = 3.0;
    st.restitution_threshold = 1.0;
    return st;
}

} // namespace tamias2d::test
