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
//
// Contact regions (WorldDef::contact_regions) split the pass among threads without reordering
// manifolds that share a body within a region: the bodies are cut into slabs, the manifolds
// within each slab form a stream of their own, and those between slabs a last stream. The
// regions' streams share no moving body, so they run at once with no waiting; the last stream
// waits, pack by pack, only for the packs it follows. Why not split each level among threads:
// a pile's levels are small (pyramid40: 2.6 packs a level), and the manifolds on either side
// of any split wait for each other at nearly every level; measured, two threads were slower
// than one (docs/performance.md, "Rejected designs").
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "tamias2d/dynamics/greedy_colours.hpp"
#include "tamias2d/math/wide.hpp"
#include "tamias2d/memory/allocator.hpp"

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

/// The group of a manifold of `count` points with separations s1, s2 (m) at preparation. Apart
/// at preparation predicts speculative in the soft iteration (rigid targets).
inline PathGroup path_group(int count, double s1, double s2) {
    if (count != 2)
        return PathGroup::point_by_point;
    return s1 > 0.0 && s2 > 0.0 ? PathGroup::block_always : PathGroup::block_rigid;
}

/// One manifold as the colouring sees it: the solver bodies it couples (0: the static body).
struct GraphEdge {
    std::uint32_t body_a = 0, body_b = 0;
    PathGroup group = PathGroup::point_by_point;
};

/// What a stream's pack waits for before it runs: stream `stream` has finished its first
/// `packs` packs of the pass.
struct StreamWait {
    std::uint32_t stream = 0, packs = 0;
};

class ConstraintGraph {
  public:
    static constexpr std::uint32_t no_constraint = 0xffffffffu;
    /// Up to four constraint indices solved together (unused lanes: no_constraint).
    using Pack = std::array<std::uint32_t, wide_lanes>;
    /// At most this many regions, and streams (each pack keeps one wait count per stream
    /// while packing).
    static constexpr std::uint32_t max_regions = 8;
    static constexpr std::uint32_t max_streams = max_regions + 1;

    /// Each manifold goes one level after the last earlier manifold sharing a moving body with
    /// it; the levels, in order, fill the packs, a pack closing early only where the next
    /// manifold follows one of its lanes on a body. Allocates only while the scene grows.
    ///
    /// With `regions` > 1 (at most max_regions) the pass is the sequential one in another order:
    /// the manifolds whose moving bodies all lie in region 0, in creation order, then those of
    /// region 1, ..., then all those between regions, by greedy colour (see between_by_colour), in
    /// creation order within a colour. The regions are slabs across `cut` (per solver body, its
    /// place along the cut axis, m), bounded where they hold about equal numbers of manifolds. Each
    /// of those runs is a stream (regions + 1 of them) with packs of its own: the regions' streams
    /// share no moving body and run at once on different threads, and the last stream waits only
    /// for the packs of the regions' streams that it follows. A manifold joins its stream's open
    /// pack only if every earlier manifold on its bodies sits in a pack opened before that one, so
    /// that a thread that runs the packs of any stream whose waits are met can always go on; any
    /// such schedule, and the packs in their stored order, give the same bits.
    ///
    /// While the manifolds couple the same bodies as at the last call that coloured, in the same
    /// number of regions, each keeps its region (or "between") from then, wherever the bodies
    /// have moved since: the regions are balanced when the manifolds change, not every step. The
    /// levels and waits then come out the same, and the path groups only order manifolds within
    /// a level, which commute; so such a call keeps that call's packs and waits (a resting pile's
    /// contacts come in the same order step after step), unless more than 1 in regroup_share of
    /// the manifolds changed group since: the packs' path groups are then brought up to date,
    /// the regions kept.
    void colour(std::span<const GraphEdge> edges, std::size_t body_count, std::uint32_t regions = 1,
                std::span<const double> cut = {});
    /// colour recolours once more than 1 in this many manifolds changed path group: a resting
    /// pile's contacts flip between "apart" and "touching" at preparation (about 3 % of
    /// pyramid40's each step), so recolouring on any change would do it nearly every step, and
    /// 1 in 32 measured slower on large_pyramid than 1 in 8 (docs/performance.md).
    static constexpr std::size_t regroup_share = 8;

