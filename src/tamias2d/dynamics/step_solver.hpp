// One step's solution of the bodies' motion (internal): the solver bodies and their loads
// (IM1, IM2, IM5), the touching manifolds coloured into packs, the substeps of the soft step
// (velocities, contact iterations, positions), the restitution pass, and the write-back of
// the bodies' new states into the world's bodies and shapes. Box2D keeps the same concerns in
// solver.c. The world calls prepare_bodies, solve and finalize in that order each step.
#pragma once

#include <cstdint>
#include <vector>

#include "tamias2d/body_def.hpp"
#include "tamias2d/dynamics/constraint_graph.hpp"
#include "tamias2d/dynamics/contacts/contact_constraint.hpp"
#include "tamias2d/dynamics/contacts/pack_streams.hpp"
#include "tamias2d/dynamics/contacts/wide_contact_solver.hpp"
#include "tamias2d/dynamics/continuous.hpp"
#include "tamias2d/dynamics/joints/joint.hpp"
#include "tamias2d/dynamics/joints/joint_rotations.hpp"
#include "tamias2d/dynamics/joints/joint_sim.hpp"
#include "tamias2d/dynamics/joints/joint_streams.hpp"
#include "tamias2d/dynamics/joints/pin_packs.hpp"
#include "tamias2d/dynamics/solver_body.hpp"
#include "tamias2d/dynamics/step_context.hpp"
#include "tamias2d/handles.hpp"
#include "tamias2d/memory/allocator.hpp"
#include "tamias2d/memory/large_array.hpp"
#include "tamias2d/world_def.hpp"

namespace tamias2d {

struct BodyStore;
class ShapeStore;
class ContactManager;
class JointStore;
class StepTasks;

class StepSolver {
  public:
    /// Room for the per-body arrays of n bodies and the per-manifold ones of `contacts`
    /// contacts without growing (WorldDef::capacity).
    void reserve(std::size_t n, std::size_t contacts) {
        solver_bodies_.reserve(n + 1);
        accelerations_.reserve(n + 1);
        angular_accelerations_.reserve(n + 1);
        linear_decay_.reserve(n + 1);
        angular_decay_.reserve(n + 1);
        solver_index_.reserve(n);
        cut_.reserve(n + 1);
        edges_.reserve(contacts);
        edge_contact_.reserve(contacts);
        edge_slot_.reserve(contacts);
        written_back_.reserve(n);
        starts_.reserve(n);
    }
    /// The solver bodies and their accelerations (IM1, IM2's loads; IM5's decay factors over
    /// the substep h): one per awake non-static body, 0 standing for every immovable one.
    /// With more than one worker, in parallel blocks of bodies, to the serial loop's results.
    void prepare_bodies(const BodyStore& bodies, const StepContext& step);
    /// The solved joints' records (JointSim) at the step's start (after prepare_bodies), in
    /// the joint passes' order (JointStreams' streams, each levelled with its plain pins in
    /// packs: PinPacks); with more than one worker and enough joints, in parallel blocks.
    void prepare_joints(const JointStore& joints, const BodyStore& bodies, const StepContext& step);
    /// The substeps of the soft step over dt and the restitution pass; the contacts' impulses
    /// are stored back for the warm start and the report, the joints keep theirs.
    /// With joints, a solve whose velocities or displacements turn non-finite (the joints'
    /// solve diverged) stops before anything is stored: diverged() names the body.
    /// With more than one worker, the bodies' integration and the contacts' preparation run in
    /// parallel blocks (each body, each pack its own), with the results of one thread.
    /// With surface motion in the world (ShapeStore::surface_motion) each manifold's tangent
    /// speed and rolling resistance (DD46, DD47) are mixed from its shapes' materials.
    void solve(ContactManager& contacts, JointStore& joints, const ShapeStore& shapes,
               const StepContext& step);
    /// The body (index in the body store) of the first solver body the last solve left
    /// non-finite, or null_index: the step must then be refused, nothing finalized.
    std::uint32_t diverged() const { return diverged_; }
    /// The packs of up to four manifolds the last solve ran (World::counters).
    std::size_t pack_count() const { return wide_solver_.order().size(); }
    /// The new velocities and poses into the bodies, and the shapes' copies and fat boxes
    /// after them (the broad phase's proxies moved), listing the dynamic bodies that moved far
    /// for continuous(), which must follow.
    /// With more than one worker the bodies are written back in parallel blocks, and the lists
    /// that follow body order (continuous pass, undecided shapes) are gathered after them.
    void finalize(BodyStore& bodies, ShapeStore& shapes, const StepContext& step);
    /// After finalize: with def.enable_continuous, the continuous pass (DD29) over the bodies
    /// finalize listed. (A stage of its own, so that World::profile can time it.)
    void continuous(BodyStore& bodies, ShapeStore& shapes, const ContactManager& contacts,
                    const JointStore& joints, const StepContext& step);

