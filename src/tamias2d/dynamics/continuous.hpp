// Continuous collision of dynamic bodies against static shapes (DD29), after the step's
// write-back: a body that moved far this step is swept from its start pose to its end pose
// against the static shapes near its path, and put back at the earliest time of impact, so
// that it cannot pass through a thin static shape between two steps. Box2D v3 has the same
// pass (its "continuous" stage of the solver).
#pragma once

#include <cstdint>
#include <vector>

#include "tamias2d/math/vec2d.hpp"
#include "tamias2d/memory/allocator.hpp"
#include "tamias2d/world_def.hpp"

namespace tamias2d {

struct BodyStore;
class ShapeStore;
class ContactManager;
class JointStore;

class ContinuousPass {
  public:
    /// Before a new write-back: no body listed.
    void clear() { fast_.clear(); }
    /// A dynamic body that moved farther this step than its speculative contacts can see
    /// (motion above the speculative distance), with its pose and velocity at the step's start.
    void add(std::uint32_t body, Vec2d start_center, double start_angle, Vec2d start_v,
             double start_w) {
        fast_.push_back({body, start_center, start_angle, start_v, start_w});
    }
    /// Sweeps the listed bodies, in index order, against the static shapes their filters let
    /// them collide with (bullets after the others, also against dynamic bodies). A body whose core
    /// (a disc about each shape's centroid, a quarter of its inner extent in radius) would reach a
    /// static shape is moved to its state at the time of impact: the pose there, and the velocity
    /// interpolated like the pose (the end velocity at an earlier pose would add energy, m g h of
    /// the height not fallen). The next step's speculative contact stops it. Its shapes follow it.
    void run(BodyStore& bodies, ShapeStore& shapes, const ContactManager& contacts,
             const JointStore& joints, const WorldDef& def);

  private:
    struct FastBody {
        std::uint32_t body;
        Vec2d c0;
        double a0;
        Vec2d v0;
        double w0;
    };
    /// One body's sweep: against static shapes, and for a bullet also against the dynamic
    /// bodies that are not bullets, at their poses now.
    void sweep(const FastBody& f, bool bullet, BodyStore& bodies, ShapeStore& shapes,
               const ContactManager& contacts, const JointStore& joints, const WorldDef& def);

    memory::vector<FastBody> fast_;
    memory::vector<std::uint32_t> nearby_; ///< scratch: the static shapes near one body's path
};

} // namespace tamias2d
