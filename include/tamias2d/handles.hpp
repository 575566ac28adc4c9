// Handles to bodies and shapes: an index plus a generation, so that a handle to something
// destroyed is detected (InvalidHandle) instead of silently reaching a recycled slot.
#pragma once

#include <cstdint>
#include <limits>

namespace tamias2d {

inline constexpr std::uint32_t null_index = std::numeric_limits<std::uint32_t>::max();

struct BodyId {
    std::uint32_t index = null_index;
    std::uint32_t generation = 0;
    friend constexpr bool operator==(const BodyId&, const BodyId&) = default;
};

struct ShapeId {
    std::uint32_t index = null_index;
    std::uint32_t generation = 0;
    friend constexpr bool operator==(const ShapeId&, const ShapeId&) = default;
};

} // namespace tamias2d
