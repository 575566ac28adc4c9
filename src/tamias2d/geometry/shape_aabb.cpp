#include "tamias2d/geometry/shape_aabb.hpp"

#include <algorithm>

namespace tamias2d {

Aabb compute_aabb(const Circle& c, const Transform& xf) {
    const Vec2d p = transform_point(xf, c.center);
    return {p.x - c.radius, p.y - c.radius, p.x + c.radius, p.y + c.radius};
}

Aabb compute_aabb(const Polygon& p, const Transform& xf) {
    const Vec2d v0 = transform_point(xf, p.vertices[0]);
    Aabb box{v0.x, v0.y, v0.x, v0.y};
    for (int i = 1; i < p.count; ++i) {
        const Vec2d v = transform_point(xf, p.vertices[i]);
        box.min_x = std::min(box.min_x, v.x);
        box.min_y = std::min(box.min_y, v.y);
        box.max_x = std::max(box.max_x, v.x);
        box.max_y = std::max(box.max_y, v.y);
    }
    return box;
}

/// \srs{IM4} the axis-aligned rectangle IM4 compares, for one placed shape.
Aabb compute_aabb(const Geometry& g, const Transform& xf) {
    return g.type == ShapeType::circle ? compute_aabb(g.circle, xf) : compute_aabb(g.polygon, xf);
}

} // namespace tamias2d
