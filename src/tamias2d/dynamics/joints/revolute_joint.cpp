#include "tamias2d/dynamics/joints/revolute_joint.hpp"

#include "tamias2d/dynamics/bridge/joints.hpp"
#include "tamias2d/dynamics/joints/joint_creation.hpp"
#include "tamias2d/dynamics/joints/joint_solver.hpp"

namespace tamias2d {

Joint make_joint(const RevoluteJointDef& def, const Body& a, const Body& b) {
    Joint j = two_body_joint(JointType::revolute, def.body_a.index, a, def.body_b.index, b,
                             def.anchor, def.collide_connected, def.break_force);
    j.enable_limit = def.enable_limit;
    j.lower_limit = def.lower_angle;
    j.upper_limit = def.upper_angle;
    j.enable_motor = def.enable_motor;
    j.motor_speed = def.motor_speed;
    j.max_motor = def.max_motor_torque;
    j.enable_spring = def.enable_spring;
    j.hertz = def.hertz;
    j.damping_ratio = def.damping_ratio;
    j.break_torque = def.break_torque;
    take_definition_controls(j, def);
    return j;
}

void warm_start_revolute(const JointSim& s, std::span<SolverBody> bodies) {
    SolverBody& a = bodies[s.solver_a];
    SolverBody& b = bodies[s.solver_b];
    bridge::apply_angular_impulse(a, b, reaction_angular_impulse(s.type, s.step));
    bridge::apply_pin_impulse(a, anchor_a(s), b, anchor_b(s), s.step.linear_impulse);
}

void solve_revolute(JointSim& s, const Joint& j, std::span<SolverBody> bodies, double h,
                    bool use_bias) {
    SolverBody& a = bodies[s.solver_a];
    SolverBody& b = bodies[s.solver_b];
    if (s.spring && use_bias) {
        // DD22's spring: the joint angle pulled to its target with the spring's own softness.
        const Softness soft = make_joint_softness(j.hertz, j.damping_ratio, h);
        const double rhs = bridge::biased_angular_error(
            bridge::joint_speed(a, b), soft.bias_rate,
            bridge::angular_spring_error(current_joint_angle(s, a, b), j.spring_target));
        const double lambda = bridge::angular_impulse(a, b, rhs, soft.mass_scale,
                                                      soft.impulse_scale, s.step.spring_impulse);
        s.step.spring_impulse += lambda;
        bridge::apply_angular_impulse(a, b, lambda);
    }
    if (s.motor)
        solve_angular_motor(s, j, a, b, h);
    if (s.limit)
        solve_angular_limits(s, j, a, b, h, use_bias);
    solve_pin(s, a, b, s.softness, use_bias);
}

} // namespace tamias2d