  private:
    /// prepare_bodies' parallel form; `across` is the axis the contact regions are cut across.
    void prepare_bodies_in_blocks(const BodyStore& store, const memory::vector<Load>& loads,
                                  const WorldDef& def, double h, Vec2d across,
                                  const StepTasks& tasks);
    /// \srs{R5} \srs{R6} IM1/IM2, the velocity half of the semi-implicit Euler step (DD4, DD7);
    /// \srs{IM5} with damping when some body is damped.
    void integrate_velocities(double h, const StepTasks& tasks);
    /// integrate_velocities on solver bodies [begin, end).
    void integrate_velocities(double h, std::size_t begin, std::size_t end);
    /// \srs{R5} \srs{R6} IM1/IM2, the position half with the new velocities (DD3, DD6).
    void integrate_positions(double h, const StepTasks& tasks);
    void integrate_positions(double h, std::size_t begin, std::size_t end);
    /// The touching manifolds with a moving body, in creation order, into edges_, edge_contact_
    /// and edge_slot_ (in parallel blocks with more than one worker); returns how many can
    /// bounce.
    std::uint32_t list_edges(const ContactManager& contacts, const StepTasks& tasks);
    /// The manifolds' lane filling and preparation into packs [begin, end) of the solve order,
    /// each pack warm started right after it with `warm_start` (then begin must be 0); with
    /// `surfaces` (else nullptr) each lane's surface motion mixed from its shapes too.
    void prepare_packs(const ContactManager& contacts, const ShapeStore* surfaces,
                       std::size_t begin, std::size_t end, bool warm_start);
    /// finalize's sweep over bodies [begin, end). `deferred`: the continuous pass's bodies and
    /// the undecided shapes are recorded per body and per shape (written_back_, starts_,
    /// undecided_) for a gather in body order, instead of being listed at once.
    template <bool deferred>
    void write_back(BodyStore& store, ShapeStore& shape_store, const WorldDef& def,
                    std::uint32_t begin, std::uint32_t end);
    /// One contact pass: the warm start (settings null) or an iteration (soft with use_bias,
    /// else the relax); with more than one stream on the tasks' threads (PackStreams), else
    /// the packs in their stored order on the calling thread.
    void contact_pass(const StepTasks& tasks, std::uint32_t streams,
                      const ContactSolverSettings* settings, bool use_bias);
    /// A solver body whose velocity or displacement is not finite after the iterations: its
    /// body's index in diverged_ (true), else null_index (false).
    bool find_divergence();
    /// The packs' impulses stored into the contacts (warm starts and totals), then the
    /// restitution pass over the `bounce_count` manifolds that can bounce, whose normal totals
    /// it writes.
    void store_impulses(ContactManager& contacts, const StepTasks& tasks,
                        std::uint32_t bounce_count, const ContactSolverSettings& st);
    /// The jointed bodies' rotations after a position half (the records' q_a, q_b).
    void turn_joints(const StepTasks& tasks);
    /// The joints' warm start, then an iteration (soft with use_bias, else the relax), each
    /// over the solved joints' records in their streams' order (joint_pass).
    void warm_start_joints(const memory::vector<Joint>& joints, const StepTasks& tasks);
    void solve_joints(const memory::vector<Joint>& joints, double h, bool use_bias,
                      const StepTasks& tasks);
    /// One joint pass over the streams' runs (PinPacks): single(record) for a joint solved
    /// alone, packs(first, count) for a run of packs; the streams in order on this thread, or
    /// with the joints split (JointStreams) and more than one worker, the runs' streams at once,
    /// then the rest.
    template <class Single, class Packs>
    void joint_pass(const StepTasks& tasks, Single& single, Packs& packs);
    /// range(begin, end) over the pin packs, in parallel blocks with more than one worker and
    /// enough packs (each pack its own).
    template <class Range> void each_pack(const StepTasks& tasks, Range& range);
    /// each(record) for every solved joint, where each touches its own record only: in
    /// parallel blocks with more than one worker and enough joints.
    template <class Each> void each_sim(const StepTasks& tasks, Each& each);
    /// DD39 and DD40 before a position half (and at the step's end): the locked velocity
    /// components zeroed, then a speed above `max_speed` slowed to it. Nothing without a lock
    /// and with an infinite limit.
    void constrain_velocities(double max_speed, const StepTasks& tasks);
    /// The moving bodies with a linear lock this step (DD39), from prepare_bodies.
    struct LockedBody {
        std::uint32_t solver;
        bool x, y;
    };
    memory::vector<LockedBody> locked_;

