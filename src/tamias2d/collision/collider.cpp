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
    k.count = p.count;
    k.center = p.centroid;
    double r2 = 0.0;
    for (int i = 0; i < p.count; ++i)
        r2 = std::max(r2, dot(p.vertices[i] - p.centroid, p.vertices[i] - p.centroid));
    k.radius = std::sqrt(r2);
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

Collider make_collider(const Geometry& g) {
    return g.type == ShapeType::polygon ? make_collider(g.polygon) : make_collider(g.circle);
}

} // namespace tamias2d
