// The joint passes split among threads (internal). With WorldDef::contact_regions = R > 1 and
// at least min_joints solved joints, the moving bodies are cut, in solver order (the order the
// game created them in), into R runs of about equal length; each joint pass then solves the
// joints whose bodies both lie in run 0, in creation order, then those of run 1, ..., and last
// the rest (a joint between runs, or one holding an immovable body), in creation order. The
// runs' joints share no body, so they are solved on several threads at once; the rest follow
// on one. An immovable side is the solver body 0 that every immovable body shares, which two
// threads would both write: such a joint is one of the rest.
//
// Why cut by creation order rather than across gravity, as the contacts' slabs are: a game
// creates together what it joins together (a ragdoll, a bridge, a chain, a grid), so few joints
// fall between runs, and the cut needs neither a sort nor the last step's cut: the order is a
// function of this step's scene and R alone, never of the workers. Why a floor on the count: a
// run of fewer joints costs the threads more to hand over than it saves, and below it the
// joints keep the creation order, the best for a chain's convergence.
#pragma once

#include <array>
#include <cstdint>

#include "tamias2d/memory/allocator.hpp"

namespace tamias2d {

/// A joint the step solves, with its solver bodies (0: immovable), whether it is a plain pin
/// (PinPacks::plain) and its sides' rotations in the step solver's array (a moving side's is
/// its solver body's). No padding: PinPacks compares lists of them byte for byte.
struct SolvedJoint {
    std::uint32_t joint = 0;
    std::uint32_t solver_a = 0, solver_b = 0;
    std::uint32_t plain = 0;
    std::uint32_t rotation_a = 0, rotation_b = 0;
};
static_assert(sizeof(SolvedJoint) == 6 * sizeof(std::uint32_t));

class JointStreams {
  public:
    static constexpr std::uint32_t max_regions = 8;
    /// Below this many solved joints they are solved in creation order in any case.
    static constexpr std::size_t min_joints = 256;

    /// Orders `solved` (creation order on entry) into its streams for R = `regions` runs of
    /// the `moving` solver bodies 1 ... moving, or leaves it as it is (regions() then 0).
    void split(memory::vector<SolvedJoint>& solved, std::uint32_t regions, std::uint32_t moving);

    /// R when the last split cut the joints into runs, else 0.
    std::uint32_t regions() const { return regions_; }
    /// Run r's joints are [begin(r), begin(r + 1)) of the ordered list; the rest are
    /// [begin(regions()), end).
    std::uint32_t begin(std::uint32_t r) const { return begin_[r]; }

  private:
    std::uint32_t regions_ = 0;
    std::array<std::uint32_t, max_regions + 2> begin_{};
    memory::vector<std::uint8_t> stream_of_; ///< per solved joint (scratch)
    memory::vector<SolvedJoint> ordered_;    ///< scratch
};

} // namespace tamias2d
