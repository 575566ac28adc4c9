// A persistent contact between two shapes whose fattened boxes overlap (internal). It lives
// from the broad phase finding the pair until the boxes separate, carrying impulses across
// steps for warm starting.
#pragma once

#include <cstddef>
#include <cstdint>

#include "tamias2d/collision/manifold.hpp"
#include "tamias2d/collision/narrow_phase.hpp"

namespace tamias2d {

/// 192 bytes on a 64-byte boundary, three cache lines. The first holds all that a contact whose
/// shapes are apart reads and writes (shapes, bodies, hint, normal, count): half the contacts
/// of a pile are such, and the narrow phase's sweep over them read all the lines (rain_16k).
/// Then one point per line. The impulses are kept apart (ContactImpulses).
struct alignas(64) Contact {
    std::uint32_t shape_a = 0, shape_b = 0; ///< shape_a < shape_b
    std::uint32_t body_a = 0, body_b = 0;   ///< their bodies (a shape never changes body)
    double friction = 0.0; ///< combined at creation and when a shape's material changes
    double restitution = 0.0;
    SeparationHint hint{}; ///< narrow-phase shortcut for pairs that stay apart
    bool touching = false;
    Manifold manifold{};

    static std::uint64_t key(std::uint32_t a, std::uint32_t b) {
        return (std::uint64_t(a < b ? a : b) << 32) | (a < b ? b : a);
    }
};

static_assert(sizeof(Contact) == 192);
static_assert(offsetof(Contact, manifold) + offsetof(Manifold, points) == 64,
              "the first line ends with the manifold's count, the points start the second");

/// Impulses of a contact's manifold points, in arrays of their own indexed like the contacts:
/// the warm-start impulses and the step's totals. The solver reads and writes them in the
/// colouring's order, scattered over the contacts; in 32-byte records they are a dense array
/// that stays in the cache (640 KB at 16k boxes), where as a line of each 192-byte contact they
/// would be gathered from about 4 MB (docs/performance.md).
struct ContactImpulses {
    double normal[2] = {0.0, 0.0};  ///< N s
    double tangent[2] = {0.0, 0.0}; ///< N s
};

} // namespace tamias2d
