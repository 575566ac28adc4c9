#include "tamias2d/geometry/shape_aabb.hpp"

namespace tamias2d {

Aabb compute_aabb(const Circle& c, const Transform& xf) {
    const Vec2d p = transform_point(xf, c.center);
    return {p.x - c.radius, p.y - c.radius, p.x + c.radius, p.y + c.radius};
}

Aabb compute_aabb(const Polygon& p, const Transform& xf) {
    return vertices_aabb(
        p.count, [&](int i) { return p.vertices[std::size_t(i)]; }, xf);
}

/// \srs{IM4} the axis-aligned rectangle IM4 compares, for one placed shape.
Aabb compute_aabb(const Geometry& g, const Transform& xf) {
    return g.type == ShapeType::circle ? compute_aabb(g.circle, xf) : compute_aabb(g.polygon, xf);
}

} // namespace tamias2d
