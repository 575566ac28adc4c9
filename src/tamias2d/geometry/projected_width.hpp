// The width a placed shape shows a flow along a direction (World::apply_wind, DD45): its
// extent across that direction.
#pragma once

#include "tamias2d/math/vec2d.hpp"
#include "tamias2d/shapes.hpp"

namespace tamias2d {

/// m: the extent of shape g, turned by q, projected on the line perpendicular to the unit
/// `direction`: a circle's diameter, a polygon's or segment's vertices' spread, a capsule's
/// core's spread plus its diameter.
double projected_width(const Geometry& g, Rot q, Vec2d direction);

} // namespace tamias2d
