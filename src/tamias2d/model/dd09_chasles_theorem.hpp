#pragma once
#include "tamias2d/units/angle.hpp"
#include "tamias2d/units/vec2.hpp"

namespace tamias2d::model::dd09 {
using namespace tamias2d::units;

/// \srs{DD9} Chasles' theorem: the velocity of point B of a rigid body is
/// v_B = v_O + omega x r_OB (omega about z, A4; per_radian turns rad m s^-1 into m s^-1).
/// (V: double, or a pack of lanes.)
template <class V>
Vec2<Over<Velocity, V>> point_velocity(Vec2<Over<Velocity, V>> v_O, Over<AngularVelocity, V> omega,
                                       Vec2<Over<Length, V>> r_OB) {
    return v_O + per_radian(cross(omega, r_OB));
}

} // namespace tamias2d::model::dd09
