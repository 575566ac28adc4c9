#pragma once
#include "tamias2d/model/dd22_angular_constraint.hpp"
#include "tamias2d/model/im6_motion_with_joints.hpp"
#include "tamias2d/units/quantities.hpp"

namespace tamias2d::model::dd24 {
using namespace tamias2d::units;
using dd08::InverseInertia;
using dd22::AngularImpulse;

/// \srs{DD24} The weld's angular impulse: Lambda = -gamma_m (thetadot + beta_theta C_theta) / k -
/// gamma_i Lambda_acc, DD22's impulse on the angle error C_theta (DD22's joint angle against the
/// reference angle) in IM6's soft form, with the weld's angular softness s (the joints' rigid
/// one, or a torsional spring's). Without the bias (the relax) the joint speed alone is
/// stopped, rigidly. The weld's point is DD19's pin, solved after this.
inline AngularImpulse angular_impulse(InverseInertia A, InverseInertia B,
                                      AngularVelocity joint_speed, Angle angle_error,
                                      const im6::Softness& s, bool use_bias,
                                      AngularImpulse accumulated) {
    if (!use_bias)
        return dd22::impulse(A, B, joint_speed, Dimensionless{1.0}, Dimensionless{}, accumulated);
    return dd22::impulse(A, B, im6::biased_velocity_error(joint_speed, s.bias_rate, angle_error),
                         s.mass_scale, s.impulse_scale, accumulated);
}

} // namespace tamias2d::model::dd24
