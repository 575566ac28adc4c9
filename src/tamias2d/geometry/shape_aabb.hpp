// The tight world-frame bounding box of a placed shape (the broad phase fattens it).
#pragma once

#include <algorithm>

#include "tamias2d/geometry/aabb.hpp"
#include "tamias2d/geometry/shape_queries.hpp" // world queries pair the box with exact tests
#include "tamias2d/math/vec2d.hpp"
#include "tamias2d/shapes.hpp"

namespace tamias2d {

/// The box of `count` body-frame vertices vertex(0) ... vertex(count - 1) placed by xf: one
/// loop for every vertex layout (a Polygon's arrays, the narrow phase's Collider), so the boxes
/// of the two agree bit for bit.
template <class VertexAt> Aabb vertices_aabb(int count, VertexAt vertex, const Transform& xf) {
    const Vec2d v0 = transform_point(xf, vertex(0));
    Aabb box{v0.x, v0.y, v0.x, v0.y};
    for (int i = 1; i < count; ++i) {
        const Vec2d v = transform_point(xf, vertex(i));
        box.min_x = std::min(box.min_x, v.x);
        box.min_y = std::min(box.min_y, v.y);
        box.max_x = std::max(box.max_x, v.x);
        box.max_y = std::max(box.max_y, v.y);
    }
    return box;
}

Aabb compute_aabb(const Circle& c, const Transform& xf);
Aabb compute_aabb(const Polygon& p, const Transform& xf);
/// A segment kind's box: its core segment's, grown by its rounding on every side.
Aabb compute_aabb(const Capsule& c, const Transform& xf);
Aabb compute_aabb(const Geometry& g, const Transform& xf);

} // namespace tamias2d
