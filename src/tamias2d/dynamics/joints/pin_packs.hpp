// Plain pins solved four at once (internal). A joint pass is a Gauss-Seidel pass: each joint
// sees the velocities the joints before it left. Within one stream (JointStreams) the joints
// are levelled: each goes one level after the last earlier joint on either of its moving
// bodies, so the joints of one level share no moving body and commute, and the levels run in
// order, in any order within each, give the creation order's bits. Within a level the plain
// pins (revolute joints with no spring, motor or limit: DD19's pin alone, the links of bridges,
// grids and ragdolls) are packed four to a pack and solved as one, each lane with the
// operations of one pin's solve (model/dd19 over packs of lanes); the other joints, and a
// level's last one to three pins, are solved one by one. The static body 0 may sit in several
// lanes of a pack: its inverse mass is 0, so every lane writes back its unchanged zeros.
//
// A stream whose levels hold fewer than four joints on average (a chain or a rope: one joint a
// level) is coloured instead: in creation order each joint takes the lowest colour that no
// joint before it on either moving body has, and the colours run in order, each as a level
// (its joints share no moving body), so that a chain's even links and then its odd ones fill
// packs. The Gauss-Seidel order is then the colours' (as Box2D v3 orders its joints), not the
// creation order: a different order of the same iteration, as deterministic. A stream whose
// colours hold fewer than four packs' worth of joints each on average (a short chain, joints
// around one body), or that needs more than 64 colours, keeps the creation order, one joint at
// a time.
//
// The solved joints are put in that order before their records are made (a packed pin has
// none: its lane is filled from its joint), and a step whose solved joints, bodies and plain
// pins are the last step's reuses its order without ordering again.
//
// Why: a pin's solve is a chain of dependent scalar operations on two bodies; four unrelated
// pins fill the four lanes of a pack of doubles (AVX2), as the contacts' packs do. A chain in
// creation order is one long such chain (each link waits for the last); by colour it packs.
#pragma once

#include <cstdint>
#include <span>

#include "tamias2d/dynamics/greedy_colours.hpp"
#include "tamias2d/dynamics/joints/joint_sim.hpp"
#include "tamias2d/dynamics/joints/joint_streams.hpp"
#include "tamias2d/dynamics/softness.hpp"
#include "tamias2d/dynamics/solver_body.hpp"
#include "tamias2d/math/vec2d.hpp"
#include "tamias2d/math/wide.hpp"
#include "tamias2d/memory/allocator.hpp"
#include "tamias2d/memory/large_array.hpp"

