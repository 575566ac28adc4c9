#include "tamias2d/dynamics/joints/prismatic_joint.hpp"

#include "tamias2d/dynamics/bridge/joints.hpp"
#include "tamias2d/dynamics/joints/joint_creation.hpp"
#include "tamias2d/dynamics/joints/joint_solver.hpp"

namespace tamias2d {

Joint make_joint(const PrismaticJointDef& def, const Body& a, const Body& b) {
    Joint j = two_body_joint(JointType::prismatic, def.body_a.index, a, def.body_b.index, b,
                             def.anchor, def.collide_connected, def.break_force);
    j.local_axis = local_axis(a, def.axis);
    j.step.axis = normalize(def.axis);
    j.enable_limit = def.enable_limit;
    j.lower_limit = def.lower_translation;
    j.upper_limit = def.upper_translation;
    j.enable_motor = def.enable_motor;
    j.motor_speed = def.motor_speed;
    j.max_motor = def.max_motor_force;
    j.break_torque = def.break_torque;
    j.enable_spring = def.enable_spring;
    j.hertz = def.hertz;
    j.damping_ratio = def.damping_ratio;
    take_definition_controls(j, def);
    return j;
}

void warm_start_prismatic(const JointSim& s, const Joint& j, std::span<SolverBody> bodies) {
    SolverBody& a = bodies[s.solver_a];
    SolverBody& b = bodies[s.solver_b];
    const LineFrame f = line_frame(s, j, a, b);
    const double axial =
        s.step.spring_impulse + s.step.motor_impulse + s.step.lower_impulse - s.step.upper_impulse;
    bridge::apply_axial_impulse(a, f.line.arm_a, b, f.line.arm_b, f.axis, axial);
    bridge::apply_axial_impulse(a, f.line.perp_arm_a, b, f.line.perp_arm_b, left_perp(f.axis),
                                s.step.perp_impulse);
    bridge::apply_angular_impulse(a, b, s.step.angular_impulse);
}

void solve_prismatic(JointSim& s, const Joint& j, std::span<SolverBody> bodies, double h,
                     bool use_bias) {
    const Softness& rigid = s.softness;
    SolverBody& a = bodies[s.solver_a];
    SolverBody& b = bodies[s.solver_b];
    const LineFrame f = line_frame(s, j, a, b);
    const bridge::Line& l = f.line;
    s.step.axis = f.axis;
    // Along the axis: the spring, the motor, the limits (DD23), each its own constraint.
    if (j.enable_spring && use_bias)
        solve_axial_spring(s, j, a, b, l.arm_a, l.arm_b, f.axis, l.translation, h);
    if (j.enable_motor) {
        const double v = bridge::axial_velocity_error(a, l.arm_a, b, l.arm_b, f.axis);
        const double lambda = bridge::axial_impulse(a, l.arm_a, b, l.arm_b, v - j.motor_speed, 1.0,
                                                    0.0, s.step.motor_impulse);
        const double updated = bridge::clamp_axial_impulse(
            s.step.motor_impulse + lambda, bridge::axial_force_impulse_bound(j.max_motor, h));
        bridge::apply_axial_impulse(a, l.arm_a, b, l.arm_b, f.axis, updated - s.step.motor_impulse);
        s.step.motor_impulse = updated;
    }
    if (j.enable_limit)
        solve_axial_limits(s, j, a, b, l.arm_a, l.arm_b, f.axis, l.translation, h, use_bias);
    // Across it and about z: the line and the angle held together (DD23's block), last so that
    // they hold best.
    const Vec2d perp = left_perp(f.axis);
    double rhs_perp = bridge::axial_velocity_error(a, l.perp_arm_a, b, l.perp_arm_b, perp);
    double rhs_angle = bridge::joint_speed(a, b);
    double mass_scale = 1.0, impulse_scale = 0.0;
    if (use_bias) {
        rhs_perp = bridge::biased_error(rhs_perp, rigid.bias_rate, l.perpendicular);
        rhs_angle =
            bridge::biased_angular_error(rhs_angle, rigid.bias_rate, current_joint_angle(s, a, b));
        mass_scale = rigid.mass_scale;
        impulse_scale = rigid.impulse_scale;
    }
    const auto [linear, angular] =
        bridge::block_impulse(a, b, l.perp_arm_a, l.perp_arm_b, rhs_perp, rhs_angle, mass_scale,
                              impulse_scale, s.step.perp_impulse, s.step.angular_impulse);
    s.step.perp_impulse += linear;
    s.step.angular_impulse += angular;
    bridge::apply_axial_impulse(a, l.perp_arm_a, b, l.perp_arm_b, perp, linear);
    bridge::apply_angular_impulse(a, b, angular);
}

} // namespace tamias2d
