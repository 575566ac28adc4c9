// Contact constraints given as an array, in and out of a WideContactSolver, for the tests of the
// packed solves and the typing benchmark. The engine never holds such an array: it fills the
// packs lane by lane from its persistent contacts and stores their impulses back into them
// (StepSolver). Built on the solver's public colour, order and prepare_pack; reading the packs
// back takes the one friend of the solver's private packs.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "tamias2d/dynamics/constraint_graph.hpp"
#include "tamias2d/dynamics/contacts/contact_constraint.hpp"
#include "tamias2d/dynamics/contacts/restitution.hpp"
#include "tamias2d/dynamics/contacts/wide_contact_solver.hpp"
#include "tamias2d/dynamics/solver_body.hpp"

namespace tamias2d {

struct WideContactSolverAccess {
    /// The packs in solve order, one per pack of the solver's order().
    static std::span<WideContactConstraint> packs(WideContactSolver& s) {
        return {s.packs_.data(), s.packs_.size()};
    }
    static std::span<const WideContactConstraint> packs(const WideContactSolver& s) {
        return {s.packs_.data(), s.packs_.size()};
    }
    /// The packs' surface motion (DD46, DD47), indexed like the packs while it is used.
    static std::span<const WideSurfaceMotion> surfaces(const WideContactSolver& s) {
        return {s.surfaces_.data(), s.surfaces_.size()};
    }
};

namespace test {

/// prepare_contact on every constraint.
inline void prepare_contacts(std::span<ContactConstraint> constraints,
                             std::span<const SolverBody> bodies) {
    for (ContactConstraint& c : constraints)
        prepare_contact(c, bodies);
}

/// A prepared constraint's edge for the colouring tests, grouped by the path its preparation
/// chose: a two-point manifold too ill-conditioned for the block goes point by point.
inline GraphEdge prepared_edge(const ContactConstraint& c) {
    return {c.body_a, c.body_b,
            c.use_block ? path_group(c.count, 0.0, 0.0) : PathGroup::point_by_point};
}

/// colour and prepare_pack for prepared constraints: their bodies, normals, friction, anchors,
/// separations and warm-start impulses are read; their edges are grouped as the engine groups
/// its contacts' (by count and separations).
inline void load(WideContactSolver& solver, std::span<const ContactConstraint> constraints,
                 std::span<const SolverBody> bodies, std::uint32_t regions = 1,
                 std::span<const double> cut = {}) {
    std::vector<GraphEdge> edges;
    edges.reserve(constraints.size());
    for (const ContactConstraint& c : constraints) {
        edges.push_back(
            {c.body_a, c.body_b,
             path_group(c.count, c.points[0].base_separation, c.points[1].base_separation)});
    }
    solver.colour(edges, bodies.size(), regions, cut);
    const auto lanes = solver.order();
    WideManifoldInput in; // one for all packs, as the world's lane filling uses it
    for (std::size_t i = 0; i < lanes.size(); ++i) {
        for (int l = 0; l < wide_lanes; ++l) {
            const std::uint32_t k = lanes[i][l];
            if (k == ConstraintGraph::no_constraint)
                clear_input_lane(in, l);
            else
                set_input_lane(in, l, constraints[k], WideContactSolver::no_slot);
        }
        solver.prepare_pack(i, in, bodies);
    }
}

/// Copies the packs' impulses (accumulated, largest and total) back into the constraints given
/// to load.
inline void store(const WideContactSolver& solver, std::span<ContactConstraint> constraints) {
    const auto order = solver.order();
    const auto packs = WideContactSolverAccess::packs(solver);
    for (std::size_t i = 0; i < order.size(); ++i) {
        const WideContactConstraint& w = packs[i];
        for (int l = 0; l < wide_lanes; ++l) {
            for (int j = 0; j < w.count[l]; ++j) {
                const WideContactConstraintPoint& q = w.points[j];
                ContactConstraintPoint& p = constraints[order[i][l]].points[j];
                p.normal_impulse = q.normal_impulse[l];
                p.tangent_impulse = q.tangent_impulse[l];
                p.max_normal_impulse = q.max_normal_impulse[l];
                p.total_normal_impulse = q.total_normal_impulse[l];
                p.total_tangent_impulse = q.total_tangent_impulse[l];
            }
        }
    }
}

} // namespace test

} // namespace tamias2d
