// The joints in the soft step (internal): what every kind shares (the step's preparation of a
// joint's frames, the anchors as the bodies turn) and the dispatch to each kind's warm start
// and iterations (revolute_joint.hpp, distance_joint.hpp).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "tamias2d/dynamics/joint.hpp"
#include "tamias2d/dynamics/softness.hpp"
#include "tamias2d/dynamics/solver_body.hpp"

namespace tamias2d {

struct BodyStore;

/// The joint's solver bodies, the anchors' offsets from the centres (body frames), the bodies'
/// angles and the centres' offset at the step's start.
void prepare_joint(Joint& j, const BodyStore& bodies,
                   const std::vector<std::uint32_t>& solver_index);

/// An anchor's offset from its body's centre in the world frame, with the body turned by the
/// rotation it has made so far in the step (dq), as the write-back will place it.
inline Vec2d anchor_offset(Vec2d frame, double angle, const SolverBody& b) {
    return rotate(Rot::from_angle(angle + b.dq), frame);
}

/// Re-applies the impulses of the previous substep (they carry the solution forward).
void warm_start_joint(const Joint& j, std::span<SolverBody> bodies);
/// \srs{IM6} One iteration of the joint: with use_bias the soft solve (the rigid parts pulled
/// back by `rigid`'s bias, a spring by its own softness for the substep h), without it the
/// relax of the rigid parts.
void solve_joint(Joint& j, std::span<SolverBody> bodies, const Softness& rigid, double h,
                 bool use_bias);

} // namespace tamias2d
