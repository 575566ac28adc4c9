// The revolute joint (internal), made from its definition and solved in the soft step: DD19's pin
// constraint, solved as IM6 states. Per substep the step warm starts it, solves it with the soft
// bias, and after the positions relaxes it without the bias, always before the contacts
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
Joint make_joint(const RevoluteJointDef& def, const Body& a, const Body& b);

/// Re-applies the impulses of the previous substep (they carry the solution forward).
void warm_start_revolute(const JointSim& s, std::span<SolverBody> bodies);
/// \srs{IM6} One iteration: with use_bias the soft solve that also pulls the pins together
/// (DD19's impulse with the soft bias), without it the rigid relax. The spring, motor and
/// limits (DD22) come first, then the pin: the pin, solved last, holds best.
void solve_revolute(JointSim& s, const Joint& j, std::span<SolverBody> bodies, double h,
                    bool use_bias);

} // namespace tamias2d
