/// \file
/// A plane that bounds a mover's translation (solve_planes, clip_vector): Box2D v3's
/// b2CollisionPlane.
#pragma once

#include <limits>

#include "tamias2d/vec2.hpp"

namespace tamias2d {

/// \srs{DD43} One constraint on a mover's translation d (m) from the pose where the plane was
/// found: n . d >= offset. World::collide_mover makes them (MoverPlane::plane); a game may
/// add its own (a soft wall: a finite push_limit).
struct CollisionPlane {
    Vec2d normal{};     ///< unit, pointing away from the obstacle (towards free space)
    double offset = 0.; ///< m: the least n . d allowed (positive: the mover must leave it)
    /// m, >= 0: the most this plane may push the translation along its normal. Infinite: a
    /// rigid plane; a finite value lets the mover press into it (a soft obstacle).
    double push_limit = std::numeric_limits<double>::infinity();
    /// m, output of solve_planes: how far this plane pushed the translation (0: not in
    /// contact). clip_vector reads it.
    double push = 0.0;
    /// Whether clip_vector removes a velocity's part into this plane (false: a soft plane
    /// that should not stop the mover).
    bool clip_velocity = true;
};

} // namespace tamias2d