namespace tamias2d {

/// A revolute joint with no spring, motor or limit: its solve is DD19's pin alone.
inline bool plain_pin(JointType type, bool spring, bool motor, bool limit) {
    return type == JointType::revolute && !spring && !motor && !limit;
}

/// One plain pin as a pack's lane holds it (what its JointSim would hold for its solve).
struct PinLane {
    std::uint32_t body_a = 0, body_b = 0; ///< solver bodies
    const Rot* q_a = nullptr;             ///< the bodies' rotations (JointSim::q_a)
    const Rot* q_b = nullptr;
    Vec2d frame_a{}, frame_b{}; ///< m, the pin from each centre, body frame
    Vec2d center_offset{};      ///< m, p_B - p_A at the step's start
    Vec2d impulse{};            ///< N s, the pin's accumulated impulse
    double angular = 0.0;       ///< N m s, the warm start's angular impulse
    Softness softness{};
};

/// Four plain pins as packs, a lane each: filled from their joints when the step's joints are
/// prepared (a packed pin has no JointSim), their impulses read back once the step is solved.
struct alignas(wide_alignment) PinPack {
    Vec2<Wide> frame_a{}, frame_b{}; ///< m, the pins from the centres, body frames
    Vec2<Wide> center_offset{};      ///< m, p_B - p_A at the step's start
    Vec2<Wide> impulse{};            ///< N s, the pin's accumulated impulse
    Wide angular{};                  ///< N m s, the warm start's angular impulse (its parts' last)
    Wide bias_rate{}, mass_scale{}, impulse_scale{}; ///< the joint's softness
    std::uint32_t body_a[wide_lanes]{}, body_b[wide_lanes]{};
    const Rot* q_a[wide_lanes]{};
    const Rot* q_b[wide_lanes]{};
};

/// One step of a stream's joint pass: the step solver's records [first, first + count),
/// `packed`: four to a pack, the packs [pack, pack + count / 4); else each solved alone.
struct PinRun {
    std::uint32_t first = 0, count = 0;
    std::uint32_t pack = 0;
    bool packed = false;
};

class PinPacks {
  public:
    /// Orders `solved` stream by stream (stream s: [bounds[s], bounds[s + 1])) into the passes'
    /// order and records the streams' runs; `body_count`: the solver bodies.
    void order(memory::vector<SolvedJoint>& solved, std::span<const std::uint32_t> bounds,
               std::size_t body_count);
    std::uint32_t streams() const {
        return stream_begin_.empty() ? 0 : std::uint32_t(stream_begin_.size()) - 1;
    }
    /// Stream s's runs, in order.
    std::span<const PinRun> runs(std::uint32_t s) const {
        return std::span<const PinRun>(runs_).subspan(stream_begin_[s],
                                                      stream_begin_[s + 1] - stream_begin_[s]);
    }
    std::size_t pack_count() const { return pack_first_.size(); }

    /// Pack `pack`'s four pins are the records [first_record(pack), first_record(pack) + 4) of
    /// the passes' order, whose records are never made (in_pack).
    std::uint32_t first_record(std::size_t pack) const { return pack_first_[pack]; }
    bool in_pack(std::size_t record) const { return in_pack_[record] != 0; }
    /// Lane `lane` of pack `pack`, and the pin's impulse there once solved.
    void fill(std::size_t pack, int lane, const PinLane& pin);
    Vec2d impulse(std::size_t pack, int lane) const {
        return {packs_[pack].impulse.x[lane], packs_[pack].impulse.y[lane]};
    }
    /// The warm start, or an iteration (soft with use_bias, else the relax), of `count` packs
    /// from `first`.
    void warm_start(std::uint32_t first, std::uint32_t count, SolverBody* bodies);
    void solve(std::uint32_t first, std::uint32_t count, SolverBody* bodies, bool use_bias);

  private:
    /// Levels (or colours) and packs one stream, solved[first, last), into ordered_ and the runs.
    void order_stream(const memory::vector<SolvedJoint>& solved, std::uint32_t first,
                      std::uint32_t last, std::size_t body_count);
    /// Each joint of solved[first, last) its colour in level_of_ (the lowest no earlier joint
    /// on either moving body took); the number of colours, or 0 where one would exceed 64.
    std::uint32_t colour_stream(const memory::vector<SolvedJoint>& solved, std::uint32_t first,
                                std::uint32_t last, std::size_t body_count);

    LargeArray<PinPack> packs_;
    memory::vector<std::uint32_t> pack_first_; ///< per pack: its first record
    memory::vector<std::uint8_t> in_pack_;     ///< per record: in a pack
    memory::vector<PinRun> runs_;
    memory::vector<std::uint32_t> stream_begin_; ///< into runs_, streams() + 1 of them
    /// The last order's input (solved and bounds) and output.
    memory::vector<SolvedJoint> last_solved_, ordered_;
    memory::vector<std::uint32_t> last_bounds_;
    std::size_t last_body_count_ = 0;
    memory::vector<std::uint32_t> mark_; ///< per solver body: one past its last level (scratch)
    GreedyColours colours_;              ///< the colours each solver body's joints took
    memory::vector<std::uint32_t> level_of_, level_start_, sorted_; ///< order_stream's scratch
};

} // namespace tamias2d
