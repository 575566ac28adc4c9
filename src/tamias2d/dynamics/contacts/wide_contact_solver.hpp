// The contact iterations of the soft step on packs of four manifolds (one per lane, grouped by
// ConstraintGraph's levels). The result equals the sequential Gauss-Seidel pass over the
// manifolds in creation order, bit for bit (tests/engine/test_wide_contact_solver.cpp).
#pragma once

#include <array>
#include <span>

#include "tamias2d/dynamics/constraint_graph.hpp"
#include "tamias2d/dynamics/contacts/contact.hpp"
#include "tamias2d/dynamics/contacts/contact_constraint.hpp"
#include "tamias2d/dynamics/contacts/wide_contact_constraint.hpp"
#include "tamias2d/dynamics/solver_body.hpp"
#include "tamias2d/dynamics/solver_settings.hpp"
#include "tamias2d/memory/large_array.hpp"

namespace tamias2d {

/// Lane l of a pack's input from a constraint's unprepared fields (bodies, contact, normal,
/// friction, count, anchors, separations, warm-start impulses); `slot` as in prepare_pack.
/// Every field of the lane is written (a point past the count gets zeros), so an input may be
/// reused pack after pack without being cleared: each lane is either set or cleared.
void set_input_lane(WideManifoldInput& in, int l, const ContactConstraint& c, std::uint32_t slot);
/// The same straight from a persistent contact (the world's path: no ContactConstraint between):
/// its solver bodies `edge`, its index, manifold, friction and warm-start impulses.
void set_input_lane(WideManifoldInput& in, int l, const GraphEdge& edge, std::uint32_t contact,
                    const Contact& c, const ContactImpulses& warm, std::uint32_t slot);
/// Lane l as an empty lane: all zeros, naming the static body 0.
void clear_input_lane(WideManifoldInput& in, int l);

class WideContactSolver {
  public:
    /// A lane's manifold cannot bounce (restitution 0): the restitution pass has no copy of it.
    static constexpr std::uint32_t no_slot = 0xffffffffu;

    /// Orders the manifolds (ConstraintGraph's levels, four to a pack, in `regions` regions
    /// across `cut`) and sizes the packs; prepare_pack then fills each pack of order().
    void colour(std::span<const GraphEdge> edges, std::size_t body_count, std::uint32_t regions = 1,
                std::span<const double> cut = {});
    /// The colouring: its streams run either in their stored order (warm_start, solve) or on
    /// several threads through PackStreams and the *_run functions below.
    const ConstraintGraph& graph() const { return graph_; }
    /// The solve order: the manifold (index into colour's edges) each lane of each pack holds.
    std::span<const ConstraintGraph::Pack> order() const { return graph_.packs(); }
    /// Prepares pack i's four lanes at once (contact_preparation.hpp) into the pack. A lane's
    /// restitution_slot is where the restitution pass keeps its own copy (no_slot: none), for
    /// store() to update.
    void prepare_pack(std::size_t i, const WideManifoldInput& in,
                      std::span<const SolverBody> bodies);
    /// prepare_pack, then warm_start's work on this pack alone. Called for every pack in order,
    /// it gives warm_start's bits (no body appears twice in a pack, and the packs apply their
    /// impulses in the same order), without a second pass over the packs.
    void prepare_pack_and_warm_start(std::size_t i, const WideManifoldInput& in,
                                     std::span<SolverBody> bodies);

    /// Re-applies the accumulated impulses (they carry the previous substep's solution forward).
    void warm_start(std::span<SolverBody> bodies);
    /// One iteration: with use_bias the soft, overlap-removing solve; without it the rigid relax.
    void solve(std::span<SolverBody> bodies, const ContactSolverSettings& settings, bool use_bias);
    /// warm_start and solve on packs [first, first + count), all of stream `stream`, whose
    /// waits are met; lanes naming the static body write into the stream's own zero body.
    void warm_start_run(std::size_t first, std::size_t count, std::uint32_t stream,
                        std::span<SolverBody> bodies);
    void solve_run(std::size_t first, std::size_t count, std::uint32_t stream,
                   std::span<SolverBody> bodies, const ContactSolverSettings& settings,
                   bool use_bias);
    /// Copies the impulses into the persistent contacts' records, indexed like the contacts: the
    /// accumulated ones into `warm` (warm start next step), the step's totals into `totals`
    /// (contact report); and, for the manifolds that can bounce, into the restitution pass's
    /// copies (by slot), whose normal totals the caller writes after that pass. Packs [begin, end):
    /// each contact and slot is written by one pack, so disjoint ranges may be stored on different
    /// threads.
    /// With surface motion, the rolling impulses go into `rolling` (indexed like the contacts).
    void store(std::span<ContactImpulses> warm, std::span<ContactImpulses> totals,
               std::span<ContactConstraint> bouncing, std::size_t begin, std::size_t end,
               std::span<double> rolling = {}) const;

    /// DD46, DD47: whether the packs of this step have surface motion (after colour; off: the
    /// solves are those of a world without any). On, every lane of every pack takes its values
    /// from set_surface_lane before the pack is warm started.
    void use_surfaces(bool on);
    bool uses_surfaces() const { return with_surfaces_; }
    /// Lane l of pack i: the target of its relative tangential velocity (DD47, m s^-1), its
    /// rolling resistance length c l (DD46, m) and its rolling impulse to warm start from
    /// (N m s).
    void set_surface_lane(std::size_t i, int l, double tangent_speed, double rolling_resistance,
                          double rolling_impulse);

    /// The clone the packs run with here: "x86-64-v4" or "avx2", or nullptr for the baseline
    /// (SSE2 on x86-64; also in unoptimised builds). The results are equal.
    static const char* instruction_set();

  private:
    /// Asks for the lines of the pack two ahead of pack i, which preparation writes next but
    /// one: a pack is written field by field, not as a stream the hardware prefetcher follows,
    /// and once the packs outgrow the caches each of its lines was a miss waited for
    /// (rain_16k: 3-5 % faster per step; a pyramid, whose packs stay in cache, unchanged).
    void prefetch_pack_after(std::size_t i) const;

    /// Tests and the typing benchmark read the packs (tests/support/wide_solver_access.hpp).
    friend struct WideContactSolverAccess;

    ConstraintGraph graph_;
    /// Per stream: where its lanes naming the static body write (never read), a line each.
    struct alignas(64) Sink {
        SolverBody body;
    };
    std::array<Sink, ConstraintGraph::max_streams> sinks_;
    LargeArray<WideContactConstraint> packs_;
    /// Indexed like packs_ while with_surfaces_ (DD46, DD47): the steps without surface motion
    /// neither fill nor read it.
    LargeArray<WideSurfaceMotion> surfaces_;
    bool with_surfaces_ = false;
    /// \srs{DD46, DD47} The surface motion (rolling resistance, tangent speed) from pack i on,
    /// or nullptr in a step without any.
    WideSurfaceMotion* surface(std::size_t i) {
        return with_surfaces_ ? surfaces_.data() + i : nullptr;
    }
};

} // namespace tamias2d
