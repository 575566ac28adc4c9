// The world's contacts (internal): one per pair of shapes whose fat boxes overlap, with the
// arrays kept parallel to them (edge inputs, warm-start and total impulses), the index by shape
// pair, the begin/end events and the report. Only this class knows that the arrays are
// parallel: contacts are added and swap-removed here. Box2D keeps the same concerns in
// contact.c.
#pragma once

#include <cstdint>
#include <exception>
#include <functional>
#include <span>
#include <utility>
#include <vector>

#include "tamias2d/collision/manifold_reuse.hpp"
#include "tamias2d/contact_hooks.hpp"
#include "tamias2d/contact_info.hpp"
#include "tamias2d/dynamics/constraint_graph.hpp"
#include "tamias2d/dynamics/contacts/contact.hpp"
#include "tamias2d/dynamics/contacts/contact_constraint.hpp"
#include "tamias2d/memory/allocator.hpp"
#include "tamias2d/memory/large_array.hpp"
#include "tamias2d/memory/pair_map.hpp"
#include "tamias2d/shape_def.hpp"

namespace tamias2d {

struct StateHasher;
struct BodyStore;
class SnapshotWriter;
class SnapshotReader;
class ShapeStore;
class JointStore;
class StepTasks;
struct StepContext;

/// DD27's rule: whether two shapes' filters let them collide (or a sensor detect a shape).
bool admits(const Filter& a, const Filter& b);

class ContactManager {
  public:
    /// Room for n contacts without growing (WorldDef::capacity).
    void reserve(std::size_t n) {
        contacts_.reserve(n);
        warm_impulses_.reserve(n);
        total_impulses_.reserve(n);
        bases_.reserve(n);
        index_.reserve(n);
        edge_inputs_.reserve(n);
        new_pairs_.reserve(n);
        doomed_.reserve(n);
        outcomes_.reserve(n);
    }
    /// Per contact, indexed alike: what the colouring needs of it, written by the narrow phase
    /// while the contact is in cache. (Reading it back from the contacts cost a pass over most
    /// of their lines: 3.8 MB per step at 16k boxes.)
    struct EdgeInput {
        std::uint32_t body_a, body_b;
        PathGroup group;
        bool touching, bounces;
    };

    /// The contacts and the arrays indexed alike, read-only: the step's solver, the islands
    /// and the hash read them; only this class adds, moves and removes their entries.
    const LargeArray<Contact>& contacts() const { return contacts_; }
    const memory::vector<EdgeInput>& edge_inputs() const { return edge_inputs_; }
    const LargeArray<ContactImpulses>& warm_impulses() const { return warm_impulses_; }
    /// Each contact's impulses summed over the last step (its hit, its push).
    const LargeArray<ContactImpulses>& total_impulses() const { return total_impulses_; }
    /// The impulse records as the step's solver writes them (WideContactSolver::store), the one
    /// writer from outside: the accumulated impulses and the step's totals, per contact.
    struct ImpulseRecords {
        std::span<ContactImpulses> warm, totals;
    };
    ImpulseRecords impulse_records() { return {warm_impulses_, total_impulses_}; }
    /// \srs{DD46} Per contact, indexed alike, once a step has had surface motion (use_rolling;
    /// empty before): the rolling resistance's accumulated angular impulse (N m s), the next
    /// step's warm start. A world without surface motion neither keeps nor moves it.
    const LargeArray<double>& rolling_impulses() const { return rolling_impulses_; }
    std::span<double> rolling_records() { return rolling_impulses_; }
    /// From now on keeps a rolling impulse per contact (0 for the contacts there are).
    void use_rolling() {
        if (!rolling_on_) {
            rolling_impulses_.resize(contacts_.size());
            rolling_on_ = true;
        }
    }
    /// The contacts that began and stopped touching in the last step, in the order found.
    const memory::vector<ContactEvent>& begin_events() const { return begin_events_; }
    const memory::vector<ContactEvent>& end_events() const { return end_events_; }
    /// A step's events start empty (and a refused step reports none).
    void clear_events() {
        begin_events_.clear();
        end_events_.clear();
    }
    /// The user's filter, asked for each new pair the rules admit (empty: none).
    std::function<bool(ShapeId, ShapeId)> custom_filter;
    /// The user's filter's answer for shapes a and b (true when there is none). An exception
    /// it throws counts as a refusal and the first is kept, so that a step asking it is still
    /// a whole step; the step then rethrows it (rethrow_filter_error).
    bool custom_admits(ShapeId a, ShapeId b) const;
    /// Rethrows, and forgets, the first exception the user's filter threw since the last call
    /// or forget_filter_error; nothing when it threw none.
    void rethrow_filter_error();
    void forget_filter_error() { filter_error_ = nullptr; }
    /// Whether the rules and the filters let shapes sa and sb collide (DD27): not two shapes of
    /// one body, two immovable bodies or bodies a joint keeps apart, no sensor (sensors have
    /// no contacts: SensorOverlaps), and admitted by the filters and the user's filter.
    bool should_collide(const BodyStore& bodies, const ShapeStore& shapes, const JointStore& joints,
                        std::uint32_t sa, std::uint32_t sb) const;

