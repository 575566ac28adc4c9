#pragma once
#include "tamias2d/units/vec2.hpp"

namespace tamias2d::model::dd17 {
using namespace tamias2d::units;

/// \srs{DD17} Linear damping: a_d = -c_v v, the acceleration of viscous damping at rate c_v
/// (s^-1), whatever the body's mass (the force is -m c_v v).
inline Vec2<Acceleration> acceleration(Rate c_v, Vec2<Velocity> v) {
    return -(c_v * v);
}

} // namespace tamias2d::model::dd17
