// The target joint (internal), made from its definition and solved in the soft step: DD21, a
// spring-damper pulling a point of one body towards a target with a bounded force (a drag with the
// mouse). Like the distance joint's spring it is a force, so it acts in the biased iteration only.
#pragma once

#include <span>

#include "tamias2d/dynamics/body.hpp"
#include "tamias2d/dynamics/joints/joint.hpp"
#include "tamias2d/dynamics/joints/joint_sim.hpp"
#include "tamias2d/dynamics/solver_body.hpp"
#include "tamias2d/joint_def.hpp"

namespace tamias2d {

/// The joint a validated definition makes, its target grabbed on body `b` as it is now.
Joint make_joint(const TargetJointDef& def, const Body& b);

void warm_start_target(const JointSim& s, std::span<SolverBody> bodies);
/// \srs{IM6} One iteration (joint_solver.hpp's solve_joint).
void solve_target(JointSim& s, const Joint& j, std::span<SolverBody> bodies, double h,
                  bool use_bias);

} // namespace tamias2d
