// Exact queries on one placed shape: point containment and ray casts (world queries run them
// on the broad phase's candidates).
#pragma once

#include <optional>

#include "tamias2d/math/vec2d.hpp"
#include "tamias2d/shapes.hpp"

namespace tamias2d {

/// Where a ray first meets a shape's boundary.
struct RayHit {
    Vec2d point{};         ///< m, world frame
    Vec2d normal{};        ///< unit outward normal of the shape at `point`
    double fraction = 0.0; ///< point = origin + fraction * translation, in [0, 1]
};

/// p (m, world) lies in the closed shape placed by xf.
bool test_point(const Geometry& g, const Transform& xf, Vec2d p);

/// The first entry of the segment origin -> origin + translation into the shape. A ray that
/// starts inside (or on the boundary moving inward) does not hit: games cast rays out of
/// bodies, and the hit they want is the next body's. Zero translation never hits.
std::optional<RayHit> ray_cast(const Geometry& g, const Transform& xf, Vec2d origin,
                               Vec2d translation);

} // namespace tamias2d
