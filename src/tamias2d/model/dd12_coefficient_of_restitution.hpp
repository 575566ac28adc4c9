#pragma once
#include "tamias2d/units/quantities.hpp"

namespace tamias2d::model::dd12 {
using namespace tamias2d::units;

/// \srs{DD12} Coefficient of restitution C_R = -(v_f^AB . n) / (v_i^AB . n). Undefined when the
/// bodies were not approaching (v_i . n = 0); callers measure it only for real impacts.
inline Dimensionless coefficient_of_restitution(Velocity v_f_n, Velocity v_i_n) {
    return -v_f_n / v_i_n;
}

/// \srs{DD12} The same law solved for the separating normal velocity: v_f . n = -C_R v_i . n.
inline Velocity separating_normal_velocity(Dimensionless C_R, Velocity v_i_n) {
    return -C_R * v_i_n;
}

} // namespace tamias2d::model::dd12