    LargeArray<SolverBody> solver_bodies_;
    memory::vector<Vec2d> accelerations_;
    memory::vector<double> angular_accelerations_;
    memory::vector<double> linear_decay_, angular_decay_; ///< IM5's factors per solver body
    bool any_damped_ = false; ///< this step: some solver body is damped (else no factors)
    memory::vector<std::uint32_t> solver_index_; ///< per body: its SolverBody (0: immovable)
    /// prepare_bodies_in_blocks' per block: its first solver body, whether one is damped.
    memory::vector<std::uint32_t> block_first_;
    memory::vector<std::uint8_t> block_damped_;
    /// Per solver body: its centre along the axis the contact streams are cut across (m).
    memory::vector<double> cut_;
    std::uint32_t diverged_ = null_index;        ///< see diverged()
    memory::vector<GraphEdge> edges_;            ///< the touching manifolds, creation order
    memory::vector<std::uint32_t> edge_contact_; ///< per edge: its contact
    memory::vector<std::uint32_t> edge_slot_;    ///< per edge: its copy in `bouncing_`, or no_slot
    struct EdgeCount {
        std::uint32_t edges = 0, bounces = 0;
    };
    memory::vector<EdgeCount> edge_block_first_; ///< list_edges' per block: its first edge, slot
    memory::vector<ContactConstraint> bouncing_; ///< manifolds with restitution, creation order
    WideContactSolver wide_solver_;
    PackStreams pack_streams_;
    JointRotations joint_rotations_;
    memory::vector<SolvedJoint> solved_; ///< the solved joints, in the passes' order
    JointStreams joint_streams_;
    PinPacks pin_packs_;
    memory::vector<JointSim> sims_; ///< the solved joints' records, as solved_
    ContinuousPass continuous_;
    /// finalize's parallel form, per body: bit 0 swept by the continuous pass (from starts_),
    /// bit 1 some shape undecided (undecided_, per shape).
    memory::vector<std::uint8_t> written_back_;
    struct Start {
        Vec2d center;
        double angle;
        Vec2d v;
        double w;
    };
    memory::vector<Start> starts_;
    memory::vector<std::uint8_t> undecided_;
};

} // namespace tamias2d
