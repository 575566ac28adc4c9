/// \file
/// Recording a world: a snapshot, then every call that changes it, and after every step its
/// state hash and its bodies' poses and velocities (docs/user-guide.md, "Recordings"). A
/// Replayer (replay.hpp) plays a recording back and finds the first step, body and field where
/// its world departs from the recorded one.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "tamias2d/config.hpp"
#include "tamias2d/export.hpp"
#include "tamias2d/result.hpp"
#include "tamias2d/world.hpp"

namespace tamias2d {

/// What a recording holds beside the calls.
struct RecordOptions {
    /// After every step, each live body's handle, centre of mass, angle, linear and angular
    /// velocity (56 bytes a body a step) beside the state hash (8 bytes a step): what lets a
    /// replay name the first body and field that diverged. Off, a replay names the first
    /// step only.
    bool body_states = true;
};

/// Records a World: made on a world, it takes its snapshot (World::snapshot); the world is then
/// changed through the Recorder's calls, which are World's own (the same arguments, results and
/// errors: see world.hpp) and each of which, once the world has accepted it, is appended to the
/// recording with its arguments. A call the world refuses (an exception) is not recorded: it
/// changed nothing. step also records the world's state hash after it (and, with
/// RecordOptions::body_states, its bodies' states).
///
/// The world is read through world() and changed only through the Recorder while it records:
/// a call made on the World itself is not in the recording, and a replay diverges where it
/// mattered. Functions cannot be recorded: a world with a custom filter
/// (World::set_custom_filter) or a body with a load function (World::set_load, BodyDef::load) is
/// refused (ValidationError, rule "recording"), by the constructor and by every call made while
/// it has one; set_custom_filter and set_load are not among the Recorder's calls. set_profiling
/// changes no bit of the simulation: call it on the World.
///
/// Recording costs nothing to a world that is not recorded (World's calls have no recording
/// branch); a recorded call costs its arguments' encoding, a step the state hash and the
/// bodies' states. The Recorder keeps a reference to the world: the world must outlive it and
/// not be moved while it records.
class TAMIAS2D_EXPORT Recorder {
  public:
    /// The version of the recording format this library writes and reads.
    static constexpr std::uint32_t format_version = 2;

    ~Recorder();
    Recorder(Recorder&&) noexcept;            ///< takes over the recording and the world
    Recorder& operator=(Recorder&&) noexcept; ///< takes over the recording and the world
    Recorder(const Recorder&) = delete;
    Recorder& operator=(const Recorder&) = delete;

    // The calls below may throw and are declared only when TAMIAS2D_EXCEPTIONS is 1 (config.hpp).
#if TAMIAS2D_EXCEPTIONS
    /// Starts recording `world` from its state now. Throws ValidationError (rule "recording")
    /// if the world has a custom filter or a body with a load function.
    explicit Recorder(World& world, RecordOptions options = {});

    /// The recorded world, to read.
    const World& world() const;
    /// The recording so far: a versioned header (magic "T2D-RECD", format version, library
    /// version, payload size, FNV-1a 64 checksum), then the snapshot and the records, all
    /// little-endian (docs/user-guide.md, "Recordings", has the format's table). May be taken
    /// at any time; recording goes on.
    std::vector<std::byte> bytes() const;
    /// The steps recorded so far.
    std::uint64_t steps() const;
    /// The calls recorded so far (steps included).
    std::uint64_t calls() const;

