#include "tamias2d/dynamics/joints/joint_creation.hpp"

namespace tamias2d {

Joint two_body_joint(JointType type, std::uint32_t index_a, const Body& a, std::uint32_t index_b,
                     const Body& b, Vec2d anchor, bool collide_connected, double break_force) {
    Joint j;
    j.type = type;
    j.body_a = index_a;
    j.body_b = index_b;
    j.local_anchor_a = inv_transform_point(a.xf, anchor);
    j.local_anchor_b = inv_transform_point(b.xf, anchor);
    j.collide_connected = collide_connected;
    j.break_force = break_force;
    j.reference_angle = b.angle - a.angle;
    return j;
}

Vec2d local_axis(const Body& a, Vec2d axis) {
    return inv_rotate(a.xf.q, normalize(axis));
}

} // namespace tamias2d
