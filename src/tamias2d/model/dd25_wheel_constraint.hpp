#pragma once
#include "tamias2d/model/dd20_distance_constraint.hpp"
#include "tamias2d/model/im6_motion_with_joints.hpp"
#include "tamias2d/units/quantities.hpp"

namespace tamias2d::model::dd25 {
using namespace tamias2d::units;
using dd08::InverseInertia;

/// \srs{DD25} The wheel's impulse across the suspension axis: lambda_perp = -gamma_m
/// (Cdot_perp + beta C_perp) / K_perp - gamma_i lambda_acc, DD23's line error C_perp (from the
/// moment arms (d + r_A) x a_perp and r_B x a_perp) held in IM6's soft form with the joints'
/// softness s, the impulse along a_perp with DD8's denominator K_perp (DD20's axial impulse).
/// Without the bias (the relax) the line's rate alone is stopped, rigidly. The suspension along
/// the axis is DD23's spring and limits, the motor DD22's.
inline Impulse line_impulse(InverseInertia A, InverseInertia B, Length perp_arm_A,
                            Length perp_arm_B, Velocity line_rate, Length line_error,
                            const im6::Softness& s, bool use_bias, Impulse accumulated) {
    if (!use_bias)
        return dd20::impulse(A, B, perp_arm_A, perp_arm_B, line_rate, Dimensionless{1.0},
                             Dimensionless{}, accumulated);
    return dd20::impulse(A, B, perp_arm_A, perp_arm_B,
                         im6::biased_velocity_error(line_rate, s.bias_rate, line_error),
                         s.mass_scale, s.impulse_scale, accumulated);
}

} // namespace tamias2d::model::dd25
