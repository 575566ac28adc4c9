// What a joint's accumulated impulses mean outside its solve: IM6's reaction force and torque,
// and DD36's break thresholds on them.
#pragma once

#include "tamias2d/dynamics/bridge/typing.hpp"
#include "tamias2d/model/dd22_angular_constraint.hpp"
#include "tamias2d/model/dd36_joint_break.hpp"
#include "tamias2d/model/im6_motion_with_joints.hpp"

namespace tamias2d::bridge {

/// IM6's reaction force (N) of a joint's impulse (N s) over the substep of rate inv_h (s^-1).
inline Vec2d reaction_force(Vec2d impulse, double inv_h) {
    return plain(m::im6::reaction(typed<u::Impulse>(impulse), u::from_value<u::Rate>(inv_h)));
}
inline double reaction_force(double impulse, double inv_h) {
    return m::im6::reaction(u::from_value<u::Impulse>(impulse), u::from_value<u::Rate>(inv_h))
        .value();
}
/// IM6's reaction torque (N m) of a joint's angular impulse (N m s).
inline double reaction_torque(double angular_impulse, double inv_h) {
    return m::im6::reaction(m::dd22::AngularImpulse::from_value(angular_impulse),
                            u::from_value<u::Rate>(inv_h))
        .value();
}

/// DD36: whether a joint whose last substep's reaction force has the magnitude `force` (N) and
/// whose reaction torque is `torque` (N m) breaks at the thresholds break_force, break_torque.
inline bool joint_breaks(double force, double break_force, double torque, double break_torque) {
    return m::dd36::breaks(u::from_value<u::Force>(force), u::from_value<u::Force>(break_force),
                           u::from_value<u::Torque>(torque),
                           u::from_value<u::Torque>(break_torque));
}

} // namespace tamias2d::bridge
