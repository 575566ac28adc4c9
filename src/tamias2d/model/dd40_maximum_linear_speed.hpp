#pragma once
#include "tamias2d/units/vec2.hpp"

namespace tamias2d::model::dd40 {
using namespace tamias2d::units;

/// \srs{DD40} Maximum linear speed: v' = v min(1, v_max / |v|), the velocity of the centre of
/// mass slowed along its own direction to at most v_max (unchanged when |v| <= v_max; v_max
/// infinite leaves every velocity unchanged).
inline Vec2<Velocity> limited_velocity(Vec2<Velocity> v, Velocity v_max) {
    if (!(norm_squared(v) > v_max * v_max))
        return v;
    return (v_max / norm(v)) * v;
}

} // namespace tamias2d::model::dd40
