#pragma once
#include "tamias2d/units/vec2.hpp"

namespace tamias2d::model::t1 {
using namespace tamias2d::units;

/// \srs{T1} Newton's second law of motion: F = m a, solved for the acceleration.
inline Vec2<Acceleration> acceleration(Vec2<Force> net_force, Mass m) {
    return net_force / m;
}

/// \srs{T1} F = m a.
inline Vec2<Force> force(Mass m, Vec2<Acceleration> a) {
    return m * a;
}

} // namespace tamias2d::model::t1
