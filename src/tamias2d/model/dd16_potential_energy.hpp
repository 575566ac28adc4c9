#pragma once
#include "tamias2d/units/vec2.hpp"

namespace tamias2d::model::dd16 {
using namespace tamias2d::units;

/// \srs{DD16} Potential energy PE = m g h with g the magnitude of the gravitational acceleration
/// (m s^-2; the SRS writes m s^-1, an erratum) and h the height above the reference.
inline Energy potential_energy(Mass m, Acceleration g, Length h) {
    return m * g * h;
}

/// \srs{DD16} The same for a gravity vector in any direction: PE = -m g . p (reference: origin).
inline Energy potential_energy(Mass m, Vec2<Acceleration> g, Vec2<Length> p) {
    return -m * dot(g, p);
}

} // namespace tamias2d::model::dd16
