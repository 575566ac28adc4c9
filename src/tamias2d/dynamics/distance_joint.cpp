#include "tamias2d/dynamics/distance_joint.hpp"

#include "tamias2d/dynamics/joint_solver.hpp"
#include "tamias2d/dynamics/model_bridge.hpp"

namespace tamias2d {

void warm_start_distance(const Joint& j, std::span<SolverBody> bodies) {
    SolverBody& a = bodies[j.solver_a];
    SolverBody& b = bodies[j.solver_b];
    const Vec2d r_a = anchor_a(j);
    const Vec2d r_b = anchor_b(j);
    bridge::apply_axial_impulse(a, bridge::moment_arm(r_a, j.axis), b,
                                bridge::moment_arm(r_b, j.axis), j.axis,
                                j.axial_impulse + j.lower_impulse - j.upper_impulse);
}

void solve_distance(Joint& j, std::span<SolverBody> bodies, const Softness& rigid, double h,
                    bool use_bias) {
    const bool spring = j.hertz > 0.0;
    // Limits bound a spring's travel (a rigid rod has none to bound); a spring is not relaxed.
    const bool limits = spring && j.enable_limit;
    if (spring && !use_bias && !limits)
        return;
    SolverBody& a = bodies[j.solver_a];
    SolverBody& b = bodies[j.solver_b];
    const Vec2d r_a = anchor_a(j);
    const Vec2d r_b = anchor_b(j);
    // The anchors' separation now: the centres have moved by dp since the step's start.
    double length = 0.0;
    bridge::distance_axis(j.center_offset + (b.dp - a.dp) + (r_b - r_a), length, j.axis);
    const double arm_a = bridge::moment_arm(r_a, j.axis), arm_b = bridge::moment_arm(r_b, j.axis);
    if (!spring || use_bias) {
        double rhs = bridge::axial_velocity_error(a, arm_a, b, arm_b, j.axis);
        double mass_scale = 1.0, impulse_scale = 0.0;
        if (use_bias) {
            const Softness soft = spring ? make_joint_softness(j.hertz, j.damping_ratio, h) : rigid;
            rhs = bridge::biased_error(rhs, soft.bias_rate,
                                       bridge::distance_position_error(length, j.length));
            mass_scale = soft.mass_scale;
            impulse_scale = soft.impulse_scale;
        }
        const double lambda = bridge::axial_impulse(a, arm_a, b, arm_b, rhs, mass_scale,
                                                    impulse_scale, j.axial_impulse);
        j.axial_impulse += lambda;
        bridge::apply_axial_impulse(a, arm_a, b, arm_b, j.axis, lambda);
    }
    if (limits)
        solve_axial_limits(j, a, b, arm_a, arm_b, j.axis, length, rigid, h, use_bias);
}

} // namespace tamias2d
