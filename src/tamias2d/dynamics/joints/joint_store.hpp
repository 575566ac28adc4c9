// The world's joints (internal): storage, slots and handles, which bodies each joins (for the
// collision filter, the islands and a body's destruction), the lever check of their anchors,
// the guard that lets a diverged step be refused, and breaking. Box2D keeps the same concerns
// in joint.c.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <span>
#include <string>
#include <vector>

#include "tamias2d/dynamics/joints/joint.hpp"
#include "tamias2d/dynamics/sleep.hpp"
#include "tamias2d/handles.hpp"
#include "tamias2d/memory/allocator.hpp"
#include "tamias2d/memory/slot_map.hpp"

namespace tamias2d {

struct StateHasher;
struct BodyStore;
class SnapshotWriter;
class SnapshotReader;
class ShapeStore;

/// How messages name a joint's kind ("revolute joint", ...).
std::string joint_kind_name(JointType type);

/// The joint angle now (DD22): B's turn against A since creation, rad.
double joint_angle_now(const Joint& j, const BodyStore& bodies);
/// The translation now along a prismatic or wheel joint's axis (DD23), m.
double joint_translation_now(const Joint& j, const BodyStore& bodies);

/// \srs{DCX_joint} Each anchor of `j` lies within supported::joint_lever_ratio_max radii of
/// gyration of its body's centre of mass. The field's name, made only to refuse, begins
/// "joint[index]." for a stored joint, "joint." for a new one (index null_index).
void validate_levers(const BodyStore& bodies, const Joint& j, std::uint32_t index);

class JointStore {
  public:
    /// The joints of the world tagged `world` (World::tag).
    explicit JointStore(std::uint32_t world) : slots(world) {}
    /// Room for n joints on up to `bodies` bodies without growing (WorldDef::capacity): each
    /// body's list holds two joints before it grows.
    void reserve(std::size_t n, std::size_t bodies);

    /// Which joints live, their handles' generations and the free slots.
    SlotMap<JointId> slots;
    memory::vector<Joint> joints;   ///< per slot
    double inv_h = 0.0;             ///< s^-1, the last step's substep rate (reaction forces)
    memory::vector<JointId> broken; ///< joints the last step broke

    /// The joint of a handle; throws InvalidHandle for a stale or unknown one, WrongWorld for
    /// one of another world.
    Joint& get(JointId id);
    const Joint& get(JointId id) const { return const_cast<JointStore*>(this)->get(id); }
    /// The joint of a handle for a reading or setter `call` that applies to the `kinds` only:
    /// throws InvalidHandle for a stale or unknown handle, WrongKind (saying `rule`) for a joint
    /// of another kind.
    Joint& get(JointId id, std::initializer_list<JointType> kinds, const char* call,
               const char* rule);
    const Joint& get(JointId id, std::initializer_list<JointType> kinds, const char* call,
                     const char* rule) const {
        return const_cast<JointStore*>(this)->get(id, kinds, call, rule);
    }
    bool is_valid(JointId id) const { return slots.is_valid(id); }
    JointId id(std::uint32_t i) const { return slots.id(i); }
    /// Whether slot i holds a joint (a destroyed joint's slot does not, until it is reused).
    bool alive(std::uint32_t i) const { return slots.live(i); }
    std::uint32_t live() const { return slots.live_count(); }

    /// A slot for a joint whose fields (bodies, anchors, options) are set; returns its index.
    std::uint32_t create(const Joint& joint);
    /// Frees joint i's slot: the step's preparation passes over a slot that holds no joint.
    void destroy(std::uint32_t i);
    /// Destroys joint i and wakes its bodies. A joint that kept its bodies from colliding
    /// (DD27) no longer does: the shapes of one of its bodies (B, or A when B is static) are
    /// touched, so that the broad phase reports their pairs again at the next step (at rest,
    /// they would not be looked for again).
    void unjoin(std::uint32_t i, BodyStore& bodies, ShapeStore& shapes);
    /// The joints of body i (empty when it has none).
    const memory::vector<std::uint32_t>& of_body(std::uint32_t body) const;
    /// Whether a joint between bodies a and b asks that their shapes not collide.
    bool filters(std::uint32_t a, std::uint32_t b) const;
    /// validate_levers for every live joint: a shape added or removed since a joint was made
    /// moves the centre of mass and changes the inertia its anchors are judged by. Nothing
    /// when no mass and no joint changed since the last check that passed.
    void check_levers(const BodyStore& bodies) const;
    /// Notes that joint j may break (a finite break force or torque): until one may, a step's
    /// break_joints reads no joint. Called wherever a threshold is set.
    void note_breakable(const Joint& j);

