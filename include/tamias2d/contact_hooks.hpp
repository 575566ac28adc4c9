/// \file
/// The game's hooks into contact solving (World's contact_hooks calls): a pre-solve callback
/// that may switch a touching pair off for one step (one-way platforms), and the functions that
/// mix two shapes' friction and restitution into a contact's (DD42).
#pragma once

#include <cstdint>
#include <functional>

#include "tamias2d/handles.hpp"
#include "tamias2d/vec2.hpp"

namespace tamias2d {

/// A touching pair as the pre-solve callback sees it: after the narrow phase, before the solver.
/// Asked by the continuous pass (a fast body about to be stopped short of a shape), it holds
/// one point, midway between the closest points of the moving shape (or of its core, when the
/// shape already overlaps) and the other shape, with their gap as its separation.
struct PreSolveContact {
    ShapeId shape_a;     ///< the first shape of the pair
    ShapeId shape_b;     ///< the second shape of the pair
    BodyId body_a;       ///< the body carrying shape_a
    BodyId body_b;       ///< the body carrying shape_b
    Vec2d normal{};      ///< unit, from shape_a into shape_b
    int point_count = 0; ///< 1 or 2: how many of `points` hold a point
    /// One manifold point.
    struct Point {
        Vec2d point{};           ///< m, world frame
        double separation = 0.0; ///< m, negative when overlapping (speculative when > 0)
    };
    Point points[2]{}; ///< the manifold's points (two for a face-to-face contact)
};

/// Asked once per touching pair per step (World::set_pre_solve): true solves the contact this
/// step, false switches it off for this step (its manifold emptied: the pair counts as not
/// touching, with the end and begin events that follow). Also asked where the continuous pass
/// would stop a fast body short of a shape: false lets it through.
using PreSolveFunction = std::function<bool(const PreSolveContact&)>;

/// Mixes two shapes' coefficients into a contact's (World::set_friction_mixing,
/// set_restitution_mixing): (value_a, user_material_a, value_b, user_material_b) -> the
/// contact's value. The user material ids are Material::user_material_id.
using MaterialMixFunction = std::function<double(double, std::uint64_t, double, std::uint64_t)>;

} // namespace tamias2d
