// Narrow phase (T5, A5, LC1): contact manifolds for each pair of shape types.
// Shapes are given in their body frames with the body transforms; the body centres of mass
// (world frame) are needed to express anchors relative to them.
#pragma once

#include <cstdint>

#include "tamias2d/collision/collider.hpp"
#include "tamias2d/collision/manifold.hpp"
#include "tamias2d/math/vec2d.hpp"
#include "tamias2d/shapes.hpp"

namespace tamias2d {

/// Points are reported when the separation is below `margin` (m), so that the solver sees
/// contacts a little before they touch (speculative contacts; no tunnelling at game speeds).
struct CollideInput {
    Transform xf_a;
    Vec2d center_a; ///< body A centre of mass, world frame
    Transform xf_b;
    Vec2d center_b;
    double margin = 0.0;
};

/// The face that last separated a pair of polygons by the margin or more, kept with the pair:
/// tested first, it rejects a pair that stays apart without the whole separating axis test (in
/// a settled pile half the pairs the broad phase reports are apart). Only a shortcut: with or
/// without it, collide returns the same manifold, bit for bit.
struct SeparationHint {
    std::int8_t face = -1; ///< -1: none
    bool on_b = false;     ///< the face is b's (else a's)
};

Manifold collide_circles(const Circle& a, const Circle& b, const CollideInput& in);
Manifold collide_polygon_circle(const Polygon& a, const Circle& b, const CollideInput& in);

/// Dispatches on the shape types. A circle-polygon pair is computed as polygon-circle with the
/// roles swapped and the result flipped, so the normal still points from a into b.
Manifold collide(const Geometry& a, const Geometry& b, const CollideInput& in,
                 SeparationHint* hint = nullptr);

/// The same for shapes made into colliders (make_collider), in place: afterwards `m` equals what
/// the form above returns, bit for bit, provided it held a manifold from collide (or a default
/// one), whose slots past its count are zero. A contact's manifold is updated this way, from
/// the colliders its shapes keep, without building and copying a new manifold.
void collide(const Collider& a, const Collider& b, const CollideInput& in, Manifold& m,
             SeparationHint* hint = nullptr);

} // namespace tamias2d
