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

namespace {

/// The core segment a -> b with rounding r; the chain segment's ghosts are set by the caller.
Collider segment_collider(ShapeType type, Vec2d a, Vec2d b, double r) {
    Collider k;
    k.type = type;
    k.count = 2;
    k.radius = r;
    k.center = 0.5 * (a + b);
    const Vec2d n = normalize(right_perp(b - a));
    for (int lane = 0; lane < 2; ++lane) {
        const Vec2d v = lane == 0 ? a : b;
        const Vec2d m = lane == 0 ? n : -n;
        k.pairs[0].vx[lane] = v.x;
        k.pairs[0].vy[lane] = v.y;
        k.pairs[0].nx[lane] = m.x;
        k.pairs[0].ny[lane] = m.y;
    }
    for (int pair = 1; pair < max_vertex_pairs; ++pair) {
        for (int lane = 0; lane < 2; ++lane) { // lanes past the count repeat vertex 0
            k.pairs[pair].vx[lane] = a.x;
            k.pairs[pair].vy[lane] = a.y;
            k.pairs[pair].nx[lane] = n.x;
            k.pairs[pair].ny[lane] = n.y;
        }
    }
    return k;
}

} // namespace

Collider make_collider(const Capsule& c) {
    return segment_collider(ShapeType::capsule, c.center1, c.center2, c.radius);
}

Collider make_collider(const Segment& s) {
    return segment_collider(ShapeType::segment, s.point1, s.point2, 0.0);
}

Collider make_collider(const ChainSegment& s) {
    Collider k = segment_collider(ShapeType::chain_segment, s.point1, s.point2, 0.0);
    k.pairs[1].vx[0] = s.ghost1.x;
    k.pairs[1].vy[0] = s.ghost1.y;
    k.pairs[1].vx[1] = s.ghost2.x;
    k.pairs[1].vy[1] = s.ghost2.y;
    return k;
}

Aabb compute_aabb(const Collider& k, const Transform& xf) {
    if (k.type == ShapeType::circle)
        return compute_aabb(Circle{k.center, k.radius}, xf);
    if (k.is_segment_kind())
        return compute_aabb(Capsule{k.vertex(0), k.vertex(1), k.radius}, xf);
    return vertices_aabb(
        k.count, [&](int i) { return k.vertex(i); }, xf);
}

bool surely_inside(const Collider& k, const Transform& xf, const Aabb& box) {
    // A circle's exact box reads only the header: the caller's test. A segment kind's reads
    // one pair: no shortcut worth a bound.
    if (k.type != ShapeType::polygon)
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
    switch (g.type) {
    case ShapeType::polygon:
        return make_collider(g.polygon);
    case ShapeType::capsule:
        return make_collider(g.capsule);
    case ShapeType::segment:
        return make_collider(g.segment);
    case ShapeType::chain_segment:
        return make_collider(g.chain_segment);
    case ShapeType::circle:
        break;
    }
    return make_collider(g.circle);
}

} // namespace tamias2d
