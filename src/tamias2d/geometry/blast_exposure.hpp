// How a placed shape lies towards a point (World::explode, DD38): its nearest point, the
// distance and direction to it, and the width the shape shows along that direction.
#pragma once

#include "tamias2d/math/vec2d.hpp"
#include "tamias2d/shapes.hpp"

namespace tamias2d {

struct BlastExposure {
    /// m, world frame: the shape's point nearest the centre, or its centroid when the centre
    /// lies in the shape (no nearest boundary point pushes it outward).
    Vec2d point{};
    double distance = 0.0; ///< m, from the centre to the shape (0 inside)
    /// Unit, from the centre to `point`; (1, 0) when they coincide.
    Vec2d direction{1.0, 0.0};
    /// m: the shape's extent across `direction` (its projection on the perpendicular line).
    double width = 0.0;
};

/// The exposure of shape g placed by xf to a blast at x (m, world frame).
BlastExposure blast_exposure(const Geometry& g, const Transform& xf, Vec2d x);

} // namespace tamias2d
