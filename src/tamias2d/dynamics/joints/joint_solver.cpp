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

void prepare_joint(Joint& j, const BodyStore& store,
                   const memory::vector<std::uint32_t>& solver_index) {
    const Body& a = store.bodies[j.body_a];
    const Body& b = store.bodies[j.body_b];
    j.step.solver_a = solver_index[j.body_a];
    j.step.solver_b = solver_index[j.body_b];
    j.step.frame_a = j.local_anchor_a - a.local_center;
    j.step.frame_b = j.local_anchor_b - b.local_center;
    j.step.angle_a = a.angle;
    j.step.angle_b = b.angle;
    j.step.center_offset = b.center - a.center;
    j.step.center_b = b.center;
}

LineFrame line_frame(const Joint& j, const SolverBody& a, const SolverBody& b) {
    const Vec2d r_a = anchor_a(j);
    const Vec2d r_b = anchor_b(j);
    const Vec2d axis = rotate(j.step.q_a, j.local_axis);
    // The anchors' separation now: the centres have moved by dp since the step's start.
    const Vec2d d = j.step.center_offset + (b.dp - a.dp) + (r_b - r_a);
    return {r_a, r_b, axis, bridge::line(d, r_a, r_b, axis)};
}

void solve_pin(Joint& j, SolverBody& a, SolverBody& b, const Softness& softness, bool use_bias) {
    const Vec2d r_a = anchor_a(j);
    const Vec2d r_b = anchor_b(j);
    Vec2d rhs = bridge::pin_velocity_error(a, r_a, b, r_b);
    double mass_scale = 1.0, impulse_scale = 0.0;
    if (use_bias) {
        // The pins' separation now: the centres have moved by dp since the step's start.
        const Vec2d c = bridge::pin_position_error(j.step.center_offset + (b.dp - a.dp), r_a, r_b);
        rhs = bridge::biased_error(rhs, softness.bias_rate, c);
        mass_scale = softness.mass_scale;
        impulse_scale = softness.impulse_scale;
    }
    const Vec2d P =
        bridge::pin_impulse(a, r_a, b, r_b, rhs, mass_scale, impulse_scale, j.step.linear_impulse);
    j.step.linear_impulse += P;
    bridge::apply_pin_impulse(a, r_a, b, r_b, P);
}

void solve_angular_motor(Joint& j, SolverBody& a, SolverBody& b, double h) {
    const double lambda = bridge::angular_impulse(a, b, bridge::joint_speed(a, b) - j.motor_speed,
                                                  1.0, 0.0, j.step.motor_impulse);
    const double updated = bridge::clamp_angular_impulse(
        j.step.motor_impulse + lambda, bridge::torque_impulse_bound(j.max_motor, h));
    bridge::apply_angular_impulse(a, b, updated - j.step.motor_impulse);
    j.step.motor_impulse = updated;
}

void solve_angular_limits(Joint& j, SolverBody& a, SolverBody& b, const Softness& softness,
                          double h, bool use_bias) {
    const double angle = current_joint_angle(j, a, b);
    for (const bool lower : {true, false}) {
        const double c = lower ? angle - j.lower_limit : j.upper_limit - angle;
        const bridge::LimitTarget t = bridge::limit_target<units::Angle>(c, softness, h, use_bias);
        // The upper bound's impulse is taken positive against the turn, then applied negated.
        const double speed = lower ? bridge::joint_speed(a, b) : -bridge::joint_speed(a, b);
        double& accumulated = lower ? j.step.lower_impulse : j.step.upper_impulse;
        const double lambda = bridge::angular_impulse(a, b, speed - t.velocity, t.mass_scale,
                                                      t.impulse_scale, accumulated);
        const double updated = std::max(accumulated + lambda, 0.0);
        const double applied = updated - accumulated;
        accumulated = updated;
        bridge::apply_angular_impulse(a, b, lower ? applied : -applied);
    }
}

void solve_axial_limits(Joint& j, SolverBody& a, SolverBody& b, double arm_a, double arm_b, Vec2d n,
                        double value, const Softness& softness, double h, bool use_bias) {
    for (const bool lower : {true, false}) {
        const double c = lower ? value - j.lower_limit : j.upper_limit - value;
        const bridge::LimitTarget t = bridge::limit_target<units::Length>(c, softness, h, use_bias);
        const double v = bridge::axial_velocity_error(a, arm_a, b, arm_b, n);
        double& accumulated = lower ? j.step.lower_impulse : j.step.upper_impulse;
        const double lambda =
            bridge::axial_impulse(a, arm_a, b, arm_b, (lower ? v : -v) - t.velocity, t.mass_scale,
                                  t.impulse_scale, accumulated);
        const double updated = std::max(accumulated + lambda, 0.0);
        const double applied = updated - accumulated;
        accumulated = updated;
        bridge::apply_axial_impulse(a, arm_a, b, arm_b, n, lower ? applied : -applied);
    }
}

void solve_axial_spring(Joint& j, SolverBody& a, SolverBody& b, double arm_a, double arm_b, Vec2d n,
                        double value, double h) {
    const Softness soft = make_joint_softness(j.hertz, j.damping_ratio, h);
    const double rhs =
        bridge::biased_error(bridge::axial_velocity_error(a, arm_a, b, arm_b, n), soft.bias_rate,
                             bridge::axial_spring_error(value, j.spring_target));
    const double lambda = bridge::axial_impulse(a, arm_a, b, arm_b, rhs, soft.mass_scale,
                                                soft.impulse_scale, j.step.spring_impulse);
    j.step.spring_impulse += lambda;
    bridge::apply_axial_impulse(a, arm_a, b, arm_b, n, lambda);
}

void warm_start_joint(const Joint& j, std::span<SolverBody> bodies) {
    switch (j.type) {
    case JointType::revolute:
        return warm_start_revolute(j, bodies);
    case JointType::distance:
        return warm_start_distance(j, bodies);
    case JointType::target:
        return warm_start_target(j, bodies);
    case JointType::prismatic:
        return warm_start_prismatic(j, bodies);
    case JointType::weld:
        return warm_start_weld(j, bodies);
    case JointType::wheel:
        return warm_start_wheel(j, bodies);
    case JointType::motor:
        return warm_start_motor(j, bodies);
    case JointType::filter: // no constraint (StepSolver::prepare_joints leaves it out)
        return;
    }
}

void solve_joint(Joint& j, std::span<SolverBody> bodies, const Softness& rigid, double h,
                 bool use_bias) {
    switch (j.type) {
    case JointType::revolute:
        return solve_revolute(j, bodies, rigid, h, use_bias);
    case JointType::distance:
        return solve_distance(j, bodies, rigid, h, use_bias);
    case JointType::target:
        return solve_target(j, bodies, h, use_bias);
    case JointType::prismatic:
        return solve_prismatic(j, bodies, rigid, h, use_bias);
    case JointType::weld:
        return solve_weld(j, bodies, rigid, h, use_bias);
    case JointType::wheel:
        return solve_wheel(j, bodies, rigid, h, use_bias);
    case JointType::motor:
        return solve_motor(j, bodies, h, use_bias);
    case JointType::filter:
        return;
    }
}

} // namespace tamias2d
