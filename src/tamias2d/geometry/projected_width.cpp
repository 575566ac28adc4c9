#include "tamias2d/geometry/projected_width.hpp"

#include <algorithm>
#include <cmath>

namespace tamias2d {

double projected_width(const Geometry& g, Rot q, Vec2d direction) {
    const Vec2d t = left_perp(direction);
    const auto spread = [&](Vec2d a, Vec2d b) {
        return std::abs(dot(t, rotate(q, b) - rotate(q, a)));
    };
    switch (g.type) {
    case ShapeType::circle:
        return 2.0 * g.circle.radius;
    case ShapeType::capsule:
        return spread(g.capsule.center1, g.capsule.center2) + 2.0 * g.capsule.radius;
    case ShapeType::segment:
        return spread(g.segment.point1, g.segment.point2);
    case ShapeType::chain_segment:
        return spread(g.chain_segment.point1, g.chain_segment.point2);
    case ShapeType::polygon:
        break;
    }
    const Polygon& p = g.polygon;
    double lo = dot(t, rotate(q, p.vertices[0])), hi = lo;
    for (int k = 1; k < p.count; ++k) {
        const double s = dot(t, rotate(q, p.vertices[std::size_t(k)]));
        lo = std::min(lo, s);
        hi = std::max(hi, s);
    }
    return hi - lo;
}

} // namespace tamias2d
