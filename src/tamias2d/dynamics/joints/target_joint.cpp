#include "tamias2d/dynamics/joints/target_joint.hpp"

#include "tamias2d/dynamics/bridge/joints.hpp"
#include "tamias2d/dynamics/joints/joint_solver.hpp"
#include "tamias2d/dynamics/softness.hpp"

namespace tamias2d {

Joint make_joint(const TargetJointDef& def, const Body& b) {
    Joint j;
    j.type = JointType::target;
    j.body_a = j.body_b = def.body.index;
    j.local_anchor_a = j.local_anchor_b = inv_transform_point(b.xf, def.target);
    j.target = def.target;
    j.hertz = def.hertz;
    j.damping_ratio = def.damping_ratio;
    j.max_force = def.max_force;
    j.collide_connected = true; // one body: nothing to filter
    return j;
}

// The target is DD19's pin with an immovable body A (DD21): a solver body of zero inverse mass
// at rest stands for it, so that the pin's formulas serve unchanged.

void warm_start_target(const JointSim& s, std::span<SolverBody> bodies) {
    SolverBody& b = bodies[s.solver_b];
    SolverBody world{};
    bridge::apply_pin_impulse(world, {}, b, anchor_b(s), s.step.linear_impulse);
}

void solve_target(JointSim& s, const Joint& j, std::span<SolverBody> bodies, double h,
                  bool use_bias) {
    if (!use_bias)
        return;
    SolverBody& b = bodies[s.solver_b];
    SolverBody world{};
    const Vec2d r = anchor_b(s);
    const Softness soft = make_joint_softness(j.hertz, j.damping_ratio, h);
    const Vec2d c = bridge::target_position_error(s.center_b + b.dp, r, j.target);
    const Vec2d rhs =
        bridge::biased_error(bridge::pin_velocity_error(world, {}, b, r), soft.bias_rate, c);
    const Vec2d P = bridge::pin_impulse(world, {}, b, r, rhs, soft.mass_scale, soft.impulse_scale,
                                        s.step.linear_impulse);
    const Vec2d old = s.step.linear_impulse;
    s.step.linear_impulse =
        bridge::clamp_impulse(old + P, bridge::force_impulse_bound(j.max_force, h));
    bridge::apply_pin_impulse(world, {}, b, r, s.step.linear_impulse - old);
}

} // namespace tamias2d
