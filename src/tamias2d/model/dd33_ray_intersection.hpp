#pragma once
#include <boost/units/cmath.hpp>

#include "tamias2d/units/vec2.hpp"

namespace tamias2d::model::dd33 {
using namespace tamias2d::units;

/// \srs{DD33} Where the line o + t u (u a unit vector, t in m) first meets the circle of radius
/// r about c: with t_mid = -(o - c) . u the parameter of the line's closest approach to the
/// centre, at the distance h from it, the line enters at t_mid - sqrt(r^2 - h^2) (`h2`, the
/// squared half chord r^2 - h^2, must be >= 0: else the line misses). This form keeps its
/// precision when the ray is long compared with the circle.
inline Length circle_entry(Length t_mid, Area half_chord_squared) {
    return t_mid - boost::units::sqrt(half_chord_squared);
}

/// \srs{DD33} Where the segment o + t d, t in [0, 1], crosses the line of a face n . (x - a) = 0
/// (n its unit normal): t = n . (a - o) / n . d, given as its numerator n . (a - o) and its
/// denominator n . d (non-zero: not parallel). Polygons clip the ray against each face so
/// (Cyrus-Beck); segments, capsules' sides and chain edges are such faces.
inline Dimensionless plane_crossing(Length numerator, Length denominator) {
    return numerator / denominator;
}

} // namespace tamias2d::model::dd33
