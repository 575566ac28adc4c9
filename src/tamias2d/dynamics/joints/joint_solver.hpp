// The joints in the soft step (internal): what every kind shares (the step's preparation of a
// joint's record, the anchors as the bodies turn, the pin, the motor, the spring and the limits
// that several kinds are built from) and the dispatch to each kind's warm start and iterations
// (revolute_joint.hpp, distance_joint.hpp, ...). Each reads and writes the joint's JointSim and
// reads its definition, the Joint, only for a part that is enabled.
#pragma once

#include <cstdint>
#include <span>

#include "tamias2d/dynamics/bridge/joints.hpp"
#include "tamias2d/dynamics/joints/joint.hpp"
#include "tamias2d/dynamics/joints/joint_sim.hpp"
#include "tamias2d/dynamics/softness.hpp"
#include "tamias2d/dynamics/solver_body.hpp"
#include "tamias2d/memory/allocator.hpp"

namespace tamias2d {

struct BodyStore;
struct Body;

/// A pin's geometry at the step's start: the anchors' offsets from their bodies' centres (body
/// frames) and the centres' offset p_B - p_A, from joint j on bodies a and b.
struct PinFrames {
    Vec2d frame_a, frame_b, center_offset;
};
PinFrames pin_frames(const Joint& j, const Body& a, const Body& b);

/// Fills s, joint j's record for this step: its solver bodies, the anchors' offsets from the
/// centres (body frames), the bodies' angles and the centres' offset at the step's start, and
/// the impulses of the last accepted step. (The rotations and the softness are the step
/// solver's.)
void prepare_joint(JointSim& s, const Joint& j, std::uint32_t index, const BodyStore& bodies,
                   const memory::vector<std::uint32_t>& solver_index);

/// The anchors' offsets from their bodies' centres in the world frame, with the bodies turned
/// as far as they have in the step.
inline Vec2d anchor_a(const JointSim& s) {
    return rotate(*s.q_a, s.frame_a);
}
inline Vec2d anchor_b(const JointSim& s) {
    return rotate(*s.q_b, s.frame_b);
}

/// The joint angle (DD22) now: the bodies' angles at the step's start plus their turn since.
inline double current_joint_angle(const JointSim& s, const SolverBody& a, const SolverBody& b) {
    return bridge::joint_angle(s.angle_a + a.dq, s.angle_b + b.dq, s.reference_angle);
}

/// A prismatic or wheel joint's line now (DD23): the anchors' offsets, the axis (fixed in
/// body A, turned with it) and the translation, line error and moment arms along it.
struct LineFrame {
    Vec2d r_a, r_b, axis;
    bridge::Line line;
};
LineFrame line_frame(const JointSim& s, const Joint& j, const SolverBody& a, const SolverBody& b);

/// \srs{IM6} DD19's pin iteration on bodies a and b: SolverBody for one pin, or WideBody for
/// four at once (pin_packs.cpp: V is then Wide), with the pins r_a, r_b from the centres now.
/// The impulse that stops the pin's velocity error, accumulated into `impulse` and applied; with
/// use_bias the soft solve that also pulls the pins together (their separation from the centres'
/// offset at the step's start and the centres' motion since), without it the rigid relax.
template <bool use_bias, class Body, class V = bridge::value_of<Body>>
void pin_iteration(Body& a, Body& b, Vec2<V> r_a, Vec2<V> r_b, Vec2<V> center_offset, V bias_rate,
                   V soft_mass_scale, V soft_impulse_scale, Vec2<V>& impulse) {
    Vec2<V> rhs = bridge::pin_velocity_error(a, r_a, b, r_b);
    V mass_scale = broadcast<V>(1.0), impulse_scale = broadcast<V>(0.0);
    if constexpr (use_bias) {
        const Vec2<V> c = bridge::pin_position_error(center_offset + (b.dp - a.dp), r_a, r_b);
        rhs = bridge::biased_error(rhs, bias_rate, c);
        mass_scale = soft_mass_scale;
        impulse_scale = soft_impulse_scale;
    }
    const Vec2<V> P = bridge::pin_impulse(a, r_a, b, r_b, rhs, mass_scale, impulse_scale, impulse);
    impulse += P;
    bridge::apply_pin_impulse(a, r_a, b, r_b, P);
}

/// \srs{IM6} DD19's pin (revolute, weld): pin_iteration with the record's pins and impulse.
void solve_pin(JointSim& s, SolverBody& a, SolverBody& b, const Softness& softness, bool use_bias);
/// DD22's motor on the relative turn, its accumulation bounded by max_motor h.
void solve_angular_motor(JointSim& s, const Joint& j, SolverBody& a, SolverBody& b, double h);
/// DD22's limits on the joint angle [lower_limit, upper_limit] (rad).
void solve_angular_limits(JointSim& s, const Joint& j, SolverBody& a, SolverBody& b, double h,
                          bool use_bias);
/// DD20/DD23: limits [lower_limit, upper_limit] on a length along the axis n with the given moment
/// arms.
void solve_axial_limits(JointSim& s, const Joint& j, SolverBody& a, SolverBody& b, double arm_a,
                        double arm_b, Vec2d n, double value, double h, bool use_bias);
/// DD23: a spring along the axis n pulling `value` to the joint's spring target (soft solve
/// only).
void solve_axial_spring(JointSim& s, const Joint& j, SolverBody& a, SolverBody& b, double arm_a,
                        double arm_b, Vec2d n, double value, double h);

/// The warm start of a joint that holds a pin (DD19) and an angle (a weld, DD24; a motor joint,
/// DD26): the held angle's impulse, then the pin's.
void warm_start_pin_and_angle(const JointSim& s, std::span<SolverBody> bodies);
/// Re-applies the impulses of the previous substep (they carry the solution forward).
void warm_start_joint(const JointSim& s, const Joint& j, std::span<SolverBody> bodies);
/// \srs{IM6} One iteration of the joint: with use_bias the soft solve (the rigid parts pulled
/// back by the record's softness, a spring by its own for the substep h), without it the relax
/// of the rigid parts.
void solve_joint(JointSim& s, const Joint& j, std::span<SolverBody> bodies, double h,
                 bool use_bias);

} // namespace tamias2d
