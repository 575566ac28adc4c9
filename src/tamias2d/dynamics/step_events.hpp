// The events a step reports beside the contacts' and the sensors' own (internal): hard hits,
// moved bodies and joint events (tamias2d/events.hpp). Each kind costs nothing while nothing
// asks for it: the counts of the shapes that ask for hits and of the bodies that ask for
// moves say whether the step's passes run at all. Box2D v3 reports the same kinds from its
// solver's finalisation (solver.c) and its joints' (joint.c).
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include "tamias2d/body_def.hpp"
#include "tamias2d/dynamics/joints/joint.hpp"
#include "tamias2d/events.hpp"
#include "tamias2d/joint_def.hpp"
#include "tamias2d/memory/allocator.hpp"
#include "tamias2d/shape_def.hpp"
#include "tamias2d/validation.hpp"

namespace tamias2d {

struct BodyStore;
class ShapeStore;
class ContactManager;
class JointStore;
struct StateHasher;
class SnapshotWriter;
class SnapshotReader;

/// A touching pair's approach speed at the step's start at its manifold point j (m s^-1):
/// -(v_B - v_A) . n at the point (DD11, through IM3's normal relative velocity).
double approach_speed(const ContactManager& contacts, std::uint32_t contact, int j,
                      const BodyStore& bodies);

class StepEvents {
  public:
    /// Room for n bodies' flags and moves without growing (WorldDef::capacity).
    void reserve(std::size_t n) {
        moves.reserve(n);
        move_flag_.reserve(n);
        moved_.reserve(n);
    }
    memory::vector<ContactHitEvent> hits;    ///< the last step's, in contact order
    memory::vector<BodyMoveEvent> moves;     ///< the last step's, in body order
    memory::vector<JointEvent> joint_events; ///< the last step's and the destructions' since

    // --- the world's objects come and go ---
    /// Body i was created from `def`.
    void body_created(std::uint32_t i, const BodyDef& def);
    /// Body i is about to be destroyed with its shapes and joints: its joints' events
    /// (body_destroyed), its shapes and its own flag leave the counts.
    void body_destroying(std::uint32_t i, const BodyStore& bodies, const ShapeStore& shapes,
                         const JointStore& joints);
    /// A shape made from `def` was created, or is about to be destroyed.
    void shape_created(const ShapeDef& def) { hit_shapes_ += def.enable_hit_events ? 1 : 0; }
    void shape_destroying(const ShapeDef& def) { hit_shapes_ -= def.enable_hit_events ? 1 : 0; }

    // --- the switches ---
    bool move_events(std::uint32_t body) const {
        return body < move_flag_.size() && move_flag_[body] != 0;
    }
    void set_move_events(std::uint32_t body, bool on);
    /// Joint j's thresholds were set: once one is finite, each step passes over the joints
    /// (until then, a world of many joints pays nothing for their events).
    void thresholds_set(const Joint& j) {
        thresholds_used_ =
            thresholds_used_ || j.force_threshold < infinite || j.torque_threshold < infinite;
    }
    /// A shape's enable_hit_events changed from `was` to `now`.
    void hit_flag_changed(bool was, bool now) {
        hit_shapes_ += std::uint32_t(now) - std::uint32_t(was);
    }

    // --- a step ---
    /// At the step's start: the last step's events go.
    void clear();
    /// After the narrow phase, before the solve (the bodies' velocities are the step's
    /// starting ones): the touching pairs one of whose shapes asks for hits, with their
    /// points' approach speeds above `threshold` (m s^-1).
    void before_solve(const BodyStore& bodies, const ShapeStore& shapes,
                      const ContactManager& contacts, double threshold);
    /// After the solve, before sleeping's update: which bodies moved this step.
    void before_sleep(const BodyStore& bodies);
    /// After the step: the hits among the candidates whose point pushed, the moved bodies'
    /// poses, the joints over a threshold and the broken ones (JointStore::broken).
    void after_step(const BodyStore& bodies, const ShapeStore& shapes,
                    const ContactManager& contacts, const JointStore& joints, bool sleeping);

    /// Feeds the event settings that are not the defaults to the state hash: a world that
    /// uses none hashes as it did before they existed.
    void hash(StateHasher& hs, const ShapeStore& shapes, const JointStore& joints,
              double threshold) const;

    // --- snapshot (World::snapshot, World::restore; dynamics/snapshot_io.hpp) ---
    /// Writes the last step's events, each body slot's move-event flag and whether a joint
    /// has had a finite threshold. The rest is a step's own (cleared at its start) or counts
    /// that read rebuilds.
    void write(SnapshotWriter& out) const;
    /// Reads what write wrote into these empty events (`bodies`, `shapes` and `joints` already
    /// read) and counts the live bodies with move events and the live shapes with hit events;
    /// throws SnapshotError for a move flag of a slot beyond the bodies' or of a dead body.
    void read(SnapshotReader& in, const BodyStore& bodies, const ShapeStore& shapes);

  private:
    struct Candidate {
        std::uint32_t contact;
        double speed[2]; ///< m s^-1 per manifold point; 0 where not above the threshold
    };
    memory::vector<Candidate> candidates_;
    memory::vector<std::uint8_t> move_flag_; ///< per body index: BodyDef::enable_move_events
    memory::vector<std::uint8_t> moved_;     ///< per body index: awake during the last solve
    bool moved_known_ = false;               ///< before_sleep ran in this step
    bool thresholds_used_ = false;           ///< some joint has had a finite threshold
    static constexpr double infinite = std::numeric_limits<double>::infinity();
    std::uint32_t move_bodies_ = 0; ///< live bodies with move events
    std::uint32_t hit_shapes_ = 0;  ///< live shapes with hit events
};

/// A joint made from `def` with its event thresholds, checked first (validate_event_threshold):
/// for World::create_joint, before the joint is stored (`events` then passes over the joints
/// after each step).
template <class Def> Joint with_event_thresholds(StepEvents& events, Joint j, const Def& def) {
    validate_event_threshold("joint.force_threshold", def.force_threshold, true);
    validate_event_threshold("joint.torque_threshold", def.torque_threshold, true);
    j.force_threshold = def.force_threshold;
    j.torque_threshold = def.torque_threshold;
    events.thresholds_set(j);
    return j;
}
/// A filter joint carries no force: it has no thresholds.
inline Joint with_event_thresholds(StepEvents&, Joint j, const FilterJointDef&) {
    return j;
}

} // namespace tamias2d
