// The shapes a body can carry: circles and convex polygons (rectangles, the SRS's shape, are
// polygons with four vertices). All coordinates are metres in the body's local frame.
#pragma once

#include <array>
#include <cstdint>
#include <span>

#include "tamias2d/vec2.hpp"

namespace tamias2d {

inline constexpr int max_polygon_vertices = 8;

struct Circle {
    Vec2d center{};      ///< m, body frame
    double radius = 0.0; ///< m, > 0
};

/// A convex polygon, vertices counter-clockwise, with outward unit edge normals:
/// normals[i] belongs to the edge vertices[i] -> vertices[i + 1].
struct Polygon {
    std::array<Vec2d, max_polygon_vertices> vertices{};
    std::array<Vec2d, max_polygon_vertices> normals{};
    Vec2d centroid{}; ///< m, body frame
    int count = 0;
};

enum class ShapeType : std::uint8_t { circle, polygon };

/// One shape: a tagged union kept trivially copyable for contiguous storage.
struct Geometry {
    ShapeType type = ShapeType::circle;
    Circle circle{};
    Polygon polygon{};
};

} // namespace tamias2d
