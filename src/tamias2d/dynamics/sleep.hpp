// Sleeping (WorldDef::enable_sleep): islands of touching bodies, the test for a body at rest,
// and each body's sleep state. An island is a connected group of non-static bodies under the
// touching contacts; a static body joins none (boxes resting on one ground are as many islands
// as there are piles). An island sleeps as a whole once every body in it has been at rest for
// time_to_sleep, and wakes as a whole when any body in it wakes: a body resting on a sleeping
// one would otherwise fall through it, or be held up by a body that no longer moves with it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "tamias2d/math/vec2d.hpp"
#include "tamias2d/memory/allocator.hpp"

namespace tamias2d {

/// A body's sleep state (the world keeps one per body, indexed alike, so that the step's sweeps
/// over sleeping bodies read these 16 bytes and not the bodies).
struct SleepState {
    double sleep_time = 0.0; ///< s at rest without a break (0 while it may not sleep)
    bool awake = false;      ///< only a movable body is ever awake
    bool enabled = true;     ///< BodyDef::enable_sleep
    bool movable = false;    ///< alive, not static and not disabled
    bool disabled = false;   ///< World::set_enabled(false): the step skips it
};

/// At rest: no faster than both tolerances (m s^-1, rad s^-1).
inline bool at_rest(Vec2d v, double w, double linear_tolerance, double angular_tolerance) {
    return dot(v, v) <= linear_tolerance * linear_tolerance &&
           w * w <= angular_tolerance * angular_tolerance;
}

/// Connected components by union-find (path halving; the larger index joins the smaller, so
/// the components and their representatives depend only on the links, in any order).
class Islands {
  public:
    /// n elements, each its own island. Allocates only while n grows.
    void reset(std::size_t n);
    void unite(std::uint32_t a, std::uint32_t b);
    /// The island's representative: its smallest element.
    std::uint32_t find(std::uint32_t a);

  private:
    memory::vector<std::uint32_t> parent_;
};

} // namespace tamias2d
