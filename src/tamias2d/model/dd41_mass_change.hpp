#pragma once
#include "tamias2d/model/dd09_chasles_theorem.hpp"
#include "tamias2d/units/vec2.hpp"

namespace tamias2d::model::dd41 {
using namespace tamias2d::units;

/// \srs{DD41} A change of a body's mass data keeps its rigid motion: the new centre of mass
/// p' takes the velocity it had as a point of the body, v' = v + omega x (p' - p) (DD9), and
/// omega' = omega. Momentum is not kept: p_momentum' = M' v' (GD1 states no rule for a change
/// of mass made from outside the system).
inline Vec2<Velocity> center_velocity(Vec2<Velocity> v, AngularVelocity omega,
                                      Vec2<Length> center_shift) {
    return dd09::point_velocity<double>(v, omega, center_shift);
}

} // namespace tamias2d::model::dd41
