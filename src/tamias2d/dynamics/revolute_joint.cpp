#include "tamias2d/dynamics/revolute_joint.hpp"

#include <algorithm>

#include "tamias2d/dynamics/joint_solver.hpp"
#include "tamias2d/dynamics/model_bridge.hpp"

namespace tamias2d {
void warm_start_revolute(const Joint& j, std::span<SolverBody> bodies) {
    SolverBody& a = bodies[j.solver_a];
    SolverBody& b = bodies[j.solver_b];
    bridge::apply_angular_impulse(a, b, reaction_angular_impulse(j));
    bridge::apply_pin_impulse(a, anchor_offset(j.frame_a, j.angle_a, a), b,
                              anchor_offset(j.frame_b, j.angle_b, b), j.linear_impulse);
}

namespace {

/// DD22's limits: one-sided, each pushing the angle back inside. A bound still ahead is
/// approached no faster than it closes in the substep (speculative: bias C / h); a bound
/// passed is pulled back softly (IM6's bias), or rigidly in the relax.
void solve_limits(Joint& j, SolverBody& a, SolverBody& b, const Softness& softness, double h,
                  bool use_bias) {
    const double angle = bridge::joint_angle(j.angle_a + a.dq, j.angle_b + b.dq, j.reference_angle);
    for (const bool lower : {true, false}) {
        const double c = lower ? angle - j.lower_angle : j.upper_angle - angle;
        double bias = 0.0, mass_scale = 1.0, impulse_scale = 0.0;
        if (c > 0.0) {
            bias = c / h;
        } else if (use_bias) {
            bias = softness.bias_rate * c;
            mass_scale = softness.mass_scale;
            impulse_scale = softness.impulse_scale;
        }
        // The upper bound's impulse is taken positive against the turn, then applied negated.
        const double speed = lower ? bridge::joint_speed(a, b) : -bridge::joint_speed(a, b);
        double& accumulated = lower ? j.lower_impulse : j.upper_impulse;
        const double lambda =
            bridge::angular_impulse(a, b, speed + bias, mass_scale, impulse_scale, accumulated);
        const double updated = std::max(accumulated + lambda, 0.0);
        const double applied = updated - accumulated;
        accumulated = updated;
        bridge::apply_angular_impulse(a, b, lower ? applied : -applied);
    }
}

} // namespace

void solve_revolute(Joint& j, std::span<SolverBody> bodies, const Softness& softness, double h,
                    bool use_bias) {
    SolverBody& a = bodies[j.solver_a];
    SolverBody& b = bodies[j.solver_b];
    if (j.enable_motor) {
        const double lambda = bridge::angular_impulse(
            a, b, bridge::joint_speed(a, b) - j.motor_speed, 1.0, 0.0, j.motor_impulse);
        const double updated =
            bridge::clamp_angular_impulse(j.motor_impulse + lambda, j.max_motor_torque * h);
        bridge::apply_angular_impulse(a, b, updated - j.motor_impulse);
        j.motor_impulse = updated;
    }
    if (j.enable_limit)
        solve_limits(j, a, b, softness, h, use_bias);
    const Vec2d r_a = anchor_offset(j.frame_a, j.angle_a, a);
    const Vec2d r_b = anchor_offset(j.frame_b, j.angle_b, b);
    Vec2d rhs = bridge::pin_velocity_error(a, r_a, b, r_b);
    double mass_scale = 1.0, impulse_scale = 0.0;
    if (use_bias) {
        // The pins' separation now: the centres have moved by dp since the step's start.
        const Vec2d c = bridge::pin_position_error(j.center_offset + (b.dp - a.dp), r_a, r_b);
        rhs += softness.bias_rate * c;
        mass_scale = softness.mass_scale;
        impulse_scale = softness.impulse_scale;
    }
    const Vec2d P =
        bridge::pin_impulse(a, r_a, b, r_b, rhs, mass_scale, impulse_scale, j.linear_impulse);
    j.linear_impulse += P;
    bridge::apply_pin_impulse(a, r_a, b, r_b, P);
}

} // namespace tamias2d
