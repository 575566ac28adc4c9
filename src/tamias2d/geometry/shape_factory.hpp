// Building valid shapes. Every shape the engine sees comes through here (or through validate),
// so the narrow phase and the mass computation may assume: finite coordinates, positive sizes,
// convex counter-clockwise polygons of 3..8 vertices with unit outward normals and no
// collinear or coincident vertices, turning round once (simple), with their vertices' centroid. Bad
// input throws ValidationError naming the field (R4).
#pragma once

#include <span>
#include <vector>

#include "tamias2d/memory/allocator.hpp"
#include "tamias2d/shapes.hpp"

namespace tamias2d {

/// A box of half extents (half_w, half_h) m centred at `center` (body frame), rotated by
/// `angle` rad (CCW, A4). Vertices start at the lower-left corner of the unrotated box.
/// Throws ValidationError (DCX_shape, DCX_finite) for non-positive or non-finite input.
Polygon make_box(double half_w, double half_h, Vec2d center = {}, double angle = 0.0);

/// The same box from its full width and height (m), as box_shape takes them: a size that is
/// not finite or not > 0 is reported as the caller gave it ("shape.width = 0"), not as the half
/// extent make_box receives.
Polygon make_box_of_size(double width, double height, Vec2d center = {}, double angle = 0.0);

/// The convex hull of `points` (m, body frame). Points closer than a relative welding tolerance
/// (1e-6 of the cloud's extent) are merged, and collinear points dropped. Throws
/// ValidationError when an input is not finite (DCX_finite), or the hull has fewer than 3
/// vertices, no area, or more than max_polygon_vertices vertices (DCX_shape).
Polygon make_polygon(std::span<const Vec2d> points);

/// A circle of `radius` m (> 0) centred at `center` (body frame).
Circle make_circle(double radius, Vec2d center = {});

/// A capsule of `radius` m (> 0) around the segment center1 -> center2 (distinct, finite).
Capsule make_capsule(Vec2d center1, Vec2d center2, double radius);

/// A two-sided segment point1 -> point2 (distinct, finite).
Segment make_segment(Vec2d point1, Vec2d point2);

/// The one-sided segments of a chain through `points` (m, body frame; at least 2, or 3 for a
/// loop; consecutive points distinct, all finite), each colliding on its right (DD31). A loop
/// also joins the last point to the first. An open chain's two ends are convex corners (their
/// ghosts lie straight behind the end, so a shape rolls round an end as round a box's corner).
memory::vector<ChainSegment> make_chain(std::span<const Vec2d> points, bool loop);

/// Wraps a shape in the tagged Geometry the world stores.
Geometry to_geometry(const Circle& c);
Geometry to_geometry(const Polygon& p);
Geometry to_geometry(const Capsule& c);
Geometry to_geometry(const Segment& s);
Geometry to_geometry(const ChainSegment& s);

/// Checks a hand-made shape against the invariants the factories guarantee (same errors).
void validate(const Circle& c);
void validate(const Polygon& p);
void validate(const Capsule& c);
void validate(const Segment& s);
void validate(const ChainSegment& s);
void validate(const Geometry& g);

/// The geometry with only its kind's member set (the other kinds' members, and a polygon's
/// vertices and normals past its count, at their defaults): what the world stores, so that no
/// unused member carries a value any reader could walk (a circle's polygon.count, say).
Geometry canonical(const Geometry& g);

/// The relative tolerance used to weld hull points and to reject slivers.
inline constexpr double hull_weld_tolerance = 1e-6;

} // namespace tamias2d
