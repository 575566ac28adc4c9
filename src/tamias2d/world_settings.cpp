// The World's settings changed between steps: each new WorldDef is checked as the constructor
// checks it (validate) before it replaces the old one, so a refused call changes nothing.
#include <cstddef>

#include "tamias2d/validation.hpp"
#include "tamias2d/world.hpp"
#include "tamias2d/world_impl.hpp"

namespace tamias2d {

namespace {

/// The world's settings with `change` made, checked whole, then taken.
template <class Change> void change_settings(World::Impl& w, Change&& change) {
    WorldDef d = w.def;
    change(d);
    validate(d);
    w.def = d;
}

} // namespace

void World::set_continuous(bool enabled) {
    impl_->def.enable_continuous = enabled;
}

void World::set_sleeping(bool enabled) {
    Impl& w = *impl_;
    if (w.def.enable_sleep == enabled)
        return;
    w.def.enable_sleep = enabled;
    if (!enabled) { // with sleeping off every movable body is awake
        for (std::uint32_t i = 0; i < w.bodies.size(); ++i)
            w.bodies.wake(i);
    }
}

void World::set_contact_tuning(double hertz, double damping_ratio, double push_max_velocity) {
    change_settings(*impl_, [&](WorldDef& d) {
        d.contact_hertz = hertz;
        d.contact_damping_ratio = damping_ratio;
        d.contact_push_max_velocity = push_max_velocity;
    });
}

void World::set_joint_tuning(double hertz, double damping_ratio) {
    change_settings(*impl_, [&](WorldDef& d) {
        d.joint_hertz = hertz;
        d.joint_damping_ratio = damping_ratio;
    });
}

void World::set_restitution_threshold(double speed) {
    change_settings(*impl_, [&](WorldDef& d) { d.restitution_threshold = speed; });
}

void World::set_maximum_linear_speed(double speed) {
    change_settings(*impl_, [&](WorldDef& d) { d.maximum_linear_speed = speed; });
}

void World::set_workers(int workers) {
    Impl& w = *impl_;
    if (w.def.workers == workers)
        return;
    WorldDef d = w.def;
    d.workers = workers;
    validate(d);
    w.tasks = StepTasks(workers, d.task_system); // (may throw: then nothing changed)
    w.def.workers = workers;
}

std::size_t World::awake_body_count() const {
    std::size_t n = 0;
    for (const SleepState& st : impl_->bodies.sleep_states)
        n += st.awake ? 1 : 0;
    return n;
}

} // namespace tamias2d
