// A shape laid out for the narrow phase (T5): made once when the shape is created, so a collision
// reads one compact record per shape instead of the Geometry (whose vertex and normal arrays lie
// in different cache lines) and never recomputes the polygon's size.
#pragma once

#include "tamias2d/geometry/aabb.hpp"
#include "tamias2d/math/vec2d.hpp"
#include "tamias2d/shapes.hpp"

namespace tamias2d {

/// Two consecutive vertices of a polygon and their edge normals, one array per coordinate (a
/// vertex per lane): one cache line, loaded as two-lane registers by the separating axis test.
struct alignas(16) VertexPair {
    double vx[2], vy[2]; ///< m, body frame
    double nx[2], ny[2]; ///< outward unit normal of the edge to the next vertex
};

inline constexpr int max_vertex_pairs = max_polygon_vertices / 2;

/// A circle, a convex polygon or a rounded segment (capsule, segment, chain segment), in its
/// body's frame. A segment kind holds its two ends as vertices 0 and 1 (pair 0) with the normals
/// n and -n, n the right normal of vertex 0 -> vertex 1, and its rounding in `radius` (0 for a
/// segment or a chain segment); a chain segment keeps its ghost vertices in pair 1's vertex
/// lanes (ghost(0), ghost(1)). A box reads two pairs and the header:
/// three cache lines when the collider starts one (the header's 32 bytes leave the rest of its
/// line to the owner).
struct alignas(16) Collider {
    /// Vertex i is lane i % 2 of pair i / 2; a lane past the count repeats vertex 0 (finite
    /// values, never read as a vertex).
    VertexPair pairs[max_vertex_pairs]{};
    ShapeType type = ShapeType::circle;
    std::uint8_t count = 0; ///< polygon vertices (0 for a circle)
    /// The polygon's largest |x| and |y| of a vertex from the centroid (body frame), as
    /// fractions of `radius` in 65535ths, rounded up: a bound of its world box that reads no
    /// vertex line (surely_inside).
    std::uint16_t extent[2]{};
    double radius = 0.0; ///< m: the circle's radius, the polygon's largest vertex distance
                         ///< from its centroid (its size, for relative tolerances), or a
                         ///< segment kind's rounding
    Vec2d center{};      ///< m: the circle's centre, the polygon's centroid or the segment's
                         ///< midpoint

    Vec2d vertex(int i) const { return {pairs[i >> 1].vx[i & 1], pairs[i >> 1].vy[i & 1]}; }
    Vec2d normal(int i) const { return {pairs[i >> 1].nx[i & 1], pairs[i >> 1].ny[i & 1]}; }
    /// A chain segment's ghost vertex: 0 before vertex 0, 1 after vertex 1.
    Vec2d ghost(int i) const { return {pairs[1].vx[i], pairs[1].vy[i]}; }
    /// A capsule, a segment or a chain segment: two vertices and a rounding radius.
    bool is_segment_kind() const { return type >= ShapeType::capsule; }
};

Collider make_collider(const Circle& c);
Collider make_collider(const Polygon& p);
Collider make_collider(const Capsule& c);
Collider make_collider(const Segment& s);
Collider make_collider(const ChainSegment& s);
Collider make_collider(const Geometry& g);

/// \srs{IM4} The shape's tight world-frame box, equal bit for bit to compute_aabb of the
/// geometry it was made from (the same loop), read from the collider's lines.
Aabb compute_aabb(const Collider& k, const Transform& xf);

/// True only if compute_aabb(k, xf) surely lies inside `box`, decided from the collider's header
/// (no vertex line is read): a resting or slowly moving polygon's test against its fat box.
/// False decides nothing; a circle always gets false (its exact box reads only the header).
bool surely_inside(const Collider& k, const Transform& xf, const Aabb& box);

} // namespace tamias2d
