// A persistent contact between two shapes whose fattened boxes overlap (internal). It lives
// from the broad phase finding the pair until the boxes separate, carrying impulses across
// steps for warm starting.
#pragma once

#include <cstddef>
#include <cstdint>

#include "tamias2d/collision/manifold.hpp"
#include "tamias2d/collision/narrow_phase.hpp"

namespace tamias2d {

/// 256 bytes on a 64-byte boundary, four cache lines. The first holds all that a contact whose
/// shapes are apart reads and writes (shapes, bodies, hint, normal, count): half the contacts
/// of a pile are such, and the narrow phase's sweep over them read all four lines (rain_16k).
/// Then one point per line, and the impulses.
struct alignas(64) Contact {
    std::uint32_t shape_a = 0, shape_b = 0; ///< shape_a < shape_b
    std::uint32_t body_a = 0, body_b = 0;   ///< their bodies (a shape never changes body)
    double friction = 0.0;                  ///< combined once: materials are fixed at creation
    double restitution = 0.0;
    SeparationHint hint{}; ///< narrow-phase shortcut for pairs that stay apart
    bool touching = false;
    Manifold manifold{};
    double normal_impulse[2] = {0.0, 0.0}; ///< N s, accumulated (warm start)
    double tangent_impulse[2] = {0.0, 0.0};
    double total_normal_impulse[2] = {0.0, 0.0}; ///< N s, applied over the last step
    double total_tangent_impulse[2] = {0.0, 0.0};

    static std::uint64_t key(std::uint32_t a, std::uint32_t b) {
        return (std::uint64_t(a < b ? a : b) << 32) | (a < b ? b : a);
    }
};

static_assert(sizeof(Contact) == 256);
static_assert(offsetof(Contact, manifold) + offsetof(Manifold, points) == 64,
              "the first line ends with the manifold's count, the points start the second");

} // namespace tamias2d
