#include "tamias2d/dynamics/motor_joint.hpp"

#include "tamias2d/dynamics/joint_solver.hpp"
#include "tamias2d/dynamics/model_bridge.hpp"

namespace tamias2d {

void warm_start_motor(const Joint& j, std::span<SolverBody> bodies) {
    SolverBody& a = bodies[j.solver_a];
    SolverBody& b = bodies[j.solver_b];
    bridge::apply_angular_impulse(a, b, j.angular_impulse);
    bridge::apply_pin_impulse(a, anchor_a(j), b, anchor_b(j), j.linear_impulse);
}

void solve_motor(Joint& j, std::span<SolverBody> bodies, double h, bool use_bias) {
    if (!use_bias)
        return;
    SolverBody& a = bodies[j.solver_a];
    SolverBody& b = bodies[j.solver_b];
    // DD26: each error asks for the velocity that removes the fraction `correction_factor` of
    // it per substep; the accumulated impulses are bounded by the largest torque and force.
    const double rate = bridge::correction_rate(j.correction_factor, h);
    const double angular =
        bridge::motor_angular_update(a, b, bridge::joint_speed(a, b), current_joint_angle(j, a, b),
                                     rate, j.max_torque, h, j.angular_impulse);
    bridge::apply_angular_impulse(a, b, angular - j.angular_impulse);
    j.angular_impulse = angular;

    const Vec2d r_a = anchor_a(j);
    const Vec2d r_b = anchor_b(j);
    const Vec2d c = bridge::pin_position_error(j.center_offset + (b.dp - a.dp), r_a, r_b);
    const Vec2d old = j.linear_impulse;
    j.linear_impulse = bridge::motor_linear_update(
        a, r_a, b, r_b, bridge::pin_velocity_error(a, r_a, b, r_b), c, rate, j.max_force, h, old);
    bridge::apply_pin_impulse(a, r_a, b, r_b, j.linear_impulse - old);
}

} // namespace tamias2d
