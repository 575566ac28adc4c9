// Graph colouring of the contact constraints by levels: constraints of one level share no body
// that moves (the static body 0 does not count), so the solver can take four of them at once,
// one per lane, and the levels keep the creation order wherever it matters, so the result is
// the sequential Gauss-Seidel pass in creation order, bit for bit.
//
// Why not the fewest colours (greedy, as Box2D v3): that reorders constraints sharing a body,
// and the order is what carries a stack's weight down within one pass. Measured with greedy
// colours (docs/performance.md, rejected designs): pyramid40's top box sags 0.185 m instead of
// 0.056 m, large_pyramid's 0.84 m (it does not stand) and 2 rain boxes escape, for the same
// speed.
//
// Packs are filled across level boundaries: the packs run in order, so a constraint may share
// a pack with the last ones of the level before unless one of those is the constraint it
// follows on a body. A pyramid has hundreds of small levels (pyramid40: 231 for 2380
// manifolds): starting a new pack at each level would leave 23 % of pyramid20's lanes empty
// and 13 % of pyramid40's, against 11 % and 3 % when packs run across levels.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "tamias2d/math/wide.hpp"

namespace tamias2d {

/// Which path of the contact iteration a manifold likely takes. Within a level manifolds
/// commute, so the colouring orders them by group: packs then mostly hold lanes that take one
/// path, and the iteration computes only that one. Any grouping gives the same results.
enum class PathGroup : std::uint8_t {
    block_always,  ///< two points, both apart: the 2x2 block in the soft and the rigid iteration
    block_rigid,   ///< two points touching: soft point by point, then the block in the relax
    point_by_point ///< one point, or two that are nearly the same constraint
};
inline constexpr std::uint32_t path_groups = 3;

/// The group of a manifold of `count` points with separations s1, s2 (m) at preparation; a
/// two-point manifold too ill-conditioned for the block (block_capable false) goes point by
/// point. Apart at preparation predicts speculative in the soft iteration (rigid targets).
inline PathGroup path_group(int count, double s1, double s2, bool block_capable = true) {
    if (count != 2 || !block_capable)
        return PathGroup::point_by_point;
    return s1 > 0.0 && s2 > 0.0 ? PathGroup::block_always : PathGroup::block_rigid;
}

/// One manifold as the colouring sees it: the solver bodies it couples (0: the static body).
struct GraphEdge {
    std::uint32_t body_a = 0, body_b = 0;
    PathGroup group = PathGroup::point_by_point;
};

class ConstraintGraph {
  public:
    static constexpr std::uint32_t no_constraint = 0xffffffffu;
    /// Up to four constraint indices solved together (unused lanes: no_constraint).
    using Pack = std::array<std::uint32_t, wide_lanes>;

    /// Each manifold goes one level after the last earlier manifold sharing a moving body with
    /// it; the levels, in order, fill the packs, a pack closing early only where the next
    /// manifold follows one of its lanes on a body. Allocates only while the scene grows.
    void colour(std::span<const GraphEdge> edges, std::size_t body_count);

    /// The solve order: the manifolds of level 0, of level 1, ..., four to a pack (by path
    /// group, then creation order, within a level).
    std::span<const Pack> packs() const { return packs_; }

  private:
    /// Per body: one past the level of its last constraint so far, while levelling; then the
    /// pack of its last constraint placed so far, while packing (no_constraint: none yet).
    std::vector<std::uint32_t> body_mark_;
    std::vector<std::uint32_t> level_of_;
    std::vector<std::uint32_t> level_start_, level_fill_;
    /// A constraint and its bodies, in solve order (what placing it in a pack reads).
    struct Placement {
        std::uint32_t index = 0;
        std::uint32_t body_a = 0, body_b = 0;
    };
    std::vector<Placement> sorted_;
    std::vector<Pack> packs_;
};

} // namespace tamias2d
