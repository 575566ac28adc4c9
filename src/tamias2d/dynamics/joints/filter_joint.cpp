#include "tamias2d/dynamics/joints/filter_joint.hpp"

namespace tamias2d {

Joint make_joint(const FilterJointDef& def, const Body&, const Body&) {
    Joint j;
    j.type = JointType::filter;
    j.body_a = def.body_a.index;
    j.body_b = def.body_b.index;
    j.collide_connected = false; // what the joint is for
    return j;                    // break_force infinite: it carries no force
}

} // namespace tamias2d
