// The filter joint (internal), made from its definition: no constraint, only DD27's joint-filtered
// pair (ContactManager's should_collide asks JointStore::filters). It has no solve: the step's
// preparation leaves it out, so it costs the solver nothing.
#pragma once

#include "tamias2d/dynamics/body.hpp"
#include "tamias2d/dynamics/joints/joint.hpp"
#include "tamias2d/joint_def.hpp"

namespace tamias2d {

/// The joint a validated definition makes between bodies `a` and `b`.
Joint make_joint(const FilterJointDef& def, const Body& a, const Body& b);

} // namespace tamias2d
