/// \file
/// The shapes a body can carry: circles, convex polygons (rectangles, the SRS's shape, are
/// polygons with four vertices), capsules, segments and the one-sided segments of chains. All
/// coordinates are metres in the body's local frame.
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

/// \srs{DD30} A capsule: the points within `radius` of the segment center1 -> center2 (a
/// rectangle with a half disc on each end). Its mass properties are DD30's closed form.
struct Capsule {
    Vec2d center1{};     ///< m, body frame: one end of the core segment
    Vec2d center2{};     ///< m, body frame: the other end, != center1
    double radius = 0.0; ///< m, > 0
};

/// A two-sided line segment of zero thickness: no area, so it adds no mass (game levels put
/// it on static bodies). Shapes collide with either side.
struct Segment {
    Vec2d point1{}; ///< m, body frame
    Vec2d point2{}; ///< m, body frame, != point1
};

/// \srs{DD31} One edge of a chain (World::create_chain makes them): a segment that collides on
/// one side only, the right of point1 -> point2 (so a counter-clockwise loop is solid inside
/// and collides outside, like a polygon), and knows its neighbours' far ends so that a shape
/// sliding across the vertex between two edges meets no "ghost" corner there. No mass.
struct ChainSegment {
    Vec2d ghost1{}; ///< m: the previous edge's start (ghost1 -> point1 is that edge)
    Vec2d point1{}; ///< m, body frame
    Vec2d point2{}; ///< m, body frame, != point1
    Vec2d ghost2{}; ///< m: the next edge's end (point2 -> ghost2 is that edge)
};

/// The kind of a Geometry.
enum class ShapeType : std::uint8_t { circle, polygon, capsule, segment, chain_segment };

/// One shape: a tagged union kept trivially copyable for contiguous storage.
struct Geometry {
    ShapeType type = ShapeType::circle; ///< which of the members holds the shape
    Circle circle{};                    ///< the shape when type is circle
    Polygon polygon{};                  ///< the shape when type is polygon
    Capsule capsule{};                  ///< the shape when type is capsule
    Segment segment{};                  ///< the shape when type is segment
    ChainSegment chain_segment{};       ///< the shape when type is chain_segment
};

} // namespace tamias2d
