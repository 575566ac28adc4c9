#include "tamias2d/dynamics/joints/motor_joint.hpp"

#include "tamias2d/dynamics/bridge/joints.hpp"
#include "tamias2d/dynamics/joints/joint_creation.hpp"
#include "tamias2d/dynamics/joints/joint_solver.hpp"

namespace tamias2d {

Joint make_joint(const MotorJointDef& def, const Body&, const Body&) {
    Joint j;
    j.type = JointType::motor;
    j.body_a = def.body_a.index;
    j.body_b = def.body_b.index;
    // DD26's pin: body_b's origin held at linear_offset in body_a's frame.
    j.local_anchor_a = def.linear_offset;
    j.local_anchor_b = {0.0, 0.0};
    j.reference_angle = def.angular_offset;
    j.max_force = def.max_force;
    j.max_torque = def.max_torque;
    j.correction_factor = def.correction_factor;
    j.collide_connected = def.collide_connected;
    j.break_force = def.break_force;
    j.break_torque = def.break_torque;
    return j;
}

void solve_motor(JointSim& s, const Joint& j, std::span<SolverBody> bodies, double h,
                 bool use_bias) {
    if (!use_bias)
        return;
    SolverBody& a = bodies[s.solver_a];
    SolverBody& b = bodies[s.solver_b];
    // DD26: each error asks for the velocity that removes the fraction `correction_factor` of
    // it per substep; the accumulated impulses are bounded by the largest torque and force.
    const double rate = bridge::correction_rate(j.correction_factor, h);
    const double angular =
        bridge::motor_angular_update(a, b, bridge::joint_speed(a, b), current_joint_angle(s, a, b),
                                     rate, j.max_torque, h, s.step.angular_impulse);
    bridge::apply_angular_impulse(a, b, angular - s.step.angular_impulse);
    s.step.angular_impulse = angular;

    const Vec2d r_a = anchor_a(s);
    const Vec2d r_b = anchor_b(s);
    const Vec2d c = bridge::pin_position_error(s.center_offset + (b.dp - a.dp), r_a, r_b);
    const Vec2d old = s.step.linear_impulse;
    s.step.linear_impulse = bridge::motor_linear_update(
        a, r_a, b, r_b, bridge::pin_velocity_error(a, r_a, b, r_b), c, rate, j.max_force, h, old);
    bridge::apply_pin_impulse(a, r_a, b, r_b, s.step.linear_impulse - old);
}

} // namespace tamias2d