    /// The solve order: the manifolds of level 0, of level 1, ..., four to a pack (by path
    /// group, then creation order, within a level); with regions, stream 0's packs in that
    /// order, then stream 1's, and so on (streams depend only on streams before them).
    std::span<const Pack> packs() const { return packs_; }
    std::uint32_t streams() const { return streams_; }
    /// Stream s's packs are [stream_begin(s), stream_begin(s + 1)) of packs().
    std::uint32_t stream_begin(std::uint32_t s) const { return stream_begin_[s]; }
    /// The other streams' progress pack i (of packs()) needs before it may run: a wait is
    /// listed only where it asks more than the stream's earlier packs already waited for.
    std::span<const StreamWait> waits(std::size_t i) const {
        return std::span<const StreamWait>(waits_).subspan(wait_begin_[i],
                                                           wait_begin_[i + 1] - wait_begin_[i]);
    }

    /// Whether some other stream waits for pack i (of packs()) to be finished: its stream
    /// reports its progress right after it.
    bool awaited(std::size_t i) const { return awaited_[i] != 0; }

  private:
    /// How many of `edges` changed path group since the last call that coloured; other_bodies
    /// if they couple other bodies, or the regions or the body count changed.
    static constexpr std::size_t other_bodies = ~std::size_t{0};
    std::size_t regrouped(std::span<const GraphEdge> edges, std::uint32_t R,
                          std::size_t body_count) const;
    /// Each manifold's stream (stream_of_), R > 1 regions across `cut`.
    void assign_streams(std::span<const GraphEdge> edges, std::uint32_t R,
                        std::span<const double> cut);
    /// The pass's order (sequence_) from stream_of_: stream by stream, creation order within
    /// (the last stream by colour first); streams_ already set.
    void sequence(std::span<const GraphEdge> edges, std::uint32_t R, std::size_t body_count);
    /// Each manifold's level (level_of_: no two of one level share a moving body, and those
    /// that share one keep their order in the sequence) and the manifolds sorted by level and
    /// path group (sorted_); `streamed`: in sequence_'s order, each stream's levels after the
    /// streams' before it.
    void level_sort(std::span<const GraphEdge> edges, std::size_t body_count, bool streamed);
    /// The packs from sorted_ (packs_, pack_stream_, stream_begin_, the waits and awaited_)
    /// for S streams.
    void place_packs(std::size_t body_count, std::uint32_t S);
    /// Orders `between` (manifolds in creation order) by their greedy colours: each in turn
    /// takes the lowest of 64 colours that no earlier one on its moving bodies took (with all
    /// 64 taken: after them all), then creation order within a colour.
    void between_by_colour(std::span<const GraphEdge> edges, std::span<std::uint32_t> between,
                           std::size_t body_count);

    /// Per body: one past the level of its last constraint so far, while levelling; then the
    /// pack of its last constraint placed so far, while packing (no_constraint: none yet).
    memory::vector<std::uint32_t> body_mark_;
    memory::vector<std::uint32_t> level_of_;
    memory::vector<std::uint32_t> level_start_, level_fill_;
    memory::vector<double> cuts_;             ///< scratch for the regions' bounds
    memory::vector<std::uint32_t> stream_of_; ///< per manifold: its stream
    /// The inputs the packs were made from (regions 0: not coloured yet; colour makes R >= 1).
    memory::vector<GraphEdge> coloured_edges_;
    std::uint32_t coloured_regions_ = 0;
    std::size_t coloured_bodies_ = 0;
    memory::vector<std::uint32_t> sequence_; ///< the manifolds in the pass's order
    GreedyColours body_colours_;             ///< the colours taken on each body (scratch)
    memory::vector<std::uint32_t> colour_of_, between_scratch_; ///< scratch of between_by_colour
    /// A constraint, its bodies and its stream, in solve order (what placing it reads).
    struct Placement {
        std::uint32_t index = 0;
        std::uint32_t body_a = 0, body_b = 0;
        std::uint32_t stream = 0;
    };
    memory::vector<Placement> sorted_;
    std::uint32_t streams_ = 1;
    memory::vector<Pack> packs_;
    memory::vector<std::uint32_t> pack_stream_;
    memory::vector<std::uint32_t> stream_begin_;
    memory::vector<std::uint32_t> wait_begin_;
    memory::vector<StreamWait> waits_;
    memory::vector<std::uint8_t> awaited_;
};

} // namespace tamias2d
