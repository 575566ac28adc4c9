// How the rain's boxes leave the container, followed after every step of a run, the same way for
// every engine (from the poses the engine reports): a box leaves when its centre first lies more
// than half a box beyond an inner wall face or below the floor. Over a wall: its centre was above
// the walls' top then (the container is open above, and a box thrown up by the impacts of the
// boxes landing after it may fall out over a wall: physics, and chaotic, as a small change to any
// setting shows; docs/performance.md). Through: below the top, or under the floor: it passed
// through a wall or the floor, which contacts must prevent. A pose that is not finite counts as
// through.
#pragma once

#include <cmath>
#include <vector>

#include "bench_engines.hpp"
#include "bench_scenes.hpp"

namespace tamias_bench {

struct RainExits {
    int through = 0, over = 0;
    int lost() const { return through + over; }
};

/// The boxes that have left so far; observe() after every step.
class RainExitWatch {
  public:
    explicit RainExitWatch(const SceneDesc& s) : left_(s.bodies.size(), 0) {}
    void observe(const SceneDesc& s, const Engine& e) {
        const double tol = 0.5 * s.box;
        for (std::size_t i = 0; i < s.bodies.size(); ++i) {
            if (!s.bodies[i].dynamic || left_[i])
                continue;
            const Probe p = e.probe(int(i));
            const bool beside = std::abs(p.p.x) > s.inner_half_w + tol;
            if (!finite(p) || beside || p.p.y < -tol) {
                left_[i] = 1;
                ++(finite(p) && beside && p.p.y > s.wall_top ? exits_.over : exits_.through);
            }
        }
    }
    RainExits exits() const { return exits_; }

  private:
    std::vector<char> left_;
    RainExits exits_;
};

/// Steps a freshly built engine `steps` times, following the boxes after every step.
inline RainExits measure_exits(const SceneDesc& s, Engine& e, int steps) {
    RainExitWatch watch(s);
    for (int n = 0; n < steps; ++n) {
        e.step();
        watch.observe(s, e);
    }
    return watch.exits();
}

} // namespace tamias_bench
