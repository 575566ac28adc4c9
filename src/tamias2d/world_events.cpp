// The World's event calls (world.hpp, "events"): the hits, moves and joint events of the last
// step, the sensors' current overlaps, and the switches of each kind. The step gathers them
// (StepEvents, dynamics/step_events.hpp; the contact and sensor stores their own).
#include <string>
#include <vector>

#include "tamias2d/dynamics/step_events.hpp"
#include "tamias2d/errors.hpp"
#include "tamias2d/world.hpp"
#include "tamias2d/world_impl.hpp"

namespace tamias2d {

std::span<const ContactHitEvent> World::contact_hit_events() const {
    return impl_->events.hits;
}

std::span<const BodyMoveEvent> World::body_move_events() const {
    return impl_->events.moves;
}

std::span<const JointEvent> World::joint_events() const {
    return impl_->events.joint_events;
}

std::vector<ShapeId> World::sensor_overlaps(ShapeId sensor) const {
    Impl& w = *impl_;
    w.shapes.get(sensor); // throws for a stale handle
    if (!w.shapes.defs[sensor.index].is_sensor)
        throw WrongKind("sensor_overlaps", "shape[" + std::to_string(sensor.index) + "]",
                        "shape that is not a sensor",
                        "must be a sensor shape (ShapeDef::is_sensor)");
    std::vector<ShapeId> out;
    for (const std::uint32_t v : w.sensors.visitors(sensor.index))
        out.push_back(w.shapes.id(v));
    return out;
}

void World::set_hit_event_threshold(double speed) {
    validate_event_threshold("hit_event_threshold", speed, false);
    impl_->def.hit_event_threshold = speed;
}

void World::set_hit_events_enabled(ShapeId shape, bool on) {
    impl_->shapes.get(shape); // throws for a stale handle
    bool& flag = impl_->shapes.defs[shape.index].enable_hit_events;
    impl_->events.hit_flag_changed(flag, on);
    flag = on;
}

bool World::hit_events_enabled(ShapeId shape) const {
    impl_->shapes.get(shape); // throws for a stale handle
    return impl_->shapes.defs[shape.index].enable_hit_events;
}

void World::set_contact_events_enabled(ShapeId shape, bool on) {
    impl_->shapes.get(shape);
    impl_->shapes.defs[shape.index].enable_contact_events = on;
}

bool World::contact_events_enabled(ShapeId shape) const {
    impl_->shapes.get(shape); // throws for a stale handle
    return impl_->shapes.defs[shape.index].enable_contact_events;
}

void World::set_sensor_events_enabled(ShapeId shape, bool on) {
    impl_->shapes.get(shape);
    impl_->shapes.defs[shape.index].enable_sensor_events = on;
}

bool World::sensor_events_enabled(ShapeId shape) const {
    impl_->shapes.get(shape); // throws for a stale handle
    return impl_->shapes.defs[shape.index].enable_sensor_events;
}

void World::set_move_events_enabled(BodyId body, bool on) {
    impl_->bodies.get(body); // throws for a stale handle
    impl_->events.set_move_events(body.index, on);
}

bool World::move_events_enabled(BodyId body) const {
    impl_->bodies.get(body);
    return impl_->events.move_events(body.index);
}

void World::set_joint_event_thresholds(JointId joint, double force, double torque) {
    Joint& j = impl_->joints.get(
        joint,
        {JointType::revolute, JointType::distance, JointType::target, JointType::prismatic,
         JointType::weld, JointType::wheel, JointType::motor},
        "set_joint_event_thresholds", "must be a joint that carries a force (not a filter joint)");
    validate_event_threshold("joint.force_threshold", force, true);
    validate_event_threshold("joint.torque_threshold", torque, true);
    j.force_threshold = force;
    j.torque_threshold = torque;
    impl_->events.thresholds_set(j);
}

double World::joint_force_threshold(JointId joint) const {
    return impl_->joints.get(joint).force_threshold;
}

double World::joint_torque_threshold(JointId joint) const {
    return impl_->joints.get(joint).torque_threshold;
}

} // namespace tamias2d
