#pragma once
#include "tamias2d/units/vec2.hpp"

namespace tamias2d::model::dd31 {
using namespace tamias2d::units;

/// Whether N lies in the arc from `from` counter-clockwise to `to` (less than a half turn), or
/// within the tolerance's angle of it. The two cross products alone would also admit the
/// directions about half a turn away when the arc is narrower than twice that angle (a barely
/// convex vertex, the back of the edge among them): N must face the arc's bisector too.
inline bool within_arc(Vec2<double> from, Vec2<double> to, Vec2<double> N, double tolerance) {
    return cross(from, N) >= -tolerance && cross(N, to) >= -tolerance && dot(N, from + to) > 0.0;
}

/// \srs{DD31} Whether a contact normal N (unit, from the chain into the shape) may come from
/// chain edge k, whose normal is n, between the edges before and after it (normals n_prev,
/// n_next). At a convex vertex (the chain turns counter-clockwise there: the surface falls away)
/// the normals between the two edges' belong to the vertex; at a flat or concave vertex none do, so
/// N must be n itself, or within the convex vertices' arcs next to it. A normal outside is the
/// neighbour's (or a ghost of the joint between edges): the edge then answers with its face.
inline bool admissible(Vec2<double> n_prev, Vec2<double> n, Vec2<double> n_next, Vec2<double> N,
                       double tolerance) {
    const bool facing = dot(n, N) > 0.0;
    if (cross(n, N) <= 0.0) // N turned clockwise from n: towards the start vertex's arc
        return cross(n_prev, n) > 0.0 ? within_arc(n_prev, n, N, tolerance)
                                      : cross(n, N) >= -tolerance && facing;
    return cross(n, n_next) > 0.0 ? within_arc(n, n_next, N, tolerance)
                                  : cross(n, N) <= tolerance && facing;
}

} // namespace tamias2d::model::dd31
