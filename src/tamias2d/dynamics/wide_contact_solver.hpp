// The contact iterations of the soft step on packs of four manifolds (one per lane, grouped by
// ConstraintGraph's levels). The result equals the sequential Gauss-Seidel pass over the
// manifolds in creation order, bit for bit (tests/dynamics/test_wide_contact_solver.cpp).
#pragma once

#include <span>
#include <vector>

#include "tamias2d/dynamics/constraint_graph.hpp"
#include "tamias2d/dynamics/contact.hpp"
#include "tamias2d/dynamics/contact_constraint.hpp"
#include "tamias2d/dynamics/contact_solver.hpp"
#include "tamias2d/dynamics/solver_body.hpp"
#include "tamias2d/dynamics/wide_contact_constraint.hpp"

namespace tamias2d {

class WideContactSolver {
  public:
    /// Colours the prepared constraints (prepare_contacts) and packs them lane by lane.
    void load(std::span<const ContactConstraint> constraints, std::span<const SolverBody> bodies);
    /// Re-applies the accumulated impulses (they carry the previous substep's solution forward).
    void warm_start(std::span<SolverBody> bodies);
    /// One iteration: with use_bias the soft, overlap-removing solve; without it the rigid relax.
    void solve(std::span<SolverBody> bodies, const ContactSolverSettings& settings, bool use_bias);
    /// Copies the impulses back into the constraints.
    void store(std::span<ContactConstraint> constraints) const;
    /// Copies the impulses into the persistent contacts (warm start next step, contact report)
    /// and, for the manifolds that can bounce, into their constraints (restitution pass).
    void store(std::span<ContactConstraint> constraints, std::span<Contact> contacts) const;

    /// The packs in solve order (the benchmark runs its own instantiation of the loops on them).
    std::span<WideContactConstraint> packs() { return packs_; }
    /// Whether this processor runs the packs with AVX2 (otherwise SSE2; the results are equal).
    static bool uses_avx2();

  private:
    ConstraintGraph graph_;
    std::vector<WideContactConstraint> packs_;
};

} // namespace tamias2d
