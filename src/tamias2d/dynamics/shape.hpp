// A shape as the world stores it (internal): what the narrow phase and the step read. The
// definition it was made from (geometry, material) is kept apart, indexed alike: the step never
// reads it, and at 16k shapes every byte streamed per step costs time (docs/performance.md).
#pragma once

#include <cstdint>

#include "tamias2d/collision/collider.hpp"
#include "tamias2d/geometry/aabb.hpp"
#include "tamias2d/handles.hpp"
#include "tamias2d/math/vec2d.hpp"

namespace tamias2d {

/// Aligned so that the collider's header and the fat box share one cache line, and the body's
/// pose and the links share the next.
struct alignas(64) Shape {
    Collider collider{}; ///< the geometry as the narrow phase reads it, made with the shape
    /// The broad phase's fat box, kept equal to it (set wherever the proxy moves), so each
    /// contact's overlap test reads it with the collider instead of the tree's node.
    Aabb fat_box{};
    /// The body's transform and centre of mass, kept equal to the body's between steps (set
    /// wherever those change): a contact reads its two shapes' lines instead of two bodies.
    Transform body_xf{};
    Vec2d body_center{};
    std::uint32_t body = 0;
    int proxy = -1;                  ///< its broad-phase proxy; -1 once destroyed
    std::uint32_t next = null_index; ///< the body's next shape (null_index: the last)

    bool alive() const { return proxy >= 0; }
};

static_assert(sizeof(Collider) % 64 == 32, "the collider's header shares a line with fat_box");
static_assert(sizeof(Shape) == sizeof(Collider) + 96, "the pose and links fill one line");

} // namespace tamias2d
