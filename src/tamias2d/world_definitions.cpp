// World::definitions: the definitions that build a world as it is now (io::scene_from_world);
// World::set_warm_starting: WorldDef::enable_warm_starting changed at run time.
#include <cmath>
#include <limits>
#include <vector>

#include "tamias2d/dynamics/joints/joint_creation.hpp"
#include "tamias2d/dynamics/joints/joint_store.hpp"
#include "tamias2d/memory/allocator.hpp"
#include "tamias2d/world.hpp"
#include "tamias2d/world_impl.hpp"

namespace tamias2d {

namespace {

/// The doubles within `ulps` steps of x, x first, then nearest first.
memory::vector<double> near(double x, int ulps) {
    memory::vector<double> out{x};
    double up = x, down = x;
    for (int k = 0; k < ulps; ++k) {
        up = std::nextafter(up, std::numeric_limits<double>::infinity());
        down = std::nextafter(down, -std::numeric_limits<double>::infinity());
        out.push_back(up);
        out.push_back(down);
    }
    return out;
}

/// The world point that is local point `la` of a body at `xa` (and `lb` of one at `xb`, when
/// given), bit for bit as joint creation computes the local points (inv_transform_point), if
/// one lies within 4 ulps per coordinate of transform_point(xa, la) (`exact` then true); that
/// point when none does.
Vec2d anchor_of(const Transform& xa, Vec2d la, const Transform* xb = nullptr, Vec2d lb = {},
                bool* exact = nullptr) {
    if (exact)
        *exact = true;
    const Vec2d w = transform_point(xa, la);
    for (const double x : near(w.x, 4))
        for (const double y : near(w.y, 4)) {
            const Vec2d c{x, y};
            const Vec2d ca = inv_transform_point(xa, c);
            if (ca.x != la.x || ca.y != la.y)
                continue;
            if (xb) {
                const Vec2d cb = inv_transform_point(*xb, c);
                if (cb.x != lb.x || cb.y != lb.y)
                    continue;
            }
            return c;
        }
    if (exact)
        *exact = false;
    return w;
}

/// The world-frame axis that gives a prismatic or wheel joint's local axis back bit for bit
/// (local_axis, as at creation) if one lies within 4 ulps; else the axis rotated to the world.
Vec2d axis_of(const Transform& xa, Vec2d local) {
    const Vec2d w = rotate(xa.q, local);
    for (const double x : near(w.x, 4))
        for (const double y : near(w.y, 4)) {
            const Vec2d c = inv_rotate(xa.q, normalize(Vec2d{x, y}));
            if (c.x == local.x && c.y == local.y)
                return {x, y};
        }
    return w;
}

/// A joint's limits and spring target measured from its angle or translation now (0 where a
/// definition made anew from the pose now puts them): a revolute joint's always, a prismatic or
/// wheel joint's when its anchors are no longer one point.
void shift_limits_to_now(Joint& j, const BodyStore& bodies, bool exact) {
    if (j.type == JointType::revolute) {
        const double angle = joint_angle_now(j, bodies); // (0 where it was made)
        j.lower_limit -= angle;
        j.upper_limit -= angle;
        j.spring_target -= angle;
    } else if (!exact && (j.type == JointType::prismatic || j.type == JointType::wheel)) {
        const double translation = joint_translation_now(j, bodies);
        j.lower_limit -= translation;
        j.upper_limit -= translation;
        j.spring_target -= translation;
    }
}

/// The fields every kind but the filter joint has (a target joint has no break force and no
/// break torque; distance joints no break torque).
template <class D> void common_fields(D& d, const Joint& j) {
    d.user_data = j.user_data;
    d.collide_connected = j.collide_connected;
    d.break_force = j.break_force;
    d.force_threshold = j.force_threshold;
    d.torque_threshold = j.torque_threshold;
    if constexpr (requires { d.spring_target; })
        d.spring_target = j.spring_target;
    if constexpr (requires { d.constraint_tuning; }) {
        if (j.tuned)
            d.constraint_tuning = ConstraintTuning{j.tuning_hertz, j.tuning_damping_ratio};
    }
}

/// The definition that makes joint `j` again where it is now. A joint whose bodies moved apart
/// from where it was made (its anchors no longer one point) is made anew with one anchor, its
/// angle and translation zero there: its limits are moved by the angle and translation it has
/// now, so that they stay where they were.
JointDefinition definition_of(Joint j, BodyId a, BodyId b, const BodyStore& bodies) {
    const Transform& xa = bodies.bodies[j.body_a].xf;
    const Transform& xb = bodies.bodies[j.body_b].xf;
    bool exact = true;
    const Vec2d anchor = anchor_of(xa, j.local_anchor_a, &xb, j.local_anchor_b, &exact);
    shift_limits_to_now(j, bodies, exact);
    const auto common = [&j](auto& d) { common_fields(d, j); };
    switch (j.type) {
    case JointType::revolute: {
        RevoluteJointDef d{.body_a = a, .body_b = b, .anchor = anchor};
        common(d);
        d.break_torque = j.break_torque;
        d.enable_limit = j.enable_limit;
        d.lower_angle = j.lower_limit;
        d.upper_angle = j.upper_limit;
        d.enable_motor = j.enable_motor;
        d.motor_speed = j.motor_speed;
        d.max_motor_torque = j.max_motor;
        d.enable_spring = j.enable_spring;
        d.hertz = j.hertz;
        d.damping_ratio = j.damping_ratio;
        return d;
    }
    case JointType::distance: {
        DistanceJointDef d{.body_a = a,
                           .body_b = b,
                           .anchor_a = anchor_of(xa, j.local_anchor_a),
                           .anchor_b = anchor_of(xb, j.local_anchor_b)};
        common(d);
        d.length = j.length;
        d.hertz = j.hertz;
        d.damping_ratio = j.damping_ratio;
        d.enable_limit = j.enable_limit;
        d.min_length = j.lower_limit;
        d.max_length = j.upper_limit;
        d.enable_motor = j.enable_motor;
        d.motor_speed = j.motor_speed;
        d.max_motor_force = j.max_motor;
        return d;
    }
    case JointType::target: {
        TargetJointDef d{b, j.target, j.hertz, j.damping_ratio, j.max_force};
        d.force_threshold = j.force_threshold;
        d.torque_threshold = j.torque_threshold;
        d.user_data = j.user_data;
        return d;
    }
    case JointType::prismatic: {
        PrismaticJointDef d{
            .body_a = a, .body_b = b, .anchor = anchor, .axis = axis_of(xa, j.local_axis)};
        common(d);
        d.break_torque = j.break_torque;
        d.enable_limit = j.enable_limit;
        d.lower_translation = j.lower_limit;
        d.upper_translation = j.upper_limit;
        d.enable_motor = j.enable_motor;
        d.motor_speed = j.motor_speed;
        d.max_motor_force = j.max_motor;
        d.enable_spring = j.enable_spring;
        d.hertz = j.hertz;
        d.damping_ratio = j.damping_ratio;
        return d;
    }
    case JointType::weld: {
        WeldJointDef d{.body_a = a, .body_b = b, .anchor = anchor};
        common(d);
        d.break_torque = j.break_torque;
        d.linear_hertz = j.hertz;
        d.linear_damping_ratio = j.damping_ratio;
        d.angular_hertz = j.angular_hertz;
        d.angular_damping_ratio = j.angular_damping_ratio;
        return d;
    }
    case JointType::wheel: {
        WheelJointDef d{
            .body_a = a, .body_b = b, .anchor = anchor, .axis = axis_of(xa, j.local_axis)};
        common(d);
        d.break_torque = j.break_torque;
        d.enable_spring = j.enable_spring;
        d.hertz = j.hertz;
        d.damping_ratio = j.damping_ratio;
        d.enable_limit = j.enable_limit;
        d.lower_translation = j.lower_limit;
        d.upper_translation = j.upper_limit;
        d.enable_motor = j.enable_motor;
        d.motor_speed = j.motor_speed;
        d.max_motor_torque = j.max_motor;
        return d;
    }
    case JointType::motor: {
        MotorJointDef d{.body_a = a, .body_b = b, .linear_offset = j.local_anchor_a};
        common(d);
        d.break_torque = j.break_torque;
        d.angular_offset = j.reference_angle;
        d.max_force = j.max_force;
        d.max_torque = j.max_torque;
        d.correction_factor = j.correction_factor;
        return d;
    }
    case JointType::filter:
        break;
    }
    FilterJointDef d{.body_a = a, .body_b = b};
    d.user_data = j.user_data;
    return d;
}

} // namespace

WorldDefinitions World::definitions() const {
    const Impl& w = *impl_;
    w.bodies.settle();
    WorldDefinitions out;
    out.world = w.def;
    for (std::uint32_t i = 0; i < w.bodies.size(); ++i) {
        if (!w.bodies.alive(i))
            continue;
        const Body& b = w.bodies.bodies[i];
        const BodySettings& set = w.bodies.settings[i];
        BodyDefinition d;
        d.id = w.bodies.id(i);
        d.def.type = b.type;
        d.def.position = b.xf.p;
        d.def.angle = b.angle;
        d.def.linear_velocity = b.v;
        d.def.angular_velocity = b.w;
        d.def.force = b.force;
        d.def.torque = b.torque;
        d.def.mass = set.mass_override;
        d.def.inertia = set.inertia_override;
        d.def.gravity_scale = b.gravity_scale;
        d.def.linear_damping = set.linear_damping;
        d.def.angular_damping = set.angular_damping;
        d.def.fixed_rotation = set.fixed_rotation;
        d.def.motion_locks = {set.lock_linear_x, set.lock_linear_y, set.fixed_rotation};
        d.def.sleep_threshold = set.sleep_threshold;
        d.def.enabled = !w.bodies.sleep_states[i].disabled;
        d.def.bullet = set.bullet;
        d.def.enable_sleep = w.bodies.sleep_states[i].enabled;
        d.def.awake = !w.def.enable_sleep || b.type == BodyType::static_body ||
                      w.bodies.sleep_states[i].awake;
        d.def.load = set.load;
        d.def.name = set.name;
        d.def.enable_move_events = w.events.move_events(i);
        d.def.user_data = set.user_data;
        for (std::uint32_t s = b.first_shape; s != null_index; s = w.shapes.shapes[s].next)
            d.shapes.push_back(w.shapes.defs[s]);
        out.bodies.push_back(std::move(d));
    }
    for (std::uint32_t i = 0; i < w.joints.joints.size(); ++i) {
        if (!w.joints.alive(i))
            continue;
        const Joint& j = w.joints.joints[i];
        out.joints.push_back(
            definition_of(j, w.bodies.id(j.body_a), w.bodies.id(j.body_b), w.bodies));
    }
    return out;
}

void World::set_warm_starting(bool enabled) {
    impl_->def.enable_warm_starting = enabled;
}

bool World::warm_starting() const {
    return impl_->def.enable_warm_starting;
}

} // namespace tamias2d
