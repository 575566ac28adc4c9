#include "tamias2d/dynamics/island_sleep.hpp"

#include <algorithm>
#include <limits>

#include "tamias2d/dynamics/body_store.hpp"
#include "tamias2d/dynamics/contacts/contact_manager.hpp"
#include "tamias2d/dynamics/joints/joint_store.hpp"

namespace tamias2d {

void IslandSleep::wake_islands(BodyStore& store, const ContactManager& contacts,
                               const JointStore& joints) {
    const std::uint32_t n = store.size();
    islands_.reset(n);
    for (const Contact& c : contacts.contacts()) {
        if (c.touching && store.sleep_states[c.body_a].movable &&
            store.sleep_states[c.body_b].movable)
            islands_.unite(c.body_a, c.body_b);
    }
    for (std::uint32_t k = 0; k < joints.joints.size(); ++k) {
        const Joint& j = joints.joints[k];
        if (joints.alive(k) && store.sleep_states[j.body_a].movable &&
            store.sleep_states[j.body_b].movable)
            islands_.unite(j.body_a, j.body_b);
    }
    island_awake_.assign(n, 0);
    for (std::uint32_t i = 0; i < n; ++i) {
        if (store.active(i))
            island_awake_[islands_.find(i)] = 1;
    }
    for (std::uint32_t i = 0; i < n; ++i) {
        if (store.sleep_states[i].movable && !store.active(i) && island_awake_[islands_.find(i)])
            store.wake(i);
    }
}

void IslandSleep::update_sleep(BodyStore& store, const StepContext& step) {
    const WorldDef& def = step.def;
    const double dt = step.dt;
    const std::uint32_t n = store.size();
    island_rest_.assign(n, std::numeric_limits<double>::infinity());
    for (std::uint32_t i = 0; i < n; ++i) {
        if (!store.active(i))
            continue;
        const Body& b = store.bodies[i];
        SleepState& st = store.sleep_states[i];
        const bool loaded =
            b.force.x != 0.0 || b.force.y != 0.0 || b.torque != 0.0 || bool(store.settings[i].load);
        const bool rest =
            st.enabled && !loaded &&
            at_rest(b.v, b.w,
                    store.settings[i].sleep_threshold.value_or(def.linear_sleep_tolerance),
                    def.angular_sleep_tolerance);
        st.sleep_time = rest ? st.sleep_time + dt : 0.0;
        double& island = island_rest_[islands_.find(i)];
        island = std::min(island, rest ? st.sleep_time : -1.0); // -1: not at rest now
    }
    for (std::uint32_t i = 0; i < n; ++i) {
        if (!store.active(i) || !(island_rest_[islands_.find(i)] >= def.time_to_sleep))
            continue;
        store.sleep_states[i].awake = false;
        store.sleep_states[i].sleep_time = 0.0;
        store.bodies[i].v = {};
        store.bodies[i].w = 0.0;
    }
}

} // namespace tamias2d
