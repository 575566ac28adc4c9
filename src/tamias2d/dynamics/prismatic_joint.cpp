#include "tamias2d/dynamics/prismatic_joint.hpp"

#include "tamias2d/dynamics/joint_solver.hpp"
#include "tamias2d/dynamics/model_bridge.hpp"

namespace tamias2d {

void warm_start_prismatic(const Joint& j, std::span<SolverBody> bodies) {
    SolverBody& a = bodies[j.solver_a];
    SolverBody& b = bodies[j.solver_b];
    const LineFrame f = line_frame(j, a, b);
    const double axial = j.spring_impulse + j.motor_impulse + j.lower_impulse - j.upper_impulse;
    bridge::apply_axial_impulse(a, f.line.arm_a, b, f.line.arm_b, f.axis, axial);
    bridge::apply_axial_impulse(a, f.line.perp_arm_a, b, f.line.perp_arm_b, left_perp(f.axis),
                                j.perp_impulse);
    bridge::apply_angular_impulse(a, b, j.angular_impulse);
}

void solve_prismatic(Joint& j, std::span<SolverBody> bodies, const Softness& rigid, double h,
                     bool use_bias) {
    SolverBody& a = bodies[j.solver_a];
    SolverBody& b = bodies[j.solver_b];
    const LineFrame f = line_frame(j, a, b);
    const bridge::Line& l = f.line;
    j.axis = f.axis;
    // Along the axis: the spring, the motor, the limits (DD23), each its own constraint.
    if (j.enable_spring && use_bias)
        solve_axial_spring(j, a, b, l.arm_a, l.arm_b, f.axis, l.translation, h);
    if (j.enable_motor) {
        const double v = bridge::axial_velocity_error(a, l.arm_a, b, l.arm_b, f.axis);
        const double lambda = bridge::axial_impulse(a, l.arm_a, b, l.arm_b, v - j.motor_speed, 1.0,
                                                    0.0, j.motor_impulse);
        const double updated = bridge::clamp_axial_impulse(
            j.motor_impulse + lambda, bridge::axial_force_impulse_bound(j.max_motor, h));
        bridge::apply_axial_impulse(a, l.arm_a, b, l.arm_b, f.axis, updated - j.motor_impulse);
        j.motor_impulse = updated;
    }
    if (j.enable_limit)
        solve_axial_limits(j, a, b, l.arm_a, l.arm_b, f.axis, l.translation, rigid, h, use_bias);
    // Across it and about z: the line and the angle held together (DD23's block), last so that
    // they hold best.
    const Vec2d perp = left_perp(f.axis);
    double rhs_perp = bridge::axial_velocity_error(a, l.perp_arm_a, b, l.perp_arm_b, perp);
    double rhs_angle = bridge::joint_speed(a, b);
    double mass_scale = 1.0, impulse_scale = 0.0;
    if (use_bias) {
        rhs_perp = bridge::biased_error(rhs_perp, rigid.bias_rate, l.perpendicular);
        rhs_angle =
            bridge::biased_angular_error(rhs_angle, rigid.bias_rate, current_joint_angle(j, a, b));
        mass_scale = rigid.mass_scale;
        impulse_scale = rigid.impulse_scale;
    }
    const auto [linear, angular] =
        bridge::block_impulse(a, b, l.perp_arm_a, l.perp_arm_b, rhs_perp, rhs_angle, mass_scale,
                              impulse_scale, j.perp_impulse, j.angular_impulse);
    j.perp_impulse += linear;
    j.angular_impulse += angular;
    bridge::apply_axial_impulse(a, l.perp_arm_a, b, l.perp_arm_b, perp, linear);
    bridge::apply_angular_impulse(a, b, angular);
}

} // namespace tamias2d