    // The recorded calls: World's mutating calls, each as world.hpp documents it (the same
    // arguments, result, errors and guarantee), recorded once the world has accepted it.
    /// World::create_body, recorded.
    BodyId create_body(const BodyDef& def);
    /// World::destroy_body, recorded.
    void destroy_body(BodyId body);
    /// World::create_shape, recorded.
    ShapeId create_shape(BodyId body, const ShapeDef& def);
    /// World::create_chain, recorded.
    std::vector<ShapeId> create_chain(BodyId body, std::span<const ShapeDef> segments);
    /// World::destroy_shape, recorded.
    void destroy_shape(ShapeId shape);
    /// World::set_filter, recorded.
    void set_filter(ShapeId shape, const Filter& filter);
    /// World::set_friction, recorded.
    void set_friction(ShapeId shape, double friction);
    /// World::set_restitution, recorded.
    void set_restitution(ShapeId shape, double restitution);
    /// World::set_density, recorded.
    void set_density(ShapeId shape, double density, bool update_body_mass = true);
    /// World::set_circle, recorded.
    void set_circle(ShapeId shape, const Circle& circle);
    /// World::set_capsule, recorded.
    void set_capsule(ShapeId shape, const Capsule& capsule);
    /// World::set_polygon, recorded.
    void set_polygon(ShapeId shape, const Polygon& polygon);
    /// World::set_segment, recorded.
    void set_segment(ShapeId shape, const Segment& segment);
    /// World::set_sensor, recorded.
    void set_sensor(ShapeId shape, bool is_sensor);
    /// World::step, recorded with the state hash after it (and the bodies' states,
    /// RecordOptions::body_states).
    void step(double dt);
    /// World::set_gravity, recorded.
    void set_gravity(Vec2d g);
    /// World::set_transform, recorded.
    void set_transform(BodyId body, Vec2d origin, double angle);
    /// World::set_velocity, recorded.
    void set_velocity(BodyId body, Vec2d v);
    /// World::set_angular_velocity, recorded.
    void set_angular_velocity(BodyId body, double omega);
    /// World::set_damping, recorded.
    void set_damping(BodyId body, double linear, double angular);
    /// World::set_force, recorded.
    void set_force(BodyId body, Vec2d force);
    /// World::set_torque, recorded.
    void set_torque(BodyId body, double torque);
    /// World::apply_force, recorded.
    void apply_force(BodyId body, Vec2d force, Vec2d world_point);
    /// World::apply_torque, recorded.
    void apply_torque(BodyId body, double torque);
    /// World::apply_impulse, recorded.
    void apply_impulse(BodyId body, Vec2d impulse, Vec2d world_point);
    /// World::create_joint, recorded.
    JointId create_joint(const RevoluteJointDef& def);
    /// World::create_joint, recorded.
    JointId create_joint(const DistanceJointDef& def);
    /// World::create_joint, recorded.
    JointId create_joint(const TargetJointDef& def);
    /// World::create_joint, recorded.
    JointId create_joint(const PrismaticJointDef& def);
    /// World::create_joint, recorded.
    JointId create_joint(const WeldJointDef& def);
    /// World::create_joint, recorded.
    JointId create_joint(const WheelJointDef& def);
    /// World::create_joint, recorded.
    JointId create_joint(const MotorJointDef& def);
    /// World::create_joint, recorded.
    JointId create_joint(const FilterJointDef& def);
    /// World::set_motor_joint_offsets, recorded.
    void set_motor_joint_offsets(JointId joint, Vec2d linear_offset, double angular_offset);
    /// World::set_joint_target, recorded.
    void set_joint_target(JointId joint, Vec2d target);
    /// World::destroy_joint, recorded.
    void destroy_joint(JointId joint);
    /// World::set_joint_motor_speed, recorded.
    void set_joint_motor_speed(JointId joint, double speed);
    /// World::enable_joint_limit, recorded.
    void enable_joint_limit(JointId joint, bool enable);
    /// World::set_joint_limits, recorded.
    void set_joint_limits(JointId joint, double lower, double upper);
    /// World::enable_joint_motor, recorded.
    void enable_joint_motor(JointId joint, bool enable);
    /// World::set_joint_max_motor_torque, recorded.
    void set_joint_max_motor_torque(JointId joint, double torque);
    /// World::set_joint_max_motor_force, recorded.
    void set_joint_max_motor_force(JointId joint, double force);
    /// World::enable_joint_spring, recorded.
    void enable_joint_spring(JointId joint, bool enable);
    /// World::set_joint_spring, recorded.
    void set_joint_spring(JointId joint, double hertz, double damping_ratio);
    /// World::set_joint_spring_target, recorded.
    void set_joint_spring_target(JointId joint, double target);
    /// World::set_distance_joint_length, recorded.
    void set_distance_joint_length(JointId joint, double length);
    /// World::set_constraint_tuning, recorded.
    void set_constraint_tuning(JointId joint, double hertz, double damping_ratio);
    /// World::set_joint_collide_connected, recorded.
    void set_joint_collide_connected(JointId joint, bool collide);
    /// World::set_joint_break_force, recorded.
    void set_joint_break_force(JointId joint, double force);
    /// World::set_joint_break_torque, recorded.
    void set_joint_break_torque(JointId joint, double torque);
    /// World::set_awake, recorded.
    void set_awake(BodyId body, bool awake);
    /// World::restore, recorded.
    void restore(std::span<const std::byte> snapshot);
    /// World::set_hit_event_threshold, recorded.
    void set_hit_event_threshold(double speed);
    /// World::set_hit_events_enabled, recorded.
    void set_hit_events_enabled(ShapeId shape, bool on);
    /// World::set_contact_events_enabled, recorded.
    void set_contact_events_enabled(ShapeId shape, bool on);
    /// World::set_sensor_events_enabled, recorded.
    void set_sensor_events_enabled(ShapeId shape, bool on);
    /// World::set_move_events_enabled, recorded.
    void set_move_events_enabled(BodyId body, bool on);
    /// World::set_joint_event_thresholds, recorded.
    void set_joint_event_thresholds(JointId joint, double force, double torque);
    /// World::explode, recorded.
    std::size_t explode(const ExplosionDef& def);
    /// World::set_user_data, recorded.
    void set_user_data(UserData data);
    /// World::set_user_data, recorded.
    void set_user_data(BodyId body, UserData data);
    /// World::set_user_data, recorded.
    void set_user_data(ShapeId shape, UserData data);
    /// World::set_user_data, recorded.
    void set_user_data(JointId joint, UserData data);
    /// World::set_body_type, recorded.
    void set_body_type(BodyId body, BodyType type);
    /// World::set_enabled, recorded.
    void set_enabled(BodyId body, bool enabled);
    /// World::set_gravity_scale, recorded.
    void set_gravity_scale(BodyId body, double scale);
    /// World::set_bullet, recorded.
    void set_bullet(BodyId body, bool bullet);
    /// World::set_motion_locks, recorded.
    void set_motion_locks(BodyId body, MotionLocks locks);
    /// World::set_fixed_rotation, recorded.
    void set_fixed_rotation(BodyId body, bool fixed);
    /// World::set_mass_data, recorded.
    void set_mass_data(BodyId body, const BodyMassData& data);
    /// World::reset_mass_data, recorded.
    void reset_mass_data(BodyId body);
    /// World::set_sleep_threshold, recorded.
    void set_sleep_threshold(BodyId body, double speed);
    /// World::wake_touching, recorded.
    void wake_touching(BodyId body);
    /// World::set_continuous, recorded.
    void set_continuous(bool enabled);
    /// World::set_sleeping, recorded.
    void set_sleeping(bool enabled);
    /// World::set_contact_tuning, recorded.
    void set_contact_tuning(double hertz, double damping_ratio, double push_max_velocity);
    /// World::set_joint_tuning, recorded.
    void set_joint_tuning(double hertz, double damping_ratio);
    /// World::set_restitution_threshold, recorded.
    void set_restitution_threshold(double speed);
    /// World::set_maximum_linear_speed, recorded.
    void set_maximum_linear_speed(double speed);
    /// World::set_workers, recorded.
    void set_workers(int workers);
    /// World::set_warm_starting, recorded.
    void set_warm_starting(bool enabled);
    /// World::set_user_material, recorded.
    void set_user_material(ShapeId shape, std::uint64_t id);
    /// World::set_target_transform, recorded.
    void set_target_transform(BodyId body, Vec2d origin, double angle, double dt);
    /// World::apply_wind, recorded.
    void apply_wind(ShapeId shape, Vec2d wind, double drag, double lift, bool wake = true);
    /// World::set_rolling_resistance, recorded.
    void set_rolling_resistance(ShapeId shape, double rolling_resistance);
    /// World::set_tangent_speed, recorded.
    void set_tangent_speed(ShapeId shape, double tangent_speed);
#endif // TAMIAS2D_EXCEPTIONS

