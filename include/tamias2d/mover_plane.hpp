/// \file
/// A plane of contact between a capsule mover and a shape of the world (World::collide_mover):
/// Box2D v3's b2PlaneResult.
#pragma once

#include "tamias2d/collision_plane.hpp"
#include "tamias2d/function_ref.hpp"
#include "tamias2d/handles.hpp"
#include "tamias2d/vec2.hpp"

namespace tamias2d {

/// \srs{DD34} A shape the mover overlaps or nearly touches, as a plane on the mover's
/// translation: plane.normal is DD34's unit direction from the shape's nearest point towards
/// the mover's core segment, plane.offset = r - d with r the mover's radius and d the
/// distance from the core to the shape (positive: it overlaps by that much and must leave).
struct MoverPlane {
    ShapeId shape;          ///< the shape met
    BodyId body;            ///< the body carrying it
    CollisionPlane plane{}; ///< ready for solve_planes (rigid, clips velocities)
    Vec2d point{};          ///< m, world frame: the shape's point nearest the mover's core
};

/// collide_mover's callback: true goes on, false stops. It must not change the world.
using MoverPlaneCallback = FunctionRef<bool(const MoverPlane&)>;

} // namespace tamias2d
