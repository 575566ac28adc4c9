// The error-returning forms of Recorder, Replayer, replay and recorded_calls: each runs its
// throwing form (recorder.cpp, replay.cpp) through detail::capture, so that a call made through
// a `try_` form is recorded exactly as the throwing form records it.
#include "tamias2d/error_returning.hpp"
#include "tamias2d/recorder.hpp"
#include "tamias2d/replay.hpp"

namespace tamias2d {

Result<Recorder> Recorder::try_create(World& world, RecordOptions options) noexcept {
    return detail::capture([&] { return Recorder(world, options); });
}

Result<const World*> Recorder::try_world() const noexcept {
    return detail::capture([&] { return &world(); });
}

Result<std::vector<std::byte>> Recorder::try_bytes() const noexcept {
    return detail::capture([&] { return bytes(); });
}

Result<std::uint64_t> Recorder::try_steps() const noexcept {
    return detail::capture([&] { return steps(); });
}

Result<std::uint64_t> Recorder::try_calls() const noexcept {
    return detail::capture([&] { return calls(); });
}

Result<BodyId> Recorder::try_create_body(const BodyDef& def) noexcept {
    return detail::capture([&] { return create_body(def); });
}

Result<void> Recorder::try_destroy_body(BodyId body) noexcept {
    return detail::capture([&] { return destroy_body(body); });
}

Result<ShapeId> Recorder::try_create_shape(BodyId body, const ShapeDef& def) noexcept {
    return detail::capture([&] { return create_shape(body, def); });
}

Result<std::vector<ShapeId>>
Recorder::try_create_chain(BodyId body, std::span<const ShapeDef> segments) noexcept {
    return detail::capture([&] { return create_chain(body, segments); });
}

Result<void> Recorder::try_destroy_shape(ShapeId shape) noexcept {
    return detail::capture([&] { return destroy_shape(shape); });
}

Result<void> Recorder::try_set_filter(ShapeId shape, const Filter& filter) noexcept {
    return detail::capture([&] { return set_filter(shape, filter); });
}

Result<void> Recorder::try_set_rolling_resistance(ShapeId shape,
                                                  double rolling_resistance) noexcept {
    return detail::capture([&] { return set_rolling_resistance(shape, rolling_resistance); });
}

Result<void> Recorder::try_set_tangent_speed(ShapeId shape, double tangent_speed) noexcept {
    return detail::capture([&] { return set_tangent_speed(shape, tangent_speed); });
}

Result<void> Recorder::try_set_friction(ShapeId shape, double friction) noexcept {
    return detail::capture([&] { return set_friction(shape, friction); });
}

Result<void> Recorder::try_set_restitution(ShapeId shape, double restitution) noexcept {
    return detail::capture([&] { return set_restitution(shape, restitution); });
}

Result<void> Recorder::try_set_density(ShapeId shape, double density,
                                       bool update_body_mass) noexcept {
    return detail::capture([&] { return set_density(shape, density, update_body_mass); });
}

Result<void> Recorder::try_set_circle(ShapeId shape, const Circle& circle) noexcept {
    return detail::capture([&] { return set_circle(shape, circle); });
}

Result<void> Recorder::try_set_capsule(ShapeId shape, const Capsule& capsule) noexcept {
    return detail::capture([&] { return set_capsule(shape, capsule); });
}

Result<void> Recorder::try_set_polygon(ShapeId shape, const Polygon& polygon) noexcept {
    return detail::capture([&] { return set_polygon(shape, polygon); });
}

Result<void> Recorder::try_set_segment(ShapeId shape, const Segment& segment) noexcept {
    return detail::capture([&] { return set_segment(shape, segment); });
}

Result<void> Recorder::try_set_sensor(ShapeId shape, bool is_sensor) noexcept {
    return detail::capture([&] { return set_sensor(shape, is_sensor); });
}

Result<void> Recorder::try_step(double dt) noexcept {
    return detail::capture([&] { return step(dt); });
}

Result<void> Recorder::try_set_gravity(Vec2d g) noexcept {
    return detail::capture([&] { return set_gravity(g); });
}

Result<void> Recorder::try_set_transform(BodyId body, Vec2d origin, double angle) noexcept {
    return detail::capture([&] { return set_transform(body, origin, angle); });
}

Result<void> Recorder::try_set_velocity(BodyId body, Vec2d v) noexcept {
    return detail::capture([&] { return set_velocity(body, v); });
}

Result<void> Recorder::try_set_angular_velocity(BodyId body, double omega) noexcept {
    return detail::capture([&] { return set_angular_velocity(body, omega); });
}

Result<void> Recorder::try_set_damping(BodyId body, double linear, double angular) noexcept {
    return detail::capture([&] { return set_damping(body, linear, angular); });
}

Result<void> Recorder::try_set_force(BodyId body, Vec2d force) noexcept {
    return detail::capture([&] { return set_force(body, force); });
}

Result<void> Recorder::try_set_torque(BodyId body, double torque) noexcept {
    return detail::capture([&] { return set_torque(body, torque); });
}

Result<void> Recorder::try_apply_force(BodyId body, Vec2d force, Vec2d world_point) noexcept {
    return detail::capture([&] { return apply_force(body, force, world_point); });
}

Result<void> Recorder::try_apply_torque(BodyId body, double torque) noexcept {
    return detail::capture([&] { return apply_torque(body, torque); });
}

Result<void> Recorder::try_apply_impulse(BodyId body, Vec2d impulse, Vec2d world_point) noexcept {
    return detail::capture([&] { return apply_impulse(body, impulse, world_point); });
}

Result<JointId> Recorder::try_create_joint(const RevoluteJointDef& def) noexcept {
    return detail::capture([&] { return create_joint(def); });
}

Result<JointId> Recorder::try_create_joint(const DistanceJointDef& def) noexcept {
    return detail::capture([&] { return create_joint(def); });
}

Result<JointId> Recorder::try_create_joint(const TargetJointDef& def) noexcept {
    return detail::capture([&] { return create_joint(def); });
}

Result<JointId> Recorder::try_create_joint(const PrismaticJointDef& def) noexcept {
    return detail::capture([&] { return create_joint(def); });
}

Result<JointId> Recorder::try_create_joint(const WeldJointDef& def) noexcept {
    return detail::capture([&] { return create_joint(def); });
}

Result<JointId> Recorder::try_create_joint(const WheelJointDef& def) noexcept {
    return detail::capture([&] { return create_joint(def); });
}

Result<JointId> Recorder::try_create_joint(const MotorJointDef& def) noexcept {
    return detail::capture([&] { return create_joint(def); });
}

Result<JointId> Recorder::try_create_joint(const FilterJointDef& def) noexcept {
    return detail::capture([&] { return create_joint(def); });
}

Result<void> Recorder::try_set_motor_joint_offsets(JointId joint, Vec2d linear_offset,
                                                   double angular_offset) noexcept {
    return detail::capture(
        [&] { return set_motor_joint_offsets(joint, linear_offset, angular_offset); });
}

Result<void> Recorder::try_set_joint_target(JointId joint, Vec2d target) noexcept {
    return detail::capture([&] { return set_joint_target(joint, target); });
}

Result<void> Recorder::try_destroy_joint(JointId joint) noexcept {
    return detail::capture([&] { return destroy_joint(joint); });
}

Result<void> Recorder::try_set_joint_motor_speed(JointId joint, double speed) noexcept {
    return detail::capture([&] { return set_joint_motor_speed(joint, speed); });
}

Result<void> Recorder::try_enable_joint_limit(JointId joint, bool enable) noexcept {
    return detail::capture([&] { return enable_joint_limit(joint, enable); });
}

Result<void> Recorder::try_set_joint_limits(JointId joint, double lower, double upper) noexcept {
    return detail::capture([&] { return set_joint_limits(joint, lower, upper); });
}

Result<void> Recorder::try_enable_joint_motor(JointId joint, bool enable) noexcept {
    return detail::capture([&] { return enable_joint_motor(joint, enable); });
}

Result<void> Recorder::try_set_joint_max_motor_torque(JointId joint, double torque) noexcept {
    return detail::capture([&] { return set_joint_max_motor_torque(joint, torque); });
}

Result<void> Recorder::try_set_joint_max_motor_force(JointId joint, double force) noexcept {
    return detail::capture([&] { return set_joint_max_motor_force(joint, force); });
}

Result<void> Recorder::try_enable_joint_spring(JointId joint, bool enable) noexcept {
    return detail::capture([&] { return enable_joint_spring(joint, enable); });
}

Result<void> Recorder::try_set_joint_spring(JointId joint, double hertz,
                                            double damping_ratio) noexcept {
    return detail::capture([&] { return set_joint_spring(joint, hertz, damping_ratio); });
}

Result<void> Recorder::try_set_joint_spring_target(JointId joint, double target) noexcept {
    return detail::capture([&] { return set_joint_spring_target(joint, target); });
}

Result<void> Recorder::try_set_distance_joint_length(JointId joint, double length) noexcept {
    return detail::capture([&] { return set_distance_joint_length(joint, length); });
}

Result<void> Recorder::try_set_constraint_tuning(JointId joint, double hertz,
                                                 double damping_ratio) noexcept {
    return detail::capture([&] { return set_constraint_tuning(joint, hertz, damping_ratio); });
}

Result<void> Recorder::try_set_joint_collide_connected(JointId joint, bool collide) noexcept {
    return detail::capture([&] { return set_joint_collide_connected(joint, collide); });
}

Result<void> Recorder::try_set_joint_break_force(JointId joint, double force) noexcept {
    return detail::capture([&] { return set_joint_break_force(joint, force); });
}

Result<void> Recorder::try_set_joint_break_torque(JointId joint, double torque) noexcept {
    return detail::capture([&] { return set_joint_break_torque(joint, torque); });
}

Result<void> Recorder::try_set_awake(BodyId body, bool awake) noexcept {
    return detail::capture([&] { return set_awake(body, awake); });
}

Result<void> Recorder::try_restore(std::span<const std::byte> snapshot) noexcept {
    return detail::capture([&] { return restore(snapshot); });
}

Result<void> Recorder::try_set_hit_event_threshold(double speed) noexcept {
    return detail::capture([&] { return set_hit_event_threshold(speed); });
}

Result<void> Recorder::try_set_hit_events_enabled(ShapeId shape, bool on) noexcept {
    return detail::capture([&] { return set_hit_events_enabled(shape, on); });
}

Result<void> Recorder::try_set_contact_events_enabled(ShapeId shape, bool on) noexcept {
    return detail::capture([&] { return set_contact_events_enabled(shape, on); });
}

Result<void> Recorder::try_set_sensor_events_enabled(ShapeId shape, bool on) noexcept {
    return detail::capture([&] { return set_sensor_events_enabled(shape, on); });
}

Result<void> Recorder::try_set_move_events_enabled(BodyId body, bool on) noexcept {
    return detail::capture([&] { return set_move_events_enabled(body, on); });
}

Result<void> Recorder::try_set_joint_event_thresholds(JointId joint, double force,
                                                      double torque) noexcept {
    return detail::capture([&] { return set_joint_event_thresholds(joint, force, torque); });
}

Result<std::size_t> Recorder::try_explode(const ExplosionDef& def) noexcept {
    return detail::capture([&] { return explode(def); });
}

Result<void> Recorder::try_set_user_data(UserData data) noexcept {
    return detail::capture([&] { return set_user_data(data); });
}

Result<void> Recorder::try_set_user_data(BodyId body, UserData data) noexcept {
    return detail::capture([&] { return set_user_data(body, data); });
}

Result<void> Recorder::try_set_user_data(ShapeId shape, UserData data) noexcept {
    return detail::capture([&] { return set_user_data(shape, data); });
}

Result<void> Recorder::try_set_user_data(JointId joint, UserData data) noexcept {
    return detail::capture([&] { return set_user_data(joint, data); });
}

Result<void> Recorder::try_set_body_type(BodyId body, BodyType type) noexcept {
    return detail::capture([&] { return set_body_type(body, type); });
}

Result<void> Recorder::try_set_enabled(BodyId body, bool enabled) noexcept {
    return detail::capture([&] { return set_enabled(body, enabled); });
}

Result<void> Recorder::try_set_gravity_scale(BodyId body, double scale) noexcept {
    return detail::capture([&] { return set_gravity_scale(body, scale); });
}

Result<void> Recorder::try_set_bullet(BodyId body, bool bullet) noexcept {
    return detail::capture([&] { return set_bullet(body, bullet); });
}

Result<void> Recorder::try_set_motion_locks(BodyId body, MotionLocks locks) noexcept {
    return detail::capture([&] { return set_motion_locks(body, locks); });
}

Result<void> Recorder::try_set_fixed_rotation(BodyId body, bool fixed) noexcept {
    return detail::capture([&] { return set_fixed_rotation(body, fixed); });
}

Result<void> Recorder::try_set_mass_data(BodyId body, const BodyMassData& data) noexcept {
    return detail::capture([&] { return set_mass_data(body, data); });
}

Result<void> Recorder::try_reset_mass_data(BodyId body) noexcept {
    return detail::capture([&] { return reset_mass_data(body); });
}

Result<void> Recorder::try_set_sleep_threshold(BodyId body, double speed) noexcept {
    return detail::capture([&] { return set_sleep_threshold(body, speed); });
}

Result<void> Recorder::try_wake_touching(BodyId body) noexcept {
    return detail::capture([&] { return wake_touching(body); });
}

Result<void> Recorder::try_set_continuous(bool enabled) noexcept {
    return detail::capture([&] { return set_continuous(enabled); });
}

Result<void> Recorder::try_set_sleeping(bool enabled) noexcept {
    return detail::capture([&] { return set_sleeping(enabled); });
}

Result<void> Recorder::try_set_contact_tuning(double hertz, double damping_ratio,
                                              double push_max_velocity) noexcept {
    return detail::capture(
        [&] { return set_contact_tuning(hertz, damping_ratio, push_max_velocity); });
}

Result<void> Recorder::try_set_joint_tuning(double hertz, double damping_ratio) noexcept {
    return detail::capture([&] { return set_joint_tuning(hertz, damping_ratio); });
}

Result<void> Recorder::try_set_restitution_threshold(double speed) noexcept {
    return detail::capture([&] { return set_restitution_threshold(speed); });
}

Result<void> Recorder::try_set_maximum_linear_speed(double speed) noexcept {
    return detail::capture([&] { return set_maximum_linear_speed(speed); });
}

Result<void> Recorder::try_set_workers(int workers) noexcept {
    return detail::capture([&] { return set_workers(workers); });
}

Result<void> Recorder::try_set_warm_starting(bool enabled) noexcept {
    return detail::capture([&] { return set_warm_starting(enabled); });
}

Result<void> Recorder::try_set_user_material(ShapeId shape, std::uint64_t id) noexcept {
    return detail::capture([&] { return set_user_material(shape, id); });
}

Result<void> Recorder::try_set_target_transform(BodyId body, Vec2d origin, double angle,
                                                double dt) noexcept {
    return detail::capture([&] { return set_target_transform(body, origin, angle, dt); });
}

Result<void> Recorder::try_apply_wind(ShapeId shape, Vec2d wind, double drag, double lift,
                                      bool wake) noexcept {
    return detail::capture([&] { return apply_wind(shape, wind, drag, lift, wake); });
}

Result<Replayer> Replayer::try_create(std::span<const std::byte> recording, int workers,
                                      const TaskSystem& task_system) noexcept {
    return detail::capture([&] { return Replayer(recording, workers, task_system); });
}

Result<const World*> Replayer::try_world() const noexcept {
    return detail::capture([&] { return &world(); });
}

Result<bool> Replayer::try_done() const noexcept {
    return detail::capture([&] { return done(); });
}

Result<std::uint64_t> Replayer::try_steps() const noexcept {
    return detail::capture([&] { return steps(); });
}

Result<std::uint64_t> Replayer::try_calls() const noexcept {
    return detail::capture([&] { return calls(); });
}

Result<std::uint64_t> Replayer::try_recorded_steps() const noexcept {
    return detail::capture([&] { return recorded_steps(); });
}

Result<std::optional<ReplayDivergence>> Replayer::try_advance() noexcept {
    return detail::capture([&] { return advance(); });
}

Result<ReplayReport> try_replay(std::span<const std::byte> recording, int workers,
                                const TaskSystem& task_system) noexcept {
    return detail::capture([&] { return replay(recording, workers, task_system); });
}

Result<std::vector<RecordedCall>>
try_recorded_calls(std::span<const std::byte> recording) noexcept {
    return detail::capture([&] { return recorded_calls(recording); });
}

} // namespace tamias2d
