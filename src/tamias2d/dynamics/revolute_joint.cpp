#include "tamias2d/dynamics/revolute_joint.hpp"

#include "tamias2d/dynamics/joint_solver.hpp"
#include "tamias2d/dynamics/model_bridge.hpp"

namespace tamias2d {

void warm_start_revolute(const Joint& j, std::span<SolverBody> bodies) {
    SolverBody& a = bodies[j.solver_a];
    SolverBody& b = bodies[j.solver_b];
    bridge::apply_angular_impulse(a, b, reaction_angular_impulse(j));
    bridge::apply_pin_impulse(a, anchor_a(j), b, anchor_b(j), j.linear_impulse);
}

void solve_revolute(Joint& j, std::span<SolverBody> bodies, const Softness& softness, double h,
                    bool use_bias) {
    SolverBody& a = bodies[j.solver_a];
    SolverBody& b = bodies[j.solver_b];
    if (j.enable_spring && use_bias) {
        // DD22's spring: the joint angle pulled to 0 with the spring's own softness.
        const Softness soft = make_joint_softness(j.hertz, j.damping_ratio, h);
        const double rhs = bridge::biased_angular_error(bridge::joint_speed(a, b), soft.bias_rate,
                                                        current_joint_angle(j, a, b));
        const double lambda = bridge::angular_impulse(a, b, rhs, soft.mass_scale,
                                                      soft.impulse_scale, j.spring_impulse);
        j.spring_impulse += lambda;
        bridge::apply_angular_impulse(a, b, lambda);
    }
    if (j.enable_motor)
        solve_angular_motor(j, a, b, h);
    if (j.enable_limit)
        solve_angular_limits(j, a, b, softness, h, use_bias);
    solve_pin(j, a, b, softness, use_bias);
}

} // namespace tamias2d
