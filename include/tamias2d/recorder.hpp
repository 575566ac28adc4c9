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

#include "tamias2d/export.hpp"
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

    /// Starts recording `world` from its state now. Throws ValidationError (rule "recording")
    /// if the world has a custom filter or a body with a load function.
    explicit Recorder(World& world, RecordOptions options = {});
    ~Recorder();
    Recorder(Recorder&&) noexcept;            ///< takes over the recording and the world
    Recorder& operator=(Recorder&&) noexcept; ///< takes over the recording and the world
    Recorder(const Recorder&) = delete;
    Recorder& operator=(const Recorder&) = delete;

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

    /// \cond INTERNAL
    struct Impl; // the recording's state (src/tamias2d/recording/recorder.cpp)
                 /// \endcond

  private:
    std::unique_ptr<Impl> impl_;
};

} // namespace tamias2d
