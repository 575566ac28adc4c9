// The sensors (internal, DD28): each sensor shape's overlapping shapes after the last step and
// the begin and end events their changes make. Sensors have no contacts: after each step every
// sensor asks the broad phase for the shapes near it and the narrow phase (R7's) whether they
// overlap, so that an event belongs to the step whose motion made it. Box2D v3 keeps sensors
// apart from contacts the same way (sensor.c).
#pragma once

#include <cstdint>
#include <vector>

#include "tamias2d/contact_info.hpp"
#include "tamias2d/memory/allocator.hpp"

namespace tamias2d {

struct BodyStore;
class ShapeStore;
class ContactManager;
class SnapshotWriter;
class SnapshotReader;

class SensorOverlaps {
  public:
    memory::vector<SensorEvent> begin_events, end_events; ///< the last step's (and destructions')

    /// A sensor shape was created: it overlaps nothing until the next step's update.
    void add(std::uint32_t sensor_shape);
    /// Shape s leaves the world (destroyed, or its body): the overlaps it ends become end
    /// events now, whether it is a sensor or a visitor. Call before its slot is released.
    void remove_shape(std::uint32_t s, const BodyStore& bodies, const ShapeStore& shapes);
    /// \srs{DD28} After a step: each sensor's overlaps now, in shape order, against the last
    /// step's; a shape that overlaps now and did not gives a begin event, one that did and no
    /// longer does an end event. Sensors in creation order, visitors in shape order.
    void update(const BodyStore& bodies, const ShapeStore& shapes, const ContactManager& rules);
    bool empty() const { return sensors_.empty(); }

    // --- snapshot (World::snapshot, World::restore; dynamics/snapshot_io.hpp) ---
    /// Writes each sensor (creation order) with the shapes it overlapped after the last step,
    /// and the last step's events.
    void write(SnapshotWriter& out) const;
    /// Reads what write wrote into this empty set (`shapes` already read); throws SnapshotError
    /// for a sensor that is not a live sensor shape or visitors that are not ascending shapes.
    void read(SnapshotReader& in, const ShapeStore& shapes);
    // --- events ---
    /// \srs{DD28} The shapes overlapping sensor shape s after the last step (less those
    /// destroyed since), in shape order: the set its begin and end events build.
    const memory::vector<std::uint32_t>& visitors(std::uint32_t sensor_shape) const;

  private:
    struct Sensor {
        std::uint32_t shape;
        memory::vector<std::uint32_t> visitors; ///< shape indices, ascending
    };
    memory::vector<Sensor> sensors_;
    memory::vector<std::uint32_t> now_; ///< scratch: one sensor's overlaps this step
};

} // namespace tamias2d