    // The error-returning forms (result.hpp): each `try_` call is the call of the same name
    // (try_create: the constructor), returning its result or the Error its throwing form would
    // throw, instead of throwing. Declared whatever TAMIAS2D_EXCEPTIONS is.
    /// the constructor, returning its Error instead of throwing it.
    static Result<Recorder> try_create(World& world, RecordOptions options = {}) noexcept;
    /// world, returning its Error instead of throwing it.
    Result<const World*> try_world() const noexcept;
    /// bytes, returning its Error instead of throwing it.
    Result<std::vector<std::byte>> try_bytes() const noexcept;
    /// steps, returning its Error instead of throwing it.
    Result<std::uint64_t> try_steps() const noexcept;
    /// calls, returning its Error instead of throwing it.
    Result<std::uint64_t> try_calls() const noexcept;
    /// create_body, returning its Error instead of throwing it.
    Result<BodyId> try_create_body(const BodyDef& def) noexcept;
    /// destroy_body, returning its Error instead of throwing it.
    Result<void> try_destroy_body(BodyId body) noexcept;
    /// create_shape, returning its Error instead of throwing it.
    Result<ShapeId> try_create_shape(BodyId body, const ShapeDef& def) noexcept;
    /// create_chain, returning its Error instead of throwing it.
    Result<std::vector<ShapeId>> try_create_chain(BodyId body,
                                                  std::span<const ShapeDef> segments) noexcept;
    /// destroy_shape, returning its Error instead of throwing it.
    Result<void> try_destroy_shape(ShapeId shape) noexcept;
    /// set_filter, returning its Error instead of throwing it.
    Result<void> try_set_filter(ShapeId shape, const Filter& filter) noexcept;
    /// set_friction, returning its Error instead of throwing it.
    Result<void> try_set_friction(ShapeId shape, double friction) noexcept;
    /// set_restitution, returning its Error instead of throwing it.
    Result<void> try_set_restitution(ShapeId shape, double restitution) noexcept;
    /// set_rolling_resistance, returning its Error instead of throwing it.
    Result<void> try_set_rolling_resistance(ShapeId shape, double rolling_resistance) noexcept;
    /// set_tangent_speed, returning its Error instead of throwing it.
    Result<void> try_set_tangent_speed(ShapeId shape, double tangent_speed) noexcept;
    /// set_density, returning its Error instead of throwing it.
    Result<void> try_set_density(ShapeId shape, double density,
                                 bool update_body_mass = true) noexcept;
    /// set_circle, returning its Error instead of throwing it.
    Result<void> try_set_circle(ShapeId shape, const Circle& circle) noexcept;
    /// set_capsule, returning its Error instead of throwing it.
    Result<void> try_set_capsule(ShapeId shape, const Capsule& capsule) noexcept;
    /// set_polygon, returning its Error instead of throwing it.
    Result<void> try_set_polygon(ShapeId shape, const Polygon& polygon) noexcept;
    /// set_segment, returning its Error instead of throwing it.
    Result<void> try_set_segment(ShapeId shape, const Segment& segment) noexcept;
    /// set_sensor, returning its Error instead of throwing it.
    Result<void> try_set_sensor(ShapeId shape, bool is_sensor) noexcept;
    /// step, returning its Error instead of throwing it.
    Result<void> try_step(double dt) noexcept;
    /// set_gravity, returning its Error instead of throwing it.
    Result<void> try_set_gravity(Vec2d g) noexcept;
    /// set_transform, returning its Error instead of throwing it.
    Result<void> try_set_transform(BodyId body, Vec2d origin, double angle) noexcept;
    /// set_velocity, returning its Error instead of throwing it.
    Result<void> try_set_velocity(BodyId body, Vec2d v) noexcept;
    /// set_angular_velocity, returning its Error instead of throwing it.
    Result<void> try_set_angular_velocity(BodyId body, double omega) noexcept;
    /// set_damping, returning its Error instead of throwing it.
    Result<void> try_set_damping(BodyId body, double linear, double angular) noexcept;
    /// set_force, returning its Error instead of throwing it.
    Result<void> try_set_force(BodyId body, Vec2d force) noexcept;
    /// set_torque, returning its Error instead of throwing it.
    Result<void> try_set_torque(BodyId body, double torque) noexcept;
    /// apply_force, returning its Error instead of throwing it.
    Result<void> try_apply_force(BodyId body, Vec2d force, Vec2d world_point) noexcept;
    /// apply_torque, returning its Error instead of throwing it.
    Result<void> try_apply_torque(BodyId body, double torque) noexcept;
    /// apply_impulse, returning its Error instead of throwing it.
    Result<void> try_apply_impulse(BodyId body, Vec2d impulse, Vec2d world_point) noexcept;
    /// create_joint, returning its Error instead of throwing it.
    Result<JointId> try_create_joint(const RevoluteJointDef& def) noexcept;
    /// create_joint, returning its Error instead of throwing it.
    Result<JointId> try_create_joint(const DistanceJointDef& def) noexcept;
    /// create_joint, returning its Error instead of throwing it.
    Result<JointId> try_create_joint(const TargetJointDef& def) noexcept;
    /// create_joint, returning its Error instead of throwing it.
    Result<JointId> try_create_joint(const PrismaticJointDef& def) noexcept;
    /// create_joint, returning its Error instead of throwing it.
    Result<JointId> try_create_joint(const WeldJointDef& def) noexcept;
    /// create_joint, returning its Error instead of throwing it.
    Result<JointId> try_create_joint(const WheelJointDef& def) noexcept;
    /// create_joint, returning its Error instead of throwing it.
    Result<JointId> try_create_joint(const MotorJointDef& def) noexcept;
    /// create_joint, returning its Error instead of throwing it.
    Result<JointId> try_create_joint(const FilterJointDef& def) noexcept;
    /// set_motor_joint_offsets, returning its Error instead of throwing it.
    Result<void> try_set_motor_joint_offsets(JointId joint, Vec2d linear_offset,
                                             double angular_offset) noexcept;
    /// set_joint_target, returning its Error instead of throwing it.
    Result<void> try_set_joint_target(JointId joint, Vec2d target) noexcept;
    /// destroy_joint, returning its Error instead of throwing it.
    Result<void> try_destroy_joint(JointId joint) noexcept;
    /// set_joint_motor_speed, returning its Error instead of throwing it.
    Result<void> try_set_joint_motor_speed(JointId joint, double speed) noexcept;
    /// enable_joint_limit, returning its Error instead of throwing it.
    Result<void> try_enable_joint_limit(JointId joint, bool enable) noexcept;
    /// set_joint_limits, returning its Error instead of throwing it.
    Result<void> try_set_joint_limits(JointId joint, double lower, double upper) noexcept;
    /// enable_joint_motor, returning its Error instead of throwing it.
    Result<void> try_enable_joint_motor(JointId joint, bool enable) noexcept;
    /// set_joint_max_motor_torque, returning its Error instead of throwing it.
    Result<void> try_set_joint_max_motor_torque(JointId joint, double torque) noexcept;
    /// set_joint_max_motor_force, returning its Error instead of throwing it.
    Result<void> try_set_joint_max_motor_force(JointId joint, double force) noexcept;
    /// enable_joint_spring, returning its Error instead of throwing it.
    Result<void> try_enable_joint_spring(JointId joint, bool enable) noexcept;
    /// set_joint_spring, returning its Error instead of throwing it.
    Result<void> try_set_joint_spring(JointId joint, double hertz, double damping_ratio) noexcept;
    /// set_joint_spring_target, returning its Error instead of throwing it.
    Result<void> try_set_joint_spring_target(JointId joint, double target) noexcept;
    /// set_distance_joint_length, returning its Error instead of throwing it.
    Result<void> try_set_distance_joint_length(JointId joint, double length) noexcept;
    /// set_constraint_tuning, returning its Error instead of throwing it.
    Result<void> try_set_constraint_tuning(JointId joint, double hertz,
                                           double damping_ratio) noexcept;
    /// set_joint_collide_connected, returning its Error instead of throwing it.
    Result<void> try_set_joint_collide_connected(JointId joint, bool collide) noexcept;
    /// set_joint_break_force, returning its Error instead of throwing it.
    Result<void> try_set_joint_break_force(JointId joint, double force) noexcept;
    /// set_joint_break_torque, returning its Error instead of throwing it.
    Result<void> try_set_joint_break_torque(JointId joint, double torque) noexcept;
    /// set_awake, returning its Error instead of throwing it.
    Result<void> try_set_awake(BodyId body, bool awake) noexcept;
    /// restore, returning its Error instead of throwing it.
    Result<void> try_restore(std::span<const std::byte> snapshot) noexcept;
    /// set_hit_event_threshold, returning its Error instead of throwing it.
    Result<void> try_set_hit_event_threshold(double speed) noexcept;
    /// set_hit_events_enabled, returning its Error instead of throwing it.
    Result<void> try_set_hit_events_enabled(ShapeId shape, bool on) noexcept;
    /// set_contact_events_enabled, returning its Error instead of throwing it.
    Result<void> try_set_contact_events_enabled(ShapeId shape, bool on) noexcept;
    /// set_sensor_events_enabled, returning its Error instead of throwing it.
    Result<void> try_set_sensor_events_enabled(ShapeId shape, bool on) noexcept;
    /// set_move_events_enabled, returning its Error instead of throwing it.
    Result<void> try_set_move_events_enabled(BodyId body, bool on) noexcept;
    /// set_joint_event_thresholds, returning its Error instead of throwing it.
    Result<void> try_set_joint_event_thresholds(JointId joint, double force,
                                                double torque) noexcept;
    /// explode, returning its Error instead of throwing it.
    Result<std::size_t> try_explode(const ExplosionDef& def) noexcept;
    /// set_user_data, returning its Error instead of throwing it.
    Result<void> try_set_user_data(UserData data) noexcept;
    /// set_user_data, returning its Error instead of throwing it.
    Result<void> try_set_user_data(BodyId body, UserData data) noexcept;
    /// set_user_data, returning its Error instead of throwing it.
    Result<void> try_set_user_data(ShapeId shape, UserData data) noexcept;
    /// set_user_data, returning its Error instead of throwing it.
    Result<void> try_set_user_data(JointId joint, UserData data) noexcept;
    /// set_body_type, returning its Error instead of throwing it.
    Result<void> try_set_body_type(BodyId body, BodyType type) noexcept;
    /// set_enabled, returning its Error instead of throwing it.
    Result<void> try_set_enabled(BodyId body, bool enabled) noexcept;
    /// set_gravity_scale, returning its Error instead of throwing it.
    Result<void> try_set_gravity_scale(BodyId body, double scale) noexcept;
    /// set_bullet, returning its Error instead of throwing it.
    Result<void> try_set_bullet(BodyId body, bool bullet) noexcept;
    /// set_motion_locks, returning its Error instead of throwing it.
    Result<void> try_set_motion_locks(BodyId body, MotionLocks locks) noexcept;
    /// set_fixed_rotation, returning its Error instead of throwing it.
    Result<void> try_set_fixed_rotation(BodyId body, bool fixed) noexcept;
    /// set_mass_data, returning its Error instead of throwing it.
    Result<void> try_set_mass_data(BodyId body, const BodyMassData& data) noexcept;
    /// reset_mass_data, returning its Error instead of throwing it.
    Result<void> try_reset_mass_data(BodyId body) noexcept;
    /// set_sleep_threshold, returning its Error instead of throwing it.
    Result<void> try_set_sleep_threshold(BodyId body, double speed) noexcept;
    /// wake_touching, returning its Error instead of throwing it.
    Result<void> try_wake_touching(BodyId body) noexcept;
    /// set_continuous, returning its Error instead of throwing it.
    Result<void> try_set_continuous(bool enabled) noexcept;
    /// set_sleeping, returning its Error instead of throwing it.
    Result<void> try_set_sleeping(bool enabled) noexcept;
    /// set_contact_tuning, returning its Error instead of throwing it.
    Result<void> try_set_contact_tuning(double hertz, double damping_ratio,
                                        double push_max_velocity) noexcept;
    /// set_joint_tuning, returning its Error instead of throwing it.
    Result<void> try_set_joint_tuning(double hertz, double damping_ratio) noexcept;
    /// set_restitution_threshold, returning its Error instead of throwing it.
    Result<void> try_set_restitution_threshold(double speed) noexcept;
    /// set_maximum_linear_speed, returning its Error instead of throwing it.
    Result<void> try_set_maximum_linear_speed(double speed) noexcept;
    /// set_workers, returning its Error instead of throwing it.
    Result<void> try_set_workers(int workers) noexcept;
    /// set_warm_starting, returning its Error instead of throwing it.
    Result<void> try_set_warm_starting(bool enabled) noexcept;
    /// set_user_material, returning its Error instead of throwing it.
    Result<void> try_set_user_material(ShapeId shape, std::uint64_t id) noexcept;
    /// set_target_transform, returning its Error instead of throwing it.
    Result<void> try_set_target_transform(BodyId body, Vec2d origin, double angle,
                                          double dt) noexcept;
    /// apply_wind, returning its Error instead of throwing it.
    Result<void> try_apply_wind(ShapeId shape, Vec2d wind, double drag, double lift,
                                bool wake = true) noexcept;

    /// \cond INTERNAL
    struct Impl; // the recording's state (src/tamias2d/recording/recorder.cpp)
                 /// \endcond

  private:
    std::unique_ptr<Impl> impl_;
};

} // namespace tamias2d
