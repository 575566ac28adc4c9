#include "tamias2d/dynamics/joints/joint_store.hpp"

#include <algorithm>
#include <string>
#include <utility>

#include "tamias2d/dynamics/body_store.hpp"
#include "tamias2d/dynamics/model_bridge.hpp"
#include "tamias2d/dynamics/shape_store.hpp"
#include "tamias2d/dynamics/state_hasher.hpp"
#include "tamias2d/errors.hpp"
#include "tamias2d/joint_kind.hpp"
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

void validate_levers(const BodyStore& bodies, const Joint& j, const std::string& at) {
    if (j.type == JointType::filter)
        return; // no anchor, no lever
    const auto [field_a, field_b] = anchor_fields(j.type);
    for (const bool side_a : {true, false}) {
        const std::uint32_t i = side_a ? j.body_a : j.body_b;
        const Body& b = bodies.bodies[i];
        const Vec2d r = (side_a ? j.local_anchor_a : j.local_anchor_b) - b.local_center;
        if (joint_lever_fits(r, b.inv_mass, b.inv_inertia))
            continue; // the field's name is made only for the message
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
    if (by_body_.size() <= top)
        by_body_.resize(top + 1);
    by_body_[joint.body_a].push_back(i);
    by_body_[joint.body_b].push_back(i);
    return i;
}

void JointStore::destroy(std::uint32_t i) {
    Joint& j = joints[i];
    for (const std::uint32_t body : {j.body_a, j.body_b}) {
        auto& list = by_body_[body];
        list.erase(std::find(list.begin(), list.end(), i));
    }
    j.step.solver_a = j.step.solver_b = 0;
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

const std::vector<std::uint32_t>& JointStore::of_body(std::uint32_t body) const {
    static const std::vector<std::uint32_t> none;
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
    for (std::uint32_t k = 0; k < joints.size(); ++k) {
        if (alive(k))
            validate_levers(bodies, joints[k], "joint[" + std::to_string(k) + "].");
    }
}

void JointStore::guard_step(const BodyStore& bodies, bool sleeping) {
    inv_h_before_ = inv_h;
    step_before_.resize(joints.size());
    for (std::size_t k = 0; k < joints.size(); ++k)
        step_before_[k] = joints[k].step;
    if (sleeping)
        sleep_before_.assign(bodies.sleep_states.begin(), bodies.sleep_states.end());
}

void JointStore::refuse_step(std::uint32_t i, BodyStore& bodies, bool sleeping) {
    for (std::size_t k = 0; k < step_before_.size(); ++k)
        joints[k].step = step_before_[k];
    inv_h = inv_h_before_;
    if (sleeping)
        std::copy(sleep_before_.begin(), sleep_before_.end(), bodies.sleep_states.begin());
    const std::string field = bodies.label(i) + ".velocity";
    throw SolverDivergence(field,
                           field + ": turned non-finite in the joints' solve; the step is refused, "
                                   "bodies, joints and clock as they were");
}

void JointStore::break_joints(BodyStore& bodies, ShapeStore& shapes) {
    for (std::uint32_t i = 0; i < joints.size(); ++i) {
        const Joint& j = joints[i];
        // \srs{DD36} The force's or the torque's threshold crossed.
        if (!alive(i) ||
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
        JointStepState& st = joints[k].step;
        st.linear_impulse = {};
        st.axial_impulse = st.motor_impulse = st.lower_impulse = st.upper_impulse = 0.0;
        st.spring_impulse = st.angular_impulse = st.perp_impulse = 0.0;
    }
}

} // namespace tamias2d
