// Time of impact of a shape swept over one step against a fixed shape (DD29): conservative
// advancement on the distance between two convex shapes. The continuous pass
// (dynamics/continuous.hpp) uses it to keep fast bodies from passing through static ones.
#pragma once

#include "tamias2d/collision/collider.hpp"
#include "tamias2d/math/vec2d.hpp"
#include "tamias2d/model/dd29_time_of_impact.hpp"

namespace tamias2d {

/// The closest approach of two convex shapes.
struct ShapeDistance {
    double distance = 0.0; ///< m: 0 when they overlap or touch, else the true gap (to rounding)
    Vec2d normal{};        ///< unit, from the first shape towards the second (when apart)
    Vec2d point_a{};       ///< m: the first shape's point nearest the second (when apart)
    Vec2d point_b{};       ///< m: the second shape's point nearest the first (when apart)
};

/// \srs{DD34} The distance between collider a placed by xa and collider b placed by xb, with
/// the closest points (World::distance and the queries read them). Apart, it is the
/// least distance between their boundaries: between a polygon's edges and the other's edges
/// (segment to segment), or from a circle's centre, less its radius. Overlapping is decided
/// first (separating axes, or a circle's centre inside), so the distance is never an edge
/// distance across an interior.
ShapeDistance shape_distance(const Collider& a, const Transform& xa, const Collider& b,
                             const Transform& xb);

/// A body's motion over a step: its centre of mass and angle vary linearly from the start
/// pose (t = 0) to the end pose (t = 1), as the step's write-back left them.
struct Sweep {
    Vec2d local_center{}; ///< m, body frame
    Vec2d c0{}, c1{};     ///< m, centre of mass at the start and end
    double a0 = 0.0, a1 = 0.0;

    /// The pose at the fraction t: DD29's linear motion of the centre and the angle.
    Transform at(double t) const {
        namespace u = tamias2d::units;
        const u::Vec2<u::Length> c =
            model::dd29::at_fraction(u::vec_from_values<u::Length>(c0.x, c0.y),
                                     u::vec_from_values<u::Length>(c1.x, c1.y), t);
        Transform xf;
        xf.q = Rot::from_angle(
            model::dd29::at_fraction(u::Angle::from_value(a0), u::Angle::from_value(a1), t)
                .value());
        xf.p = Vec2d{c.x.value(), c.y.value()} - rotate(xf.q, local_center);
        return xf;
    }
};

/// The farthest point of a collider from `pivot` (body frame), m: its reach as the body turns.
double reach(const Collider& k, Vec2d pivot);

enum class ToiState {
    separated,  ///< no approach within `target` before t_max
    hit,        ///< t is the first time found at which the gap is within target + tolerance
    overlapped, ///< already within target + tolerance at t = 0
};

struct ToiResult {
    ToiState state = ToiState::separated;
    double t = 1.0;     ///< fraction of the step; the gap at t is never below target
    int iterations = 0; ///< distance evaluations after t = 0
};

/// \srs{DD29} The earliest fraction t in [0, t_max] of the sweep at which `moving` comes within
/// `target` (+ `tolerance`) of `fixed` (placed by `fixed_xf`), by conservative advancement:
/// from the closest points, the plane between them keeps the shapes apart until every point
/// of the moving shape could have crossed it, which bounds the next step in t (DD29's
/// advance). Every t it visits is safe: the gap there is at least `target`. After
/// `max_iterations` without converging (a grazing approach) it reports the last safe t as a hit.
ToiResult time_of_impact(const Collider& moving, const Sweep& sweep, const Collider& fixed,
                         const Transform& fixed_xf, double target, double tolerance,
                         double t_max = 1.0, int max_iterations = 30);

} // namespace tamias2d
