// One contact manifold's share of a soft-step iteration (warm start, normal solve, friction),
// written once as a template over the value type V: V = double solves one manifold
// (ContactConstraint, SolverBody), V = Wide solves four manifolds that share no body, one per
// lane (WideContactConstraint, WideBody; see wide_contact_solver.cpp). The field names of the
// two constraint and body types match, and both points are always processed: an unused second
// point is all zeros and changes nothing. Every formula is a call into the model layer through
// Model (bridge::Model: DD8, DD9, DD11, IM3, IM7's impulse, target and two-point solve, on
// Boost.Units quantities); the benchmark also
// instantiates the iteration with the same formulas on plain doubles, to show that the typing
// costs nothing (verification/bench/typing_kernel.hpp).
//
// A manifold's surface motion (DD46's rolling resistance, DD47's tangent speed) is an optional
// last argument, a pointer to its SurfaceMotionOver<V>; without it (nullptr, the default) the
// functions are those of a world without surface motion, operation for operation.
#pragma once

#include <cstddef>
#include <type_traits>

#include "tamias2d/dynamics/bridge/contacts.hpp"
#include "tamias2d/dynamics/solver_settings.hpp"
#include "tamias2d/math/vec2d.hpp"
#include "tamias2d/math/wide.hpp"

namespace tamias2d::iteration {

using bridge::value_of;

template <class V> Vec2<V> tangent_of(Vec2<V> n) {
    return right_perp(n);
}

/// Separation of a point now, from the separation at preparation and the substep motions
/// (rotations linearised: r' ~ r + dq x r, accurate for the small rotations of a step; with
/// (dq x r) . n = dq (r x n), the moment arms give the rotations' share).
template <class Point, class Body, class V = value_of<Body>>
V current_separation(const Point& cp, const Body& a, const Body& b, Vec2<V> n) {
    return cp.base_separation +
           (dot(b.dp - a.dp, n) + (b.dq * cp.normal_arm_b - a.dq * cp.normal_arm_a));
}

/// IM7's target of a point for this iteration and its impulse's scales (model/im7's
/// target_velocity: a speculative gap closes within the substep; with bias, an overlap beyond
/// the slop is pushed out softly; lane by lane on a pack).
template <class V> using NormalTarget = bridge::Target<V>;
using bridge::TwoPointSolution;

/// Whether a surface argument is given (a pointer) or not (nullptr).
template <class Surface> inline constexpr bool has_surface = !std::is_null_pointer_v<Surface>;

/// Re-applies the accumulated impulses (they carry the previous substep's solution forward),
/// the rolling resistance's last (DD46).
template <class Model = bridge::Model, class Constraint, class Body, class Surface = std::nullptr_t>
void warm_start(Constraint& c, Body& a, Body& b, Surface s = nullptr) {
    const auto t = tangent_of(c.normal);
    for (auto& cp : c.points) {
        Model::apply_impulse(a, b, cp.normal_arm_a, cp.normal_arm_b, c.normal, cp.normal_impulse);
        Model::apply_impulse(a, b, cp.tangent_arm_a, cp.tangent_arm_b, t, cp.tangent_impulse);
        cp.total_normal_impulse += cp.normal_impulse;
        cp.total_tangent_impulse += cp.tangent_impulse;
    }
    if constexpr (has_surface<Surface>)
        Model::apply_rolling_impulse(a, b, s->rolling_impulse);
}

/// Sets point j's accumulated normal impulse for this substep and applies the change.
template <class Model, class Constraint, class Body, class V = value_of<Body>>
void apply_normal_delta(Constraint& c, int j, Body& a, Body& b, V updated) {
    auto& cp = c.points[j];
    const V delta = updated - cp.normal_impulse;
    cp.normal_impulse = updated;
    cp.max_normal_impulse = max(cp.max_normal_impulse, updated);
    cp.total_normal_impulse += delta;
    Model::apply_impulse(a, b, cp.normal_arm_a, cp.normal_arm_b, c.normal, delta);
}

/// Point j alone, from the bodies' current velocities (DD8 with the soft target): its new
/// accumulated impulse, clamped to push only.
template <class Model, class Constraint, class Body, class V = value_of<Body>>
V point_update(const Constraint& c, int j, const Body& a, const Body& b,
               const NormalTarget<V>& nt) {
    const auto& cp = c.points[j];
    const V vn = Model::relative_velocity(a, b, cp.normal_arm_a, cp.normal_arm_b, c.normal);
    const V lambda =
        Model::soft_impulse(nt.mass_scale, Model::impulse_to_reach(vn, nt.target, cp.normal_mass),
                            nt.impulse_scale, cp.normal_impulse);
    return max(cp.normal_impulse + lambda, broadcast<V>(0.0));
}

/// Both points at once (IM7's 2x2 LCP, LC1) for targets t1, t2 with rigid masses, from the
/// current velocities and the accumulated impulses x1, x2 that the LCP keeps non-negative.
template <class Model = bridge::Model, class Constraint, class Body, class V = value_of<Body>>
TwoPointSolution<V> block_update(const Constraint& c, const Body& a, const Body& b, V t1, V t2,
                                 V x1, V x2) {
    const auto& p1 = c.points[0];
    const auto& p2 = c.points[1];
    const V vn1 = Model::relative_velocity(a, b, p1.normal_arm_a, p1.normal_arm_b, c.normal);
    const V vn2 = Model::relative_velocity(a, b, p2.normal_arm_a, p2.normal_arm_b, c.normal);
    return Model::two_point_impulses(c.k11, c.k12, c.k22, c.inv_k11, c.inv_k12, c.inv_k22,
                                     p1.normal_mass, p2.normal_mass, vn1, vn2, t1, t2, x1, x2);
}

/// Friction (LC2) at each point: the relative tangential velocity driven to 0, or with a surface
/// to its tangent speed (DD47), within mu lambda_n; then the rolling resistance (DD46).
template <class Model, class Constraint, class Body, class Surface = std::nullptr_t>
void solve_friction(Constraint& c, Body& a, Body& b, Surface s = nullptr) {
    using V = value_of<Body>;
    const auto t = tangent_of(c.normal);
    V target = broadcast<V>(0.0);
    if constexpr (has_surface<Surface>)
        target = s->tangent_speed;
    for (auto& cp : c.points) {
        const V vt = Model::relative_velocity(a, b, cp.tangent_arm_a, cp.tangent_arm_b, t);
        const V max_f = c.friction * cp.normal_impulse;
        const V lambda = Model::impulse_to_reach(vt, target, cp.tangent_mass);
        const V updated = min(max(cp.tangent_impulse + lambda, -max_f), max_f);
        const V delta = updated - cp.tangent_impulse;
        cp.tangent_impulse = updated;
        cp.total_tangent_impulse += delta;
        Model::apply_impulse(a, b, cp.tangent_arm_a, cp.tangent_arm_b, t, delta);
    }
    if constexpr (has_surface<Surface>) {
        const V bound = Model::rolling_impulse_bound(
            s->rolling_resistance, c.points[0].normal_impulse + c.points[1].normal_impulse);
        const V updated = Model::rolling_impulse_update(a, b, s->rolling_impulse, bound);
        const V delta = updated - s->rolling_impulse;
        s->rolling_impulse = updated;
        Model::apply_rolling_impulse(a, b, delta);
    }
}

/// One iteration for one manifold (or one per lane): with use_bias the soft, overlap-removing
/// solve; without it the rigid relax. Two well-conditioned points with rigid targets are solved
/// together (the LCP), exactly; otherwise point by point, each seeing the other's impulse.
template <bool use_bias, class Model = bridge::Model, class Constraint, class Body,
          class Surface = std::nullptr_t>
void solve(Constraint& c, Body& a, Body& b, const ContactSolverSettings& st, Surface s = nullptr) {
    using V = value_of<Body>;
    const NormalTarget<V> nt[2] = {
        Model::template target<use_bias>(current_separation(c.points[0], a, b, c.normal), st),
        Model::template target<use_bias>(current_separation(c.points[1], a, b, c.normal), st)};
    const V one = broadcast<V>(1.0);
    const auto soft = either(nt[0].mass_scale != one, nt[1].mass_scale != one);
    const auto block = and_not(c.use_block, soft);
    // Block lanes take the LCP's impulses, computed from the velocities before either point;
    // the others go point by point. Applying point 1's change, then point 2's, is what both
    // do (for the block, exact for the linear system).
    TwoPointSolution<V> x{};
    if (any(block))
        x = block_update<Model>(c, a, b, nt[0].target, nt[1].target, c.points[0].normal_impulse,
                                c.points[1].normal_impulse);
    const bool sequential_lanes = !all(block);
    for (int j = 0; j < 2; ++j) {
        V updated = j == 0 ? x.x1 : x.x2;
        if (sequential_lanes)
            updated = select(block, updated, point_update<Model>(c, j, a, b, nt[j]));
        apply_normal_delta<Model>(c, j, a, b, updated);
    }
    solve_friction<Model>(c, a, b, s);
}

/// The same with the choice made at run time (tests, one manifold at a time).
template <class Model = bridge::Model, class Constraint, class Body, class Surface = std::nullptr_t>
void solve(Constraint& c, Body& a, Body& b, const ContactSolverSettings& st, bool use_bias,
           Surface s = nullptr) {
    if (use_bias)
        solve<true, Model>(c, a, b, st, s);
    else
        solve<false, Model>(c, a, b, st, s);
}

} // namespace tamias2d::iteration
