#pragma once
#include "tamias2d/units/vec2.hpp"

namespace tamias2d::model::dd04 {
using namespace tamias2d::units;

/// \srs{DD4} Linear acceleration a = dv/dt: over one step with a held constant, dv = a dt.
inline Vec2<Velocity> velocity_change_over(Vec2<Acceleration> a, Time dt) {
    return a * dt;
}

/// \srs{DD4} The mean acceleration over an interval.
inline Vec2<Acceleration> mean_acceleration(Vec2<Velocity> dv, Time dt) {
    return dv / dt;
}

} // namespace tamias2d::model::dd04
