// Constraint drift of the joint scenes: how far apart the two anchor points of a pin have come.
// Measured from the outside, the same way for every engine: each anchor is fixed in its body's
// frame at creation (from the scene's initial poses), and its world position at any time follows
// from the body's origin and angle as the engine reports them (Probe).
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "bench_engines.hpp"
#include "bench_scenes.hpp"

namespace tamias_bench {

/// A joint's anchor in the frame of each of its two bodies.
struct LocalAnchors {
    V2 on_a{}, on_b{};
};

inline V2 to_local(const BodyDesc& b, V2 world) {
    const double c = std::cos(b.angle), s = std::sin(b.angle);
    const double dx = world.x - b.position.x, dy = world.y - b.position.y;
    return {c * dx + s * dy, -s * dx + c * dy};
}

inline V2 to_world(const Probe& p, V2 local) {
    const double c = std::cos(p.angle), s = std::sin(p.angle);
    return {p.p.x + c * local.x - s * local.y, p.p.y + s * local.x + c * local.y};
}

inline std::vector<LocalAnchors> local_anchors(const SceneDesc& s) {
    std::vector<LocalAnchors> out;
    out.reserve(s.joints.size());
    for (const JointDesc& j : s.joints) {
        out.push_back({to_local(s.bodies[std::size_t(j.a)], j.anchor),
                       to_local(s.bodies[std::size_t(j.b)], j.anchor)});
    }
    return out;
}

/// m: the largest distance between a joint's two anchors over all the scene's joints; infinite
/// when a body's pose is not finite.
inline double largest_separation(const SceneDesc& s, const std::vector<LocalAnchors>& anchors,
                                 const Engine& e) {
    double worst = 0.0;
    for (std::size_t k = 0; k < s.joints.size(); ++k) {
        const V2 pa = to_world(e.probe(s.joints[k].a), anchors[k].on_a);
        const V2 pb = to_world(e.probe(s.joints[k].b), anchors[k].on_b);
        const double d = std::hypot(pa.x - pb.x, pa.y - pb.y);
        if (!std::isfinite(d))
            return INFINITY;
        worst = std::max(worst, d);
    }
    return worst;
}

/// The drift over one run: sampled after every step.
struct JointDrift {
    double max = 0.0;       ///< m, the largest separation seen
    int max_step = 0;       ///< the step (1-based) after which it was seen
    double end = 0.0;       ///< m, after the last step
    double max_speed = 0.0; ///< m s^-1, the fastest dynamic body seen
    /// Whether the chain (or grid) held, judged against the scene's apart_separation (half a
    /// link): "intact" (no pin ever that far apart), "rejoined" (apart at some step, not at the
    /// end), "apart at the end", or "exploded" (a pose became NaN or infinite, or a body moved
    /// faster than ten times the speed free fall reaches over the run: energy the scene never
    /// had).
    std::string outcome;
};

/// The drift so far; observe() after every step, outcome() after the last.
class JointDriftWatch {
  public:
    /// `steps`: the run's length, which bounds the speed free fall can reach.
    JointDriftWatch(const SceneDesc& s, int steps)
        : anchors_(local_anchors(s)),
          speed_bound_(10.0 * std::hypot(s.gravity.x, s.gravity.y) * steps * s.dt) {}
    void observe(const SceneDesc& s, const Engine& e) {
        ++step_;
        const double sep = largest_separation(s, anchors_, e);
        if (!(sep <= d_.max)) {
            d_.max = sep;
            d_.max_step = step_;
        }
        d_.end = sep;
        for (std::size_t b = 0; b < s.bodies.size(); ++b) {
            if (!s.bodies[b].dynamic)
                continue;
            const Probe p = e.probe(int(b));
            const double v = std::hypot(p.v.x, p.v.y);
            d_.max_speed = std::isfinite(v) ? std::max(d_.max_speed, v) : INFINITY;
        }
    }
    JointDrift outcome(const SceneDesc& s) const {
        JointDrift d = d_;
        if (!std::isfinite(d.max) || !(d.max_speed <= speed_bound_))
            d.outcome = "exploded";
        else if (d.max < s.apart_separation)
            d.outcome = "intact";
        else if (d.end < s.apart_separation)
            d.outcome = "rejoined";
        else
            d.outcome = "apart at the end";
        return d;
    }

  private:
    std::vector<LocalAnchors> anchors_;
    double speed_bound_;
    int step_ = 0;
    JointDrift d_;
};

/// Runs `steps` steps of a freshly built engine, sampling the separation after each.
inline JointDrift measure_drift(const SceneDesc& s, Engine& e, int steps) {
    JointDriftWatch watch(s, steps);
    for (int i = 1; i <= steps; ++i) {
        e.step();
        watch.observe(s, e);
    }
    return watch.outcome(s);
}

} // namespace tamias_bench
