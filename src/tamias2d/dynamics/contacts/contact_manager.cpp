#include "tamias2d/dynamics/contacts/contact_manager.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "tamias2d/collision/narrow_phase.hpp"
#include "tamias2d/dynamics/body_store.hpp"
#include "tamias2d/dynamics/joints/joint_store.hpp"
#include "tamias2d/dynamics/shape_store.hpp"
#include "tamias2d/dynamics/snapshot_io.hpp"
#include "tamias2d/dynamics/state_hasher.hpp"
#include "tamias2d/dynamics/step_context.hpp"
#include "tamias2d/errors.hpp"
#include "tamias2d/math/prefetch.hpp"
#include "tamias2d/memory/allocator.hpp"
#include "tamias2d/model/dd27_collision_filter.hpp"
#include "tamias2d/model/dd42_material_mixing.hpp"
#include "tamias2d/parallel/step_tasks.hpp"
#include "tamias2d/units/quantities.hpp"

namespace tamias2d {

namespace u = tamias2d::units;

/// DD27's rule on two shapes' filters.
bool admits(const Filter& a, const Filter& b) {
    return model::dd27::should_collide({a.category_bits, a.mask_bits, a.group_index},
                                       {b.category_bits, b.mask_bits, b.group_index});
}

namespace {

/// What the colouring needs of a contact (EdgeInput).
ContactManager::EdgeInput edge_input(const Contact& c) {
    // (The separations only matter with two points: read for one, or none, they would fetch
    // the point lines of a pair that is apart.)
    const int n = c.manifold.count;
    const PathGroup group =
        n == 2 ? path_group(n, c.manifold.points[0].separation, c.manifold.points[1].separation)
               : path_group(n, 0.0, 0.0);
    return {c.body_a, c.body_b, group, c.touching, c.restitution > 0.0};
}

} // namespace

void ContactManager::destroy(std::uint32_t i, BodyStore& bodies, const ShapeStore& shapes) {
    infos_stale_ = true; // a destroyed body's or shape's contacts leave the report at once
    Contact& c = contacts_[i];
    if (c.touching) {
        bodies.wake(c.body_a); // what held the other up, or pushed it, is gone
        bodies.wake(c.body_b);
        if (reports_events(shapes, c.shape_a, c.shape_b))
            end_events_.push_back({shapes.id(c.shape_a), shapes.id(c.shape_b),
                                   bodies.id(shapes.shapes[c.shape_a].body),
                                   bodies.id(shapes.shapes[c.shape_b].body)});
    }
    index_.erase(Contact::key(c.shape_a, c.shape_b));
    const std::uint32_t last = std::uint32_t(contacts_.size() - 1);
    if (i != last) {
        contacts_[i] = contacts_[last];
        warm_impulses_[i] = warm_impulses_[last];
        total_impulses_[i] = total_impulses_[last];
        bases_[i] = bases_[last];
        // (A step that bad_alloc stopped before its narrow phase leaves the contacts find_new
        // added without an edge input.)
        if (last < edge_inputs_.size())
            edge_inputs_[i] = edge_inputs_[last];
        else if (i < edge_inputs_.size())
            edge_inputs_[i] = edge_input(contacts_[i]);
        if (rolling_on_)
            rolling_impulses_[i] = rolling_impulses_[last];
        index_.assign(Contact::key(contacts_[i].shape_a, contacts_[i].shape_b), i);
    }
    contacts_.pop_back();
    warm_impulses_.pop_back();
    total_impulses_.pop_back();
    bases_.pop_back();
    if (edge_inputs_.size() > contacts_.size())
        edge_inputs_.pop_back();
    if (rolling_on_)
        rolling_impulses_.pop_back();
}

void ContactManager::destroy_of_shape(std::uint32_t s, BodyStore& bodies,
                                      const ShapeStore& shapes) {
    for (std::uint32_t i = std::uint32_t(contacts_.size()); i-- > 0;) {
        if (contacts_[i].shape_a == s || contacts_[i].shape_b == s)
            destroy(i, bodies, shapes);
    }
}

void ContactManager::wake_touching(std::uint32_t i, BodyStore& bodies) const {
    for (const Contact& c : contacts_) {
        if (c.touching && (c.body_a == i || c.body_b == i)) {
            bodies.wake(c.body_a);
            bodies.wake(c.body_b);
        }
    }
}

void ContactManager::destroy_between(std::uint32_t a, std::uint32_t b, BodyStore& bodies,
                                     const ShapeStore& shapes) {
    for (std::uint32_t i = std::uint32_t(contacts_.size()); i-- > 0;) {
        const Contact& c = contacts_[i];
        if ((c.body_a == a && c.body_b == b) || (c.body_a == b && c.body_b == a))
            destroy(i, bodies, shapes);
    }
}

bool ContactManager::should_collide(const BodyStore& bodies, const ShapeStore& shapes,
                                    const JointStore& joints, std::uint32_t sa,
                                    std::uint32_t sb) const {
    const std::uint32_t ia = shapes.shapes[sa].body, ib = shapes.shapes[sb].body;
    const Body& a = bodies.bodies[ia];
    const Body& b = bodies.bodies[ib];
    if (ia == ib)
        return false;
    if (a.type != BodyType::dynamic && b.type != BodyType::dynamic)
        return false;
    if (bodies.disabled(ia) || bodies.disabled(ib)) // (World::set_enabled)
        return false;
    if (joints.live() != 0 && joints.filters(ia, ib))
        return false;
    const ShapeDef& da = shapes.defs[sa];
    const ShapeDef& db = shapes.defs[sb];
    if (da.is_sensor || db.is_sensor)
        return false;
    return admits(da.filter, db.filter) && custom_admits(shapes.id(sa), shapes.id(sb));
}

bool ContactManager::custom_admits(ShapeId a, ShapeId b) const {
    if (!custom_filter)
        return true;
    try {
        return custom_filter(a, b);
    } catch (...) {
        // Unwinding from here would leave the step half done (bodies moved, pairs the broad
        // phase has reported and forgotten never made contacts): refuse the pair, finish.
        if (!filter_error_)
            filter_error_ = std::current_exception();
        return false;
    }
}

void ContactManager::rethrow_filter_error() {
    if (filter_error_)
        std::rethrow_exception(std::exchange(filter_error_, nullptr));
}

void ContactManager::refilter(std::uint32_t s, BodyStore& bodies, const ShapeStore& shapes,
                              const JointStore& joints) {
    // Every answer first, then the destructions: a filter that throws changes nothing.
    forget_filter_error();
    doomed_.clear();
    for (std::uint32_t i = std::uint32_t(contacts_.size()); i-- > 0;) {
        const Contact& c = contacts_[i];
        if ((c.shape_a == s || c.shape_b == s) &&
            !should_collide(bodies, shapes, joints, c.shape_a, c.shape_b))
            doomed_.push_back(i);
    }
    rethrow_filter_error();
    for (const std::uint32_t i : doomed_) // descending: each swap-removal moves a kept one
        destroy(i, bodies, shapes);
}

void ContactManager::find_new(const BodyStore& bodies, ShapeStore& shapes,
                              const JointStore& joints) {
    // Pairs a bad_alloc left unexamined in the last call first (the broad phase has forgotten
    // their moves and would not report them again): those whose shapes still exist and whose
    // fat boxes still overlap, merged with the new ones in the broad phase's sorted order.
    std::size_t kept = 0;
    for (std::size_t i = pending_begin_; i < pending_end_; ++i) {
        const Shape& a = shapes.shapes[new_pairs_[i].first];
        const Shape& b = shapes.shapes[new_pairs_[i].second];
        if (a.alive() && b.alive() && overlaps(a.fat_box, b.fat_box))
            new_pairs_[kept++] = new_pairs_[i];
    }
    new_pairs_.resize(kept);
    pending_begin_ = 0;
    pending_end_ = kept;
    shapes.broad_phase.update_pairs(new_pairs_);
    if (kept > 0) {
        const auto middle = new_pairs_.begin() + static_cast<std::ptrdiff_t>(kept);
        std::inplace_merge(new_pairs_.begin(), middle, new_pairs_.end());
        new_pairs_.erase(std::unique(new_pairs_.begin(), new_pairs_.end()), new_pairs_.end());
    }
    pending_end_ = new_pairs_.size();
    // Most pairs the broad phase reports are contacts already (rain_16k: 78 %), so the index
    // is asked first, its slots eight pairs ahead: one line per pair, where the filter's shapes
    // and bodies are four scattered lines.
    constexpr std::size_t ahead = 8;
    for (std::size_t i = 0; i < new_pairs_.size(); ++i) {
        if (i + ahead < new_pairs_.size())
            index_.prefetch(
                Contact::key(new_pairs_[i + ahead].first, new_pairs_[i + ahead].second));
        pending_begin_ = i; // until this pair is done: a bad_alloc below leaves it pending
        const auto [ua, ub] = new_pairs_[i];
        const std::uint32_t sa = std::min(ua, ub), sb = std::max(ua, ub);
        const std::uint64_t key = Contact::key(sa, sb);
        if (index_.contains(key) || !should_collide(bodies, shapes, joints, sa, sb))
            continue;
        Contact c;
        c.shape_a = sa;
        c.shape_b = sb;
        c.body_a = shapes.shapes[sa].body;
        c.body_b = shapes.shapes[sb].body;
        try { // \srs{DD42}
            const Mixed m = mix(shapes, sa, sb, friction_mixing, restitution_mixing);
            c.friction = m.friction;
            c.restitution = m.restitution;
        } catch (...) {
            // As a filter's exception: the pair is refused, the step finishes and rethrows.
            if (!filter_error_)
                filter_error_ = std::current_exception();
            continue;
        }
        // All the memory first, so that a bad_alloc leaves the parallel arrays and the index
        // agreeing.
        contacts_.reserve_more(1);
        warm_impulses_.reserve_more(1);
        total_impulses_.reserve_more(1);
        bases_.reserve_more(1);
        if (rolling_on_)
            rolling_impulses_.reserve_more(1);
        index_.insert(key, std::uint32_t(contacts_.size()));
        contacts_.push_back(c);
        warm_impulses_.emplace_back();
        total_impulses_.emplace_back();
        bases_.emplace_back();
        if (rolling_on_)
            rolling_impulses_.emplace_back();
    }
    pending_begin_ = pending_end_ = 0;
}

namespace {

/// What the narrow phase found for one contact.
enum class Narrowed : std::uint8_t {
    kept,      ///< not updated: both bodies asleep or static (sleeping on)
    separated, ///< the fat boxes no longer overlap: the contact is to be destroyed
    same,      ///< updated; touching as before
    changed    ///< updated; began or stopped touching (an event, and with sleeping a wake)
};

/// \srs{R7} One contact's narrow phase: its manifold, its warm-start impulses, its basis and
/// its edge input, all its own (so contacts may be updated on different threads).
inline Narrowed narrow_contact(Contact& c, ContactImpulses& warm, ManifoldBasis& basis,
                               ContactManager::EdgeInput& edge, const Shape& sa, const Shape& sb,
                               double speculative_distance, double reuse_distance) {
    if (!overlaps(sa.fat_box, sb.fat_box))
        return Narrowed::separated;
    // A touching manifold whose bodies have barely moved against each other is kept, with the
    // same points and so the same warm start (manifold_reuse.hpp).
    if (reuse_distance > 0.0 && c.manifold.count > 0 &&
        reuse_manifold(c.manifold, basis, sa.body_xf.q, sb.body_xf.q, sa.body_center,
                       sb.body_center, reuse_distance)) {
        edge = edge_input(c);
        return Narrowed::same;
    }
    const CollideInput in{sa.body_xf, sa.body_center, sb.body_xf, sb.body_center,
                          speculative_distance};
    // Warm starting needs only the old points' ids and impulses: the manifold itself is
    // rewritten in place (building a new one and copying it in cost a fifth of this loop).
    // Only the points in use are read: a pair that stays apart reads the first line only.
    const int old_count = c.manifold.count;
    std::uint32_t old_id[2] = {};
    double old_n[2] = {}, old_t[2] = {};
    for (int k = 0; k < old_count; ++k) {
        old_id[k] = c.manifold.points[k].id.key();
        old_n[k] = warm.normal[k];
        old_t[k] = warm.tangent[k];
    }
    collide(sa.collider, sb.collider, in, c.manifold, &c.hint);
    // \srs{IM7} Warm starting: a point keeps its impulses when the same features touch
    // again, and starts from none otherwise.
    // (Chosen in registers, then stored: zeroing first made GCC call memset twice.)
    for (int j = 0; j < c.manifold.count; ++j) {
        double normal = 0.0, tangent = 0.0;
        for (int k = 0; k < old_count; ++k) {
            if (old_id[k] == c.manifold.points[j].id.key()) {
                normal = old_n[k];
                tangent = old_t[k];
            }
        }
        warm.normal[j] = normal;
        warm.tangent[j] = tangent;
    }
    if (reuse_distance > 0.0)
        record_basis(basis, c.manifold, sa.body_xf.q, sb.body_xf.q, sa.body_center, sb.body_center);
    const bool was = c.touching;
    c.touching = c.manifold.count > 0;
    edge = edge_input(c);
    return c.touching != was ? Narrowed::changed : Narrowed::same;
}

/// Asks for the lines of a contact's shapes that its narrow phase reads first.
inline void prefetch_shapes(const Contact& c, const LargeArray<Shape>& shape) {
    for (const Shape* s : {&shape[c.shape_a], &shape[c.shape_b]}) {
        prefetch(&s->fat_box);
        prefetch(&s->body_xf);
        prefetch(&s->collider.pairs[0]);
        prefetch(&s->collider.pairs[1]);
    }
}

} // namespace

void ContactManager::edge_inputs_for_new() {
    for (std::size_t i = edge_inputs_.size(); i < contacts_.size(); ++i)
        edge_inputs_.push_back(edge_input(contacts_[i]));
}

void ContactManager::keep_all() {
    edge_inputs_for_new();
}

void ContactManager::update(BodyStore& bodies, const ShapeStore& shapes, const StepContext& step) {
    const bool sleeping = step.sleeping;
    const double speculative_distance = step.def.speculative_distance;
    const double reuse_distance = step.def.manifold_reuse_distance;
    const StepTasks& tasks = step.tasks;
    doomed_.clear();
    const auto count = std::uint32_t(contacts_.size()); // the loop adds and removes none
    edge_inputs_for_new();
    constexpr std::uint32_t block = 128; // contacts: ~5 us of work
    if (tasks.parallel() && count > block) {
        update_in_blocks(bodies, shapes, sleeping, speculative_distance, reuse_distance, tasks,
                         block);
    } else {
        const auto& shape = shapes.shapes;
        constexpr std::uint32_t ahead = 6; // contacts: the shapes' lines arrive before use
        for (std::uint32_t i = 0; i < count; ++i) {
            if (i + ahead < count) {
                const Contact& next = contacts_[i + ahead];
                // (A contact kept as it is, below, reads no shape.)
                if (!sleeping || bodies.active(next.body_a) || bodies.active(next.body_b))
                    prefetch_shapes(next, shape);
            }
            Contact& c = contacts_[i];
            if (sleeping && !bodies.active(c.body_a) && !bodies.active(c.body_b))
                continue; // its edge input stands too, from its last update
            Narrowed r =
                narrow_contact(c, warm_impulses_[i], bases_[i], edge_inputs_[i], shape[c.shape_a],
                               shape[c.shape_b], speculative_distance, reuse_distance);
            if (pre_solve && r != Narrowed::separated && c.touching &&
                asks_pre_solve(shapes, c.shape_a, c.shape_b))
                r = Narrowed(pre_solved(i, std::uint8_t(r), bodies, shapes));
            if (r == Narrowed::separated)
                doomed_.push_back(i);
            else if (r == Narrowed::changed)
                touch_changed(c, bodies, shapes, sleeping);
        }
    }
    // Descending, so swap-removal never moves a contact that is still to be removed.
    for (auto it = doomed_.rbegin(); it != doomed_.rend(); ++it)
        destroy(*it, bodies, shapes); // moves the last contact into the gap
}

void ContactManager::touch_changed(const Contact& c, BodyStore& bodies, const ShapeStore& shapes,
                                   bool sleeping) {
    if (sleeping) { // a body met, or left, another: both islands wake
        bodies.wake(c.body_a);
        bodies.wake(c.body_b);
    }
    if (!reports_events(shapes, c.shape_a, c.shape_b))
        return;
    (c.touching ? begin_events_ : end_events_)
        .push_back({shapes.id(c.shape_a), shapes.id(c.shape_b),
                    bodies.id(shapes.shapes[c.shape_a].body),
                    bodies.id(shapes.shapes[c.shape_b].body)});
}

// The serial loop's results and order, in two passes: the contacts' own updates in parallel
// blocks, then in contact order what depends on order (the doomed list, the events, the wakes).
// A wake in the serial loop can make a later contact of a sleeping body due for update: the
// second pass updates such a contact then, from the same inputs (the shapes do not change in
// between), so the same contacts are updated, to the same bits, as by the serial loop.
void ContactManager::update_in_blocks(BodyStore& bodies, const ShapeStore& shapes, bool sleeping,
                                      double speculative_distance, double reuse_distance,
                                      const StepTasks& tasks, std::uint32_t block) {
    const auto& shape = shapes.shapes;
    const auto count = std::uint32_t(contacts_.size());
    if (outcomes_.size() < count)
        outcomes_.resize(count); // only while the scene grows
    auto run = [&](int first, int last) {
        const std::uint32_t begin = std::uint32_t(first) * block;
        const std::uint32_t end = std::min(count, std::uint32_t(last) * block);
        constexpr std::uint32_t ahead = 6;
        for (std::uint32_t i = begin; i < end; ++i) {
            if (i + ahead < end) {
                const Contact& next = contacts_[i + ahead];
                if (!sleeping || bodies.active(next.body_a) || bodies.active(next.body_b))
                    prefetch_shapes(next, shape);
            }
            Contact& c = contacts_[i];
            if (sleeping && !bodies.active(c.body_a) && !bodies.active(c.body_b)) {
                outcomes_[i] = std::uint8_t(Narrowed::kept);
                continue;
            }
            outcomes_[i] = std::uint8_t(
                narrow_contact(c, warm_impulses_[i], bases_[i], edge_inputs_[i], shape[c.shape_a],
                               shape[c.shape_b], speculative_distance, reuse_distance));
        }
    };
    tasks.for_each_block(blocks_of(count, block), run);
    for (std::uint32_t i = 0; i < count; ++i) {
        auto r = Narrowed(outcomes_[i]);
        Contact& c = contacts_[i];
        if (r == Narrowed::kept) {
            if (!bodies.active(c.body_a) && !bodies.active(c.body_b))
                continue;
            r = narrow_contact(c, warm_impulses_[i], bases_[i], edge_inputs_[i], shape[c.shape_a],
                               shape[c.shape_b], speculative_distance, reuse_distance);
        }
        if (pre_solve && r != Narrowed::separated && c.touching &&
            asks_pre_solve(shapes, c.shape_a, c.shape_b))
            r = Narrowed(pre_solved(i, std::uint8_t(r), bodies, shapes));
        if (r == Narrowed::separated)
            doomed_.push_back(i);
        else if (r == Narrowed::changed)
            touch_changed(c, bodies, shapes, sleeping);
    }
}

void ContactManager::unprepared_constraint(ContactConstraint& cc, const GraphEdge& edge,
                                           std::uint32_t contact) const {
    const Contact& c = contacts_[contact];
    const ContactImpulses& warm = warm_impulses_[contact];
    cc.body_a = edge.body_a;
    cc.body_b = edge.body_b;
    cc.contact = contact;
    cc.normal = c.manifold.normal;
    cc.friction = c.friction;
    cc.restitution = c.restitution;
    cc.count = c.manifold.count;
    for (int j = 0; j < cc.count; ++j) {
        const ManifoldPoint& mp = c.manifold.points[j];
        ContactConstraintPoint& cp = cc.points[j];
        cp.r_a = mp.anchor_a;
        cp.r_b = mp.anchor_b;
        cp.base_separation = mp.separation;
        cp.normal_impulse = warm.normal[j];
        cp.tangent_impulse = warm.tangent[j];
    }
}

const memory::vector<ContactInfo>& ContactManager::report(const BodyStore& bodies,
                                                          const ShapeStore& shapes) {
    if (!infos_stale_)
        return infos_;
    infos_stale_ = false;
    infos_.clear();
    for (std::size_t i = 0; i < contacts_.size(); ++i) {
        const Contact& c = contacts_[i];
        if (!c.touching)
            continue;
        const ContactImpulses& total = total_impulses_[i];
        ContactInfo ci;
        ci.shape_a = shapes.id(c.shape_a);
        ci.shape_b = shapes.id(c.shape_b);
        ci.body_a = bodies.id(shapes.shapes[c.shape_a].body);
        ci.body_b = bodies.id(shapes.shapes[c.shape_b].body);
        ci.normal = c.manifold.normal;
        ci.point_count = c.manifold.count;
        for (int j = 0; j < c.manifold.count; ++j) {
            ci.points[j] = {c.manifold.points[j].point, c.manifold.points[j].separation,
                            total.normal[j], total.tangent[j]};
        }
        infos_.push_back(ci);
    }
    return infos_;
}

bool ContactManager::asks_pre_solve(const ShapeStore& shapes, std::uint32_t sa, std::uint32_t sb) {
    return shapes.defs[sa].enable_pre_solve || shapes.defs[sb].enable_pre_solve;
}

bool ContactManager::reports_events(const ShapeStore& shapes, std::uint32_t sa, std::uint32_t sb) {
    return shapes.defs[sa].enable_contact_events && shapes.defs[sb].enable_contact_events;
}

void ContactManager::hash(StateHasher& hs, bool reuse) const {
    hs(std::uint64_t(size()));
    for (std::size_t i = 0; i < size(); ++i) {
        const Contact& c = contacts_[i];
        hs(std::uint64_t(c.shape_a) << 32 | c.shape_b);
        hs(std::uint64_t(c.manifold.count));
        for (int j = 0; j < c.manifold.count; ++j) {
            hs(c.manifold.points[j].point);
            hs(c.manifold.points[j].separation);
            hs(warm_impulses_[i].normal[j]);
            hs(warm_impulses_[i].tangent[j]);
        }
        if (rolling_on_) // (DD46; a world without surface motion hashes as it always did)
            hs(rolling_impulses_[i]);
        if (reuse && c.manifold.count > 0) {
            // What a reused manifold is computed from (manifold_reuse.hpp).
            const ManifoldBasis& b = bases_[i];
            for (const double x : {b.q_a.c, b.q_a.s, b.q_b.c, b.q_b.s})
                hs(x);
            hs(b.b_in_a);
            for (int j = 0; j < c.manifold.count; ++j) {
                hs(b.separation[j]);
                hs(b.on_a[j]);
            }
        }
    }
}

// --- snapshot ---

namespace {

/// Every field of a contact and of its entries in the parallel arrays, in the snapshot's order
/// (the writer and the reader both call it): the one place a field added to them is added to
/// snapshots.
template <class IO, class C, class W, class B>
void contact_fields(IO& io, C& c, W& warm, W& total, B& basis) {
    io("shape_a", c.shape_a);
    io("shape_b", c.shape_b);
    io("body_a", c.body_a);
    io("body_b", c.body_b);
    io("friction", c.friction);
    io("restitution", c.restitution);
    io("hint.face", c.hint.face);
    io("hint.on_b", c.hint.on_b);
    io("touching", c.touching);
    io("manifold.normal", c.manifold.normal);
    io("manifold.count", c.manifold.count);
    for (auto& p : c.manifold.points) {
        io("point", p.point);
        io("anchor_a", p.anchor_a);
        io("anchor_b", p.anchor_b);
        io("separation", p.separation);
        io("id.index_a", p.id.index_a);
        io("id.type_a", p.id.type_a);
        io("id.index_b", p.id.index_b);
        io("id.type_b", p.id.type_b);
    }
    for (int k = 0; k < 2; ++k) {
        io("warm.normal", warm.normal[k]);
        io("warm.tangent", warm.tangent[k]);
        io("total.normal", total.normal[k]);
        io("total.tangent", total.tangent[k]);
    }
    io("basis.q_a", basis.q_a);
    io("basis.q_b", basis.q_b);
    io("basis.b_in_a", basis.b_in_a);
    for (int k = 0; k < 2; ++k) {
        io("basis.separation", basis.separation[k]);
        io("basis.on_a", basis.on_a[k]);
    }
    io("basis.arm_a", basis.arm_a);
    io("basis.arm_b", basis.arm_b);
}

template <class IO, class E> void edge_input_fields(IO& io, E& e) {
    io("body_a", e.body_a);
    io("body_b", e.body_b);
    io.enumeration("group", e.group, PathGroup::point_by_point);
    io("touching", e.touching);
    io("bounces", e.bounces);
}

template <class IO, class E> void event_fields(IO& io, E& e) {
    io.handle("shape_a", e.shape_a);
    io.handle("shape_b", e.shape_b);
    io.handle("body_a", e.body_a);
    io.handle("body_b", e.body_b);
}

} // namespace

void ContactManager::write(SnapshotWriter& out) const {
    out.section("CONT");
    out.count("contacts", size());
    for (std::uint32_t i = 0; i < size(); ++i)
        contact_fields(out, contacts_[i], warm_impulses_[i], total_impulses_[i], bases_[i]);
    out.count("edge_inputs", edge_inputs_.size());
    for (const EdgeInput& e : edge_inputs_)
        edge_input_fields(out, e);
    for (const auto* events : {&begin_events_, &end_events_}) {
        out.count("events", events->size());
        for (const ContactEvent& e : *events)
            event_fields(out, e);
    }
    out.count("pending_pairs", pending_end_ - pending_begin_);
    for (std::size_t k = pending_begin_; k < pending_end_; ++k) {
        out("pending.first", new_pairs_[k].first);
        out("pending.second", new_pairs_[k].second);
    }
    out("rolling", rolling_on_); // DD46
    if (rolling_on_)
        for (std::uint32_t i = 0; i < size(); ++i)
            out("rolling_impulse", rolling_impulses_[i]);
}

void ContactManager::read(SnapshotReader& in, const BodyStore& bodies, const ShapeStore& shapes) {
    in.section("CONT");
    const std::uint32_t ns = std::uint32_t(shapes.shapes.size());
    const std::size_t n = in.count("contacts", 300, null_index - 1);
    contacts_.resize(n);
    warm_impulses_.resize(n);
    total_impulses_.resize(n);
    bases_.resize(n);
    for (std::uint32_t i = 0; i < n; ++i) {
        in.in("contacts", i);
        const std::size_t at = in.offset();
        Contact& c = contacts_[i];
        c = Contact{};
        contact_fields(in, c, warm_impulses_[i], total_impulses_[i], bases_[i]);
        const bool shapes_ok =
            c.shape_a < c.shape_b && c.shape_b < ns && shapes.shapes[c.shape_a].alive() &&
            shapes.shapes[c.shape_b].alive() && shapes.shapes[c.shape_a].body == c.body_a &&
            shapes.shapes[c.shape_b].body == c.body_b;
        in.require(shapes_ok && c.body_a < bodies.size() && c.body_b < bodies.size(), "shape_a",
                   "must be two live shapes, shape_a < shape_b, of the bodies named", at);
        in.require(c.manifold.count >= 0 && c.manifold.count <= 2, "manifold.count",
                   "must be in [0, 2]", at);
        const std::uint64_t key = Contact::key(c.shape_a, c.shape_b);
        in.require(!index_.contains(key), "shape_a", "must name a pair of no other contact", at);
        index_.insert(key, i);
    }
    in.in(nullptr);
    const std::size_t edges = in.count("edge_inputs", 11, n);
    edge_inputs_.resize(edges);
    for (std::size_t k = 0; k < edges; ++k) {
        in.in("edge_inputs", k);
        const std::size_t at = in.offset();
        EdgeInput& e = edge_inputs_[k];
        edge_input_fields(in, e);
        // Every world holds its contacts' own (edge_input), and a step reads a sleeping pair's
        // without a narrow phase: its bodies name solver slots.
        const EdgeInput own = edge_input(contacts_[k]);
        in.require(e.body_a == own.body_a, "body_a", "must be its contact's body_a", at);
        in.require(e.body_b == own.body_b, "body_b", "must be its contact's body_b", at);
        in.require(e.group == own.group, "group",
                   "must be the path group of its contact's manifold", at);
        in.require(e.touching == own.touching, "touching", "must be its contact's touching", at);
        in.require(e.bounces == own.bounces, "bounces",
                   "must be whether its contact's restitution is > 0", at);
    }
    for (auto* events : {&begin_events_, &end_events_}) {
        const std::size_t m = in.count("events", 32);
        events->resize(m);
        for (std::size_t k = 0; k < m; ++k) {
            in.in("contact_events", k);
            event_fields(in, (*events)[k]);
        }
    }
    in.in(nullptr);
    const std::size_t pending = in.count("pending_pairs", 8);
    new_pairs_.resize(pending);
    for (auto& [a, b] : new_pairs_) {
        in.index("pending.first", a, ns);
        in.index("pending.second", b, ns);
    }
    pending_begin_ = 0;
    pending_end_ = pending;
    in("rolling", rolling_on_); // DD46
    rolling_impulses_.resize(rolling_on_ ? n : 0);
    for (std::size_t i = 0; i < rolling_impulses_.size(); ++i)
        in("rolling_impulse", rolling_impulses_[i]);
    infos_stale_ = true;
}

// --- shape_control ---

void ContactManager::refresh_materials(std::uint32_t s, const ShapeStore& shapes) {
    // Every value first (a mixing function may refuse one), then the writes.
    remixed_.clear();
    for (std::uint32_t i = 0; i < contacts_.size(); ++i) {
        const Contact& c = contacts_[i];
        if (c.shape_a == s || c.shape_b == s)
            remixed_.push_back(
                mix(shapes, c.shape_a, c.shape_b, friction_mixing, restitution_mixing));
    }
    std::size_t k = 0;
    for (std::uint32_t i = 0; i < contacts_.size(); ++i) {
        Contact& c = contacts_[i];
        if (c.shape_a != s && c.shape_b != s)
            continue;
        c.friction = remixed_[k].friction;
        c.restitution = remixed_[k].restitution;
        ++k;
        if (i < edge_inputs_.size())
            edge_inputs_[i].bounces = c.restitution > 0.0;
    }
    infos_stale_ = true;
}

void ContactManager::rematerial(std::uint32_t s, ShapeStore& shapes, const Material& m) {
    Material& stored = shapes.defs[s].material;
    const Material old = stored;
    stored = m;
    try {
        refresh_materials(s, shapes); // writes nothing when it throws
    } catch (...) {
        stored = old;
        throw;
    }
}

// --- contact_hooks ---

ContactManager::Mixed ContactManager::mix(const ShapeStore& shapes, std::uint32_t sa,
                                          std::uint32_t sb, const MaterialMixFunction& friction,
                                          const MaterialMixFunction& restitution) {
    namespace dd42 = model::dd42;
    using u::Dimensionless;
    const Material& ma = shapes.defs[sa].material;
    const Material& mb = shapes.defs[sb].material;
    Mixed m;
    m.friction = friction
                     ? friction(ma.friction, ma.user_material_id, mb.friction, mb.user_material_id)
                     : dd42::mixed_friction(u::from_value<Dimensionless>(ma.friction),
                                            u::from_value<Dimensionless>(mb.friction))
                           .value();
    if (!dd42::valid_friction(u::from_value<Dimensionless>(m.friction)))
        throw ValidationError("friction_mixing", m.friction, "must return a finite friction >= 0",
                              "DCX_friction");
    m.restitution =
        restitution
            ? restitution(ma.restitution, ma.user_material_id, mb.restitution, mb.user_material_id)
            : dd42::mixed_restitution(u::from_value<Dimensionless>(ma.restitution),
                                      u::from_value<Dimensionless>(mb.restitution))
                  .value();
    if (!dd42::valid_restitution(u::from_value<Dimensionless>(m.restitution)))
        throw ValidationError("restitution_mixing", m.restitution,
                              "must return a restitution in [0, 1]", "DCI_CR");
    return m;
}

void ContactManager::remix(const ShapeStore& shapes, BodyStore& bodies,
                           MaterialMixFunction friction, MaterialMixFunction restitution) {
    remixed_.clear();
    remixed_.reserve(contacts_.size());
    for (std::uint32_t i = 0; i < contacts_.size(); ++i)
        remixed_.push_back(
            mix(shapes, contacts_[i].shape_a, contacts_[i].shape_b, friction, restitution));
    friction_mixing = std::move(friction);
    restitution_mixing = std::move(restitution);
    for (std::uint32_t i = 0; i < contacts_.size(); ++i) {
        Contact& c = contacts_[i];
        const Mixed& m = remixed_[i];
        if (c.friction == m.friction && c.restitution == m.restitution)
            continue; // (the same bits: nothing changes, nothing wakes)
        c.friction = m.friction;
        c.restitution = m.restitution;
        if (i < edge_inputs_.size())
            edge_inputs_[i].bounces = c.restitution > 0.0;
        if (c.touching) {
            bodies.wake(c.body_a);
            bodies.wake(c.body_b);
        }
    }
    infos_stale_ = true;
}

std::uint8_t ContactManager::pre_solved(std::uint32_t i, std::uint8_t r, const BodyStore& bodies,
                                        const ShapeStore& shapes) {
    Contact& c = contacts_[i];
    PreSolveContact pc;
    pc.shape_a = shapes.id(c.shape_a);
    pc.shape_b = shapes.id(c.shape_b);
    pc.body_a = bodies.id(c.body_a);
    pc.body_b = bodies.id(c.body_b);
    pc.normal = c.manifold.normal;
    pc.point_count = c.manifold.count;
    for (int j = 0; j < c.manifold.count; ++j)
        pc.points[j] = {c.manifold.points[j].point, c.manifold.points[j].separation};
    bool solved = true;
    try {
        solved = pre_solve(pc);
    } catch (...) {
        // As a filter's exception: the step finishes (this contact solved) and rethrows.
        if (!filter_error_)
            filter_error_ = std::current_exception();
    }
    if (solved)
        return r;
    // Off for this step: no points, not touching (the next narrow phase computes it afresh,
    // with no warm start: no point keeps an id).
    const bool was = Narrowed(r) == Narrowed::changed ? false : true;
    c.manifold.count = 0;
    c.touching = false;
    edge_inputs_[i] = edge_input(c);
    return std::uint8_t(was ? Narrowed::changed : Narrowed::same);
}

bool ContactManager::admits_impact(const BodyStore& bodies, const ShapeStore& shapes,
                                   std::uint32_t moving, std::uint32_t fixed, Vec2d normal,
                                   Vec2d point, double gap) const {
    // The order a contact of the pair has (find_new: the lower shape index first).
    const bool moving_first = moving < fixed;
    const std::uint32_t sa = moving_first ? moving : fixed, sb = moving_first ? fixed : moving;
    PreSolveContact pc;
    pc.shape_a = shapes.id(sa);
    pc.shape_b = shapes.id(sb);
    pc.body_a = bodies.id(shapes.shapes[sa].body);
    pc.body_b = bodies.id(shapes.shapes[sb].body);
    pc.normal = moving_first ? normal : -normal;
    pc.point_count = 1;
    pc.points[0] = {point, gap};
    try {
        return pre_solve(pc);
    } catch (...) {
        if (!filter_error_)
            filter_error_ = std::current_exception();
        return true;
    }
}

// --- definitions ---

void ContactManager::forget_warm_starts() {
    for (std::size_t i = 0; i < warm_impulses_.size(); ++i)
        warm_impulses_[i] = ContactImpulses{};
    for (std::size_t i = 0; i < rolling_impulses_.size(); ++i)
        rolling_impulses_[i] = 0.0;
}

} // namespace tamias2d
