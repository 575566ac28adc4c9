#pragma once
#include "tamias2d/model/im6_motion_with_joints.hpp"
#include "tamias2d/units/quantities.hpp"

namespace tamias2d::model::dd37 {
using namespace tamias2d::units;

/// A joint's stiffness and damping ratio of IM6's soft bias.
struct Tuning {
    Rate hertz;
    Dimensionless damping_ratio;
};

/// \srs{DD37} The softness over the substep h = dt / n of a joint with a tuning of its own
/// (f_k, zeta_k), which it uses in place of the world's (f_J, zeta): IM6's coefficients of
/// (f_k, zeta_k), f_k capped at a quarter of the substep rate as IM6 caps f_J.
inline im6::Softness softness(Tuning t, int substeps, Time dt, Time h) {
    return im6::softness(im6::frequency(t.hertz, substeps, dt), t.damping_ratio, h);
}

} // namespace tamias2d::model::dd37
