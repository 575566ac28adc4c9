// Recorder: a world's snapshot, then each call it accepts with its arguments (recorded_calls.hpp
// encodes them), each step with its outcome (recording_format.hpp has the layout).
#include "tamias2d/recorder.hpp"

#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <vector>

#include "tamias2d/errors.hpp"
#include "tamias2d/memory/allocator.hpp"
#include "tamias2d/recording/recorded_calls.hpp"
#include "tamias2d/recording/recording_format.hpp"
#include "tamias2d/world_impl.hpp"

namespace tamias2d {

using recording::Call;

struct Recorder::Impl : memory::HookAllocated<Recorder::Impl> {
    World* world = nullptr;
    RecordOptions options{};
    memory::vector<std::byte> payload;
    std::uint64_t steps = 0;
    std::uint64_t calls = 0;

    /// Refuses to go on while the world holds a function (it cannot be recorded).
    void check_world() const {
        if (const char* field = recording::recorded_function(*world))
            throw ValidationError(ValidationError::NotANumber{}, field,
                                  "must be empty while the world is recorded (a function cannot "
                                  "be recorded: docs/user-guide.md, \"Recordings\")",
                                  "recording");
    }

    /// A record's code and a place for its size.
    static SnapshotWriter begin(Call call) {
        SnapshotWriter w;
        w.u8(std::uint8_t(call));
        w.u32(0);
        return w;
    }
    /// The record's size in its place; room for it in the payload, so that appending it once
    /// the world has accepted the call cannot fail.
    void prepare(SnapshotWriter& w, std::size_t more = 0) {
        const std::size_t size = w.size() + more - recording::record_head;
        if (size > std::numeric_limits<std::uint32_t>::max())
            throw std::length_error("Recorder: a call's arguments exceed 4 GiB");
        for (int k = 0; k < 4; ++k)
            w.written()[std::size_t(1 + k)] = std::byte(size >> (8 * k));
        payload.reserve(payload.size() + w.size() + more);
        w.reserve(w.size() + more);
    }
    void commit(const SnapshotWriter& w) {
        const std::span<const std::byte> b = w.written();
        payload.insert(payload.end(), b.begin(), b.end());
        ++calls;
    }
};

namespace {

/// Records call C: its arguments encoded, the world's call made, the record appended if the
/// world accepted it.
template <Call C, class... A> auto record(Recorder::Impl& r, const A&... args) {
    constexpr auto member = recording::member_of<C>();
    using Result = typename recording::MemberTraits<std::remove_const_t<decltype(member)>>::Result;
    r.check_world();
    SnapshotWriter w = Recorder::Impl::begin(C);
    recording::write_arguments(w, args...);
    r.prepare(w);
    if constexpr (std::is_void_v<Result>) {
        (r.world->*member)(args...);
        r.commit(w);
    } else {
        Result out = (r.world->*member)(args...);
        r.commit(w);
        return out;
    }
}

} // namespace

Recorder::Recorder(World& world, RecordOptions options) : impl_(std::make_unique<Impl>()) {
    impl_->world = &world;
    impl_->options = options;
    impl_->check_world();
    SnapshotWriter snap;
    write_snapshot(RecordingAccess::impl(world), snap);
    const memory::vector<std::byte> snapshot = snap.finish();
    SnapshotWriter w;
    w.u32(options.body_states ? recording::flag_body_states : 0);
    w.u64(snapshot.size());
    w.append(snapshot);
    impl_->payload = w.finish();
}
Recorder::~Recorder() = default;
Recorder::Recorder(Recorder&&) noexcept = default;
Recorder& Recorder::operator=(Recorder&&) noexcept = default;

const World& Recorder::world() const {
    return *impl_->world;
}
std::uint64_t Recorder::steps() const {
    return impl_->steps;
}
std::uint64_t Recorder::calls() const {
    return impl_->calls;
}

std::vector<std::byte> Recorder::bytes() const {
    std::vector<std::byte> bytes; // the caller's (std::allocator)
    SnapshotWriter w(bytes);
    w.reserve(recording::header_size + impl_->payload.size());
    for (const char c : recording::magic)
        w.u8(std::uint8_t(c));
    w.u32(format_version);
    w.u32(recording::library_version_code);
    w.u64(impl_->payload.size());
    const std::uint64_t sum = recording::fnv1a_64(impl_->payload, recording::fnv1a_64(w.written()));
    w.u64(sum);
    w.append(impl_->payload);
    w.finish_in_storage();
    return bytes;
}

void Recorder::step(double dt) {
    Impl& r = *impl_;
    r.check_world();
    SnapshotWriter w = Impl::begin(Call::step);
    w("dt", dt);
    // The outcome's room: the hash, and the bodies (a step creates and destroys none).
    const std::size_t outcome =
        8 + (r.options.body_states ? 4 + recording::body_state_size * r.world->body_count() : 0);
    r.prepare(w, outcome);
    r.world->step(dt);
    w.u64(r.world->state_hash());
    if (r.options.body_states)
        recording::write_body_states(w, *r.world);
    r.commit(w);
    ++r.steps;
}

// --- the recorded calls (recorded_calls.hpp names their codes) ---

BodyId Recorder::create_body(const BodyDef& def) {
    return record<Call::create_body>(*impl_, def);
}
void Recorder::destroy_body(BodyId body) {
    record<Call::destroy_body>(*impl_, body);
}
ShapeId Recorder::create_shape(BodyId body, const ShapeDef& def) {
    return record<Call::create_shape>(*impl_, body, def);
}
std::vector<ShapeId> Recorder::create_chain(BodyId body, std::span<const ShapeDef> segments) {
    return record<Call::create_chain>(*impl_, body, segments);
}
void Recorder::destroy_shape(ShapeId shape) {
    record<Call::destroy_shape>(*impl_, shape);
}
void Recorder::set_filter(ShapeId shape, const Filter& filter) {
    record<Call::set_filter>(*impl_, shape, filter);
}
void Recorder::set_friction(ShapeId shape, double friction) {
    record<Call::set_friction>(*impl_, shape, friction);
}
void Recorder::set_rolling_resistance(ShapeId shape, double rolling_resistance) {
    record<Call::set_rolling_resistance>(*impl_, shape, rolling_resistance);
}
void Recorder::set_tangent_speed(ShapeId shape, double tangent_speed) {
    record<Call::set_tangent_speed>(*impl_, shape, tangent_speed);
}
void Recorder::set_restitution(ShapeId shape, double restitution) {
    record<Call::set_restitution>(*impl_, shape, restitution);
}
void Recorder::set_density(ShapeId shape, double density, bool update_body_mass) {
    record<Call::set_density>(*impl_, shape, density, update_body_mass);
}
void Recorder::set_circle(ShapeId shape, const Circle& circle) {
    record<Call::set_circle>(*impl_, shape, circle);
}
void Recorder::set_capsule(ShapeId shape, const Capsule& capsule) {
    record<Call::set_capsule>(*impl_, shape, capsule);
}
void Recorder::set_polygon(ShapeId shape, const Polygon& polygon) {
    record<Call::set_polygon>(*impl_, shape, polygon);
}
void Recorder::set_segment(ShapeId shape, const Segment& segment) {
    record<Call::set_segment>(*impl_, shape, segment);
}
void Recorder::set_sensor(ShapeId shape, bool is_sensor) {
    record<Call::set_sensor>(*impl_, shape, is_sensor);
}
void Recorder::set_gravity(Vec2d g) {
    record<Call::set_gravity>(*impl_, g);
}
void Recorder::set_transform(BodyId body, Vec2d origin, double angle) {
    record<Call::set_transform>(*impl_, body, origin, angle);
}
void Recorder::set_velocity(BodyId body, Vec2d v) {
    record<Call::set_velocity>(*impl_, body, v);
}
void Recorder::set_angular_velocity(BodyId body, double omega) {
    record<Call::set_angular_velocity>(*impl_, body, omega);
}
void Recorder::set_damping(BodyId body, double linear, double angular) {
    record<Call::set_damping>(*impl_, body, linear, angular);
}
void Recorder::set_force(BodyId body, Vec2d force) {
    record<Call::set_force>(*impl_, body, force);
}
void Recorder::set_torque(BodyId body, double torque) {
    record<Call::set_torque>(*impl_, body, torque);
}
void Recorder::apply_force(BodyId body, Vec2d force, Vec2d world_point) {
    record<Call::apply_force>(*impl_, body, force, world_point);
}
void Recorder::apply_torque(BodyId body, double torque) {
    record<Call::apply_torque>(*impl_, body, torque);
}
void Recorder::apply_impulse(BodyId body, Vec2d impulse, Vec2d world_point) {
    record<Call::apply_impulse>(*impl_, body, impulse, world_point);
}
JointId Recorder::create_joint(const RevoluteJointDef& def) {
    return record<Call::create_revolute_joint>(*impl_, def);
}
JointId Recorder::create_joint(const DistanceJointDef& def) {
    return record<Call::create_distance_joint>(*impl_, def);
}
JointId Recorder::create_joint(const TargetJointDef& def) {
    return record<Call::create_target_joint>(*impl_, def);
}
JointId Recorder::create_joint(const PrismaticJointDef& def) {
    return record<Call::create_prismatic_joint>(*impl_, def);
}
JointId Recorder::create_joint(const WeldJointDef& def) {
    return record<Call::create_weld_joint>(*impl_, def);
}
JointId Recorder::create_joint(const WheelJointDef& def) {
    return record<Call::create_wheel_joint>(*impl_, def);
}
JointId Recorder::create_joint(const MotorJointDef& def) {
    return record<Call::create_motor_joint>(*impl_, def);
}
JointId Recorder::create_joint(const FilterJointDef& def) {
    return record<Call::create_filter_joint>(*impl_, def);
}
void Recorder::set_motor_joint_offsets(JointId joint, Vec2d linear_offset, double angular_offset) {
    record<Call::set_motor_joint_offsets>(*impl_, joint, linear_offset, angular_offset);
}
void Recorder::set_joint_target(JointId joint, Vec2d target) {
    record<Call::set_joint_target>(*impl_, joint, target);
}
void Recorder::destroy_joint(JointId joint) {
    record<Call::destroy_joint>(*impl_, joint);
}
void Recorder::set_joint_motor_speed(JointId joint, double speed) {
    record<Call::set_joint_motor_speed>(*impl_, joint, speed);
}
void Recorder::enable_joint_limit(JointId joint, bool enable) {
    record<Call::enable_joint_limit>(*impl_, joint, enable);
}
void Recorder::set_joint_limits(JointId joint, double lower, double upper) {
    record<Call::set_joint_limits>(*impl_, joint, lower, upper);
}
void Recorder::enable_joint_motor(JointId joint, bool enable) {
    record<Call::enable_joint_motor>(*impl_, joint, enable);
}
void Recorder::set_joint_max_motor_torque(JointId joint, double torque) {
    record<Call::set_joint_max_motor_torque>(*impl_, joint, torque);
}
void Recorder::set_joint_max_motor_force(JointId joint, double force) {
    record<Call::set_joint_max_motor_force>(*impl_, joint, force);
}
void Recorder::enable_joint_spring(JointId joint, bool enable) {
    record<Call::enable_joint_spring>(*impl_, joint, enable);
}
void Recorder::set_joint_spring(JointId joint, double hertz, double damping_ratio) {
    record<Call::set_joint_spring>(*impl_, joint, hertz, damping_ratio);
}
void Recorder::set_joint_spring_target(JointId joint, double target) {
    record<Call::set_joint_spring_target>(*impl_, joint, target);
}
void Recorder::set_distance_joint_length(JointId joint, double length) {
    record<Call::set_distance_joint_length>(*impl_, joint, length);
}
void Recorder::set_constraint_tuning(JointId joint, double hertz, double damping_ratio) {
    record<Call::set_constraint_tuning>(*impl_, joint, hertz, damping_ratio);
}
void Recorder::set_joint_collide_connected(JointId joint, bool collide) {
    record<Call::set_joint_collide_connected>(*impl_, joint, collide);
}
void Recorder::set_joint_break_force(JointId joint, double force) {
    record<Call::set_joint_break_force>(*impl_, joint, force);
}
void Recorder::set_joint_break_torque(JointId joint, double torque) {
    record<Call::set_joint_break_torque>(*impl_, joint, torque);
}
void Recorder::set_awake(BodyId body, bool awake) {
    record<Call::set_awake>(*impl_, body, awake);
}
void Recorder::restore(std::span<const std::byte> snapshot) {
    record<Call::restore>(*impl_, snapshot);
}
void Recorder::set_hit_event_threshold(double speed) {
    record<Call::set_hit_event_threshold>(*impl_, speed);
}
void Recorder::set_hit_events_enabled(ShapeId shape, bool on) {
    record<Call::set_hit_events_enabled>(*impl_, shape, on);
}
void Recorder::set_contact_events_enabled(ShapeId shape, bool on) {
    record<Call::set_contact_events_enabled>(*impl_, shape, on);
}
void Recorder::set_sensor_events_enabled(ShapeId shape, bool on) {
    record<Call::set_sensor_events_enabled>(*impl_, shape, on);
}
void Recorder::set_move_events_enabled(BodyId body, bool on) {
    record<Call::set_move_events_enabled>(*impl_, body, on);
}
void Recorder::set_joint_event_thresholds(JointId joint, double force, double torque) {
    record<Call::set_joint_event_thresholds>(*impl_, joint, force, torque);
}
std::size_t Recorder::explode(const ExplosionDef& def) {
    return record<Call::explode>(*impl_, def);
}
void Recorder::set_user_data(UserData data) {
    record<Call::set_world_user_data>(*impl_, data);
}
void Recorder::set_user_data(BodyId body, UserData data) {
    record<Call::set_body_user_data>(*impl_, body, data);
}
void Recorder::set_user_data(ShapeId shape, UserData data) {
    record<Call::set_shape_user_data>(*impl_, shape, data);
}
void Recorder::set_user_data(JointId joint, UserData data) {
    record<Call::set_joint_user_data>(*impl_, joint, data);
}
void Recorder::set_body_type(BodyId body, BodyType type) {
    record<Call::set_body_type>(*impl_, body, type);
}
void Recorder::set_enabled(BodyId body, bool enabled) {
    record<Call::set_enabled>(*impl_, body, enabled);
}
void Recorder::set_gravity_scale(BodyId body, double scale) {
    record<Call::set_gravity_scale>(*impl_, body, scale);
}
void Recorder::set_bullet(BodyId body, bool bullet) {
    record<Call::set_bullet>(*impl_, body, bullet);
}
void Recorder::set_motion_locks(BodyId body, MotionLocks locks) {
    record<Call::set_motion_locks>(*impl_, body, locks);
}
void Recorder::set_fixed_rotation(BodyId body, bool fixed) {
    record<Call::set_fixed_rotation>(*impl_, body, fixed);
}
void Recorder::set_mass_data(BodyId body, const BodyMassData& data) {
    record<Call::set_mass_data>(*impl_, body, data);
}
void Recorder::reset_mass_data(BodyId body) {
    record<Call::reset_mass_data>(*impl_, body);
}
void Recorder::set_sleep_threshold(BodyId body, double speed) {
    record<Call::set_sleep_threshold>(*impl_, body, speed);
}
void Recorder::set_warm_starting(bool enabled) {
    record<Call::set_warm_starting>(*impl_, enabled);
}
void Recorder::set_user_material(ShapeId shape, std::uint64_t id) {
    record<Call::set_user_material>(*impl_, shape, id);
}
void Recorder::set_target_transform(BodyId body, Vec2d origin, double angle, double dt) {
    record<Call::set_target_transform>(*impl_, body, origin, angle, dt);
}
void Recorder::apply_wind(ShapeId shape, Vec2d wind, double drag, double lift, bool wake) {
    record<Call::apply_wind>(*impl_, shape, wind, drag, lift, wake);
}
void Recorder::wake_touching(BodyId body) {
    record<Call::wake_touching>(*impl_, body);
}
void Recorder::set_continuous(bool enabled) {
    record<Call::set_continuous>(*impl_, enabled);
}
void Recorder::set_sleeping(bool enabled) {
    record<Call::set_sleeping>(*impl_, enabled);
}
void Recorder::set_contact_tuning(double hertz, double damping_ratio, double push_max_velocity) {
    record<Call::set_contact_tuning>(*impl_, hertz, damping_ratio, push_max_velocity);
}
void Recorder::set_joint_tuning(double hertz, double damping_ratio) {
    record<Call::set_joint_tuning>(*impl_, hertz, damping_ratio);
}
void Recorder::set_restitution_threshold(double speed) {
    record<Call::set_restitution_threshold>(*impl_, speed);
}
void Recorder::set_maximum_linear_speed(double speed) {
    record<Call::set_maximum_linear_speed>(*impl_, speed);
}
void Recorder::set_workers(int workers) {
    record<Call::set_workers>(*impl_, workers);
}

} // namespace tamias2d
