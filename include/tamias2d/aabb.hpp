/// \file
/// Axis-aligned bounding boxes: the region argument of World::query_aabb and the boxes of the
/// broad phase (SRS IM4 decides when two of them overlap).
#pragma once

namespace tamias2d {

/// An axis-aligned box in the world frame, by its lower-left and upper-right corners (m).
/// A valid box has min_x <= max_x and min_y <= max_y (World::query_aabb refuses another).
struct Aabb {
    double min_x = 0.0; ///< m, left edge
    double min_y = 0.0; ///< m, bottom edge
    double max_x = 0.0; ///< m, right edge
    double max_y = 0.0; ///< m, top edge
};

} // namespace tamias2d
