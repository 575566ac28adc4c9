// Sleeping's two stages of a step (internal; the rules are in sleep.hpp): before the solver,
// the islands of this step's touching contacts, an island with an awake body waking whole;
// after it, each body's time at rest, and an island at rest long enough falling asleep. Run
// only with WorldDef::enable_sleep and some body awake.
#pragma once

#include <cstdint>
#include <vector>

#include "tamias2d/dynamics/sleep.hpp"
#include "tamias2d/dynamics/step_context.hpp"
#include "tamias2d/memory/allocator.hpp"

namespace tamias2d {

struct BodyStore;
class ContactManager;
class JointStore;

class IslandSleep {
  public:
    /// The islands of the touching contacts and the joints; an island with an awake body wakes
    /// whole (a body met a sleeping one, or was changed through the API).
    void wake_islands(BodyStore& bodies, const ContactManager& contacts, const JointStore& joints);
    /// After the step: each awake body's time at rest, and an island whose bodies have all
    /// been at rest for time_to_sleep falls asleep (velocities zero: they no longer move). A
    /// body that may not sleep, or carries a persistent load, is never at rest.
    void update_sleep(BodyStore& bodies, const StepContext& step);

  private:
    // Per island (at its representative): whether a body of it is awake, and its bodies'
    // shortest time at rest.
    Islands islands_;
    memory::vector<std::uint8_t> island_awake_;
    memory::vector<double> island_rest_;
};

} // namespace tamias2d
