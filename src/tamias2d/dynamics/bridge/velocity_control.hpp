// Run-time control of a body's velocity: motion locks (DD39), the speed limit (DD40), a mass
// change's shift of the centre (DD41).
#pragma once

#include "tamias2d/dynamics/bridge/typing.hpp"
#include "tamias2d/model/dd39_motion_locks.hpp"
#include "tamias2d/model/dd40_maximum_linear_speed.hpp"
#include "tamias2d/model/dd41_mass_change.hpp"

namespace tamias2d::bridge {

inline Vec2d locked_velocity(Vec2d v, bool lock_x, bool lock_y) {
    return plain(m::dd39::projected_velocity(typed<u::Velocity>(v), lock_x, lock_y));
}
inline Vec2d limited_velocity(Vec2d v, double v_max) {
    return plain(
        m::dd40::limited_velocity(typed<u::Velocity>(v), u::from_value<u::Velocity>(v_max)));
}
inline Vec2d shifted_center_velocity(Vec2d v, double w, Vec2d shift) {
    return plain(m::dd41::center_velocity(
        typed<u::Velocity>(v), u::from_value<u::AngularVelocity>(w), typed<u::Length>(shift)));
}

} // namespace tamias2d::bridge
