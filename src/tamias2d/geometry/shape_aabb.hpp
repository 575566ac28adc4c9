// The tight world-frame bounding box of a placed shape (the broad phase fattens it).
#pragma once

#include "tamias2d/geometry/aabb.hpp"
#include "tamias2d/geometry/shape_queries.hpp" // world queries pair the box with exact tests
#include "tamias2d/geometry/shapes.hpp"

namespace tamias2d {

Aabb compute_aabb(const Circle& c, const Transform& xf);
Aabb compute_aabb(const Polygon& p, const Transform& xf);
Aabb compute_aabb(const Geometry& g, const Transform& xf);

} // namespace tamias2d
