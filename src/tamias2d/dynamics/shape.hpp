// A shape as the world stores it (internal).
#pragma once

#include <cstdint>

#include "tamias2d/collision/collider.hpp"
#include "tamias2d/geometry/aabb.hpp"
#include "tamias2d/shape_def.hpp"

namespace tamias2d {

/// Aligned so that the collider's vertex pairs each fill one cache line.
struct alignas(64) Shape {
    Collider collider{}; ///< the geometry as the narrow phase reads it, made with the shape
    std::uint32_t generation = 0;
    bool alive = false;
    std::uint32_t body = 0;
    Geometry geometry{};
    Material material{};
    int proxy = -1;
};

} // namespace tamias2d
