// The prismatic joint in the soft step (internal): DD23's line and angle held, with a spring, a
// motor and limits along the axis, solved as IM6 states (joint_solver.hpp).
#pragma once

#include <span>

#include "tamias2d/dynamics/joint.hpp"
#include "tamias2d/dynamics/softness.hpp"
#include "tamias2d/dynamics/solver_body.hpp"

namespace tamias2d {

/// Re-applies the impulses of the previous substep (they carry the solution forward).
void warm_start_prismatic(const Joint& j, std::span<SolverBody> bodies);
/// \srs{IM6} One iteration (DD23): with use_bias the soft solve, without it the rigid relax.
void solve_prismatic(Joint& j, std::span<SolverBody> bodies, const Softness& rigid, double h,
                     bool use_bias);

} // namespace tamias2d
