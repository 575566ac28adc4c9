#include "tamias2d/dynamics/joints/joint_store.hpp"

#include <algorithm>
#include <limits>
#include <string>
#include <utility>

#include "tamias2d/dynamics/body_store.hpp"
#include "tamias2d/dynamics/bridge/joint_reactions.hpp"
#include "tamias2d/dynamics/bridge/joints.hpp"
#include "tamias2d/dynamics/shape_store.hpp"
#include "tamias2d/dynamics/snapshot_io.hpp"
#include "tamias2d/dynamics/state_hasher.hpp"
#include "tamias2d/errors.hpp"
#include "tamias2d/joint_kind.hpp"
#include "tamias2d/memory/allocator.hpp"
#include "tamias2d/validation.hpp"

namespace tamias2d {

namespace {

/// The input field that placed each anchor of a joint of this type (for DCX_joint's lever).
std::pair<const char*, const char*> anchor_fields(JointType type) {
    switch (type) {
    case JointType::distance:
        return {"anchor_a", "anchor_b"};
    case JointType::target:
        return {"target", "target"};
    case JointType::motor:
        return {"linear_offset", "body_b (its origin)"};
    default:
        return {"anchor", "anchor"};
    }
}

} // namespace

std::string joint_kind_name(JointType type) {
    // One name per kind, the public JointKind's (joint_kind.hpp lists the kinds in this order).
    return std::string(to_string(type)) + " joint";
}

double joint_angle_now(const Joint& j, const BodyStore& bodies) {
    return bridge::joint_angle(bodies.bodies[j.body_a].angle, bodies.bodies[j.body_b].angle,
                               j.reference_angle);
}

double joint_translation_now(const Joint& j, const BodyStore& bodies) {
    const Body& a = bodies.bodies[j.body_a];
    const Body& b = bodies.bodies[j.body_b];
    const Vec2d r_a = rotate(a.xf.q, j.local_anchor_a - a.local_center);
    const Vec2d r_b = rotate(b.xf.q, j.local_anchor_b - b.local_center);
    return bridge::line((b.center + r_b) - (a.center + r_a), r_a, r_b, rotate(a.xf.q, j.local_axis))
        .translation;
}

void validate_levers(const BodyStore& bodies, const Joint& j, std::uint32_t index) {
    if (j.type == JointType::filter)
        return; // no anchor, no lever
    const auto [field_a, field_b] = anchor_fields(j.type);
    for (const bool side_a : {true, false}) {
        const std::uint32_t i = side_a ? j.body_a : j.body_b;
        const Body& b = bodies.bodies[i];
        const Vec2d r = (side_a ? j.local_anchor_a : j.local_anchor_b) - b.local_center;
        if (joint_lever_fits(r, b.inv_mass, b.inv_inertia))
            continue; // the field's name is made only for the message
        const std::string at =
            index == null_index ? "joint." : "joint[" + std::to_string(index) + "].";
        validate_joint_lever(at + (side_a ? field_a : field_b) + " (on " + bodies.label(i) + ")", r,
                             b.inv_mass, b.inv_inertia);
    }
}

Joint& JointStore::get(JointId id) {
    slots.check(id);
    return joints[id.index];
}

Joint& JointStore::get(JointId id, std::initializer_list<JointType> kinds, const char* call,
                       const char* rule) {
    return get_of(id, std::span<const JointType>(kinds.begin(), kinds.size()), call, rule);
}

std::uint32_t JointStore::create(const Joint& joint) {
    const std::uint32_t i = slots.acquire();
    if (i == joints.size())
        joints.emplace_back();
    joints[i] = joint;
    const std::uint32_t top = std::max(joint.body_a, joint.body_b);
    if (by_body_.size() <= top) {
        std::size_t k = by_body_.size();
        by_body_.resize(top + 1);
        for (; k <= top && !spare_lists_.empty(); ++k) { // (reserve's lists: moved, no block)
            by_body_[k] = std::move(spare_lists_.back());
            spare_lists_.pop_back();
        }
    }
    by_body_[joint.body_a].push_back(i);
    by_body_[joint.body_b].push_back(i);
    note_breakable(joint);
    levers_checked_at_ = ~std::uint64_t{0};
    return i;
}

void JointStore::destroy(std::uint32_t i) {
    Joint& j = joints[i];
    for (const std::uint32_t body : {j.body_a, j.body_b}) {
        auto& list = by_body_[body];
        list.erase(std::find(list.begin(), list.end(), i));
    }
    slots.release(i);
}

void JointStore::unjoin(std::uint32_t i, BodyStore& bodies, ShapeStore& shapes) {
    const Joint& j = joints[i];
    bodies.wake(j.body_a);
    bodies.wake(j.body_b);
    if (!j.collide_connected)
        touch_pairs(j, bodies, shapes);
    destroy(i);
}

void JointStore::reserve(std::size_t n, std::size_t bodies) {
    slots.reserve(n);
    joints.reserve(n);
    broken.reserve(n);
    sleep_before_.reserve(bodies);
    // The lists as many bodies as are hinted will have, each with room for two joints, kept
    // aside until create() lengthens by_body_ (its length is what snapshots hold).
    by_body_.reserve(bodies);
    for (memory::vector<std::uint32_t>& list : by_body_)
        list.reserve(2);
    spare_lists_.reserve(bodies);
    while (by_body_.size() + spare_lists_.size() < bodies) {
        spare_lists_.emplace_back();
        spare_lists_.back().reserve(2);
    }
}

const memory::vector<std::uint32_t>& JointStore::of_body(std::uint32_t body) const {
    static const memory::vector<std::uint32_t> none;
    return body < by_body_.size() ? by_body_[body] : none;
}

bool JointStore::filters(std::uint32_t a, std::uint32_t b) const {
    for (const std::uint32_t i : of_body(a)) {
        const Joint& j = joints[i];
        if (!j.collide_connected &&
            ((j.body_a == a && j.body_b == b) || (j.body_a == b && j.body_b == a)))
            return true;
    }
    return false;
}

void JointStore::check_levers(const BodyStore& bodies) const {
    if (levers_checked_at_ == bodies.mass_epoch)
        return;
    for (std::uint32_t k = 0; k < joints.size(); ++k) {
        if (alive(k))
            validate_levers(bodies, joints[k], k);
    }
    levers_checked_at_ = bodies.mass_epoch;
}

void JointStore::guard_step(const BodyStore& bodies, bool sleeping) {
    inv_h_before_ = inv_h;
    if (sleeping)
        sleep_before_.assign(bodies.sleep_states.begin(), bodies.sleep_states.end());
}

void JointStore::refuse_step(std::uint32_t i, BodyStore& bodies, bool sleeping) {
    inv_h = inv_h_before_;
    if (sleeping)
        std::copy(sleep_before_.begin(), sleep_before_.end(), bodies.sleep_states.begin());
    const std::string field = bodies.label(i) + ".velocity";
    throw SolverDivergence(field,
                           field + ": turned non-finite in the joints' solve; the step is refused, "
                                   "bodies, joints and clock as they were");
}

namespace {

/// A break threshold that no reading exceeds (DD36: the joint never breaks).
constexpr double never = std::numeric_limits<double>::infinity();

} // namespace

void JointStore::note_breakable(const Joint& j) {
    breakable_ = breakable_ || j.break_force != never || j.break_torque != never;
}

void JointStore::break_joints(BodyStore& bodies, ShapeStore& shapes) {
    if (!breakable_)
        return;
    for (std::uint32_t i = 0; i < joints.size(); ++i) {
        const Joint& j = joints[i];
        // \srs{DD36} The force's or the torque's threshold crossed. (No reading can exceed an
        // infinite threshold: such a joint's reaction is not computed.)
        if (!alive(i) || (j.break_force == never && j.break_torque == never) ||
            !bridge::joint_breaks(
                bridge::reaction_force(length(reaction_impulse(j)), inv_h), j.break_force,
                bridge::reaction_torque(reaction_angular_impulse(j), inv_h), j.break_torque))
            continue;
        broken.push_back(id(i));
        unjoin(i, bodies, shapes);
    }
}

void JointStore::hash(StateHasher& hs) const {
    if (live() > 0) { // (so that worlds without joints hash as they always did)
        for (std::uint32_t i = 0; i < joints.size(); ++i) {
            const Joint& j = joints[i];
            hs(std::uint64_t(slots.generation(i)) << 1 | std::uint64_t(alive(i)));
            if (!alive(i))
                continue;
            hs(std::uint64_t(j.type));
            hs(std::uint64_t(j.body_a) << 32 | j.body_b);
            hs(j.local_anchor_a);
            hs(j.local_anchor_b);
            hs(j.step.linear_impulse);
            hs(j.length);
            hs(j.hertz);
            hs(j.damping_ratio);
            hs(j.step.axial_impulse);
            hs(j.target);
            hs(j.reference_angle);
            hs(std::uint64_t(j.enable_limit) << 1 | std::uint64_t(j.enable_motor));
            hs(j.lower_limit);
            hs(j.upper_limit);
            hs(j.motor_speed);
            hs(j.max_motor);
            hs(j.step.motor_impulse);
            hs(j.step.lower_impulse);
            hs(j.step.upper_impulse);
            hs(j.max_force);
            hs(j.local_axis);
            hs(std::uint64_t(j.enable_spring));
            hs(j.step.spring_impulse);
            hs(j.step.angular_impulse);
            hs(j.step.perp_impulse);
            hs(j.angular_hertz);
            hs(j.angular_damping_ratio);
            hs(j.max_torque);
            hs(j.correction_factor);
            hs(j.break_force);
            hs(std::uint64_t(j.collide_connected));
            hash_controls(hs, j);
        }
    }
}

// --- snapshot ---

namespace {

/// Every field of a joint, in the snapshot's order (the writer and the reader both call it): the
/// one place a field added to Joint or JointStepState is added to snapshots.
template <class IO, class J> void joint_fields(IO& io, J& j) {
    io.enumeration("type", j.type, JointType::filter);
    io("collide_connected", j.collide_connected);
    io("body_a", j.body_a);
    io("body_b", j.body_b);
    io("local_anchor_a", j.local_anchor_a);
    io("local_anchor_b", j.local_anchor_b);
    io("break_force", j.break_force);
    io("force_threshold", j.force_threshold);
    io("torque_threshold", j.torque_threshold);
    io("length", j.length);
    io("hertz", j.hertz);
    io("damping_ratio", j.damping_ratio);
    io("enable_spring", j.enable_spring);
    io("local_axis", j.local_axis);
    io("reference_angle", j.reference_angle);
    io("enable_limit", j.enable_limit);
    io("enable_motor", j.enable_motor);
    io("lower_limit", j.lower_limit);
    io("upper_limit", j.upper_limit);
    io("motor_speed", j.motor_speed);
    io("max_motor", j.max_motor);
    io("angular_hertz", j.angular_hertz);
    io("angular_damping_ratio", j.angular_damping_ratio);
    io("target", j.target);
    io("max_force", j.max_force);
    io("max_torque", j.max_torque);
    io("correction_factor", j.correction_factor);
    io("spring_target", j.spring_target);
    io("break_torque", j.break_torque);
    io("tuned", j.tuned);
    io("tuning_hertz", j.tuning_hertz);
    io("tuning_damping_ratio", j.tuning_damping_ratio);
    io.user_data("user_data", j.user_data);
    auto& st = j.step;
    io("step.linear_impulse", st.linear_impulse);
    io("step.axial_impulse", st.axial_impulse);
    io("step.axis", st.axis);
    io("step.motor_impulse", st.motor_impulse);
    io("step.lower_impulse", st.lower_impulse);
    io("step.upper_impulse", st.upper_impulse);
    io("step.spring_impulse", st.spring_impulse);
    io("step.angular_impulse", st.angular_impulse);
    io("step.perp_impulse", st.perp_impulse);
}

} // namespace

void JointStore::write(SnapshotWriter& out) const {
    out.section("JOIN");
    slots.write(out);
    for (const Joint& j : joints)
        joint_fields(out, j);
    out.count("by_body", by_body_.size());
    for (const auto& list : by_body_) {
        out.count("of_body", list.size());
        for (const std::uint32_t i : list)
            out.index("of_body", i, std::uint32_t(joints.size()));
    }
    out("inv_h", inv_h);
    out.count("broken", broken.size());
    for (const JointId& b : broken)
        out.handle("broken", b);
}

void JointStore::read(SnapshotReader& in, const BodyStore& bodies) {
    in.section("JOIN");
    in.in("joints");
    slots.read(in);
    const std::size_t n = slots.size();
    joints.resize(n);
    breakable_ = false;
    levers_checked_at_ = ~std::uint64_t{0};
    for (std::uint32_t i = 0; i < n; ++i) {
        in.in("joints", i);
        const std::size_t at = in.offset();
        Joint& j = joints[i];
        j = Joint{};
        joint_fields(in, j);
        if (!alive(i))
            continue;
        in.require(j.body_a < bodies.size() && j.body_b < bodies.size() && bodies.alive(j.body_a) &&
                       bodies.alive(j.body_b),
                   "body_a", "a live joint's bodies must live", at);
        // The bounds the solve clamps impulses to (DD22, DD23, DD26; DD21's force) are never
        // negative: a definition is refused otherwise, and a clamp's bounds must not cross.
        for (const auto& [field, value] : {std::pair{"max_motor", j.max_motor},
                                           {"max_torque", j.max_torque},
                                           {"max_force", j.max_force}})
            in.require(value >= 0.0, field, "must be >= 0 (it bounds an impulse)", at);
        note_breakable(j);
    }
    in.in(nullptr);
    // Each live joint once in its body_a's list and once in its body_b's (twice in one list
    // when they are the same body): destroy finds it there.
    memory::vector<std::uint8_t> seen(n, 0); // bit 0: under body_a, bit 1: under body_b
    const std::size_t lists = in.count("joints.by_body", 8, bodies.size());
    by_body_.resize(lists);
    for (std::uint32_t body = 0; body < lists; ++body) {
        in.in("joints.by_body", body);
        const std::size_t m = in.count("of_body", 4, 2 * n);
        by_body_[body].resize(m);
        for (std::uint32_t& i : by_body_[body]) {
            const std::size_t at = in.offset();
            in.index("of_body", i, std::uint32_t(n));
            const Joint& j = joints[i];
            if (alive(i) && j.body_a == body && !(seen[i] & 1))
                seen[i] |= 1;
            else if (alive(i) && j.body_b == body && !(seen[i] & 2))
                seen[i] |= 2;
            else
                in.fail_at(at, "of_body", "must list a live joint of this body, once");
        }
    }
    in.in(nullptr);
    for (std::uint32_t i = 0; i < n; ++i) {
        if (alive(i) && seen[i] != 3) // (message built only to fail)
            in.fail("joints.by_body",
                    "must list live joint " + decimal(std::uint64_t(i)) + " under both its bodies");
    }
    in("joints.inv_h", inv_h);
    const std::size_t nb = in.count("joints.broken", 8);
    broken.resize(nb);
    for (JointId& b : broken)
        in.handle("broken", b);
}

// --- joint_control ---

Joint& JointStore::get_of(JointId id, std::span<const JointType> kinds, const char* call,
                          const char* rule) {
    Joint& j = get(id);
    if (std::find(kinds.begin(), kinds.end(), j.type) == kinds.end())
        throw WrongKind(call, "joint[" + std::to_string(id.index) + "]", joint_kind_name(j.type),
                        rule);
    return j;
}

void JointStore::touch_pairs(const Joint& j, const BodyStore& bodies, ShapeStore& shapes) {
    const std::uint32_t body =
        bodies.bodies[j.body_b].type == BodyType::static_body ? j.body_a : j.body_b;
    for (std::uint32_t s = bodies.bodies[body].first_shape; s != null_index;
         s = shapes.shapes[s].next)
        shapes.broad_phase.touch_proxy(shapes.shapes[s].proxy);
}

void JointStore::hash_controls(StateHasher& hs, const Joint& j) {
    // Only when one differs from its default: joints never set so hash as they always did.
    if (j.spring_target == 0.0 && !j.tuned && j.break_torque == Joint{}.break_torque)
        return;
    hs(j.spring_target);
    hs(j.break_torque);
    hs(std::uint64_t(j.tuned));
    hs(j.tuning_hertz);
    hs(j.tuning_damping_ratio);
}

// --- run-time control ---

void JointStore::wake_joined(std::uint32_t i, BodyStore& bodies) const {
    for (const std::uint32_t k : of_body(i)) {
        bodies.wake(joints[k].body_a);
        bodies.wake(joints[k].body_b);
    }
}

void JointStore::clear_impulses(std::uint32_t i) {
    for (const std::uint32_t k : of_body(i)) {
        forget_impulses(joints[k].step);
    }
}

// --- definitions ---

void JointStore::forget_warm_starts() {
    for (Joint& j : joints)
        forget_impulses(j.step);
}

} // namespace tamias2d
