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

Aabb compute_aabb(const Capsule& c, const Transform& xf) {
    const Vec2d a = transform_point(xf, c.center1);
    const Vec2d b = transform_point(xf, c.center2);
    return {std::min(a.x, b.x) - c.radius, std::min(a.y, b.y) - c.radius,
            std::max(a.x, b.x) + c.radius, std::max(a.y, b.y) + c.radius};
}

/// \srs{IM4} the axis-aligned rectangle IM4 compares, for one placed shape.
Aabb compute_aabb(const Geometry& g, const Transform& xf) {
    switch (g.type) {
    case ShapeType::polygon:
        return compute_aabb(g.polygon, xf);
    case ShapeType::capsule:
        return compute_aabb(g.capsule, xf);
    case ShapeType::segment:
        return compute_aabb(Capsule{g.segment.point1, g.segment.point2, 0.0}, xf);
    case ShapeType::chain_segment:
        return compute_aabb(Capsule{g.chain_segment.point1, g.chain_segment.point2, 0.0}, xf);
    case ShapeType::circle:
        break;
    }
    return compute_aabb(g.circle, xf);
}

} // namespace tamias2d
