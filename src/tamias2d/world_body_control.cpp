// The World's body control calls: a body's type, enabled state, gravity scale, bullet flag,
// motion locks, mass data and sleep threshold changed after creation. Each checks everything
// before it changes anything (or, where the check needs the change made, undoes it before it
// throws), and a value a body already has changes nothing.
#include <cstdint>
#include <string>

#include "tamias2d/errors.hpp"
#include "tamias2d/math/same_bits.hpp"
#include "tamias2d/validation.hpp"
#include "tamias2d/world.hpp"
#include "tamias2d/world_impl.hpp"

namespace tamias2d {

namespace {

using math::same_bits;
bool same(const std::optional<double>& a, const std::optional<double>& b) {
    return a.has_value() == b.has_value() && (!a || same_bits(*a, *b));
}
bool same(const std::optional<Vec2d>& a, const std::optional<Vec2d>& b) {
    return a.has_value() == b.has_value() &&
           (!a || (same_bits(a->x, b->x) && same_bits(a->y, b->y)));
}

/// \srs{DCX_joint} Runs `change` on body i's mass, then checks its joints' levers with the
/// new mass; if one no longer fits, the body is put back as it was and the ValidationError
/// goes to the caller: the world unchanged.
template <class Change> void change_mass(World::Impl& w, std::uint32_t i, Change&& change) {
    Body& b = w.bodies.bodies[i];
    const Body body_before = b;
    const BodySettings settings_before = w.bodies.settings[i];
    const SleepState sleep_before = w.bodies.sleep_states[i];
    change();
    try {
        for (const std::uint32_t k : w.joints.of_body(i))
            validate_levers(w.bodies, w.joints.joints[k], k);
    } catch (...) {
        b = body_before;
        w.bodies.settings[i] = settings_before;
        w.bodies.sleep_states[i] = sleep_before;
        w.shapes.sync_poses(b);
        throw;
    }
}

/// Body i's contacts removed, with their end events and their bodies woken.
void drop_contacts(World::Impl& w, const Body& b) {
    for (std::uint32_t s = b.first_shape; s != null_index; s = w.shapes.shapes[s].next)
        w.contacts.destroy_of_shape(s, w.bodies, w.shapes);
}

} // namespace

/// \srs{R2} A body's type changed at run time: its mass is the new type's (none for static
/// and kinematic bodies), and a static body does not move.
void World::set_body_type(BodyId id, BodyType type) {
    Impl& w = *impl_;
    Body& b = w.bodies.get(id);
    if (type != BodyType::static_body && type != BodyType::kinematic && type != BodyType::dynamic)
        throw ValidationError("type", double(static_cast<int>(type)),
                              "must be static, kinematic or dynamic", "R2");
    if (b.type == type)
        return;
    const std::uint32_t i = id.index;
    // The new type's mass, checked against the joints' levers before anything else changes.
    change_mass(w, i, [&] { w.bodies.change_type(i, type, w.shapes); });
    drop_contacts(w, b);
    w.shapes.refile_proxies(b);
    w.joints.clear_impulses(i);
    w.joints.wake_joined(i, w.bodies);
}

void World::set_enabled(BodyId id, bool enabled) {
    Impl& w = *impl_;
    const Body& b = w.bodies.get(id);
    const std::uint32_t i = id.index;
    if (enabled == !w.bodies.sleep_states[i].disabled)
        return;
    if (!enabled) {
        drop_contacts(w, b);
        w.bodies.set_disabled(i, true);
        w.joints.clear_impulses(i);
    } else {
        w.bodies.set_disabled(i, false);
        w.shapes.refile_proxies(b); // its pairs, at the next step
    }
    w.joints.wake_joined(i, w.bodies);
}
bool World::is_enabled(BodyId id) const {
    impl_->bodies.get(id); // handle check
    return !impl_->bodies.sleep_states[id.index].disabled;
}

void World::set_gravity_scale(BodyId id, double scale) {
    Body& b = impl_->bodies.get(id);
    require_within("gravity_scale", scale, supported::input_max, "");
    if (same_bits(b.gravity_scale, scale))
        return;
    b.gravity_scale = scale;
    impl_->bodies.wake(id.index);
}
double World::gravity_scale(BodyId id) const {
    return impl_->bodies.get(id).gravity_scale;
}

void World::set_bullet(BodyId id, bool bullet) {
    impl_->bodies.get(id); // handle check
    impl_->bodies.settings[id.index].bullet = bullet;
}
bool World::is_bullet(BodyId id) const {
    impl_->bodies.get(id); // handle check
    return impl_->bodies.settings[id.index].bullet;
}

/// \srs{DD39} Locks set at run time: a locked motion stops now and stays stopped.
void World::set_motion_locks(BodyId id, MotionLocks locks) {
    Impl& w = *impl_;
    w.bodies.get(id); // handle check
    if (locks == motion_locks(id))
        return;
    const std::uint32_t i = id.index;
    BodySettings& set = w.bodies.settings[i];
    if (locks.angular != set.fixed_rotation) {
        // The inverse moment of inertia follows the lock (update_mass), and a joint's lever is
        // judged by it.
        change_mass(w, i, [&] {
            set.fixed_rotation = locks.angular;
            w.bodies.update_mass_keeping_motion(i, w.shapes);
        });
    }
    w.bodies.set_linear_locks(i, locks.linear_x, locks.linear_y);
    w.bodies.wake(i);
}
MotionLocks World::motion_locks(BodyId id) const {
    impl_->bodies.get(id); // handle check
    const BodySettings& set = impl_->bodies.settings[id.index];
    return {set.lock_linear_x, set.lock_linear_y, set.fixed_rotation};
}
void World::set_fixed_rotation(BodyId id, bool fixed) {
    MotionLocks locks = motion_locks(id);
    locks.angular = fixed;
    set_motion_locks(id, locks);
}
bool World::fixed_rotation(BodyId id) const {
    return motion_locks(id).angular;
}

/// \srs{DD41} The mass data overridden at run time: the rigid motion kept.
void World::set_mass_data(BodyId id, const BodyMassData& data) {
    Impl& w = *impl_;
    const Body& b = w.bodies.get(id);
    if (b.type != BodyType::dynamic)
        throw WrongKind("set_mass_data", w.bodies.label(id.index),
                        std::string(to_string(b.type)) + " body",
                        "must be a dynamic body (a static or kinematic body has no mass, R2)");
    validate_mass("mass_data.mass", data.mass);
    validate_inertia("mass_data.inertia", data.inertia);
    require_within("mass_data.center", data.center, supported::input_max, "m");
    const std::uint32_t i = id.index;
    BodySettings& set = w.bodies.settings[i];
    if (same(set.mass_override, data.mass) && same(set.inertia_override, data.inertia) &&
        same(set.center_override, data.center))
        return;
    change_mass(w, i, [&] {
        set.mass_override = data.mass;
        set.inertia_override = data.inertia;
        set.center_override = data.center;
        w.bodies.update_mass_keeping_motion(i, w.shapes);
    });
    w.bodies.wake(i);
}
BodyMassData World::mass_data(BodyId id) const {
    const Body& b = impl_->bodies.get(id);
    return {b.mass, b.local_center, b.inertia};
}
void World::reset_mass_data(BodyId id) {
    Impl& w = *impl_;
    w.bodies.get(id); // handle check
    const std::uint32_t i = id.index;
    BodySettings& set = w.bodies.settings[i];
    if (!set.mass_override && !set.inertia_override && !set.center_override)
        return; // already the shapes' (update_mass keeps it so)
    change_mass(w, i, [&] {
        set.mass_override.reset();
        set.inertia_override.reset();
        set.center_override.reset();
        w.bodies.update_mass_keeping_motion(i, w.shapes);
    });
    w.bodies.wake(i);
}

void World::set_sleep_threshold(BodyId id, double speed) {
    Impl& w = *impl_;
    w.bodies.get(id); // handle check
    validate_sleep_threshold("sleep_threshold", speed);
    std::optional<double>& threshold = w.bodies.settings[id.index].sleep_threshold;
    if (same(threshold, speed))
        return;
    threshold = speed;
    w.bodies.wake(id.index);
}
double World::sleep_threshold(BodyId id) const {
    impl_->bodies.get(id); // handle check
    return impl_->bodies.settings[id.index].sleep_threshold.value_or(
        impl_->def.linear_sleep_tolerance);
}

void World::wake_touching(BodyId id) {
    impl_->bodies.get(id); // handle check
    impl_->contacts.wake_touching(id.index, impl_->bodies);
}

} // namespace tamias2d
