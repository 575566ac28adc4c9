/// \file
/// Handles to bodies, shapes and joints: an index, a generation and the tag of the world that
/// issued them, so that a handle to something destroyed is detected (InvalidHandle) instead of
/// silently reaching a reused slot, and a handle of another world is refused (WrongWorld) instead
/// of naming whatever lives in the same slot of this one. Handles are small, trivially copyable
/// values, compared with == and usable as keys of std::unordered_map (std::hash below).
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <type_traits>

namespace tamias2d {

/// The index of a handle that names nothing.
inline constexpr std::uint32_t null_index = std::numeric_limits<std::uint32_t>::max();

/// A body of a World. Default-constructed, it names no body.
struct BodyId {
    std::uint32_t index = null_index; ///< slot in the world's body storage
    std::uint32_t generation = 0;     ///< which use of the slot: bumped when it is reused
    std::uint32_t world = 0;          ///< World::tag() of the world that issued it (0: none)
    /// Same world, same slot and same generation: the same body.
    friend constexpr bool operator==(const BodyId&, const BodyId&) = default;
};

/// A shape of a World. Default-constructed, it names no shape.
struct ShapeId {
    std::uint32_t index = null_index; ///< slot in the world's shape storage
    std::uint32_t generation = 0;     ///< which use of the slot: bumped when it is reused
    std::uint32_t world = 0;          ///< World::tag() of the world that issued it (0: none)
    /// Same world, same slot and same generation: the same shape.
    friend constexpr bool operator==(const ShapeId&, const ShapeId&) = default;
};

/// A joint of a World. Default-constructed, it names no joint.
struct JointId {
    std::uint32_t index = null_index; ///< slot in the world's joint storage
    std::uint32_t generation = 0;     ///< which use of the slot: bumped when it is reused
    std::uint32_t world = 0;          ///< World::tag() of the world that issued it (0: none)
    /// Same world, same slot and same generation: the same joint.
    friend constexpr bool operator==(const JointId&, const JointId&) = default;
};

static_assert(std::is_trivially_copyable_v<BodyId> && sizeof(BodyId) == 12);
static_assert(std::is_trivially_copyable_v<ShapeId> && sizeof(ShapeId) == 12);
static_assert(std::is_trivially_copyable_v<JointId> && sizeof(JointId) == 12);

namespace detail {
/// A hash of a handle's three words: the index and generation in one 64-bit word, the world
/// tag mixed in, then SplitMix64's finalizer so that every input bit reaches every output bit.
constexpr std::size_t hash_handle(std::uint32_t index, std::uint32_t generation,
                                  std::uint32_t world) {
    std::uint64_t x =
        (std::uint64_t(generation) << 32 | index) ^ (std::uint64_t(world) * 0x9e3779b97f4a7c15ull);
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
    return std::size_t(x ^ (x >> 31));
}
} // namespace detail

} // namespace tamias2d

namespace std {

/// BodyId as a key of unordered containers: equal handles hash equal.
template <> struct hash<tamias2d::BodyId> {
    /// The handle's three words, mixed (detail::hash_handle).
    std::size_t operator()(const tamias2d::BodyId& id) const noexcept {
        return tamias2d::detail::hash_handle(id.index, id.generation, id.world);
    }
};

/// ShapeId as a key of unordered containers: equal handles hash equal.
template <> struct hash<tamias2d::ShapeId> {
    /// The handle's three words, mixed (detail::hash_handle).
    std::size_t operator()(const tamias2d::ShapeId& id) const noexcept {
        return tamias2d::detail::hash_handle(id.index, id.generation, id.world);
    }
};

/// JointId as a key of unordered containers: equal handles hash equal.
template <> struct hash<tamias2d::JointId> {
    /// The handle's three words, mixed (detail::hash_handle).
    std::size_t operator()(const tamias2d::JointId& id) const noexcept {
        return tamias2d::detail::hash_handle(id.index, id.generation, id.world);
    }
};

} // namespace std
