#include "view_geometry.hpp"

#include <cmath>

namespace tamias2d::view {

using nlohmann::json;

json point_json(Vec2d v) {
    return json::array({v.x, v.y});
}

json geometry_json(const Geometry& g) {
    const auto ends = [](Vec2d a, Vec2d b) { return json::array({a.x, a.y, b.x, b.y}); };
    switch (g.type) {
    case ShapeType::polygon: {
        json points = json::array();
        for (int k = 0; k < g.polygon.count; ++k) {
            const Vec2d v = g.polygon.vertices[static_cast<std::size_t>(k)];
            points.push_back(v.x);
            points.push_back(v.y);
        }
        return {{"p", std::move(points)}};
    }
    case ShapeType::capsule:
        return {{"cap", ends(g.capsule.center1, g.capsule.center2)}, {"r", g.capsule.radius}};
    case ShapeType::segment:
        return {{"seg", ends(g.segment.point1, g.segment.point2)}};
    case ShapeType::chain_segment:
        return {{"edge", ends(g.chain_segment.point1, g.chain_segment.point2)}};
    case ShapeType::circle:
        break;
    }
    return {{"c", point_json(g.circle.center)}, {"r", g.circle.radius}};
}

Vec2d to_body_frame(const World& world, BodyId id, Vec2d p) {
    const Vec2d o = world.origin(id);
    const double a = world.orientation(id);
    const double c = std::cos(a), s = std::sin(a);
    const Vec2d d = p - o;
    return {c * d.x + s * d.y, -s * d.x + c * d.y};
}

} // namespace tamias2d::view
