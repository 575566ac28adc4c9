// Graph colouring of the contact constraints by levels: constraints of one level share no body
// that moves (the static body 0 does not count), so the solver can take four of them at once,
// one per lane, and the levels keep the creation order wherever it matters, so the result is
// the sequential Gauss-Seidel pass in creation order, bit for bit.
//
// Why not the fewest colours (greedy, as Box2D v3): that reorders constraints sharing a body,
// and the order is what carries a stack's weight down within one pass. Tried (session 3,
// docs/performance.md): pyramid40's top box sagged 0.185 m instead of 0.056 m, large_pyramid's
// 0.84 m (it no longer stands) and 2 rain boxes escaped, for the same speed.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "tamias2d/math/wide.hpp"

namespace tamias2d {

/// One manifold as the colouring sees it: the solver bodies it couples (0: the static body) and
/// whether it is likely solved as a two-point block (those go first within a level, so that
/// packs mostly take one path of the iteration; any answer gives the same results).
struct GraphEdge {
    std::uint32_t body_a = 0, body_b = 0;
    bool block = false;
};

class ConstraintGraph {
  public:
    static constexpr std::uint32_t no_constraint = 0xffffffffu;
    /// Up to four constraint indices solved together (unused lanes: no_constraint).
    using Pack = std::array<std::uint32_t, wide_lanes>;

    /// Each manifold goes one level after the last earlier manifold sharing a moving body with
    /// it. Allocates only while the scene grows.
    void colour(std::span<const GraphEdge> edges, std::size_t body_count);

    /// The solve order: the packs of level 0, of level 1, ... (creation order within a level).
    std::span<const Pack> packs() const { return packs_; }

  private:
    std::vector<std::uint32_t> body_level_; ///< one past the level of the body's last constraint
    std::vector<std::uint32_t> level_of_;
    std::vector<std::uint32_t> level_start_, level_fill_;
    std::vector<std::uint32_t> sorted_;
    std::vector<Pack> packs_;
};

} // namespace tamias2d
