#include "tamias2d/dynamics/joints/joint_solver.hpp"

#include <algorithm>

#include "tamias2d/dynamics/body_store.hpp"
#include "tamias2d/dynamics/joints/distance_joint.hpp"
#include "tamias2d/dynamics/joints/motor_joint.hpp"
#include "tamias2d/dynamics/joints/prismatic_joint.hpp"
#include "tamias2d/dynamics/joints/revolute_joint.hpp"
#include "tamias2d/dynamics/joints/target_joint.hpp"
#include "tamias2d/dynamics/joints/weld_joint.hpp"
#include "tamias2d/dynamics/joints/wheel_joint.hpp"
#include "tamias2d/memory/allocator.hpp"

namespace tamias2d {

PinFrames pin_frames(const Joint& j, const Body& a, const Body& b) {
    return {j.local_anchor_a - a.local_center, j.local_anchor_b - b.local_center,
            b.center - a.center};
}

void prepare_joint(JointSim& s, const Joint& j, std::uint32_t index, const BodyStore& store,
                   const memory::vector<std::uint32_t>& solver_index) {
    const Body& a = store.bodies[j.body_a];
    const Body& b = store.bodies[j.body_b];
    s.solver_a = solver_index[j.body_a];
    s.solver_b = solver_index[j.body_b];
    s.joint = index;
    s.type = j.type;
    s.spring = j.enable_spring;
    s.motor = j.enable_motor;
    s.limit = j.enable_limit;
    s.tuned = j.tuned;
    const PinFrames f = pin_frames(j, a, b);
    s.frame_a = f.frame_a;
    s.frame_b = f.frame_b;
    s.center_offset = f.center_offset;
    s.reference_angle = j.reference_angle;
    s.angle_a = a.angle;
    s.angle_b = b.angle;
    s.step = j.step;
    s.center_b = b.center;
}

LineFrame line_frame(const JointSim& s, const Joint& j, const SolverBody& a, const SolverBody& b) {
    const Vec2d r_a = anchor_a(s);
    const Vec2d r_b = anchor_b(s);
    const Vec2d axis = rotate(*s.q_a, j.local_axis);
    // The anchors' separation now: the centres have moved by dp since the step's start.
    const Vec2d d = s.center_offset + (b.dp - a.dp) + (r_b - r_a);
    return {r_a, r_b, axis, bridge::line(d, r_a, r_b, axis)};
}

void solve_pin(JointSim& s, SolverBody& a, SolverBody& b, const Softness& softness, bool use_bias) {
    const Vec2d r_a = anchor_a(s);
    const Vec2d r_b = anchor_b(s);
    if (use_bias)
        pin_iteration<true>(a, b, r_a, r_b, s.center_offset, softness.bias_rate,
                            softness.mass_scale, softness.impulse_scale, s.step.linear_impulse);
    else
        pin_iteration<false>(a, b, r_a, r_b, s.center_offset, softness.bias_rate,
                             softness.mass_scale, softness.impulse_scale, s.step.linear_impulse);
}

void solve_angular_motor(JointSim& s, const Joint& j, SolverBody& a, SolverBody& b, double h) {
    const double lambda = bridge::angular_impulse(a, b, bridge::joint_speed(a, b) - j.motor_speed,
                                                  1.0, 0.0, s.step.motor_impulse);
    const double updated = bridge::clamp_angular_impulse(
        s.step.motor_impulse + lambda, bridge::torque_impulse_bound(j.max_motor, h));
    bridge::apply_angular_impulse(a, b, updated - s.step.motor_impulse);
    s.step.motor_impulse = updated;
}

void solve_angular_limits(JointSim& s, const Joint& j, SolverBody& a, SolverBody& b, double h,
                          bool use_bias) {
    const Softness& softness = s.softness;
    const double angle = current_joint_angle(s, a, b);
    for (const bool lower : {true, false}) {
        const double c = lower ? angle - j.lower_limit : j.upper_limit - angle;
        const bridge::LimitTarget t = bridge::limit_target<units::Angle>(c, softness, h, use_bias);
        // The upper bound's impulse is taken positive against the turn, then applied negated.
        const double speed = lower ? bridge::joint_speed(a, b) : -bridge::joint_speed(a, b);
        double& accumulated = lower ? s.step.lower_impulse : s.step.upper_impulse;
        const double lambda = bridge::angular_impulse(a, b, speed - t.velocity, t.mass_scale,
                                                      t.impulse_scale, accumulated);
        const double updated = std::max(accumulated + lambda, 0.0);
        const double applied = updated - accumulated;
        accumulated = updated;
        bridge::apply_angular_impulse(a, b, lower ? applied : -applied);
    }
}

void solve_axial_limits(JointSim& s, const Joint& j, SolverBody& a, SolverBody& b, double arm_a,
                        double arm_b, Vec2d n, double value, double h, bool use_bias) {
    const Softness& softness = s.softness;
    for (const bool lower : {true, false}) {
        const double c = lower ? value - j.lower_limit : j.upper_limit - value;
        const bridge::LimitTarget t = bridge::limit_target<units::Length>(c, softness, h, use_bias);
        const double v = bridge::axial_velocity_error(a, arm_a, b, arm_b, n);
        double& accumulated = lower ? s.step.lower_impulse : s.step.upper_impulse;
        const double lambda =
            bridge::axial_impulse(a, arm_a, b, arm_b, (lower ? v : -v) - t.velocity, t.mass_scale,
                                  t.impulse_scale, accumulated);
        const double updated = std::max(accumulated + lambda, 0.0);
        const double applied = updated - accumulated;
        accumulated = updated;
        bridge::apply_axial_impulse(a, arm_a, b, arm_b, n, lower ? applied : -applied);
    }
}

void solve_axial_spring(JointSim& s, const Joint& j, SolverBody& a, SolverBody& b, double arm_a,
                        double arm_b, Vec2d n, double value, double h) {
    const Softness soft = make_joint_softness(j.hertz, j.damping_ratio, h);
    const double rhs =
        bridge::biased_error(bridge::axial_velocity_error(a, arm_a, b, arm_b, n), soft.bias_rate,
                             bridge::axial_spring_error(value, j.spring_target));
    const double lambda = bridge::axial_impulse(a, arm_a, b, arm_b, rhs, soft.mass_scale,
                                                soft.impulse_scale, s.step.spring_impulse);
    s.step.spring_impulse += lambda;
    bridge::apply_axial_impulse(a, arm_a, b, arm_b, n, lambda);
}

void warm_start_pin_and_angle(const JointSim& s, std::span<SolverBody> bodies) {
    SolverBody& a = bodies[s.solver_a];
    SolverBody& b = bodies[s.solver_b];
    bridge::apply_angular_impulse(a, b, s.step.angular_impulse);
    bridge::apply_pin_impulse(a, anchor_a(s), b, anchor_b(s), s.step.linear_impulse);
}

void warm_start_joint(const JointSim& s, const Joint& j, std::span<SolverBody> bodies) {
    switch (s.type) {
    case JointType::revolute:
        return warm_start_revolute(s, bodies);
    case JointType::distance:
        return warm_start_distance(s, j, bodies);
    case JointType::target:
        return warm_start_target(s, bodies);
    case JointType::prismatic:
        return warm_start_prismatic(s, j, bodies);
    case JointType::weld:
        return warm_start_pin_and_angle(s, bodies);
    case JointType::wheel:
        return warm_start_wheel(s, j, bodies);
    case JointType::motor:
        return warm_start_pin_and_angle(s, bodies);
    case JointType::filter: // no constraint (StepSolver::prepare_joints leaves it out)
        return;
    }
}

void solve_joint(JointSim& s, const Joint& j, std::span<SolverBody> bodies, double h,
                 bool use_bias) {
    switch (s.type) {
    case JointType::revolute:
        return solve_revolute(s, j, bodies, h, use_bias);
    case JointType::distance:
        return solve_distance(s, j, bodies, h, use_bias);
    case JointType::target:
        return solve_target(s, j, bodies, h, use_bias);
    case JointType::prismatic:
        return solve_prismatic(s, j, bodies, h, use_bias);
    case JointType::weld:
        return solve_weld(s, j, bodies, h, use_bias);
    case JointType::wheel:
        return solve_wheel(s, j, bodies, h, use_bias);
    case JointType::motor:
        return solve_motor(s, j, bodies, h, use_bias);
    case JointType::filter:
        return;
    }
}

} // namespace tamias2d