    /// Before a step's solve, with joints: keeps what the step changes and a refused step
    /// must give back (the sleep states the islands may wake, the substep rate the reaction
    /// forces are read with; the joints' impulses are written only once a step is accepted,
    /// StepSolver::solve). The vector is reused: no allocation in a steady state.
    void guard_step(const BodyStore& bodies, bool sleeping);
    /// The solve diverged at body i (StepSolver::diverged): gives back what
    /// guard_step kept and refuses the step naming the body (SolverDivergence). Nothing was
    /// finalized, so the bodies are as they were.
    [[noreturn]] void refuse_step(std::uint32_t i, BodyStore& bodies, bool sleeping);
    /// After the step: a joint whose reaction force exceeded its break force is destroyed
    /// (unjoin) and listed in `broken`.
    void break_joints(BodyStore& bodies, ShapeStore& shapes);

    /// Feeds the joints to the state hash (World::state_hash): with any live joint, each
    /// slot's generation and life, a live joint's definition and impulses.
    void hash(StateHasher& hs) const;

    // --- snapshot (World::snapshot, World::restore; dynamics/snapshot_io.hpp) ---
    /// Writes every slot (definition, generation, step state with its impulses), the free
    /// slots, each body's joint list in its order, the substep rate and the last step's broken
    /// joints.
    void write(SnapshotWriter& out) const;
    /// Reads what write wrote into this empty store (`bodies` already read); throws
    /// SnapshotError for a live joint of a body that does not live, or joint lists that do not
    /// list each live joint once under each of its bodies.
    void read(SnapshotReader& in, const BodyStore& bodies);
    // --- joint_control ---
    /// get's kind check for a list of kinds kept by the caller (WrongKind saying `rule`).
    Joint& get_of(JointId id, std::span<const JointType> kinds, const char* call, const char* rule);
    const Joint& get_of(JointId id, std::span<const JointType> kinds, const char* call,
                        const char* rule) const {
        return const_cast<JointStore*>(this)->get_of(id, kinds, call, rule);
    }
    /// Marks the shapes of one of joint j's bodies (B, or A when B is static) moved, so that
    /// the broad phase reports their pairs again at the next step: a pair the joint kept from
    /// colliding (at rest, it would not be looked for again) may now collide.
    static void touch_pairs(const Joint& j, const BodyStore& bodies, ShapeStore& shapes);
    /// Feeds what the joint_control calls set to the state hash, when any differs from its
    /// default (a spring target, a break torque, a tuning of the joint's own).
    static void hash_controls(StateHasher& hs, const Joint& j);
    // --- run-time control (World::set_body_type, set_enabled) ---
    /// Wakes the bodies of every joint of body i.
    void wake_joined(std::uint32_t i, BodyStore& bodies) const;
    /// Zeroes the impulses (the warm start and the reaction) of every joint of body i: a
    /// joint that stops being solved must not keep the last ones, to break with or to warm
    /// start from when it is solved again.
    void clear_impulses(std::uint32_t i);
    // --- definitions (WorldDef::enable_warm_starting) ---
    /// Zeroes every joint's impulses, so that the step's solve starts from none (warm
    /// starting off).
    void forget_warm_starts();

  private:
    memory::vector<memory::vector<std::uint32_t>> by_body_; ///< per body index: its joints
    /// Empty lists with room for two joints (reserve), taken by create() as by_body_ grows.
    memory::vector<memory::vector<std::uint32_t>> spare_lists_;
    bool breakable_ = false; ///< some joint has had a finite break threshold (note_breakable)
    /// BodyStore::mass_epoch at the last check_levers that passed (all ones: none since a
    /// joint was made or read).
    mutable std::uint64_t levers_checked_at_ = ~std::uint64_t{0};
    // What guard_step keeps: the sleep states and the substep rate.
    memory::vector<SleepState> sleep_before_;
    double inv_h_before_ = 0.0;
};

} // namespace tamias2d
