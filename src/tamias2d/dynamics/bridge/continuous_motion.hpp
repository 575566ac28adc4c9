// DD29: how far a body's points move over a step, and its linear motion within the step, as
// continuous collision sweeps them.
#pragma once

#include "tamias2d/dynamics/bridge/typing.hpp"
#include "tamias2d/model/dd29_time_of_impact.hpp"

namespace tamias2d::bridge {

/// DD29's bound on how far any point of a body moves when its centre moves `translation` (m)
/// and it turns `rotation` (rad, >= 0), its points at most `reach` (m) from the centre.
inline double motion_bound(double translation, double rotation, double reach) {
    return m::dd29::motion_bound(u::from_value<u::Length>(translation),
                                 u::from_value<u::Angle>(rotation), u::from_value<u::Length>(reach))
        .value();
}

/// DD29's linear motion over the step: a centre (m), an angle (rad), a velocity (m s^-1) or an
/// angular velocity (rad s^-1) at the fraction t, from its values at the start and the end.
inline Vec2d center_at(Vec2d start, Vec2d end, double t) {
    return plain(m::dd29::at_fraction(typed<u::Length>(start), typed<u::Length>(end), t));
}
inline double angle_at(double start, double end, double t) {
    return m::dd29::at_fraction(u::from_value<u::Angle>(start), u::from_value<u::Angle>(end), t)
        .value();
}
inline Vec2d velocity_at(Vec2d start, Vec2d end, double t) {
    return plain(m::dd29::at_fraction(typed<u::Velocity>(start), typed<u::Velocity>(end), t));
}
inline double angular_velocity_at(double start, double end, double t) {
    return m::dd29::at_fraction(u::from_value<u::AngularVelocity>(start),
                                u::from_value<u::AngularVelocity>(end), t)
        .value();
}

} // namespace tamias2d::bridge
