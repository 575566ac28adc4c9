// A shape as the world stores it (internal).
#pragma once

#include <cstdint>

#include "tamias2d/collision/collider.hpp"
#include "tamias2d/geometry/aabb.hpp"
#include "tamias2d/shape_def.hpp"

namespace tamias2d {

/// Aligned so that the collider's header and the cached fat box share one cache line.
struct alignas(64) Shape {
    Collider collider{}; ///< the geometry as the narrow phase reads it, made with the shape
    /// The broad phase's fat box, copied once per step before the contacts are updated, so each
    /// contact's overlap test reads it with the collider instead of the tree's node.
    Aabb fat_box{};
    /// The body's transform and centre of mass, copied with fat_box: a contact reads its two
    /// shapes' lines, filled in order, instead of two scattered bodies.
    Transform body_xf{};
    Vec2d body_center{};
    std::uint32_t generation = 0;
    bool alive = false;
    std::uint32_t body = 0;
    Geometry geometry{};
    Material material{};
    int proxy = -1;
};

static_assert(sizeof(Collider) % 64 == 32, "the collider's header shares a line with fat_box");

} // namespace tamias2d
