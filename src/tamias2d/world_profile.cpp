// World::set_profiling, profile and counters: the step's stage times (StepProfiler, marked by
// World::step and World::Impl::solve) and the world's counts, taken when asked.
#include <cstdint>

#include "tamias2d/dynamics/sleep.hpp"
#include "tamias2d/world.hpp"
#include "tamias2d/world_impl.hpp"

namespace tamias2d {

void World::set_profiling(bool on) {
    StepProfiler& p = impl_->profiler;
    if (p.enabled && !on)
        p.last = {};
    p.enabled = on;
}

bool World::profiling() const {
    return impl_->profiler.enabled;
}

StepProfile World::profile() const {
    return impl_->profiler.last;
}

WorldCounters World::counters() const {
    const Impl& w = *impl_;
    WorldCounters c;
    c.bodies = w.bodies.count();
    c.joints = w.joints.live();
    const std::uint32_t n = w.bodies.size();
    for (std::uint32_t i = 0; i < n; ++i) {
        if (w.bodies.sleep_states[i].movable && w.bodies.sleep_states[i].awake)
            ++c.awake_bodies;
    }
    for (std::uint32_t s = 0; s < w.shapes.shapes.size(); ++s)
        c.shapes += w.shapes.shapes[s].alive() ? 1 : 0;
    c.pairs = w.contacts.size();
    // The islands as sleeping forms them (sleep.hpp): movable bodies under the touching
    // contacts and the joints.
    Islands islands;
    islands.reset(n);
    const auto movable = [&](std::uint32_t b) { return w.bodies.sleep_states[b].movable; };
    for (const Contact& k : w.contacts.contacts()) {
        if (!k.touching)
            continue;
        ++c.touching;
        c.contact_points += std::size_t(k.manifold.count);
        if (movable(k.body_a) && movable(k.body_b))
            islands.unite(k.body_a, k.body_b);
    }
    for (std::uint32_t i = 0; i < w.joints.joints.size(); ++i) {
        const Joint& j = w.joints.joints[i];
        if (w.joints.alive(i) && movable(j.body_a) && movable(j.body_b))
            islands.unite(j.body_a, j.body_b);
    }
    for (std::uint32_t i = 0; i < n; ++i) {
        if (movable(i) && islands.find(i) == i)
            ++c.islands;
    }
    c.solver_packs = w.solver.pack_count();
    return c;
}

} // namespace tamias2d
