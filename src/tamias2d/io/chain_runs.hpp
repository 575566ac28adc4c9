/// \file
/// How scene_to_json writes chain segments back: a run of a body's shapes that chain_shapes
/// makes again, bit for bit, from its points is written as one "chain"; any other chain segment
/// keeps its ghosts as a "chain_segment". So the written form is short and parses to the same
/// shapes.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "tamias2d/shape_def.hpp"

namespace tamias2d::io {

/// Shapes [first, first + count) of a body, chain segments each linked to the next (one starts
/// where the one before ends, and their ghosts are each other's far ends), with one material,
/// filter and sensor flag.
struct ChainRun {
    std::size_t count = 0;     ///< >= 1
    std::vector<Vec2d> points; ///< the chain's points: count + 1, or count for a loop
    bool loop = false;         ///< the last segment leads back to the first
    /// chain_shapes(points, loop, material) makes exactly these shapes (else an open end's
    /// ghost is not the one chain_shapes makes, and each shape is written with its ghosts).
    bool reproduced = false;
};

/// The longest run that starts at shapes[first], a chain segment.
ChainRun chain_run_at(std::span<const ShapeDef> shapes, std::size_t first);

} // namespace tamias2d::io
