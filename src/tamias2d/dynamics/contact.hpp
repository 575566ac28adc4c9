// A persistent contact between two shapes whose fattened boxes overlap (internal). It lives
// from the broad phase finding the pair until the boxes separate, carrying impulses across
// steps for warm starting.
#pragma once

#include <cstdint>

#include "tamias2d/collision/manifold.hpp"
#include "tamias2d/collision/narrow_phase.hpp"

namespace tamias2d {

/// 256 bytes on a 64-byte boundary: four cache lines (with `touching` last, after the impulses,
/// it was 264 bytes, five or six lines; now it sits in the padding after the manifold).
struct alignas(64) Contact {
    std::uint32_t shape_a = 0, shape_b = 0; ///< shape_a < shape_b
    std::uint32_t body_a = 0, body_b = 0;   ///< their bodies (a shape never changes body)
    double friction = 0.0;                  ///< combined once: materials are fixed at creation
    double restitution = 0.0;
    Manifold manifold{};
    SeparationHint hint{}; ///< narrow-phase shortcut for pairs that stay apart
    bool touching = false;
    double normal_impulse[2] = {0.0, 0.0}; ///< N s, accumulated (warm start)
    double tangent_impulse[2] = {0.0, 0.0};
    double total_normal_impulse[2] = {0.0, 0.0}; ///< N s, applied over the last step
    double total_tangent_impulse[2] = {0.0, 0.0};

    static std::uint64_t key(std::uint32_t a, std::uint32_t b) {
        return (std::uint64_t(a < b ? a : b) << 32) | (a < b ? b : a);
    }
};

static_assert(sizeof(Contact) == 256);

} // namespace tamias2d
