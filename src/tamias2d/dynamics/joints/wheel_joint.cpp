#include "tamias2d/dynamics/joints/wheel_joint.hpp"

#include "tamias2d/dynamics/bridge/joints.hpp"
#include "tamias2d/dynamics/joints/joint_creation.hpp"
#include "tamias2d/dynamics/joints/joint_solver.hpp"

namespace tamias2d {

Joint make_joint(const WheelJointDef& def, const Body& a, const Body& b) {
    Joint j = two_body_joint(JointType::wheel, def.body_a.index, a, def.body_b.index, b, def.anchor,
                             def.collide_connected, def.break_force);
    j.local_axis = local_axis(a, def.axis);
    j.step.axis = normalize(def.axis);
    j.enable_spring = def.enable_spring;
    j.hertz = def.hertz;
    j.damping_ratio = def.damping_ratio;
    j.enable_limit = def.enable_limit;
    j.lower_limit = def.lower_translation;
    j.upper_limit = def.upper_translation;
    j.enable_motor = def.enable_motor;
    j.motor_speed = def.motor_speed;
    j.max_motor = def.max_motor_torque;
    j.break_torque = def.break_torque;
    take_definition_controls(j, def);
    return j;
}

void warm_start_wheel(const JointSim& s, const Joint& j, std::span<SolverBody> bodies) {
    SolverBody& a = bodies[s.solver_a];
    SolverBody& b = bodies[s.solver_b];
    const LineFrame f = line_frame(s, j, a, b);
    const double axial = s.step.spring_impulse + s.step.lower_impulse - s.step.upper_impulse;
    bridge::apply_axial_impulse(a, f.line.arm_a, b, f.line.arm_b, f.axis, axial);
    bridge::apply_axial_impulse(a, f.line.perp_arm_a, b, f.line.perp_arm_b, left_perp(f.axis),
                                s.step.perp_impulse);
    bridge::apply_angular_impulse(a, b, s.step.motor_impulse);
}

void solve_wheel(JointSim& s, const Joint& j, std::span<SolverBody> bodies, double h,
                 bool use_bias) {
    const Softness& rigid = s.softness;
    SolverBody& a = bodies[s.solver_a];
    SolverBody& b = bodies[s.solver_b];
    if (j.enable_motor)
        solve_angular_motor(s, j, a, b, h);
    const LineFrame f = line_frame(s, j, a, b);
    const bridge::Line& l = f.line;
    s.step.axis = f.axis;
    // The suspension: a spring along the axis, limits on its travel (DD25).
    if (j.enable_spring && use_bias)
        solve_axial_spring(s, j, a, b, l.arm_a, l.arm_b, f.axis, l.translation, h);
    if (j.enable_limit)
        solve_axial_limits(s, j, a, b, l.arm_a, l.arm_b, f.axis, l.translation, h, use_bias);
    // The wheel kept on the line (DD25: DD23's line constraint alone, the wheel turns freely).
    const Vec2d perp = left_perp(f.axis);
    const double lambda = bridge::wheel_line_impulse(
        a, b, l.perp_arm_a, l.perp_arm_b,
        bridge::axial_velocity_error(a, l.perp_arm_a, b, l.perp_arm_b, perp), l.perpendicular,
        rigid, use_bias, s.step.perp_impulse);
    s.step.perp_impulse += lambda;
    bridge::apply_axial_impulse(a, l.perp_arm_a, b, l.perp_arm_b, perp, lambda);
}

} // namespace tamias2d
