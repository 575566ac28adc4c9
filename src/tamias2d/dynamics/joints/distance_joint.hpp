// The distance joint (internal), made from its definition and solved in the soft step: DD20's
// constraint along the anchors' axis, rigid (IM6's soft bias, relaxed like the revolute joint) or a
// spring-damper (the joint's own softness, in the biased iteration only: a spring is a force, not
// an error to relax), and DD35's motor on the length's rate.
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
Joint make_joint(const DistanceJointDef& def, const Body& a, const Body& b);

void warm_start_distance(const JointSim& s, const Joint& j, std::span<SolverBody> bodies);
/// \srs{IM6} One iteration (joint_solver.hpp's solve_joint).
void solve_distance(JointSim& s, const Joint& j, std::span<SolverBody> bodies, double h,
                    bool use_bias);

} // namespace tamias2d
