/// \file
/// The shapes a body can carry: circles and convex polygons (rectangles, the SRS's shape, are
/// polygons with four vertices). All coordinates are metres in the body's local frame.
#pragma once

#include <array>
#include <cstdint>
#include <span>

#include "tamias2d/vec2.hpp"

namespace tamias2d {

/// The most vertices a Polygon holds (as in Box2D: enough for game shapes, fixed size storage).
inline constexpr int max_polygon_vertices = 8;

/// A disc of a given radius around a centre in the body frame.
struct Circle {
    Vec2d center{};      ///< m, body frame
    double radius = 0.0; ///< m, > 0
};

/// A convex polygon, vertices counter-clockwise, with outward unit edge normals:
/// normals[i] belongs to the edge vertices[i] -> vertices[i + 1].
struct Polygon {
    std::array<Vec2d, max_polygon_vertices> vertices{}; ///< m, body frame; the first `count`
    std::array<Vec2d, max_polygon_vertices> normals{};  ///< unit; the first `count`
    Vec2d centroid{};                                   ///< m, body frame
    int count = 0;                                      ///< 3 to max_polygon_vertices
};

/// The kind of a Geometry.
enum class ShapeType : std::uint8_t { circle, polygon };

/// One shape: a tagged union kept trivially copyable for contiguous storage.
struct Geometry {
    ShapeType type = ShapeType::circle; ///< which of the two members holds the shape
    Circle circle{};                    ///< the shape when type is circle
    Polygon polygon{};                  ///< the shape when type is polygon
};

} // namespace tamias2d
