// The motor joint (internal), made from its definition and solved in the soft step: DD26, body B
// driven towards a pose relative to body A with bounded force and torque (joint_solver.hpp).
#pragma once

#include <span>

#include "tamias2d/dynamics/body.hpp"
#include "tamias2d/dynamics/joints/joint.hpp"
#include "tamias2d/dynamics/joints/joint_sim.hpp"
#include "tamias2d/dynamics/solver_body.hpp"
#include "tamias2d/joint_def.hpp"

namespace tamias2d {

/// The joint a validated definition makes, its anchors fixed on bodies `a` and `b` as they
/// are now.
Joint make_joint(const MotorJointDef& def, const Body& a, const Body& b);

// Its warm start is joint_solver.hpp's warm_start_pin_and_angle.

/// \srs{IM6} One iteration (DD26), in the soft solve only: the relax would brake the drive.
void solve_motor(JointSim& s, const Joint& j, std::span<SolverBody> bodies, double h,
                 bool use_bias);

} // namespace tamias2d
