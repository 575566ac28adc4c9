#include "tamias2d/dynamics/joint_solver.hpp"

#include "tamias2d/dynamics/body_store.hpp"
#include "tamias2d/dynamics/distance_joint.hpp"
#include "tamias2d/dynamics/revolute_joint.hpp"
#include "tamias2d/dynamics/target_joint.hpp"

namespace tamias2d {

void prepare_joint(Joint& j, const BodyStore& store,
                   const std::vector<std::uint32_t>& solver_index) {
    const Body& a = store.bodies[j.body_a];
    const Body& b = store.bodies[j.body_b];
    j.solver_a = solver_index[j.body_a];
    j.solver_b = solver_index[j.body_b];
    j.frame_a = j.local_anchor_a - a.local_center;
    j.frame_b = j.local_anchor_b - b.local_center;
    j.angle_a = a.angle;
    j.angle_b = b.angle;
    j.center_offset = b.center - a.center;
    j.center_b = b.center;
}

void warm_start_joint(const Joint& j, std::span<SolverBody> bodies) {
    switch (j.type) {
    case JointType::revolute:
        warm_start_revolute(j, bodies);
        return;
    case JointType::distance:
        warm_start_distance(j, bodies);
        return;
    case JointType::target:
        warm_start_target(j, bodies);
        return;
    }
}

void solve_joint(Joint& j, std::span<SolverBody> bodies, const Softness& rigid, double h,
                 bool use_bias) {
    switch (j.type) {
    case JointType::revolute:
        solve_revolute(j, bodies, rigid, h, use_bias);
        return;
    case JointType::distance:
        solve_distance(j, bodies, rigid, h, use_bias);
        return;
    case JointType::target:
        solve_target(j, bodies, h, use_bias);
        return;
    }
}

} // namespace tamias2d
