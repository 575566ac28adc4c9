#pragma once
#include "tamias2d/model/dd08_collision_impulse.hpp"
#include "tamias2d/model/dd20_distance_constraint.hpp"
#include "tamias2d/model/dd23_line_constraint.hpp"
#include "tamias2d/units/vec2.hpp"

namespace tamias2d::model::dd35 {
using namespace tamias2d::units;
using dd08::InverseInertia;

/// \srs{DD35} A distance joint's motor after one iteration: the rate of change of the anchors'
/// distance, Ldot = Cdot (DD20's velocity error along the axis n), driven to the motor speed
/// v_m by the rigid impulse -(Ldot - v_m) / K (K: DD8's denominator for the anchors' moment
/// arms), its accumulation over the substep h bounded by the motor's largest force:
/// Lambda_acc <- clamp(Lambda_acc - (Ldot - v_m) / K, -F_max h, F_max h). Returns the new
/// accumulated impulse (N s); the impulse applied is its change.
inline Impulse motor_update(InverseInertia A, InverseInertia B, Length arm_A, Length arm_B,
                            Velocity length_rate, Velocity motor_speed, Force max_force, Time h,
                            Impulse accumulated) {
    const Impulse lambda = dd20::impulse(A, B, arm_A, arm_B, length_rate - motor_speed,
                                         Dimensionless{1.0}, Dimensionless{}, accumulated);
    return dd23::clamp(accumulated + lambda, dd23::impulse_bound(max_force, h));
}

} // namespace tamias2d::model::dd35
