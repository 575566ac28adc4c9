/// \file
/// A mover's translation that satisfies its collision planes (solve_planes), and a velocity
/// clipped against them (clip_vector): Box2D v3's b2SolvePlanes and b2ClipVector.
#pragma once

#include <span>

#include "tamias2d/collision_plane.hpp"
#include "tamias2d/config.hpp"
#include "tamias2d/export.hpp"
#include "tamias2d/result.hpp"
#include "tamias2d/vec2.hpp"

namespace tamias2d {

/// What solve_planes found.
struct PlaneSolverResult {
    Vec2d translation{};    ///< m: the translation closest to the target the planes allow
    int iterations = 0;     ///< sweeps over the planes made
    bool converged = false; ///< the last sweep's pushes summed to less than the tolerance
};

#if TAMIAS2D_EXCEPTIONS
/// \srs{DD43} The translation d closest to `target` (m) with n_i . d >= offset_i for every
/// plane, each plane pushing at most its push_limit: minimise |d - target|^2 by projected
/// Gauss-Seidel on the planes' pushes p_i (d = target + sum p_i n_i, 0 <= p_i <= limit_i),
/// sweeping the planes in order until a sweep changes the pushes by less than `tolerance` (m)
/// in sum, or after `max_iterations` sweeps. Writes each plane's push (CollisionPlane::push).
/// Normals must be unit; with none, the target is returned. A pure function: no world.
TAMIAS2D_EXPORT PlaneSolverResult solve_planes(Vec2d target, std::span<CollisionPlane> planes,
                                               double tolerance = 1e-9, int max_iterations = 200);

/// \srs{DD43} `v` without its parts into the planes solve_planes pressed against (push > 0 and
/// clip_velocity): for each in order, v -= min(0, v . n) n. A character's velocity after a
/// move, so that it slides along a wall or a slope instead of pressing into it.
TAMIAS2D_EXPORT Vec2d clip_vector(Vec2d v, std::span<const CollisionPlane> planes);
#endif // TAMIAS2D_EXCEPTIONS

// The error-returning forms (result.hpp): each `try_` call is the call of the same name,
// returning its result or the Error its throwing form would throw, instead of throwing.
// Declared whatever TAMIAS2D_EXCEPTIONS is.
/// solve_planes, returning its Error instead of throwing it.
TAMIAS2D_EXPORT Result<PlaneSolverResult> try_solve_planes(Vec2d target,
                                                           std::span<CollisionPlane> planes,
                                                           double tolerance = 1e-9,
                                                           int max_iterations = 200) noexcept;
/// clip_vector, returning its Error instead of throwing it.
TAMIAS2D_EXPORT Result<Vec2d> try_clip_vector(Vec2d v,
                                              std::span<const CollisionPlane> planes) noexcept;

} // namespace tamias2d
