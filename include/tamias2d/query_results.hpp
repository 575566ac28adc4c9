/// \file
/// What the World's queries answer (World::ray_cast, shape_cast, distance, closest_point), and
/// the callbacks that see their hits one by one.
#pragma once

#include "tamias2d/function_ref.hpp"
#include "tamias2d/handles.hpp"
#include "tamias2d/vec2.hpp"

namespace tamias2d {

/// Where a ray meets a shape (World::ray_cast).
struct RayCastHit {
    ShapeId shape;         ///< the shape hit
    BodyId body;           ///< the body carrying it
    Vec2d point{};         ///< m
    Vec2d normal{};        ///< unit, outward from the shape
    double fraction = 0.0; ///< along the ray's translation, in [0, 1]
};

/// Where a cast shape first touches a shape of the world (World::shape_cast).
struct ShapeCastHit {
    ShapeId shape; ///< the shape hit
    BodyId body;   ///< the body carrying it
    /// m: the point of the hit shape nearest the cast shape at `fraction` (the cast origin
    /// moved to that fraction when they overlap at the start).
    Vec2d point{};
    /// Unit, outward from the hit shape towards the cast shape at `fraction`; zero when they
    /// overlap at the start (fraction 0), where no direction is defined.
    Vec2d normal{};
    /// The cast shape's origin is origin + fraction * translation when it touches, in [0, 1].
    double fraction = 0.0;
};

/// \srs{DD34} The closest points of two shapes, or of a shape and a point (World::distance,
/// World::closest_point).
struct ClosestPoints {
    /// m: the least distance between the two (0 when they touch or overlap).
    double distance = 0.0;
    bool overlapping = false; ///< they share a point (distance 0); the points are then not set
    Vec2d point_a{};          ///< m: on the first shape
    Vec2d point_b{};          ///< m: on the second shape (the point itself for closest_point)
    Vec2d normal{};           ///< unit, from point_a towards point_b (zero when overlapping)
};

/// What a ray or shape cast callback returns for a hit (Box2D v3's b2CastResultFcn convention):
///   -1 (any negative value): ignore this shape and go on, the cast not clipped;
///    0: stop the cast now;
///    the hit's fraction: clip the cast there, so that only nearer hits are reported from now on;
///    1: go on without clipping (every hit is reported).
/// A value between 0 and 1 clips the cast at that fraction. Callbacks must not change the world.
using RayCastCallback = FunctionRef<double(const RayCastHit&)>;
/// The shape cast's callback: returns as a RayCastCallback does.
using ShapeCastCallback = FunctionRef<double(const ShapeCastHit&)>;
/// An overlap query's callback: true goes on, false stops the query. It must not change the
/// world.
using OverlapCallback = FunctionRef<bool(ShapeId)>;

} // namespace tamias2d
