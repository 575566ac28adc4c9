#include "tamias2d/dynamics/joints/weld_joint.hpp"

#include "tamias2d/dynamics/bridge/joints.hpp"
#include "tamias2d/dynamics/joints/joint_creation.hpp"
#include "tamias2d/dynamics/joints/joint_solver.hpp"

namespace tamias2d {

Joint make_joint(const WeldJointDef& def, const Body& a, const Body& b) {
    Joint j = two_body_joint(JointType::weld, def.body_a.index, a, def.body_b.index, b, def.anchor,
                             def.collide_connected, def.break_force);
    j.hertz = def.linear_hertz;
    j.damping_ratio = def.linear_damping_ratio;
    j.angular_hertz = def.angular_hertz;
    j.angular_damping_ratio = def.angular_damping_ratio;
    j.break_torque = def.break_torque;
    take_definition_controls(j, def);
    return j;
}

void solve_weld(JointSim& s, const Joint& j, std::span<SolverBody> bodies, double h,
                bool use_bias) {
    const Softness& rigid = s.softness;
    SolverBody& a = bodies[s.solver_a];
    SolverBody& b = bodies[s.solver_b];
    // A soft part is a spring (hertz > 0): its own softness, and no relax, which would undo it.
    const bool soft_angle = j.angular_hertz > 0.0, soft_pin = j.hertz > 0.0;
    if (use_bias || !soft_angle) {
        // DD24: the angle first, the point (DD19) last.
        const Softness angular =
            soft_angle ? make_joint_softness(j.angular_hertz, j.angular_damping_ratio, h) : rigid;
        const double lambda = bridge::weld_angular_impulse(a, b, bridge::joint_speed(a, b),
                                                           current_joint_angle(s, a, b), angular,
                                                           use_bias, s.step.angular_impulse);
        s.step.angular_impulse += lambda;
        bridge::apply_angular_impulse(a, b, lambda);
    }
    if (use_bias || !soft_pin)
        solve_pin(s, a, b, soft_pin ? make_joint_softness(j.hertz, j.damping_ratio, h) : rigid,
                  use_bias);
}

} // namespace tamias2d
