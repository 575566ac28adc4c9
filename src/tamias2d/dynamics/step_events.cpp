#include "tamias2d/dynamics/step_events.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "tamias2d/dynamics/body_store.hpp"
#include "tamias2d/dynamics/bridge/joint_reactions.hpp"
#include "tamias2d/dynamics/bridge/point_impulse.hpp"
#include "tamias2d/dynamics/contacts/contact_manager.hpp"
#include "tamias2d/dynamics/joints/joint_store.hpp"
#include "tamias2d/dynamics/shape_store.hpp"
#include "tamias2d/dynamics/snapshot_io.hpp"
#include "tamias2d/dynamics/state_hasher.hpp"
#include "tamias2d/errors.hpp"
#include "tamias2d/memory/allocator.hpp"
#include "tamias2d/units/angle.hpp"
#include "tamias2d/validation.hpp"
#include "tamias2d/world_def.hpp"

namespace tamias2d {

double approach_speed(const ContactManager& contacts, std::uint32_t contact, int j,
                      const BodyStore& bodies) {
    const Contact& c = contacts.contacts()[contact];
    const ManifoldPoint& mp = c.manifold.points[j];
    const Vec2d n = c.manifold.normal;
    // DD11 along n (IM3's form): the velocity of B's point relative to A's; approaching < 0.
    return -bridge::relative_velocity(bodies.bodies[c.body_a], bodies.bodies[c.body_b],
                                      bridge::moment_arm(mp.anchor_a, n),
                                      bridge::moment_arm(mp.anchor_b, n), n);
}

void StepEvents::body_created(std::uint32_t i, const BodyDef& def) {
    if (move_flag_.size() <= i)
        move_flag_.resize(std::size_t(i) + 1, 0);
    move_flag_[i] = 0;
    set_move_events(i, def.enable_move_events);
}

void StepEvents::set_move_events(std::uint32_t body, bool on) {
    if (move_events(body) == on)
        return;
    move_flag_[body] = on ? 1 : 0;
    if (on)
        ++move_bodies_;
    else
        --move_bodies_;
}

void StepEvents::body_destroying(std::uint32_t i, const BodyStore& bodies, const ShapeStore& shapes,
                                 const JointStore& joints) {
    // Destroyed last first (World::destroy_body's order), so that the events list them so.
    const memory::vector<std::uint32_t>& of_body = joints.of_body(i);
    for (auto it = of_body.rbegin(); it != of_body.rend(); ++it) {
        const Joint& j = joints.joints[*it];
        joint_events.push_back(
            {joints.id(*it), JointEventKind::body_destroyed, bodies.id(j.body_a),
             bodies.id(j.body_b), bridge::reaction_force(reaction_impulse(j), joints.inv_h),
             bridge::reaction_torque(reaction_angular_impulse(j), joints.inv_h)});
    }
    for (std::uint32_t s = bodies.bodies[i].first_shape; s != null_index; s = shapes.shapes[s].next)
        shape_destroying(shapes.defs[s]);
    set_move_events(i, false);
}

void StepEvents::clear() {
    hits.clear();
    moves.clear();
    joint_events.clear();
    candidates_.clear();
    moved_known_ = false;
}

void StepEvents::before_solve(const BodyStore& bodies, const ShapeStore& shapes,
                              const ContactManager& contacts, double threshold) {
    if (hit_shapes_ == 0)
        return;
    for (std::uint32_t i = 0; i < contacts.size(); ++i) {
        const Contact& c = contacts.contacts()[i];
        if (!c.touching ||
            !(shapes.defs[c.shape_a].enable_hit_events || shapes.defs[c.shape_b].enable_hit_events))
            continue;
        if (!bodies.active(c.body_a) && !bodies.active(c.body_b))
            continue; // neither moves this step: no approach
        Candidate k{i, {0.0, 0.0}};
        bool any = false;
        for (int j = 0; j < c.manifold.count; ++j) {
            const double speed = approach_speed(contacts, i, j, bodies);
            if (speed > threshold) {
                k.speed[j] = speed;
                any = true;
            }
        }
        if (any)
            candidates_.push_back(k);
    }
}

void StepEvents::before_sleep(const BodyStore& bodies) {
    if (move_bodies_ == 0)
        return;
    moved_.resize(bodies.size());
    for (std::uint32_t i = 0; i < bodies.size(); ++i)
        moved_[i] = bodies.sleep_states[i].awake ? 1 : 0;
    moved_known_ = true;
}

void StepEvents::after_step(const BodyStore& bodies, const ShapeStore& shapes,
                            const ContactManager& contacts, const JointStore& joints,
                            bool sleeping) {
    // Hits: a candidate point counts if it pushed (a speculative point may approach fast and
    // not touch within the step); the fastest such point is the hit's.
    for (const Candidate& k : candidates_) {
        const Contact& c = contacts.contacts()[k.contact];
        const ContactImpulses& total = contacts.total_impulses()[k.contact];
        int best = -1;
        for (int j = 0; j < c.manifold.count; ++j) {
            if (k.speed[j] > 0.0 && total.normal[j] > 0.0 &&
                (best < 0 || k.speed[j] > k.speed[best]))
                best = j;
        }
        if (best < 0)
            continue;
        hits.push_back({shapes.id(c.shape_a), shapes.id(c.shape_b), bodies.id(c.body_a),
                        bodies.id(c.body_b), c.manifold.points[best].point, c.manifold.normal,
                        k.speed[best]});
    }
    // Moves: the bodies that were awake in the solve (with sleeping off, every movable one).
    if (move_bodies_ != 0 && (!sleeping || moved_known_)) {
        for (std::uint32_t i = 0; i < bodies.size(); ++i) {
            if (!move_events(i) || !bodies.alive(i))
                continue;
            const bool moved = sleeping ? moved_[i] != 0 : bodies.sleep_states[i].awake;
            if (!moved)
                continue;
            const Body& b = bodies.bodies[i];
            moves.push_back({bodies.id(i), b.xf.p, units::wrap_orientation(b.angle),
                             sleeping && !bodies.sleep_states[i].awake});
        }
    }
    // Joints: those that broke (in the order they broke), then those over a threshold.
    for (const JointId id : joints.broken) {
        const Joint& j = joints.joints[id.index]; // (its record stays until the slot is reused)
        joint_events.push_back(
            {id, JointEventKind::broke, bodies.id(j.body_a), bodies.id(j.body_b),
             bridge::reaction_force(reaction_impulse(j), joints.inv_h),
             bridge::reaction_torque(reaction_angular_impulse(j), joints.inv_h)});
    }
    if (joints.live() == 0 || !thresholds_used_)
        return;
    for (std::uint32_t i = 0; i < joints.joints.size(); ++i) {
        const Joint& j = joints.joints[i];
        if (!joints.alive(i) || (j.force_threshold == std::numeric_limits<double>::infinity() &&
                                 j.torque_threshold == std::numeric_limits<double>::infinity()))
            continue;
        const Vec2d force = bridge::reaction_force(reaction_impulse(j), joints.inv_h);
        const double torque = bridge::reaction_torque(reaction_angular_impulse(j), joints.inv_h);
        if (length(force) > j.force_threshold || std::abs(torque) > j.torque_threshold)
            joint_events.push_back({joints.id(i), JointEventKind::threshold_exceeded,
                                    bodies.id(j.body_a), bodies.id(j.body_b), force, torque});
    }
}

void StepEvents::hash(StateHasher& hs, const ShapeStore& shapes, const JointStore& joints,
                      double threshold) const {
    if (threshold != WorldDef{}.hit_event_threshold)
        hs(threshold);
    const ShapeDef none{};
    for (std::uint32_t i = 0; i < shapes.shapes.size(); ++i) {
        if (!shapes.shapes[i].alive())
            continue;
        const ShapeDef& d = shapes.defs[i];
        if (d.enable_contact_events != none.enable_contact_events ||
            d.enable_sensor_events != none.enable_sensor_events ||
            d.enable_hit_events != none.enable_hit_events)
            hs(std::uint64_t(i) << 3 | std::uint64_t(d.enable_contact_events) << 2 |
               std::uint64_t(d.enable_sensor_events) << 1 | std::uint64_t(d.enable_hit_events));
    }
    for (std::uint32_t i = 0; i < move_flag_.size(); ++i) {
        if (move_flag_[i] != 0)
            hs(std::uint64_t(i) << 1 | 1u);
    }
    for (std::uint32_t i = 0; i < joints.joints.size(); ++i) {
        const Joint& j = joints.joints[i];
        if (joints.alive(i) && (j.force_threshold != std::numeric_limits<double>::infinity() ||
                                j.torque_threshold != std::numeric_limits<double>::infinity())) {
            hs(std::uint64_t(i));
            hs(j.force_threshold);
            hs(j.torque_threshold);
        }
    }
}

// --- snapshot ---

namespace {

/// Every field of each event kind, in the snapshot's order (the writer and the reader both
/// call them): the one place a field added to an event is added to snapshots.
template <class IO, class E> void hit_fields(IO& io, E& e) {
    io.handle("shape_a", e.shape_a);
    io.handle("shape_b", e.shape_b);
    io.handle("body_a", e.body_a);
    io.handle("body_b", e.body_b);
    io("point", e.point);
    io("normal", e.normal);
    io("approach_speed", e.approach_speed);
}

template <class IO, class E> void move_fields(IO& io, E& e) {
    io.handle("body", e.body);
    io("origin", e.origin);
    io("angle", e.angle);
    io("fell_asleep", e.fell_asleep);
}

template <class IO, class E> void joint_event_fields(IO& io, E& e) {
    io.handle("joint", e.joint);
    io.enumeration("kind", e.kind, JointEventKind::body_destroyed);
    io.handle("body_a", e.body_a);
    io.handle("body_b", e.body_b);
    io("force", e.force);
    io("torque", e.torque);
}

} // namespace

void StepEvents::write(SnapshotWriter& out) const {
    out.section("EVNT");
    out.count("hits", hits.size());
    for (const ContactHitEvent& e : hits)
        hit_fields(out, e);
    out.count("moves", moves.size());
    for (const BodyMoveEvent& e : moves)
        move_fields(out, e);
    out.count("joint_events", joint_events.size());
    for (const JointEvent& e : joint_events)
        joint_event_fields(out, e);
    out.count("move_flags", move_flag_.size());
    for (const std::uint8_t f : move_flag_)
        out("move_flag", f != 0);
    out("thresholds_used", thresholds_used_);
}

void StepEvents::read(SnapshotReader& in, const BodyStore& bodies, const ShapeStore& shapes) {
    in.section("EVNT");
    hits.resize(in.count("hits", 72));
    for (std::size_t k = 0; k < hits.size(); ++k) {
        in.in("hits", k);
        hit_fields(in, hits[k]);
    }
    in.in(nullptr);
    moves.resize(in.count("moves", 33, bodies.size()));
    for (std::size_t k = 0; k < moves.size(); ++k) {
        in.in("moves", k);
        move_fields(in, moves[k]);
    }
    in.in(nullptr);
    joint_events.resize(in.count("joint_events", 49));
    for (std::size_t k = 0; k < joint_events.size(); ++k) {
        in.in("joint_events", k);
        joint_event_fields(in, joint_events[k]);
    }
    in.in(nullptr);
    // One flag per body slot, as body_created keeps them: a shorter list is no world's.
    const std::size_t flags_at = in.offset();
    move_flag_.resize(in.count("move_flags", 1, bodies.size()));
    in.require(move_flag_.size() == bodies.size(), "move_flags", "must be one per body slot",
               flags_at);
    move_bodies_ = 0;
    for (std::uint32_t i = 0; i < move_flag_.size(); ++i) {
        const std::size_t at = in.offset();
        bool on = false;
        in("move_flag", on);
        in.require(!on || bodies.alive(i), "move_flag", "must be off for a dead body", at);
        move_flag_[i] = on ? 1 : 0;
        move_bodies_ += on ? 1 : 0;
    }
    in("thresholds_used", thresholds_used_);
    hit_shapes_ = 0;
    for (std::uint32_t s = 0; s < shapes.shapes.size(); ++s)
        hit_shapes_ += shapes.slots.live(s) && shapes.defs[s].enable_hit_events ? 1 : 0;
    candidates_.clear();
    moved_.clear();
    moved_known_ = false;
}

} // namespace tamias2d
