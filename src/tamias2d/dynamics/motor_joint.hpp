// The motor joint in the soft step (internal): DD26, body B driven towards a pose relative to
// body A with bounded force and torque (joint_solver.hpp).
#pragma once

#include <span>

#include "tamias2d/dynamics/joint.hpp"
#include "tamias2d/dynamics/solver_body.hpp"

namespace tamias2d {

/// Re-applies the impulses of the previous substep (they carry the solution forward).
void warm_start_motor(const Joint& j, std::span<SolverBody> bodies);
/// \srs{IM6} One iteration (DD26), in the soft solve only: the relax would brake the drive.
void solve_motor(Joint& j, std::span<SolverBody> bodies, double h, bool use_bias);

} // namespace tamias2d
