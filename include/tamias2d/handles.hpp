/// \file
/// Handles to bodies, shapes and joints: an index plus a generation, so that a handle to something
/// destroyed is detected (InvalidHandle) instead of silently reaching a recycled slot.
#pragma once

#include <cstdint>
#include <limits>

namespace tamias2d {

/// The index of a handle that names nothing.
inline constexpr std::uint32_t null_index = std::numeric_limits<std::uint32_t>::max();

/// A body of a World. Default-constructed, it names no body.
struct BodyId {
    std::uint32_t index = null_index; ///< slot in the world's body storage
    std::uint32_t generation = 0;     ///< which use of the slot: bumped when it is reused
    /// Same slot and same generation: the same body.
    friend constexpr bool operator==(const BodyId&, const BodyId&) = default;
};

/// A shape of a World. Default-constructed, it names no shape.
struct ShapeId {
    std::uint32_t index = null_index; ///< slot in the world's shape storage
    std::uint32_t generation = 0;     ///< which use of the slot: bumped when it is reused
    /// Same slot and same generation: the same shape.
    friend constexpr bool operator==(const ShapeId&, const ShapeId&) = default;
};

/// A joint of a World. Default-constructed, it names no joint.
struct JointId {
    std::uint32_t index = null_index; ///< slot in the world's joint storage
    std::uint32_t generation = 0;     ///< which use of the slot: bumped when it is reused
    /// Same slot and same generation: the same joint.
    friend constexpr bool operator==(const JointId&, const JointId&) = default;
};

} // namespace tamias2d
