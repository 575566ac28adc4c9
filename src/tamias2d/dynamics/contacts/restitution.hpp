// The restitution pass of the soft step (DD12 on the pre-step normal velocity, after the
// substeps; see docs/design.md) and the scalar preparation of the manifolds it solves. The
// substeps' contact iterations run on packs of four manifolds (wide_contact_solver.hpp,
// contact_iteration.hpp).
#pragma once

#include <cstdint>
#include <span>

#include "tamias2d/dynamics/contacts/contact_constraint.hpp"
#include "tamias2d/dynamics/solver_body.hpp"
#include "tamias2d/dynamics/solver_settings.hpp"

namespace tamias2d {

/// Effective masses (DD8), block matrices and the pre-step normal velocities of one constraint
/// (the world prepares each as it builds it). The constraint's bodies, normal, friction,
/// restitution, count and its points' anchors, separations and warm-start impulses must be
/// filled in; everything else is set here (points past count are never read).
void prepare_contact(ContactConstraint& c, std::span<const SolverBody> bodies);
/// DD12: where bodies approached (v_n < -threshold) and pushed, drive v_n to -C_R v_n(before),
/// solved on the step's total impulses over all manifolds (a few Gauss-Seidel passes) with
/// targets that keep the step's impulses from adding kinetic energy (docs/verification.md, E1/E3).
/// `bouncing` holds, in creation order, the manifolds with a restitution above 0 (the others
/// never bounce, so the pass does not see them), with their impulses after the iterations.
void apply_restitution(std::span<ContactConstraint> bouncing, std::span<SolverBody> bodies,
                       const ContactSolverSettings& settings);

} // namespace tamias2d