    std::uint32_t size() const { return std::uint32_t(contacts_.size()); }

    /// New contacts for the pairs the broad phase found since the last step (creation order),
    /// except between two shapes of one body, two immovable bodies, or bodies a joint keeps
    /// from colliding.
    void find_new(const BodyStore& bodies, ShapeStore& shapes, const JointStore& joints);
    /// \srs{R7} Narrow phase for every contact; contacts whose fat boxes separated are
    /// destroyed. With sleeping on, a contact between bodies that do not move this step (asleep
    /// or static) is kept as it is: neither has moved since it was last updated. With more
    /// than one worker the contacts are updated in parallel blocks; the results, the events and
    /// their order are those of one thread, bit for bit. A touching contact whose bodies have
    /// moved less than `reuse_distance` (m) against each other since its manifold was computed
    /// keeps that manifold, its separations brought up to date (manifold_reuse.hpp; 0: never).
    /// (`reuse_distance`: StepContext::def's manifold_reuse_distance; the speculative
    /// distance is its speculative_distance.)
    void update(BodyStore& bodies, const ShapeStore& shapes, const StepContext& step);
    /// Every body asleep: every contact stands as it is, its edge input included (a new one
    /// gets its contact's, edge_inputs_for_new).
    void keep_all();
    /// Destroys every contact of shape s (its end events and wakes included).
    void destroy_of_shape(std::uint32_t s, BodyStore& bodies, const ShapeStore& shapes);
    /// Destroys every contact between bodies a and b (a joint now keeps them apart).
    void destroy_between(std::uint32_t a, std::uint32_t b, BodyStore& bodies,
                         const ShapeStore& shapes);
    /// Destroys the contacts of shape s that its filter (changed) no longer admits; the pairs
    /// it now admits are found by the next step (its proxy is marked moved by the caller).
    void refilter(std::uint32_t s, BodyStore& bodies, const ShapeStore& shapes,
                  const JointStore& joints);
    /// Wakes every body touching body i: what keeps them up may have gone (a static body does
    /// not move in a step, so its contacts with sleeping bodies are not updated).
    void wake_touching(std::uint32_t i, BodyStore& bodies) const;

    /// A manifold as the solver takes it, before preparation: bodies, normal, materials,
    /// anchors, separations and the impulses to warm start from.
    void unprepared_constraint(ContactConstraint& cc, const GraphEdge& edge,
                               std::uint32_t contact) const;

    /// The touching pairs after the last step; built when first asked for after a step or a
    /// destruction: most steps of a game never read it, and copying every contact out each
    /// step cost a few percent of a pile's step.
    const memory::vector<ContactInfo>& report(const BodyStore& bodies, const ShapeStore& shapes);
    void report_stale() { infos_stale_ = true; }

    /// Feeds the contacts to the state hash (World::state_hash): each contact's shapes,
    /// manifold points and warm-start impulses, and with manifold reuse on (`reuse`) the
    /// poses its manifold was computed at.
    void hash(StateHasher& hs, bool reuse) const;

    // --- snapshot (World::snapshot, World::restore; dynamics/snapshot_io.hpp) ---
    /// Writes every contact in storage order with its parallel arrays (edge input, warm-start
    /// and total impulses, manifold basis), the last step's events and the pairs a bad_alloc
    /// left pending. The user's filter is not data: it is not written.
    void write(SnapshotWriter& out) const;
    /// Reads what write wrote into this empty manager (`shapes` and `bodies` already read) and
    /// rebuilds the index by shape pair; throws SnapshotError for a contact whose shapes are
    /// not two live shapes (in order, once) of the bodies it names, or a manifold of more than
    /// two points.
    void read(SnapshotReader& in, const BodyStore& bodies, const ShapeStore& shapes);
    // --- events ---
    /// Whether the begin and end events of the pair of shapes sa and sb are reported: both
    /// shapes allow them (ShapeDef::enable_contact_events).
    static bool reports_events(const ShapeStore& shapes, std::uint32_t sa, std::uint32_t sb);
    /// Whether the pre-solve callback is asked about the pair of shapes sa and sb (their
    /// contact, or the continuous pass's stop): either shape allows it
    /// (ShapeDef::enable_pre_solve).
    static bool asks_pre_solve(const ShapeStore& shapes, std::uint32_t sa, std::uint32_t sb);
    // --- shape_control ---
    /// Shape s's material changed: its contacts take the new combined friction and restitution
    /// now (the manifolds and impulses are kept).
    void refresh_materials(std::uint32_t s, const ShapeStore& shapes);
    /// Gives shape s the material m (validated by the caller) and its contacts the values
    /// mixed from it (refresh_materials), all or nothing: a mixing function's refusal restores
    /// the shape's material and throws.
    void rematerial(std::uint32_t s, ShapeStore& shapes, const Material& m);

