#pragma once
#include "tamias2d/units/vec2.hpp"

namespace tamias2d::model::dd03 {
using namespace tamias2d::units;

/// \srs{DD3} Linear velocity v = dr/dt. Over one step of length dt with v held constant the
/// displacement is r = v dt; the integrator (IM1) uses this with the end-of-step velocity.
inline Vec2<Length> displacement_over(Vec2<Velocity> v, Time dt) {
    return v * dt;
}

/// \srs{DD3} The mean velocity over an interval: finite-difference form of v = dr/dt.
inline Vec2<Velocity> mean_velocity(Vec2<Length> r, Time dt) {
    return r / dt;
}

} // namespace tamias2d::model::dd03
