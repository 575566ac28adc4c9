#include "tamias2d/dynamics/joints/distance_joint.hpp"

#include "tamias2d/dynamics/bridge/joints.hpp"
#include "tamias2d/dynamics/bridge/point_impulse.hpp"
#include "tamias2d/dynamics/joints/joint_creation.hpp"
#include "tamias2d/dynamics/joints/joint_solver.hpp"

namespace tamias2d {

Joint make_joint(const DistanceJointDef& def, const Body& a, const Body& b) {
    Joint j;
    j.type = JointType::distance;
    j.body_a = def.body_a.index;
    j.body_b = def.body_b.index;
    j.local_anchor_a = inv_transform_point(a.xf, def.anchor_a);
    j.local_anchor_b = inv_transform_point(b.xf, def.anchor_b);
    j.length = def.length.value_or(length(def.anchor_b - def.anchor_a));
    j.hertz = def.hertz;
    j.damping_ratio = def.damping_ratio;
    j.enable_limit = def.enable_limit;
    j.lower_limit = def.min_length;
    j.upper_limit = def.max_length;
    j.enable_motor = def.enable_motor;
    j.motor_speed = def.motor_speed;
    j.max_motor = def.max_motor_force;
    j.collide_connected = def.collide_connected;
    j.break_force = def.break_force;
    take_definition_controls(j, def);
    return j;
}

void warm_start_distance(const JointSim& s, const Joint& j, std::span<SolverBody> bodies) {
    SolverBody& a = bodies[s.solver_a];
    SolverBody& b = bodies[s.solver_b];
    const Vec2d r_a = anchor_a(s);
    const Vec2d r_b = anchor_b(s);
    bridge::apply_axial_impulse(a, bridge::moment_arm(r_a, s.step.axis), b,
                                bridge::moment_arm(r_b, s.step.axis), s.step.axis,
                                distance_axial_impulse(j, s.step));
}

void solve_distance(JointSim& s, const Joint& j, std::span<SolverBody> bodies, double h,
                    bool use_bias) {
    const Softness& rigid = s.softness;
    const bool spring = j.hertz > 0.0;
    // A rigid rod holds the length unless the motor drives it (DD35: the rod gives way to the
    // motor, a winch). Limits bound a free length's travel (a rigid rod has none to bound); a
    // spring is not relaxed.
    const bool motor = j.enable_motor;
    const bool limits = (spring || motor) && j.enable_limit;
    if (spring && !use_bias && !limits && !motor)
        return;
    SolverBody& a = bodies[s.solver_a];
    SolverBody& b = bodies[s.solver_b];
    const Vec2d r_a = anchor_a(s);
    const Vec2d r_b = anchor_b(s);
    // The anchors' separation now: the centres have moved by dp since the step's start.
    double length = 0.0;
    bridge::distance_axis(s.center_offset + (b.dp - a.dp) + (r_b - r_a), length, s.step.axis);
    const double arm_a = bridge::moment_arm(r_a, s.step.axis),
                 arm_b = bridge::moment_arm(r_b, s.step.axis);
    if (spring ? use_bias : !motor) {
        double rhs = bridge::axial_velocity_error(a, arm_a, b, arm_b, s.step.axis);
        double mass_scale = 1.0, impulse_scale = 0.0;
        if (use_bias) {
            const Softness soft = spring ? make_joint_softness(j.hertz, j.damping_ratio, h) : rigid;
            rhs = bridge::biased_error(rhs, soft.bias_rate,
                                       bridge::distance_position_error(length, j.length));
            mass_scale = soft.mass_scale;
            impulse_scale = soft.impulse_scale;
        }
        const double lambda = bridge::axial_impulse(a, arm_a, b, arm_b, rhs, mass_scale,
                                                    impulse_scale, s.step.axial_impulse);
        s.step.axial_impulse += lambda;
        bridge::apply_axial_impulse(a, arm_a, b, arm_b, s.step.axis, lambda);
    }
    if (motor) {
        const double rate = bridge::axial_velocity_error(a, arm_a, b, arm_b, s.step.axis);
        const double updated = bridge::distance_motor_update(
            a, arm_a, b, arm_b, rate, j.motor_speed, j.max_motor, h, s.step.motor_impulse);
        bridge::apply_axial_impulse(a, arm_a, b, arm_b, s.step.axis,
                                    updated - s.step.motor_impulse);
        s.step.motor_impulse = updated;
    }
    if (limits)
        solve_axial_limits(s, j, a, b, arm_a, arm_b, s.step.axis, length, h, use_bias);
}

} // namespace tamias2d