    // --- contact_hooks ---
    /// The user's pre-solve callback (World::set_pre_solve; empty: none).
    PreSolveFunction pre_solve;
    /// Whether the continuous pass (DD29) may stop a body where its shape `moving` comes
    /// within reach of shape `fixed`: the pre-solve callback's answer about that pair, asked
    /// as about their contact (the shapes in a contact's order, the normal from shape_a into
    /// shape_b) with one point, `point`, at the separation `gap`; `normal` runs from `moving`
    /// towards `fixed`. Asked only with a callback set and a shape that allows it
    /// (asks_pre_solve), before the caller measures the point. An exception of the callback is
    /// kept, as pre_solved keeps it, and the pair counts as solved: the body is stopped. A
    /// one-way platform's rule thus also lets a fast body through.
    bool admits_impact(const BodyStore& bodies, const ShapeStore& shapes, std::uint32_t moving,
                       std::uint32_t fixed, Vec2d normal, Vec2d point, double gap) const;
    /// The user's mixing functions (World::set_friction_mixing, set_restitution_mixing; empty:
    /// DD42's default rules).
    MaterialMixFunction friction_mixing, restitution_mixing;
    /// A contact's friction and restitution.
    struct Mixed {
        double friction = 0.0, restitution = 0.0;
    };
    /// \srs{DD42} The friction and restitution of a contact between shapes sa and sb, by the
    /// given functions (empty: DD42's defaults). Throws ValidationError naming the function
    /// ("friction_mixing", "restitution_mixing") for a value that is not a friction (finite,
    /// >= 0: DCX_friction) or a restitution ([0, 1]: DCI_CR); what a function throws passes.
    static Mixed mix(const ShapeStore& shapes, std::uint32_t sa, std::uint32_t sb,
                     const MaterialMixFunction& friction, const MaterialMixFunction& restitution);
    /// Every contact's materials mixed again by new mixing functions, all or none: each is
    /// computed (and checked, mix) before the first is written, so a refusal changes nothing.
    /// The functions are then kept; the bodies of a touching contact whose value changed are
    /// woken.
    void remix(const ShapeStore& shapes, BodyStore& bodies, MaterialMixFunction friction,
               MaterialMixFunction restitution);
    // --- definitions (WorldDef::enable_warm_starting) ---
    /// Zeroes every contact's accumulated impulses, so that the step's solve starts from none
    /// (warm starting off).
    void forget_warm_starts();

  private:
    /// Contact i, touching after its narrow phase (`r`), handed to the pre-solve callback: a
    /// refusal empties its manifold for this step (not touching). Returns what the narrow
    /// phase then found. An exception of the callback is kept (filter_error_) and the contact
    /// is solved.
    std::uint8_t pre_solved(std::uint32_t i, std::uint8_t r, const BodyStore& bodies,
                            const ShapeStore& shapes);
    memory::vector<Mixed> remixed_; ///< remix's values, all computed before any is written
    /// The edge inputs of the contacts find_new added, each its contact's: a step keeps a pair
    /// whose bodies are asleep without a narrow phase, and still reads its edge input.
    void edge_inputs_for_new();

    /// Tests fill the arrays of their own contacts (tests/support).
    friend struct ContactManagerAccess;

    LargeArray<Contact> contacts_;
    memory::vector<EdgeInput> edge_inputs_;
    /// Per contact, indexed alike: the accumulated impulses (warm start) and the last step's
    /// totals (contact report).
    LargeArray<ContactImpulses> warm_impulses_, total_impulses_;
    /// Per contact, indexed alike: the poses its manifold was computed at (manifold reuse).
    LargeArray<ManifoldBasis> bases_;
    /// Per contact, indexed alike while rolling_on_ (use_rolling).
    LargeArray<double> rolling_impulses_;
    bool rolling_on_ = false;
    memory::vector<ContactEvent> begin_events_, end_events_;

    void destroy(std::uint32_t i, BodyStore& bodies, const ShapeStore& shapes);
    /// update's parallel form: the contacts' own work in blocks of `block`, then the rest in
    /// contact order.
    void update_in_blocks(BodyStore& bodies, const ShapeStore& shapes, bool sleeping,
                          double speculative_distance, double reuse_distance,
                          const StepTasks& tasks, std::uint32_t block);
    /// A contact began or stopped touching: its event, and with sleeping its bodies woken.
    void touch_changed(const Contact& c, BodyStore& bodies, const ShapeStore& shapes,
                       bool sleeping);

    /// The first exception of the user's filter (custom_admits), of the pre-solve callback or
    /// of a mixing function (a bad value included), for the step to rethrow.
    mutable std::exception_ptr filter_error_;

    PairMap index_; ///< contact by Contact::key of its shapes
    // Per-step scratch, kept to avoid allocation in steady state.
    memory::vector<std::pair<std::uint32_t, std::uint32_t>> new_pairs_;
    /// new_pairs_[pending_begin_, pending_end_): pairs a bad_alloc in find_new left unexamined.
    std::size_t pending_begin_ = 0, pending_end_ = 0;
    memory::vector<std::uint32_t> doomed_;
    memory::vector<std::uint8_t> outcomes_; ///< per contact: update_in_blocks's first pass
    memory::vector<ContactInfo> infos_;
    bool infos_stale_ = true;
};

} // namespace tamias2d
