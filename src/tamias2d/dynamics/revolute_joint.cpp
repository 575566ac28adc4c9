#include "tamias2d/dynamics/revolute_joint.hpp"

#include "tamias2d/dynamics/joint_solver.hpp"
#include "tamias2d/dynamics/model_bridge.hpp"

namespace tamias2d {
void warm_start_revolute(const Joint& j, std::span<SolverBody> bodies) {
    SolverBody& a = bodies[j.solver_a];
    SolverBody& b = bodies[j.solver_b];
    bridge::apply_pin_impulse(a, anchor_offset(j.frame_a, j.angle_a, a), b,
                              anchor_offset(j.frame_b, j.angle_b, b), j.linear_impulse);
}

void solve_revolute(Joint& j, std::span<SolverBody> bodies, const Softness& softness,
                    bool use_bias) {
    SolverBody& a = bodies[j.solver_a];
    SolverBody& b = bodies[j.solver_b];
    const Vec2d r_a = anchor_offset(j.frame_a, j.angle_a, a);
    const Vec2d r_b = anchor_offset(j.frame_b, j.angle_b, b);
    Vec2d rhs = bridge::pin_velocity_error(a, r_a, b, r_b);
    double mass_scale = 1.0, impulse_scale = 0.0;
    if (use_bias) {
        // The pins' separation now: the centres have moved by dp since the step's start.
        const Vec2d c = bridge::pin_position_error(j.center_offset + (b.dp - a.dp), r_a, r_b);
        rhs += softness.bias_rate * c;
        mass_scale = softness.mass_scale;
        impulse_scale = softness.impulse_scale;
    }
    const Vec2d P =
        bridge::pin_impulse(a, r_a, b, r_b, rhs, mass_scale, impulse_scale, j.linear_impulse);
    j.linear_impulse += P;
    bridge::apply_pin_impulse(a, r_a, b, r_b, P);
}

} // namespace tamias2d
