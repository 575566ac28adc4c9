#include "tamias2d/dynamics/wheel_joint.hpp"

#include "tamias2d/dynamics/joint_solver.hpp"
#include "tamias2d/dynamics/model_bridge.hpp"

namespace tamias2d {

void warm_start_wheel(const Joint& j, std::span<SolverBody> bodies) {
    SolverBody& a = bodies[j.solver_a];
    SolverBody& b = bodies[j.solver_b];
    const LineFrame f = line_frame(j, a, b);
    const double axial = j.spring_impulse + j.lower_impulse - j.upper_impulse;
    bridge::apply_axial_impulse(a, f.line.arm_a, b, f.line.arm_b, f.axis, axial);
    bridge::apply_axial_impulse(a, f.line.perp_arm_a, b, f.line.perp_arm_b, left_perp(f.axis),
                                j.perp_impulse);
    bridge::apply_angular_impulse(a, b, j.motor_impulse);
}

void solve_wheel(Joint& j, std::span<SolverBody> bodies, const Softness& rigid, double h,
                 bool use_bias) {
    SolverBody& a = bodies[j.solver_a];
    SolverBody& b = bodies[j.solver_b];
    if (j.enable_motor)
        solve_angular_motor(j, a, b, h);
    const LineFrame f = line_frame(j, a, b);
    const bridge::Line& l = f.line;
    j.axis = f.axis;
    // The suspension: a spring along the axis, limits on its travel (DD25).
    if (j.enable_spring && use_bias)
        solve_axial_spring(j, a, b, l.arm_a, l.arm_b, f.axis, l.translation, h);
    if (j.enable_limit)
        solve_axial_limits(j, a, b, l.arm_a, l.arm_b, f.axis, l.translation, rigid, h, use_bias);
    // The wheel kept on the line (DD25: DD23's line constraint alone, the wheel turns freely).
    const Vec2d perp = left_perp(f.axis);
    const double lambda = bridge::wheel_line_impulse(
        a, b, l.perp_arm_a, l.perp_arm_b,
        bridge::axial_velocity_error(a, l.perp_arm_a, b, l.perp_arm_b, perp), l.perpendicular,
        rigid, use_bias, j.perp_impulse);
    j.perp_impulse += lambda;
    bridge::apply_axial_impulse(a, l.perp_arm_a, b, l.perp_arm_b, perp, lambda);
}

} // namespace tamias2d
