// The error-returning forms of World (world.hpp, "error-returning forms"): each runs its
// throwing form through detail::capture (error_returning.hpp), the one place where an
// exception becomes an Error.
#include "tamias2d/error_returning.hpp"
#include "tamias2d/world.hpp"

namespace tamias2d {

Result<World> World::try_create(const WorldDef& def) noexcept {
    return detail::capture([&] { return World(def); });
}

Result<std::uint32_t> World::try_tag() const noexcept {
    return detail::capture([&] { return tag(); });
}

Result<BodyId> World::try_create_body(const BodyDef& def) noexcept {
    return detail::capture([&] { return create_body(def); });
}

Result<void> World::try_destroy_body(BodyId body) noexcept {
    return detail::capture([&] { return destroy_body(body); });
}

Result<ShapeId> World::try_create_shape(BodyId body, const ShapeDef& def) noexcept {
    return detail::capture([&] { return create_shape(body, def); });
}

Result<std::vector<ShapeId>> World::try_create_chain(BodyId body,
                                                     std::span<const ShapeDef> segments) noexcept {
    return detail::capture([&] { return create_chain(body, segments); });
}

Result<void> World::try_destroy_shape(ShapeId shape) noexcept {
    return detail::capture([&] { return destroy_shape(shape); });
}

Result<void> World::try_set_filter(ShapeId shape, const Filter& filter) noexcept {
    return detail::capture([&] { return set_filter(shape, filter); });
}

Result<Filter> World::try_filter(ShapeId shape) const noexcept {
    return detail::capture([&] { return filter(shape); });
}

Result<void> World::try_set_custom_filter(std::function<bool(ShapeId, ShapeId)> filter) noexcept {
    return detail::capture([&] { return set_custom_filter(std::move(filter)); });
}

Result<bool> World::try_is_valid(BodyId body) const noexcept {
    return detail::capture([&] { return is_valid(body); });
}

Result<bool> World::try_is_valid(ShapeId shape) const noexcept {
    return detail::capture([&] { return is_valid(shape); });
}

Result<std::vector<BodyId>> World::try_bodies() const noexcept {
    return detail::capture([&] { return bodies(); });
}

Result<std::vector<ShapeId>> World::try_shapes(BodyId body) const noexcept {
    return detail::capture([&] { return shapes(body); });
}

Result<std::size_t> World::try_body_count() const noexcept {
    return detail::capture([&] { return body_count(); });
}

Result<void> World::try_set_friction(ShapeId shape, double friction) noexcept {
    return detail::capture([&] { return set_friction(shape, friction); });
}

Result<double> World::try_friction(ShapeId shape) const noexcept {
    return detail::capture([&] { return friction(shape); });
}

Result<void> World::try_set_rolling_resistance(ShapeId shape, double rolling_resistance) noexcept {
    return detail::capture([&] { return set_rolling_resistance(shape, rolling_resistance); });
}

Result<double> World::try_rolling_resistance(ShapeId shape) const noexcept {
    return detail::capture([&] { return rolling_resistance(shape); });
}

Result<void> World::try_set_tangent_speed(ShapeId shape, double tangent_speed) noexcept {
    return detail::capture([&] { return set_tangent_speed(shape, tangent_speed); });
}

Result<double> World::try_tangent_speed(ShapeId shape) const noexcept {
    return detail::capture([&] { return tangent_speed(shape); });
}

Result<void> World::try_set_restitution(ShapeId shape, double restitution) noexcept {
    return detail::capture([&] { return set_restitution(shape, restitution); });
}

Result<double> World::try_restitution(ShapeId shape) const noexcept {
    return detail::capture([&] { return restitution(shape); });
}

Result<void> World::try_set_density(ShapeId shape, double density, bool update_body_mass) noexcept {
    return detail::capture([&] { return set_density(shape, density, update_body_mass); });
}

Result<double> World::try_density(ShapeId shape) const noexcept {
    return detail::capture([&] { return density(shape); });
}

Result<void> World::try_set_circle(ShapeId shape, const Circle& circle) noexcept {
    return detail::capture([&] { return set_circle(shape, circle); });
}

Result<void> World::try_set_capsule(ShapeId shape, const Capsule& capsule) noexcept {
    return detail::capture([&] { return set_capsule(shape, capsule); });
}

Result<void> World::try_set_polygon(ShapeId shape, const Polygon& polygon) noexcept {
    return detail::capture([&] { return set_polygon(shape, polygon); });
}

Result<void> World::try_set_segment(ShapeId shape, const Segment& segment) noexcept {
    return detail::capture([&] { return set_segment(shape, segment); });
}

Result<Geometry> World::try_shape_geometry(ShapeId shape) const noexcept {
    return detail::capture([&] { return shape_geometry(shape); });
}

Result<void> World::try_set_sensor(ShapeId shape, bool is_sensor) noexcept {
    return detail::capture([&] { return set_sensor(shape, is_sensor); });
}

Result<bool> World::try_is_sensor(ShapeId shape) const noexcept {
    return detail::capture([&] { return is_sensor(shape); });
}

Result<void> World::try_step(double dt) noexcept {
    return detail::capture([&] { return step(dt); });
}

Result<double> World::try_time() const noexcept {
    return detail::capture([&] { return time(); });
}

Result<void> World::try_set_gravity(Vec2d g) noexcept {
    return detail::capture([&] { return set_gravity(g); });
}

Result<Vec2d> World::try_gravity() const noexcept {
    return detail::capture([&] { return gravity(); });
}

Result<WorldDef> World::try_settings() const noexcept {
    return detail::capture([&] { return settings(); });
}

Result<BodyState> World::try_state(BodyId body) const noexcept {
    return detail::capture([&] { return state(body); });
}

Result<Vec2d> World::try_position(BodyId body) const noexcept {
    return detail::capture([&] { return position(body); });
}

Result<Vec2d> World::try_origin(BodyId body) const noexcept {
    return detail::capture([&] { return origin(body); });
}

Result<double> World::try_orientation(BodyId body) const noexcept {
    return detail::capture([&] { return orientation(body); });
}

Result<Vec2d> World::try_velocity(BodyId body) const noexcept {
    return detail::capture([&] { return velocity(body); });
}

Result<double> World::try_angular_velocity(BodyId body) const noexcept {
    return detail::capture([&] { return angular_velocity(body); });
}

Result<double> World::try_mass(BodyId body) const noexcept {
    return detail::capture([&] { return mass(body); });
}

Result<double> World::try_inertia(BodyId body) const noexcept {
    return detail::capture([&] { return inertia(body); });
}

Result<Vec2d> World::try_local_center(BodyId body) const noexcept {
    return detail::capture([&] { return local_center(body); });
}

Result<BodyType> World::try_type(BodyId body) const noexcept {
    return detail::capture([&] { return type(body); });
}

Result<std::string> World::try_name(BodyId body) const noexcept {
    return detail::capture([&] { return name(body); });
}

Result<void> World::try_set_transform(BodyId body, Vec2d origin, double angle) noexcept {
    return detail::capture([&] { return set_transform(body, origin, angle); });
}

Result<void> World::try_set_velocity(BodyId body, Vec2d v) noexcept {
    return detail::capture([&] { return set_velocity(body, v); });
}

Result<void> World::try_set_angular_velocity(BodyId body, double omega) noexcept {
    return detail::capture([&] { return set_angular_velocity(body, omega); });
}

Result<void> World::try_set_damping(BodyId body, double linear, double angular) noexcept {
    return detail::capture([&] { return set_damping(body, linear, angular); });
}

Result<double> World::try_linear_damping(BodyId body) const noexcept {
    return detail::capture([&] { return linear_damping(body); });
}

Result<double> World::try_angular_damping(BodyId body) const noexcept {
    return detail::capture([&] { return angular_damping(body); });
}

Result<void> World::try_set_force(BodyId body, Vec2d force) noexcept {
    return detail::capture([&] { return set_force(body, force); });
}

Result<void> World::try_set_torque(BodyId body, double torque) noexcept {
    return detail::capture([&] { return set_torque(body, torque); });
}

Result<void> World::try_apply_force(BodyId body, Vec2d force, Vec2d world_point) noexcept {
    return detail::capture([&] { return apply_force(body, force, world_point); });
}

Result<void> World::try_apply_torque(BodyId body, double torque) noexcept {
    return detail::capture([&] { return apply_torque(body, torque); });
}

Result<void> World::try_apply_impulse(BodyId body, Vec2d impulse, Vec2d world_point) noexcept {
    return detail::capture([&] { return apply_impulse(body, impulse, world_point); });
}

Result<void> World::try_set_load(BodyId body, LoadFunction load) noexcept {
    return detail::capture([&] { return set_load(body, std::move(load)); });
}

Result<JointId> World::try_create_joint(const RevoluteJointDef& def) noexcept {
    return detail::capture([&] { return create_joint(def); });
}

Result<JointId> World::try_create_joint(const DistanceJointDef& def) noexcept {
    return detail::capture([&] { return create_joint(def); });
}

Result<JointId> World::try_create_joint(const TargetJointDef& def) noexcept {
    return detail::capture([&] { return create_joint(def); });
}

Result<JointId> World::try_create_joint(const PrismaticJointDef& def) noexcept {
    return detail::capture([&] { return create_joint(def); });
}

Result<JointId> World::try_create_joint(const WeldJointDef& def) noexcept {
    return detail::capture([&] { return create_joint(def); });
}

Result<JointId> World::try_create_joint(const WheelJointDef& def) noexcept {
    return detail::capture([&] { return create_joint(def); });
}

Result<JointId> World::try_create_joint(const MotorJointDef& def) noexcept {
    return detail::capture([&] { return create_joint(def); });
}

Result<JointId> World::try_create_joint(const FilterJointDef& def) noexcept {
    return detail::capture([&] { return create_joint(def); });
}

Result<void> World::try_set_motor_joint_offsets(JointId joint, Vec2d linear_offset,
                                                double angular_offset) noexcept {
    return detail::capture(
        [&] { return set_motor_joint_offsets(joint, linear_offset, angular_offset); });
}

Result<void> World::try_set_joint_target(JointId joint, Vec2d target) noexcept {
    return detail::capture([&] { return set_joint_target(joint, target); });
}

Result<void> World::try_destroy_joint(JointId joint) noexcept {
    return detail::capture([&] { return destroy_joint(joint); });
}

Result<bool> World::try_is_valid(JointId joint) const noexcept {
    return detail::capture([&] { return is_valid(joint); });
}

Result<Vec2d> World::try_joint_reaction_force(JointId joint) const noexcept {
    return detail::capture([&] { return joint_reaction_force(joint); });
}

Result<double> World::try_joint_reaction_torque(JointId joint) const noexcept {
    return detail::capture([&] { return joint_reaction_torque(joint); });
}

Result<double> World::try_joint_angle(JointId joint) const noexcept {
    return detail::capture([&] { return joint_angle(joint); });
}

Result<double> World::try_joint_translation(JointId joint) const noexcept {
    return detail::capture([&] { return joint_translation(joint); });
}

Result<void> World::try_set_joint_motor_speed(JointId joint, double speed) noexcept {
    return detail::capture([&] { return set_joint_motor_speed(joint, speed); });
}

Result<std::span<const JointId>> World::try_broken_joints() const noexcept {
    return detail::capture([&] { return broken_joints(); });
}

Result<std::size_t> World::try_joint_count() const noexcept {
    return detail::capture([&] { return joint_count(); });
}

Result<JointKind> World::try_joint_kind(JointId joint) const noexcept {
    return detail::capture([&] { return joint_kind(joint); });
}

Result<BodyId> World::try_joint_body_a(JointId joint) const noexcept {
    return detail::capture([&] { return joint_body_a(joint); });
}

Result<BodyId> World::try_joint_body_b(JointId joint) const noexcept {
    return detail::capture([&] { return joint_body_b(joint); });
}

Result<void> World::try_enable_joint_limit(JointId joint, bool enable) noexcept {
    return detail::capture([&] { return enable_joint_limit(joint, enable); });
}

Result<bool> World::try_is_joint_limit_enabled(JointId joint) const noexcept {
    return detail::capture([&] { return is_joint_limit_enabled(joint); });
}

Result<void> World::try_set_joint_limits(JointId joint, double lower, double upper) noexcept {
    return detail::capture([&] { return set_joint_limits(joint, lower, upper); });
}

Result<JointLimits> World::try_joint_limits(JointId joint) const noexcept {
    return detail::capture([&] { return joint_limits(joint); });
}

Result<void> World::try_enable_joint_motor(JointId joint, bool enable) noexcept {
    return detail::capture([&] { return enable_joint_motor(joint, enable); });
}

Result<bool> World::try_is_joint_motor_enabled(JointId joint) const noexcept {
    return detail::capture([&] { return is_joint_motor_enabled(joint); });
}

Result<double> World::try_joint_motor_speed(JointId joint) const noexcept {
    return detail::capture([&] { return joint_motor_speed(joint); });
}

Result<void> World::try_set_joint_max_motor_torque(JointId joint, double torque) noexcept {
    return detail::capture([&] { return set_joint_max_motor_torque(joint, torque); });
}

Result<double> World::try_joint_max_motor_torque(JointId joint) const noexcept {
    return detail::capture([&] { return joint_max_motor_torque(joint); });
}

Result<void> World::try_set_joint_max_motor_force(JointId joint, double force) noexcept {
    return detail::capture([&] { return set_joint_max_motor_force(joint, force); });
}

Result<double> World::try_joint_max_motor_force(JointId joint) const noexcept {
    return detail::capture([&] { return joint_max_motor_force(joint); });
}

Result<void> World::try_enable_joint_spring(JointId joint, bool enable) noexcept {
    return detail::capture([&] { return enable_joint_spring(joint, enable); });
}

Result<bool> World::try_is_joint_spring_enabled(JointId joint) const noexcept {
    return detail::capture([&] { return is_joint_spring_enabled(joint); });
}

Result<void> World::try_set_joint_spring(JointId joint, double hertz,
                                         double damping_ratio) noexcept {
    return detail::capture([&] { return set_joint_spring(joint, hertz, damping_ratio); });
}

Result<double> World::try_joint_spring_hertz(JointId joint) const noexcept {
    return detail::capture([&] { return joint_spring_hertz(joint); });
}

Result<double> World::try_joint_spring_damping_ratio(JointId joint) const noexcept {
    return detail::capture([&] { return joint_spring_damping_ratio(joint); });
}

Result<void> World::try_set_joint_spring_target(JointId joint, double target) noexcept {
    return detail::capture([&] { return set_joint_spring_target(joint, target); });
}

Result<double> World::try_joint_spring_target(JointId joint) const noexcept {
    return detail::capture([&] { return joint_spring_target(joint); });
}

Result<void> World::try_set_distance_joint_length(JointId joint, double length) noexcept {
    return detail::capture([&] { return set_distance_joint_length(joint, length); });
}

Result<double> World::try_distance_joint_length(JointId joint) const noexcept {
    return detail::capture([&] { return distance_joint_length(joint); });
}

Result<void> World::try_set_constraint_tuning(JointId joint, double hertz,
                                              double damping_ratio) noexcept {
    return detail::capture([&] { return set_constraint_tuning(joint, hertz, damping_ratio); });
}

Result<ConstraintTuning> World::try_constraint_tuning(JointId joint) const noexcept {
    return detail::capture([&] { return constraint_tuning(joint); });
}

Result<void> World::try_set_joint_collide_connected(JointId joint, bool collide) noexcept {
    return detail::capture([&] { return set_joint_collide_connected(joint, collide); });
}

Result<bool> World::try_joint_collide_connected(JointId joint) const noexcept {
    return detail::capture([&] { return joint_collide_connected(joint); });
}

Result<void> World::try_set_joint_break_force(JointId joint, double force) noexcept {
    return detail::capture([&] { return set_joint_break_force(joint, force); });
}

Result<double> World::try_joint_break_force(JointId joint) const noexcept {
    return detail::capture([&] { return joint_break_force(joint); });
}

Result<void> World::try_set_joint_break_torque(JointId joint, double torque) noexcept {
    return detail::capture([&] { return set_joint_break_torque(joint, torque); });
}

Result<double> World::try_joint_break_torque(JointId joint) const noexcept {
    return detail::capture([&] { return joint_break_torque(joint); });
}

Result<bool> World::try_is_awake(BodyId body) const noexcept {
    return detail::capture([&] { return is_awake(body); });
}

Result<void> World::try_set_awake(BodyId body, bool awake) noexcept {
    return detail::capture([&] { return set_awake(body, awake); });
}

Result<double> World::try_kinetic_energy() const noexcept {
    return detail::capture([&] { return kinetic_energy(); });
}

Result<double> World::try_potential_energy() const noexcept {
    return detail::capture([&] { return potential_energy(); });
}

Result<Vec2d> World::try_linear_momentum() const noexcept {
    return detail::capture([&] { return linear_momentum(); });
}

Result<std::span<const ContactInfo>> World::try_contacts() const noexcept {
    return detail::capture([&] { return contacts(); });
}

Result<std::span<const ContactEvent>> World::try_contact_begin_events() const noexcept {
    return detail::capture([&] { return contact_begin_events(); });
}

Result<std::span<const ContactEvent>> World::try_contact_end_events() const noexcept {
    return detail::capture([&] { return contact_end_events(); });
}

Result<std::span<const SensorEvent>> World::try_sensor_begin_events() const noexcept {
    return detail::capture([&] { return sensor_begin_events(); });
}

Result<std::span<const SensorEvent>> World::try_sensor_end_events() const noexcept {
    return detail::capture([&] { return sensor_end_events(); });
}

Result<std::vector<ShapeId>> World::try_query_aabb(const Aabb& box) const noexcept {
    return detail::capture([&] { return query_aabb(box); });
}

Result<std::vector<ShapeId>> World::try_query_point(Vec2d point) const noexcept {
    return detail::capture([&] { return query_point(point); });
}

Result<std::optional<RayCastHit>> World::try_ray_cast(Vec2d origin,
                                                      Vec2d translation) const noexcept {
    return detail::capture([&] { return ray_cast(origin, translation); });
}

Result<std::vector<std::byte>> World::try_snapshot() const noexcept {
    return detail::capture([&] { return snapshot(); });
}

Result<void> World::try_snapshot(std::vector<std::byte>& bytes) const noexcept {
    return detail::capture([&] { return snapshot(bytes); });
}

Result<World> World::try_from_snapshot(std::span<const std::byte> snapshot, int workers,
                                       const TaskSystem& task_system) noexcept {
    return detail::capture([&] { return from_snapshot(snapshot, workers, task_system); });
}

Result<void> World::try_restore(std::span<const std::byte> snapshot) noexcept {
    return detail::capture([&] { return restore(snapshot); });
}

Result<WorldDefinitions> World::try_definitions() const noexcept {
    return detail::capture([&] { return definitions(); });
}

Result<std::optional<RayCastHit>> World::try_ray_cast(Vec2d origin, Vec2d translation,
                                                      const QueryFilter& filter) const noexcept {
    return detail::capture([&] { return ray_cast(origin, translation, filter); });
}

Result<std::vector<RayCastHit>> World::try_ray_cast_all(Vec2d origin, Vec2d translation,
                                                        const QueryFilter& filter) const noexcept {
    return detail::capture([&] { return ray_cast_all(origin, translation, filter); });
}

Result<std::size_t> World::try_ray_cast_all(Vec2d origin, Vec2d translation,
                                            const QueryFilter& filter,
                                            std::span<RayCastHit> out) const noexcept {
    return detail::capture([&] { return ray_cast_all(origin, translation, filter, out); });
}

Result<std::optional<RayCastHit>>
World::try_ray_cast_any(Vec2d origin, Vec2d translation, const QueryFilter& filter) const noexcept {
    return detail::capture([&] { return ray_cast_any(origin, translation, filter); });
}

Result<void> World::try_ray_cast(Vec2d origin, Vec2d translation, const QueryFilter& filter,
                                 RayCastCallback callback) const noexcept {
    return detail::capture(
        [&] { return ray_cast(origin, translation, filter, std::move(callback)); });
}

Result<std::optional<RayCastHit>> World::try_ray_cast(ShapeId shape, Vec2d origin,
                                                      Vec2d translation) const noexcept {
    return detail::capture([&] { return ray_cast(shape, origin, translation); });
}

Result<std::optional<ShapeCastHit>>
World::try_shape_cast(const Geometry& shape, Vec2d origin, double angle, Vec2d translation,
                      const QueryFilter& filter) const noexcept {
    return detail::capture([&] { return shape_cast(shape, origin, angle, translation, filter); });
}

Result<void> World::try_shape_cast(const Geometry& shape, Vec2d origin, double angle,
                                   Vec2d translation, const QueryFilter& filter,
                                   ShapeCastCallback callback) const noexcept {
    return detail::capture(
        [&] { return shape_cast(shape, origin, angle, translation, filter, std::move(callback)); });
}

Result<double> World::try_cast_tolerance(const Geometry& shape, Vec2d translation) noexcept {
    return detail::capture([&] { return cast_tolerance(shape, translation); });
}

Result<std::vector<ShapeId>> World::try_query_aabb(const Aabb& box,
                                                   const QueryFilter& filter) const noexcept {
    return detail::capture([&] { return query_aabb(box, filter); });
}

Result<void> World::try_query_aabb(const Aabb& box, const QueryFilter& filter,
                                   OverlapCallback callback) const noexcept {
    return detail::capture([&] { return query_aabb(box, filter, std::move(callback)); });
}

Result<std::vector<ShapeId>> World::try_query_point(Vec2d point,
                                                    const QueryFilter& filter) const noexcept {
    return detail::capture([&] { return query_point(point, filter); });
}

Result<void> World::try_query_point(Vec2d point, const QueryFilter& filter,
                                    OverlapCallback callback) const noexcept {
    return detail::capture([&] { return query_point(point, filter, std::move(callback)); });
}

Result<std::vector<ShapeId>> World::try_overlap_shape(const Geometry& shape, Vec2d origin,
                                                      double angle,
                                                      const QueryFilter& filter) const noexcept {
    return detail::capture([&] { return overlap_shape(shape, origin, angle, filter); });
}

Result<void> World::try_overlap_shape(const Geometry& shape, Vec2d origin, double angle,
                                      const QueryFilter& filter,
                                      OverlapCallback callback) const noexcept {
    return detail::capture(
        [&] { return overlap_shape(shape, origin, angle, filter, std::move(callback)); });
}

Result<ClosestPoints> World::try_distance(ShapeId a, ShapeId b) const noexcept {
    return detail::capture([&] { return distance(a, b); });
}

Result<ClosestPoints> World::try_closest_point(ShapeId shape, Vec2d point) const noexcept {
    return detail::capture([&] { return closest_point(shape, point); });
}

Result<std::span<const ContactHitEvent>> World::try_contact_hit_events() const noexcept {
    return detail::capture([&] { return contact_hit_events(); });
}

Result<std::span<const BodyMoveEvent>> World::try_body_move_events() const noexcept {
    return detail::capture([&] { return body_move_events(); });
}

Result<std::span<const JointEvent>> World::try_joint_events() const noexcept {
    return detail::capture([&] { return joint_events(); });
}

Result<std::vector<ShapeId>> World::try_sensor_overlaps(ShapeId sensor) const noexcept {
    return detail::capture([&] { return sensor_overlaps(sensor); });
}

Result<void> World::try_set_hit_event_threshold(double speed) noexcept {
    return detail::capture([&] { return set_hit_event_threshold(speed); });
}

Result<void> World::try_set_hit_events_enabled(ShapeId shape, bool on) noexcept {
    return detail::capture([&] { return set_hit_events_enabled(shape, on); });
}

Result<bool> World::try_hit_events_enabled(ShapeId shape) const noexcept {
    return detail::capture([&] { return hit_events_enabled(shape); });
}

Result<void> World::try_set_contact_events_enabled(ShapeId shape, bool on) noexcept {
    return detail::capture([&] { return set_contact_events_enabled(shape, on); });
}

Result<bool> World::try_contact_events_enabled(ShapeId shape) const noexcept {
    return detail::capture([&] { return contact_events_enabled(shape); });
}

Result<void> World::try_set_sensor_events_enabled(ShapeId shape, bool on) noexcept {
    return detail::capture([&] { return set_sensor_events_enabled(shape, on); });
}

Result<bool> World::try_sensor_events_enabled(ShapeId shape) const noexcept {
    return detail::capture([&] { return sensor_events_enabled(shape); });
}

Result<void> World::try_set_move_events_enabled(BodyId body, bool on) noexcept {
    return detail::capture([&] { return set_move_events_enabled(body, on); });
}

Result<bool> World::try_move_events_enabled(BodyId body) const noexcept {
    return detail::capture([&] { return move_events_enabled(body); });
}

Result<void> World::try_set_joint_event_thresholds(JointId joint, double force,
                                                   double torque) noexcept {
    return detail::capture([&] { return set_joint_event_thresholds(joint, force, torque); });
}

Result<double> World::try_joint_force_threshold(JointId joint) const noexcept {
    return detail::capture([&] { return joint_force_threshold(joint); });
}

Result<double> World::try_joint_torque_threshold(JointId joint) const noexcept {
    return detail::capture([&] { return joint_torque_threshold(joint); });
}

Result<void> World::try_draw(DebugDraw& draw) const noexcept {
    return detail::capture([&] { return this->draw(draw); });
}

Result<void> World::try_set_profiling(bool on) noexcept {
    return detail::capture([&] { return set_profiling(on); });
}

Result<bool> World::try_profiling() const noexcept {
    return detail::capture([&] { return profiling(); });
}

Result<StepProfile> World::try_profile() const noexcept {
    return detail::capture([&] { return profile(); });
}

Result<WorldCounters> World::try_counters() const noexcept {
    return detail::capture([&] { return counters(); });
}

Result<std::size_t> World::try_explode(const ExplosionDef& def) noexcept {
    return detail::capture([&] { return explode(def); });
}

Result<double> World::try_cast_mover(const Capsule& mover, Vec2d translation,
                                     const QueryFilter& filter) const noexcept {
    return detail::capture([&] { return cast_mover(mover, translation, filter); });
}

Result<std::vector<MoverPlane>> World::try_collide_mover(const Capsule& mover,
                                                         const QueryFilter& filter) const noexcept {
    return detail::capture([&] { return collide_mover(mover, filter); });
}

Result<void> World::try_collide_mover(const Capsule& mover, const QueryFilter& filter,
                                      MoverPlaneCallback callback) const noexcept {
    return detail::capture([&] { return collide_mover(mover, filter, std::move(callback)); });
}

Result<void> World::try_set_target_transform(BodyId body, Vec2d origin, double angle,
                                             double dt) noexcept {
    return detail::capture([&] { return set_target_transform(body, origin, angle, dt); });
}

Result<void> World::try_apply_wind(ShapeId shape, Vec2d wind, double drag, double lift,
                                   bool wake) noexcept {
    return detail::capture([&] { return apply_wind(shape, wind, drag, lift, wake); });
}

Result<void> World::try_set_user_data(UserData data) noexcept {
    return detail::capture([&] { return set_user_data(data); });
}

Result<UserData> World::try_user_data() const noexcept {
    return detail::capture([&] { return user_data(); });
}

Result<void> World::try_set_user_data(BodyId body, UserData data) noexcept {
    return detail::capture([&] { return set_user_data(body, data); });
}

Result<UserData> World::try_user_data(BodyId body) const noexcept {
    return detail::capture([&] { return user_data(body); });
}

Result<void> World::try_set_user_data(ShapeId shape, UserData data) noexcept {
    return detail::capture([&] { return set_user_data(shape, data); });
}

Result<UserData> World::try_user_data(ShapeId shape) const noexcept {
    return detail::capture([&] { return user_data(shape); });
}

Result<void> World::try_set_user_data(JointId joint, UserData data) noexcept {
    return detail::capture([&] { return set_user_data(joint, data); });
}

Result<UserData> World::try_user_data(JointId joint) const noexcept {
    return detail::capture([&] { return user_data(joint); });
}

Result<BodyId> World::try_body(ShapeId shape) const noexcept {
    return detail::capture([&] { return body(shape); });
}

Result<ShapeType> World::try_shape_type(ShapeId shape) const noexcept {
    return detail::capture([&] { return shape_type(shape); });
}

Result<Geometry> World::try_geometry(ShapeId shape) const noexcept {
    return detail::capture([&] { return geometry(shape); });
}

Result<Aabb> World::try_shape_aabb(ShapeId shape) const noexcept {
    return detail::capture([&] { return shape_aabb(shape); });
}

Result<Aabb> World::try_body_aabb(BodyId body) const noexcept {
    return detail::capture([&] { return body_aabb(body); });
}

Result<std::vector<JointId>> World::try_joints(BodyId body) const noexcept {
    return detail::capture([&] { return joints(body); });
}

Result<std::vector<ContactInfo>> World::try_contacts(BodyId body) const noexcept {
    return detail::capture([&] { return contacts(body); });
}

Result<void> World::try_set_body_type(BodyId body, BodyType type) noexcept {
    return detail::capture([&] { return set_body_type(body, type); });
}

Result<void> World::try_set_enabled(BodyId body, bool enabled) noexcept {
    return detail::capture([&] { return set_enabled(body, enabled); });
}

Result<bool> World::try_is_enabled(BodyId body) const noexcept {
    return detail::capture([&] { return is_enabled(body); });
}

Result<void> World::try_set_gravity_scale(BodyId body, double scale) noexcept {
    return detail::capture([&] { return set_gravity_scale(body, scale); });
}

Result<double> World::try_gravity_scale(BodyId body) const noexcept {
    return detail::capture([&] { return gravity_scale(body); });
}

Result<void> World::try_set_bullet(BodyId body, bool bullet) noexcept {
    return detail::capture([&] { return set_bullet(body, bullet); });
}

Result<bool> World::try_is_bullet(BodyId body) const noexcept {
    return detail::capture([&] { return is_bullet(body); });
}

Result<void> World::try_set_motion_locks(BodyId body, MotionLocks locks) noexcept {
    return detail::capture([&] { return set_motion_locks(body, locks); });
}

Result<MotionLocks> World::try_motion_locks(BodyId body) const noexcept {
    return detail::capture([&] { return motion_locks(body); });
}

Result<void> World::try_set_fixed_rotation(BodyId body, bool fixed) noexcept {
    return detail::capture([&] { return set_fixed_rotation(body, fixed); });
}

Result<bool> World::try_fixed_rotation(BodyId body) const noexcept {
    return detail::capture([&] { return fixed_rotation(body); });
}

Result<void> World::try_set_mass_data(BodyId body, const BodyMassData& data) noexcept {
    return detail::capture([&] { return set_mass_data(body, data); });
}

Result<BodyMassData> World::try_mass_data(BodyId body) const noexcept {
    return detail::capture([&] { return mass_data(body); });
}

Result<void> World::try_reset_mass_data(BodyId body) noexcept {
    return detail::capture([&] { return reset_mass_data(body); });
}

Result<void> World::try_set_sleep_threshold(BodyId body, double speed) noexcept {
    return detail::capture([&] { return set_sleep_threshold(body, speed); });
}

Result<double> World::try_sleep_threshold(BodyId body) const noexcept {
    return detail::capture([&] { return sleep_threshold(body); });
}

Result<void> World::try_wake_touching(BodyId body) noexcept {
    return detail::capture([&] { return wake_touching(body); });
}

Result<void> World::try_set_pre_solve(PreSolveFunction callback) noexcept {
    return detail::capture([&] { return set_pre_solve(std::move(callback)); });
}

Result<void> World::try_set_friction_mixing(MaterialMixFunction mix) noexcept {
    return detail::capture([&] { return set_friction_mixing(std::move(mix)); });
}

Result<void> World::try_set_restitution_mixing(MaterialMixFunction mix) noexcept {
    return detail::capture([&] { return set_restitution_mixing(std::move(mix)); });
}

Result<void> World::try_set_user_material(ShapeId shape, std::uint64_t id) noexcept {
    return detail::capture([&] { return set_user_material(shape, id); });
}

Result<std::uint64_t> World::try_user_material(ShapeId shape) const noexcept {
    return detail::capture([&] { return user_material(shape); });
}

Result<void> World::try_set_continuous(bool enabled) noexcept {
    return detail::capture([&] { return set_continuous(enabled); });
}

Result<void> World::try_set_sleeping(bool enabled) noexcept {
    return detail::capture([&] { return set_sleeping(enabled); });
}

Result<void> World::try_set_contact_tuning(double hertz, double damping_ratio,
                                           double push_max_velocity) noexcept {
    return detail::capture(
        [&] { return set_contact_tuning(hertz, damping_ratio, push_max_velocity); });
}

Result<void> World::try_set_joint_tuning(double hertz, double damping_ratio) noexcept {
    return detail::capture([&] { return set_joint_tuning(hertz, damping_ratio); });
}

Result<void> World::try_set_restitution_threshold(double speed) noexcept {
    return detail::capture([&] { return set_restitution_threshold(speed); });
}

Result<void> World::try_set_maximum_linear_speed(double speed) noexcept {
    return detail::capture([&] { return set_maximum_linear_speed(speed); });
}

Result<void> World::try_set_workers(int workers) noexcept {
    return detail::capture([&] { return set_workers(workers); });
}

Result<std::size_t> World::try_awake_body_count() const noexcept {
    return detail::capture([&] { return awake_body_count(); });
}

Result<void> World::try_set_warm_starting(bool enabled) noexcept {
    return detail::capture([&] { return set_warm_starting(enabled); });
}

Result<bool> World::try_warm_starting() const noexcept {
    return detail::capture([&] { return warm_starting(); });
}

Result<std::uint64_t> World::try_state_hash() const noexcept {
    return detail::capture([&] { return state_hash(); });
}

} // namespace tamias2d
