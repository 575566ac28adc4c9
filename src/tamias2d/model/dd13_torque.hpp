#pragma once
#include "tamias2d/units/angle.hpp"
#include "tamias2d/units/vec2.hpp"

namespace tamias2d::model::dd13 {
using namespace tamias2d::units;

/// \srs{DD13} Torque tau = r x F about the point r is measured from (z component, A4 CCW > 0).
inline Torque torque(Vec2<Length> r, Vec2<Force> F) {
    return per_radian(cross(r, F));
}

} // namespace tamias2d::model::dd13
