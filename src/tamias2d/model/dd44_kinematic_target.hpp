#pragma once
#include <cmath>

#include "tamias2d/units/angle.hpp"
#include "tamias2d/units/vec2.hpp"

namespace tamias2d::model::dd44 {
using namespace tamias2d::units;

/// \srs{DD44} The shortest turn from phi to the target angle theta: theta - phi less the whole
/// turns nearest it, Delta = (theta - phi) - 2 pi round((theta - phi) / 2 pi), in [-pi, pi]
/// (IEEE remainder: exact for the difference it is given).
inline Angle shortest_turn(Angle phi, Angle theta) {
    return Angle::from_value(std::remainder((theta - phi).value(), two_pi));
}

/// \srs{DD44} The velocity of the centre of mass that carries it from c to the target's c_t in
/// one step of dt: v = (c_t - c) / dt (DD3 read backwards: the displacement over dt).
inline Vec2<Velocity> target_velocity(Vec2<Length> c, Vec2<Length> c_target, Time dt) {
    return (c_target - c) / dt;
}

/// \srs{DD44} The angular velocity that turns the body through the shortest turn Delta in one
/// step of dt: omega = Delta / dt (DD6 read backwards).
inline AngularVelocity target_angular_velocity(Angle turn, Time dt) {
    return turn / dt;
}

} // namespace tamias2d::model::dd44
