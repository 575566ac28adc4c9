#pragma once
#include "tamias2d/units/angle.hpp"
#include "tamias2d/units/vec2.hpp"

namespace tamias2d::model::dd09 {
using namespace tamias2d::units;

/// \srs{DD9} Chasles' theorem: the velocity of point B of a rigid body is
/// v_B = v_O + omega x r_OB (omega about z, A4; per_radian turns rad m s^-1 into m s^-1).
inline Vec2<Velocity> point_velocity(Vec2<Velocity> v_O, AngularVelocity omega, Vec2<Length> r_OB) {
    return v_O + per_radian(cross(omega, r_OB));
}

} // namespace tamias2d::model::dd09
