// Contact manifolds: what the narrow phase tells the solver about one touching shape pair.
#pragma once

#include <cstdint>

#include "tamias2d/math/vec2d.hpp"

namespace tamias2d {

/// Identifies which features (vertex or edge of each shape) produced a contact point, so the
/// solver can carry its impulses over to the next step (warm starting).
struct FeatureId {
    std::uint8_t index_a = 0;
    std::uint8_t type_a = 0; ///< 0 vertex, 1 face
    std::uint8_t index_b = 0;
    std::uint8_t type_b = 0;
    constexpr std::uint32_t key() const {
        return std::uint32_t(index_a) | std::uint32_t(type_a) << 8 | std::uint32_t(index_b) << 16 |
               std::uint32_t(type_b) << 24;
    }
    friend constexpr bool operator==(const FeatureId&, const FeatureId&) = default;
};

struct ManifoldPoint {
    Vec2d point{};           ///< m, world frame: midway between the two surfaces
    Vec2d anchor_a{};        ///< m, point relative to body A's centre of mass, world orientation
    Vec2d anchor_b{};        ///< m, point relative to body B's centre of mass, world orientation
    double separation = 0.0; ///< m, negative when penetrating
    FeatureId id{};
};

/// Up to two points (vertex-edge gives one, A5; edge-edge gives two, LC1). The normal is a
/// unit vector pointing from shape A into shape B (A's outward normal at the contact).
struct Manifold {
    Vec2d normal{};
    int count = 0; ///< before the points: a contact whose shapes are apart reads no point
    ManifoldPoint points[2]{};
};

} // namespace tamias2d
