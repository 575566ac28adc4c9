// The prismatic joint (internal), made from its definition and solved in the soft step: DD23's line
// and angle held, with a spring, a motor and limits along the axis, solved as IM6 states
// (joint_solver.hpp).
#pragma once

#include <span>

#include "tamias2d/dynamics/body.hpp"
#include "tamias2d/dynamics/joints/joint.hpp"
#include "tamias2d/dynamics/joints/joint_sim.hpp"
#include "tamias2d/dynamics/softness.hpp"
#include "tamias2d/dynamics/solver_body.hpp"
#include "tamias2d/joint_def.hpp"

namespace tamias2d {

/// The joint a validated definition makes, its anchors fixed on bodies `a` and `b` as they
/// are now.
Joint make_joint(const PrismaticJointDef& def, const Body& a, const Body& b);

/// Re-applies the impulses of the previous substep (they carry the solution forward).
void warm_start_prismatic(const JointSim& s, const Joint& j, std::span<SolverBody> bodies);
/// \srs{IM6} One iteration (DD23): with use_bias the soft solve, without it the rigid relax.
void solve_prismatic(JointSim& s, const Joint& j, std::span<SolverBody> bodies, double h,
                     bool use_bias);

} // namespace tamias2d
