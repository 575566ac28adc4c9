#include "tamias2d/geometry/blast_exposure.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace tamias2d {

namespace {

/// The point of segment a -> b nearest x.
Vec2d nearest_on_segment(Vec2d a, Vec2d b, Vec2d x) {
    const Vec2d e = b - a;
    const double ee = dot(e, e);
    const double t = ee > 0.0 ? std::clamp(dot(x - a, e) / ee, 0.0, 1.0) : 0.0;
    return a + t * e;
}

/// A round shape (a circle, or a capsule's core widened by r): nearest point from the core's
/// nearest point q, or the core's centre `mid` when x lies within r of the core.
void round_exposure(BlastExposure& e, Vec2d q, double r, Vec2d mid, Vec2d x) {
    const double d = length(q - x);
    if (d <= r) {
        e.point = mid;
        e.distance = 0.0;
    } else {
        e.point = q + (r / d) * (x - q);
        e.distance = d - r;
    }
}

} // namespace

BlastExposure blast_exposure(const Geometry& g, const Transform& xf, Vec2d x) {
    BlastExposure e;
    std::array<Vec2d, max_polygon_vertices> v{};
    int count = 0;
    double radius = 0.0; // a round shape's: added on both sides of its core's width
    switch (g.type) {
    case ShapeType::circle: {
        const Vec2d c = transform_point(xf, g.circle.center);
        round_exposure(e, c, g.circle.radius, c, x);
        v[0] = c;
        count = 1;
        radius = g.circle.radius;
        break;
    }
    case ShapeType::capsule: {
        const Vec2d a = transform_point(xf, g.capsule.center1);
        const Vec2d b = transform_point(xf, g.capsule.center2);
        round_exposure(e, nearest_on_segment(a, b, x), g.capsule.radius, 0.5 * (a + b), x);
        v[0] = a;
        v[1] = b;
        count = 2;
        radius = g.capsule.radius;
        break;
    }
    case ShapeType::segment:
    case ShapeType::chain_segment: {
        const bool seg = g.type == ShapeType::segment;
        const Vec2d a = transform_point(xf, seg ? g.segment.point1 : g.chain_segment.point1);
        const Vec2d b = transform_point(xf, seg ? g.segment.point2 : g.chain_segment.point2);
        round_exposure(e, nearest_on_segment(a, b, x), 0.0, 0.5 * (a + b), x);
        v[0] = a;
        v[1] = b;
        count = 2;
        break;
    }
    case ShapeType::polygon: {
        const Polygon& p = g.polygon;
        count = p.count;
        bool inside = true;
        for (int k = 0; k < count; ++k) {
            const auto i = std::size_t(k);
            v[i] = transform_point(xf, p.vertices[i]);
            if (dot(rotate(xf.q, p.normals[i]), x - v[i]) > 0.0)
                inside = false;
        }
        if (inside) {
            e.point = transform_point(xf, p.centroid);
            e.distance = 0.0;
            break;
        }
        double best = std::numeric_limits<double>::infinity();
        for (int k = 0; k < count; ++k) {
            const Vec2d q =
                nearest_on_segment(v[std::size_t(k)], v[std::size_t((k + 1) % count)], x);
            const double d = length(q - x);
            if (d < best) {
                best = d;
                e.point = q;
            }
        }
        e.distance = best;
        break;
    }
    }
    const Vec2d to = e.point - x;
    const double l = length(to);
    e.direction = l > 0.0 ? Vec2d{to.x / l, to.y / l} : Vec2d{1.0, 0.0};
    const Vec2d t = left_perp(e.direction);
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (int k = 0; k < count; ++k) {
        const double s = dot(t, v[std::size_t(k)]);
        lo = std::min(lo, s);
        hi = std::max(hi, s);
    }
    e.width = (hi - lo) + 2.0 * radius;
    return e;
}

} // namespace tamias2d
