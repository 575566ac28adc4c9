// Reusing a touching contact's manifold while its two bodies have barely moved against each
// other (internal). In a resting pile most contacts see almost no relative motion from one step
// to the next, and the separating axis test and clipping that rebuild their manifolds cost a
// quarter of a stacked pyramid's step. Box2D v3 reuses manifolds the same way ("contact
// recycling"); this is its own formulation, with a bound stated on what it leaves out.
//
// The manifold's points are kept as pairs of material points, one fixed in each body, that
// coincided when the manifold was computed. While it is reused, each point's separation is
// recomputed exactly from the bodies' poses (the two material points' distance along the
// normal), and the point itself is put midway between them, both moment arms measured to it, so
// that the two bodies' impulses still act at one point (momentum and angular momentum exchanged
// exactly); the normal keeps its direction. The manifold is computed afresh as soon as either of
// these could exceed the tolerance d:
//  - the relative drift: how far the two material points of any contact point can have moved
//    apart since the manifold was computed (in A's frame: B's centre's displacement plus the
//    relative turn's chord times the point's distance from B's centre; in B's frame alike; the
//    smaller bound holds, since the distance between two points is the same in every frame);
//  - the turn: how far either body's rotation has carried a moment arm (chord times arm), which
//    bounds how far the normal's direction lags the bodies' (per metre of arm).
// So every reused point lies within d / 2 of both of its material points, and its separation is
// exact for that pair; where shapes slide or roll over each other by more than d, the manifold
// is rebuilt. d = 0 turns reuse off.
#pragma once

#include <algorithm>
#include <cmath>

#include "tamias2d/collision/manifold.hpp"
#include "tamias2d/math/vec2d.hpp"

namespace tamias2d {

/// The bodies' poses a contact's manifold was computed at, and its points then. 112 bytes, kept
/// beside the contact (ContactManager::bases).
struct ManifoldBasis {
    Rot q_a{}, q_b{};          ///< the bodies' rotations
    Vec2d b_in_a{};            ///< B's centre of mass in A's frame (m)
    double separation[2] = {}; ///< m, per point
    Vec2d on_a[2] = {};        ///< m, per point: the point in A's frame, from A's centre of mass
    /// m: the points' largest distance from A's and from B's centre of mass. Fixed while the
    /// manifold is reused, so measured here once, not in every check.
    double arm_a = 0.0, arm_b = 0.0;
};

/// The chord |q - q0| of the turn from q0 to q: 2 sin(|angle| / 2), how far a unit arm moved.
inline double turn_chord(Rot q, Rot q0) {
    const double dc = q.c - q0.c, ds = q.s - q0.s;
    return std::sqrt(dc * dc + ds * ds);
}

/// The rotation from q0 to q (q q0^-1).
inline Rot turn_between(Rot q, Rot q0) {
    return {q.c * q0.c + q.s * q0.s, q.s * q0.c - q.c * q0.s};
}

/// The rotation that takes A's frame into B's at the basis's poses.
inline Rot a_to_b(const ManifoldBasis& basis) {
    const Rot rel0 = turn_between(basis.q_b, basis.q_a);
    return {rel0.c, -rel0.s};
}

/// Basis point j in B's frame, from B's centre (it coincided with on_a[j] then).
inline Vec2d on_b(const ManifoldBasis& basis, Rot a_to_b0, int j) {
    return rotate(a_to_b0, basis.on_a[j] - basis.b_in_a);
}

/// Records the poses `m` was just computed at (centres of mass ca, cb; rotations qa, qb).
inline void record_basis(ManifoldBasis& basis, const Manifold& m, Rot qa, Rot qb, Vec2d ca,
                         Vec2d cb) {
    basis.q_a = qa;
    basis.q_b = qb;
    basis.b_in_a = inv_rotate(qa, cb - ca);
    for (int j = 0; j < m.count; ++j) {
        basis.separation[j] = m.points[j].separation;
        basis.on_a[j] = inv_rotate(qa, m.points[j].anchor_a);
    }
    const Rot a_to_b0 = a_to_b(basis);
    basis.arm_a = basis.arm_b = 0.0;
    for (int j = 0; j < m.count; ++j) {
        basis.arm_a = std::max(basis.arm_a, length(basis.on_a[j]));
        basis.arm_b = std::max(basis.arm_b, length(on_b(basis, a_to_b0, j)));
    }
}

/// Updates touching manifold `m` for the bodies' current poses and returns true when it may be
/// reused within `tolerance` (m; > 0); returns false, leaving `m` alone, when it must be
/// computed afresh.
inline bool reuse_manifold(Manifold& m, const ManifoldBasis& basis, Rot qa, Rot qb, Vec2d ca,
                           Vec2d cb, double tolerance) {
    const double arm_a = basis.arm_a, arm_b = basis.arm_b;
    if (turn_chord(qa, basis.q_a) * arm_a > tolerance ||
        turn_chord(qb, basis.q_b) * arm_b > tolerance)
        return false;
    // B's rotation relative to A's, then and now; A's frame into B's, then.
    const Rot rel0 = turn_between(basis.q_b, basis.q_a), rel = turn_between(qb, qa);
    const Rot a_to_b0 = a_to_b(basis);
    const double chord_rel = turn_chord(rel, rel0);
    const Vec2d d = cb - ca;
    // The smaller bound holds: B's frame is measured only when A's bound is over.
    const double in_a = length(inv_rotate(qa, d) - basis.b_in_a) + chord_rel * arm_b;
    // In B's frame A's centre is at -d, and was at -(B in A) turned into B's frame of then.
    if (in_a > tolerance &&
        length(inv_rotate(qb, d) - rotate(a_to_b0, basis.b_in_a)) + chord_rel * arm_a > tolerance)
        return false;
    for (int j = 0; j < m.count; ++j) {
        ManifoldPoint& p = m.points[j];
        const Vec2d pa = ca + rotate(qa, basis.on_a[j]);
        const Vec2d pb = cb + rotate(qb, on_b(basis, a_to_b0, j));
        p.separation = basis.separation[j] + dot(pb - pa, m.normal);
        p.point = 0.5 * (pa + pb);
        p.anchor_a = p.point - ca;
        p.anchor_b = p.point - cb;
    }
    return true;
}

} // namespace tamias2d
