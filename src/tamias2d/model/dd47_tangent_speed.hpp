#pragma once
#include <cmath>

#include "tamias2d/units/quantities.hpp"

namespace tamias2d::model::dd47 {
using namespace tamias2d::units;

/// \srs{DD47} The relative tangential velocity (of b with respect to a, along the right
/// perpendicular of the normal from a into b) that friction drives a contact towards: the sum
/// s_a + s_b of its two surfaces' own speeds, each along the tangent turning clockwise around
/// its shape. 0 for two surfaces at rest: Coulomb friction's sticking (LC2).
inline Velocity friction_target(Velocity s_a, Velocity s_b) {
    return s_a + s_b;
}

/// \srs{DD47} A tangent speed is valid when finite (any sign).
inline bool valid_tangent_speed(double s) {
    return std::isfinite(s);
}

} // namespace tamias2d::model::dd47
