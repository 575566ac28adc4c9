// The joints in the soft step (internal): what every kind shares (the step's preparation of a
// joint's frames, the anchors as the bodies turn, the pin, the motor, the spring and the
// limits that several kinds are built from) and the dispatch to each kind's warm start and
// iterations (revolute_joint.hpp, distance_joint.hpp, ...).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "tamias2d/dynamics/joints/joint.hpp"
#include "tamias2d/dynamics/model_bridge.hpp"
#include "tamias2d/dynamics/softness.hpp"
#include "tamias2d/dynamics/solver_body.hpp"
#include "tamias2d/memory/allocator.hpp"

namespace tamias2d {

struct BodyStore;

/// The joint's solver bodies, the anchors' offsets from the centres (body frames), the bodies'
/// angles and the centres' offset at the step's start.
void prepare_joint(Joint& j, const BodyStore& bodies,
                   const memory::vector<std::uint32_t>& solver_index);

/// The anchors' offsets from their bodies' centres in the world frame, with the bodies turned
/// as far as they have in the step (q_a, q_b: the step solver keeps them current).
inline Vec2d anchor_a(const Joint& j) {
    return rotate(j.step.q_a, j.step.frame_a);
}
inline Vec2d anchor_b(const Joint& j) {
    return rotate(j.step.q_b, j.step.frame_b);
}

/// The joint angle (DD22) now: the bodies' angles at the step's start plus their turn since.
inline double current_joint_angle(const Joint& j, const SolverBody& a, const SolverBody& b) {
    return bridge::joint_angle(j.step.angle_a + a.dq, j.step.angle_b + b.dq, j.reference_angle);
}

/// A prismatic or wheel joint's line now (DD23): the anchors' offsets, the axis (fixed in
/// body A, turned with it) and the translation, line error and moment arms along it.
struct LineFrame {
    Vec2d r_a, r_b, axis;
    bridge::Line line;
};
LineFrame line_frame(const Joint& j, const SolverBody& a, const SolverBody& b);

/// \srs{IM6} DD19's pin (revolute, weld): with use_bias the soft solve that also pulls the
/// pins together, without it the rigid relax.
void solve_pin(Joint& j, SolverBody& a, SolverBody& b, const Softness& softness, bool use_bias);
/// DD22's motor on the relative turn, its accumulation bounded by max_motor h.
void solve_angular_motor(Joint& j, SolverBody& a, SolverBody& b, double h);
/// DD22's limits on the joint angle [lower_limit, upper_limit] (rad).
void solve_angular_limits(Joint& j, SolverBody& a, SolverBody& b, const Softness& softness,
                          double h, bool use_bias);
/// DD20/DD23: limits [lower_limit, upper_limit] on a length along the axis n with the given moment
/// arms.
void solve_axial_limits(Joint& j, SolverBody& a, SolverBody& b, double arm_a, double arm_b, Vec2d n,
                        double value, const Softness& softness, double h, bool use_bias);
/// DD23: a spring along the axis n pulling `value` to the joint's spring target (soft solve
/// only).
void solve_axial_spring(Joint& j, SolverBody& a, SolverBody& b, double arm_a, double arm_b, Vec2d n,
                        double value, double h);

/// Re-applies the impulses of the previous substep (they carry the solution forward).
void warm_start_joint(const Joint& j, std::span<SolverBody> bodies);
/// \srs{IM6} One iteration of the joint: with use_bias the soft solve (the rigid parts pulled
/// back by `rigid`'s bias, a spring by its own softness for the substep h), without it the
/// relax of the rigid parts.
void solve_joint(Joint& j, std::span<SolverBody> bodies, const Softness& rigid, double h,
                 bool use_bias);

} // namespace tamias2d
