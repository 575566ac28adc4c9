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

/// \srs{DD9} The same theorem along a unit direction n: v_B . n = v_O . n + omega (r_OB x n),
/// since (omega x r) . n = omega (r x n). The moment arm r_OB x n is DD8's (dd08::moment_arm);
/// the contact solver keeps it for the whole step, so a point's normal velocity costs three
/// products instead of six.
template <class V>
Over<Velocity, V> point_velocity_along(Vec2<Over<Velocity, V>> v_O, Over<AngularVelocity, V> omega,
                                       Over<Length, V> arm, Vec2<V> n) {
    return dot(v_O, n) + per_radian(omega * arm);
}

} // namespace tamias2d::model::dd09
