#include "tamias2d/collision/collider.hpp"

#include <algorithm>
#include <cmath>

#include "tamias2d/geometry/shape_aabb.hpp"

namespace tamias2d {

Collider make_collider(const Circle& c) {
    Collider k;
    k.type = ShapeType::circle;
    k.radius = c.radius;
    k.center = c.center;
    return k;
}

Collider make_collider(const Polygon& p) {
    Collider k;
    k.type = ShapeType::polygon;
    k.count = static_cast<std::uint8_t>(p.count);
    k.center = p.centroid;
    double r2 = 0.0;
    for (int i = 0; i < p.count; ++i)
        r2 = std::max(r2, dot(p.vertices[i] - p.centroid, p.vertices[i] - p.centroid));
    k.radius = std::sqrt(r2);
    for (int axis = 0; axis < 2; ++axis) {
        double h = 0.0;
        for (int i = 0; i < p.count; ++i) {
            const Vec2d u = p.vertices[i] - p.centroid;
            h = std::max(h, std::abs(axis == 0 ? u.x : u.y));
        }
        // Up, so the bound holds; |u| <= radius, so the fraction is at most one.
        k.extent[axis] =
            static_cast<std::uint16_t>(std::min(65535.0, std::ceil(h / k.radius * 65535.0)));
    }
    for (int i = 0; i < max_polygon_vertices; ++i) {
        const int from = i < p.count ? i : 0;
        VertexPair& pair = k.pairs[i / 2];
        pair.vx[i % 2] = p.vertices[from].x;
        pair.vy[i % 2] = p.vertices[from].y;
        pair.nx[i % 2] = p.normals[from].x;
        pair.ny[i % 2] = p.normals[from].y;
    }
    return k;
}

Aabb compute_aabb(const Collider& k, const Transform& xf) {
    if (k.type == ShapeType::circle)
        return compute_aabb(Circle{k.center, k.radius}, xf);
    return vertices_aabb(
        k.count, [&](int i) { return k.vertex(i); }, xf);
}

bool surely_inside(const Collider& k, const Transform& xf, const Aabb& box) {
    if (k.type == ShapeType::circle) // its exact box reads only the header: the caller's test
        return false;
    // Each vertex is the centroid plus u with |u.x| <= hx and |u.y| <= hy, so once rotated its
    // offset is within |c| hx + |s| hy along x and |s| hx + |c| hy along y.
    constexpr double unit = 1.0 / 65535.0;
    const double hx = k.radius * (k.extent[0] * unit);
    const double hy = k.radius * (k.extent[1] * unit);
    const double c = std::abs(xf.q.c), s = std::abs(xf.q.s);
    const double ex = c * hx + s * hy, ey = s * hx + c * hy;
    const Vec2d o = transform_point(xf, k.center);
    // Slack for rounding, in this bound and in compute_aabb's own arithmetic: some 10^6 ulps
    // of the coordinates, still far below any margin.
    const double slack = 1e-9 * (k.radius + std::abs(o.x) + std::abs(o.y));
    return box.min_x <= o.x - ex - slack && box.min_y <= o.y - ey - slack &&
           o.x + ex + slack <= box.max_x && o.y + ey + slack <= box.max_y;
}

Collider make_collider(const Geometry& g) {
    return g.type == ShapeType::polygon ? make_collider(g.polygon) : make_collider(g.circle);
}

} // namespace tamias2d
