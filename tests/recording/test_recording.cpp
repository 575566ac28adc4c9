// Recordings: a run recorded through a Recorder replays with the same bits, and a replay that
// departs from its recording names the first step, body and field.
//
// Oracle: the recorded run itself: its state hash and its bodies' states after every step, which
// the Recorder writes from the world it records (World::state_hash and the bodies' own values),
// against the replayed world's; for a perturbed recording, the step and the body the
// perturbation touches, known from how the test made it. The recording's bytes are read by this
// file's own walk of the documented format (docs/user-guide.md, "Recordings") with its own
// FNV-1a 64, not by the library's reader. A determinism property of the engine, not an SRS item:
// the `determinism` tag; the refusals are the `reliability` tag.
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "tamias2d/io/scene.hpp"
#include "tamias2d/recorder.hpp"
#include "tamias2d/recording/recorded_calls.hpp"
#include "tamias2d/replay.hpp"
#include "tamias2d/world.hpp"

namespace utf = boost::unit_test;
namespace fs = std::filesystem;
using namespace tamias2d;

namespace {

using Bytes = std::vector<std::byte>;

std::uint64_t fnv1a(const std::byte* p, std::size_t n, std::uint64_t h) {
    for (std::size_t k = 0; k < n; ++k) {
        h ^= std::uint64_t(p[k]);
        h *= 0x100000001b3ull;
    }
    return h;
}

/// The checksum made right after a change: FNV-1a 64 of the header's first 24 bytes, then the
/// payload (the documented layout).
void fix_checksum(Bytes& b) {
    const std::uint64_t h =
        fnv1a(b.data() + 32, b.size() - 32, fnv1a(b.data(), 24, 0xcbf29ce484222325ull));
    for (int k = 0; k < 8; ++k)
        b[std::size_t(24 + k)] = std::byte(h >> (8 * k));
}

std::uint64_t le(const Bytes& b, std::size_t at, int n) {
    std::uint64_t v = 0;
    for (int k = 0; k < n; ++k)
        v |= std::uint64_t(b[at + std::size_t(k)]) << (8 * k);
    return v;
}

/// The records as the format lays them out: (code, offset of the arguments, size).
struct RawRecord {
    std::uint8_t code;
    std::size_t offset;
    std::size_t size;
};
std::vector<RawRecord> walk(const Bytes& b) {
    std::size_t at = 32 + 4; // the header, the flags
    const std::size_t snapshot = std::size_t(le(b, at, 8));
    at += 8 + snapshot;
    std::vector<RawRecord> out;
    while (at < b.size()) {
        const auto code = std::uint8_t(b[at]);
        const auto size = std::size_t(le(b, at + 1, 4));
        out.push_back({code, at + 5, size});
        at += 5 + size;
    }
    BOOST_REQUIRE_EQUAL(at, b.size());
    return out;
}

std::uint8_t code_of(std::string_view name) {
    const auto& names = tamias2d::recording::call_names;
    return std::uint8_t(std::find(names.begin(), names.end(), name) - names.begin());
}

BodyDef dynamic_at(Vec2d p) {
    BodyDef d;
    d.position = p;
    return d;
}

/// Three balls far apart in free fall over a ground: the middle one is given an impulse after
/// step 7. Returns the recording and the ball's handle.
Bytes three_balls(RecordOptions options, BodyId* kicked = nullptr) {
    World world;
    Recorder rec(world, options);
    BodyDef ground;
    ground.type = BodyType::static_body;
    rec.create_shape(rec.create_body(ground), box_shape(200.0, 1.0));
    BodyId balls[3];
    for (int k = 0; k < 3; ++k) {
        balls[k] = rec.create_body(dynamic_at({-20.0 + 20.0 * k, 10.0}));
        rec.create_shape(balls[k], circle_shape(0.5));
    }
    for (int s = 1; s <= 20; ++s) {
        if (s == 8)
            rec.apply_impulse(balls[1], {3.0, 1.0}, rec.world().position(balls[1]));
        rec.step(1.0 / 60.0);
    }
    if (kicked)
        *kicked = balls[1];
    return rec.bytes();
}

} // namespace

BOOST_AUTO_TEST_SUITE(recordings)

// Oracle: the recorded state hash and body states of every step; every recorded call of the
// library's list made once (the list's size from recorded_calls.hpp), on 1 and 3 workers.
BOOST_AUTO_TEST_CASE(every_recorded_call_replays_with_the_same_bits, *utf::label("determinism")) {
    WorldDef wd;
    wd.enable_sleep = true;
    World world(wd);
    Recorder rec(world);
    const double dt = 1.0 / 60.0;
    BodyDef sd;
    sd.type = BodyType::static_body;
    const BodyId ground = rec.create_body(sd);
    rec.create_shape(ground, box_shape(40.0, 1.0));
    const ShapeId seg = rec.create_shape(ground, segment_shape({-20.0, 3.0}, {-15.0, 3.0}));
    const BodyId terrain = rec.create_body(sd);
    const Vec2d pts[] = {{10.0, 0.5}, {12.0, 1.0}, {14.0, 0.5}, {16.0, 1.5}};
    rec.create_chain(terrain, chain_shapes(pts, false));
    BodyId b[8];
    ShapeId s[8];
    for (int k = 0; k < 8; ++k) {
        b[k] = rec.create_body(dynamic_at({-8.0 + 2.0 * k, 2.0 + 0.3 * k}));
        s[k] = k % 3 == 0   ? rec.create_shape(b[k], box_shape(0.8, 0.8))
               : k % 3 == 1 ? rec.create_shape(b[k], circle_shape(0.4))
                            : rec.create_shape(b[k], capsule_shape({-0.3, 0.0}, {0.3, 0.0}, 0.2));
    }
    RevoluteJointDef rj{.body_a = b[0], .body_b = b[1], .anchor = {-7.0, 2.2}};
    const JointId rev = rec.create_joint(rj);
    DistanceJointDef dj{
        .body_a = b[1], .body_b = b[2], .anchor_a = {-6.0, 2.3}, .anchor_b = {-4.0, 2.6}};
    const JointId dist = rec.create_joint(dj);
    const JointId target = rec.create_joint(TargetJointDef{.body = b[3], .target = {-2.0, 3.0}});
    PrismaticJointDef pj{.body_a = ground, .body_b = b[4], .anchor = {0.0, 3.2}};
    const JointId pri = rec.create_joint(pj);
    rec.create_joint(WeldJointDef{.body_a = b[5], .body_b = b[6], .anchor = {3.0, 3.6}});
    rec.create_joint(WheelJointDef{.body_a = b[6], .body_b = b[7], .anchor = {5.0, 4.1}});
    const JointId motor = rec.create_joint(MotorJointDef{.body_a = ground, .body_b = b[5]});
    const JointId filt = rec.create_joint(FilterJointDef{.body_a = b[0], .body_b = b[7]});
    for (int k = 0; k < 10; ++k)
        rec.step(dt);
    const Bytes snap = rec.world().snapshot();
    // Shapes.
    rec.set_filter(s[0], Filter{0x2, 0xFFFF, 0});
    rec.set_friction(s[1], 0.7);
    rec.set_restitution(s[1], 0.3);
    rec.set_density(s[0], 2.0);
    rec.set_circle(s[1], Circle{{0.0, 0.0}, 0.45});
    rec.set_capsule(s[2], Capsule{{-0.25, 0.0}, {0.25, 0.0}, 0.25});
    rec.set_polygon(s[0], box_shape(0.9, 0.7).geometry.polygon);
    rec.set_segment(seg, Segment{{-20.0, 3.5}, {-15.0, 3.0}});
    rec.set_sensor(s[3], true);
    rec.step(dt);
    // Bodies and loads.
    rec.set_gravity({0.5, -9.0});
    rec.set_transform(b[2], {-4.0, 3.0}, 0.2);
    rec.set_velocity(b[2], {0.5, 0.0});
    rec.set_angular_velocity(b[2], 1.0);
    rec.set_damping(b[2], 0.1, 0.2);
    rec.set_force(b[3], {1.0, 0.0});
    rec.set_torque(b[3], 0.5);
    rec.apply_force(b[4], {2.0, 0.0}, {0.0, 3.0});
    rec.apply_torque(b[4], 0.3);
    rec.apply_impulse(b[5], {0.2, 0.1}, {3.0, 3.6});
    rec.set_awake(b[6], true);
    rec.step(dt);
    // Joints.
    rec.set_motor_joint_offsets(motor, {3.0, 3.0}, 0.1);
    rec.set_joint_target(target, {-2.0, 3.5});
    rec.set_joint_motor_speed(rev, 1.0);
    rec.enable_joint_limit(rev, true);
    rec.set_joint_limits(rev, -0.5, 0.5);
    rec.enable_joint_motor(rev, true);
    rec.set_joint_max_motor_torque(rev, 10.0);
    rec.set_joint_max_motor_force(pri, 5.0);
    rec.set_joint_spring(rev, 2.0, 0.5);
    rec.enable_joint_spring(rev, true);
    rec.set_joint_spring_target(rev, 0.1);
    rec.set_distance_joint_length(dist, 1.8);
    rec.set_constraint_tuning(rev, 30.0, 1.0);
    rec.set_joint_collide_connected(rev, true);
    rec.set_joint_break_force(rev, 1e6);
    rec.set_joint_break_torque(rev, 1e6);
    rec.set_joint_event_thresholds(dist, 100.0, 100.0);
    rec.step(dt);
    // Events, explosion, user data.
    rec.set_hit_event_threshold(0.5);
    rec.set_hit_events_enabled(s[0], true);
    rec.set_contact_events_enabled(s[1], false);
    rec.set_sensor_events_enabled(s[2], false);
    rec.set_move_events_enabled(b[2], true);
    rec.explode(ExplosionDef{.position = {-3.0, 1.0}, .radius = 3.0, .impulse_per_length = 0.2});
    rec.set_user_data(UserData{7});
    rec.set_user_data(b[1], UserData{8});
    rec.set_user_data(s[1], UserData{9});
    rec.set_user_data(filt, UserData{10});
    rec.step(dt);
    // Body controls.
    rec.set_body_type(b[7], BodyType::kinematic);
    rec.set_target_transform(b[7], {6.0, 4.5}, 0.3, dt);
    rec.step(dt);
    rec.set_body_type(b[7], BodyType::dynamic);
    rec.set_enabled(b[6], false);
    rec.step(dt);
    rec.set_enabled(b[6], true);
    rec.set_gravity_scale(b[2], 0.5);
    rec.set_bullet(b[2], true);
    rec.set_motion_locks(b[4], MotionLocks{false, true, false});
    rec.set_fixed_rotation(b[3], true);
    rec.set_mass_data(b[2], BodyMassData{2.0, {0.05, 0.0}, 0.4});
    rec.step(dt);
    rec.reset_mass_data(b[2]);
    rec.set_sleep_threshold(b[1], 0.1);
    rec.wake_touching(ground);
    // World settings.
    rec.set_continuous(false);
    rec.set_sleeping(false);
    rec.set_contact_tuning(30.0, 5.0, 2.0);
    rec.set_joint_tuning(50.0, 1.5);
    rec.set_restitution_threshold(0.5);
    rec.set_maximum_linear_speed(100.0);
    rec.set_workers(2);
    rec.set_warm_starting(false);
    rec.step(dt);
    rec.set_warm_starting(true);
    rec.set_user_material(s[1], 7);
    rec.apply_wind(s[2], {4.0, 0.0}, 1.0, 0.5);
    rec.set_rolling_resistance(s[1], 0.2);
    rec.set_tangent_speed(s[0], 1.5);
    for (int k = 0; k < 5; ++k)
        rec.step(dt);
    // Destruction, then the state of step 10 again.
    rec.destroy_joint(filt);
    rec.destroy_shape(seg);
    rec.destroy_body(b[7]);
    rec.step(dt);
    rec.restore(snap);
    for (int k = 0; k < 5; ++k)
        rec.step(dt);

    const Bytes bytes = rec.bytes();
    std::set<std::string_view> seen;
    for (const RecordedCall& c : recorded_calls(bytes))
        seen.insert(c.name);
    BOOST_TEST(seen.size() == tamias2d::recording::call_names.size());
    for (const std::string_view name : tamias2d::recording::call_names)
        BOOST_TEST(seen.count(name) == 1u, name);
    for (const int workers : {1, 3}) {
        const ReplayReport r = replay(bytes, workers);
        BOOST_TEST(r.matched(), (r.divergence ? r.divergence->message : ""));
        BOOST_TEST(r.steps == rec.steps());
        BOOST_TEST(r.calls == rec.calls());
        BOOST_TEST(r.recorded_steps == rec.steps());
    }
}

// Oracle: the recorded hashes and states; every example scene (but spinning, whose loads are
// functions) for up to 60 steps, with an impulse, a gravity change, a new body and a destroyed
// body mid-run, replayed on 1 and 4 workers.
BOOST_AUTO_TEST_CASE(example_scenes_replay_with_the_same_bits, *utf::label("determinism")) {
    std::vector<fs::path> scenes;
    for (const auto& e : fs::directory_iterator(TAMIAS_EXAMPLE_SCENES))
        if (e.path().extension() == ".json")
            scenes.push_back(e.path());
    std::sort(scenes.begin(), scenes.end());
    for (const fs::path& path : scenes) {
        const io::Scene scene = io::load_scene(path);
        const std::string name = path.stem().string();
        if (name == "spinning" || name == "large_pyramid" || name == "rain")
            continue; // (load functions; the two largest: their size, not their kind)
        World world(scene.world);
        const std::vector<BodyId> ids = io::build_world(scene, world);
        Recorder rec(world);
        BodyId dynamic{};
        for (const BodyId id : ids)
            if (world.type(id) == BodyType::dynamic)
                dynamic = id;
        for (int s = 1; s <= 60; ++s) {
            if (s == 15 && world.is_valid(dynamic))
                rec.apply_impulse(dynamic, {0.5, 1.0}, world.position(dynamic));
            if (s == 25)
                rec.set_gravity({1.0, -9.0});
            if (s == 35)
                rec.create_shape(rec.create_body(dynamic_at({0.0, 30.0})), circle_shape(0.3));
            if (s == 45 && world.is_valid(dynamic))
                rec.destroy_body(dynamic);
            rec.step(scene.dt);
        }
        for (const int workers : {1, 4}) {
            const ReplayReport r = replay(rec.bytes(), workers);
            BOOST_TEST(r.matched(), name << ": " << (r.divergence ? r.divergence->message : ""));
            BOOST_TEST(r.steps == 60u, name);
        }
    }
}

// Oracle: the impulse given to the middle ball before step 8 (its x component's lowest bit
// flipped in the bytes, the checksum made right): the replay departs at step 8, at that ball
// (the others fly apart from it and touch nothing), in a field its velocity changes.
BOOST_AUTO_TEST_CASE(a_flipped_impulse_bit_is_found_at_its_step_and_body,
                     *utf::label("determinism")) {
    BodyId kicked;
    Bytes bytes = three_balls({}, &kicked);
    BOOST_TEST_REQUIRE(replay(bytes).matched());
    const std::vector<RawRecord> records = walk(bytes);
    const auto impulse = std::find_if(records.begin(), records.end(), [](const RawRecord& r) {
        return r.code == code_of("apply_impulse");
    });
    BOOST_REQUIRE(impulse != records.end());
    // Arguments: the body (index, generation), then impulse.x.
    bytes[impulse->offset + 8] ^= std::byte{1};
    fix_checksum(bytes);
    const ReplayReport r = replay(bytes);
    BOOST_TEST_REQUIRE(!r.matched());
    const ReplayDivergence& d = *r.divergence;
    BOOST_TEST(d.step == 8u);
    BOOST_TEST_REQUIRE(d.body.has_value());
    BOOST_TEST(d.body->index == kicked.index);
    BOOST_TEST(d.body->generation == kicked.generation);
    BOOST_TEST((d.field == "position.x" || d.field == "linear_velocity.x"), d.field);
    BOOST_TEST(d.recorded_bits != d.replayed_bits);
    BOOST_TEST(d.message.find("step 8: body " + std::to_string(kicked.index)) == 0u, d.message);
    BOOST_TEST(r.steps == 8u);
}

// Oracle: step 5's dt with its mantissa's bit 24 flipped (a relative change of 2^-28; the lowest
// bit may round away in the velocities and leave only the time different): every falling ball
// moves differently in that step, so the replay departs at step 5 at the first ball in slot order
// (the static ground, slot 0, does not move).
BOOST_AUTO_TEST_CASE(a_flipped_dt_bit_is_found_at_its_step, *utf::label("determinism")) {
    Bytes bytes = three_balls({});
    const std::vector<RawRecord> records = walk(bytes);
    int steps = 0;
    for (const RawRecord& rec : records)
        if (rec.code == code_of("step") && ++steps == 5) {
            bytes[rec.offset + 3] ^= std::byte{1};
            break;
        }
    fix_checksum(bytes);
    const ReplayReport r = replay(bytes);
    BOOST_TEST_REQUIRE(!r.matched());
    BOOST_TEST(r.divergence->step == 5u);
    BOOST_TEST_REQUIRE(r.divergence->body.has_value());
    BOOST_TEST(r.divergence->body->index == 1u);
}

// Oracle: the same perturbation without body states: the step is found, no body is named (the
// recording holds none), and the recording is smaller by the bodies' 56 bytes a step.
BOOST_AUTO_TEST_CASE(without_body_states_the_step_is_found, *utf::label("determinism")) {
    Bytes bytes = three_balls(RecordOptions{.body_states = false});
    BOOST_TEST(bytes.size() + 20 * (4 + 4 * 56) == three_balls({}).size());
    BOOST_TEST_REQUIRE(replay(bytes).matched());
    for (const RawRecord& rec : walk(bytes))
        if (rec.code == code_of("apply_impulse"))
            bytes[rec.offset + 8] ^= std::byte{1};
    fix_checksum(bytes);
    const ReplayReport r = replay(bytes);
    BOOST_TEST_REQUIRE(!r.matched());
    BOOST_TEST(r.divergence->step == 8u);
    BOOST_TEST(!r.divergence->body.has_value());
    BOOST_TEST(r.divergence->field == "state_hash");
}

// Oracle: the documented header: each defect named by its field, nothing replayed.
BOOST_AUTO_TEST_CASE(a_defective_recording_is_refused, *utf::label("reliability")) {
    const Bytes good = three_balls({});
    auto refused_at = [](const Bytes& b, const std::string& field) {
        try {
            Replayer r(b);
            BOOST_ERROR("accepted, expected a refusal at " << field);
        } catch (const RecordingError& e) {
            BOOST_TEST(e.field == field, e.what());
        }
    };
    Bytes b = good;
    b[100] ^= std::byte{0x10};
    refused_at(b, "header.checksum");
    refused_at(Bytes(good.begin(), good.end() - 3), "header.payload_size");
    refused_at(Bytes(good.begin(), good.begin() + 10), "header");
    World w;
    refused_at(w.snapshot(), "header.magic");
    b = good;
    b[8] = std::byte{99};
    refused_at(b, "header.format_version");
    b = good; // a call code beyond the list, checksum made right
    b[walk(good)[0].offset - 5] = std::byte{250};
    fix_checksum(b);
    refused_at(b, "records[0]");
    b = good; // a byte of the embedded snapshot changed, the recording's checksum made right:
    // the snapshot's own checksum refuses it (at offset 44: the header, flags, snapshot size)
    b[44 + 40] ^= std::byte{0x01};
    fix_checksum(b);
    try {
        Replayer r(b);
        BOOST_ERROR("a recording with a changed snapshot was accepted");
    } catch (const RecordingError& e) {
        BOOST_TEST(e.field.rfind("snapshot.", 0) == 0u, e.what());
        BOOST_TEST(e.offset >= 44u, e.what());
    }
    b = good; // a record's size pointing past the end
    b[walk(good)[0].offset - 4] = std::byte{0xFF};
    b[walk(good)[0].offset - 3] = std::byte{0xFF};
    fix_checksum(b);
    refused_at(b, "records[0]");
}

// Oracle: the world's state hash and the recording's bytes before the refused call.
BOOST_AUTO_TEST_CASE(a_refused_call_is_not_recorded_and_changes_nothing,
                     *utf::label("reliability")) {
    World world;
    Recorder rec(world);
    const BodyId body = rec.create_body(dynamic_at({0.0, 1.0}));
    const ShapeId shape = rec.create_shape(body, circle_shape(0.5));
    rec.step(0.01);
    const Bytes before = rec.bytes();
    const std::uint64_t hash = world.state_hash();
    BOOST_CHECK_THROW(rec.set_friction(shape, -1.0), ValidationError);
    BOOST_CHECK_THROW(rec.step(-1.0), ValidationError);
    BOOST_CHECK_THROW(rec.destroy_body(BodyId{}), InvalidHandle);
    BOOST_TEST(rec.bytes() == before);
    BOOST_TEST(world.state_hash() == hash);
    BOOST_TEST(replay(rec.bytes()).matched());
}

// Oracle: the documented rule: a function cannot be recorded, so a world holding one is
// refused (ValidationError naming it), leaving the world and the recording as they were.
BOOST_AUTO_TEST_CASE(functions_are_refused, *utf::label("reliability")) {
    {
        World world;
        world.set_custom_filter([](ShapeId, ShapeId) { return true; });
        try {
            Recorder rec(world);
            BOOST_ERROR("a world with a custom filter was recorded");
        } catch (const ValidationError& e) {
            BOOST_TEST(e.field == "world.custom_filter");
        }
    }
    World world;
    Recorder rec(world);
    const BodyId body = rec.create_body(dynamic_at({0.0, 1.0}));
    BodyDef loaded = dynamic_at({1.0, 1.0});
    loaded.load = [](double) { return Load{}; };
    const Bytes before = rec.bytes();
    try {
        rec.create_body(loaded);
        BOOST_ERROR("a body with a load function was recorded");
    } catch (const ValidationError& e) {
        BOOST_TEST(e.field == "body.load");
    }
    BOOST_TEST(world.body_count() == 1u);
    world.set_load(body, [](double) { return Load{}; }); // on the World itself: no recording
    const std::uint64_t hash = world.state_hash();
    BOOST_CHECK_THROW(rec.step(0.01), ValidationError);
    BOOST_TEST(world.state_hash() == hash);
    BOOST_TEST(rec.bytes() == before);
}

// Oracle: recording changes nothing: the same calls on an unrecorded world give the same state
// hash after every step.
BOOST_AUTO_TEST_CASE(recording_changes_no_bit, *utf::label("determinism")) {
    World plain;
    World recorded;
    Recorder rec(recorded);
    for (World* w : {&plain}) {
        const BodyId b = w->create_body(dynamic_at({0.0, 2.0}));
        w->create_shape(b, box_shape(1.0, 1.0));
    }
    const BodyId b = rec.create_body(dynamic_at({0.0, 2.0}));
    rec.create_shape(b, box_shape(1.0, 1.0));
    for (int s = 0; s < 30; ++s) {
        plain.step(0.01);
        rec.step(0.01);
        BOOST_TEST(plain.state_hash() == recorded.state_hash());
    }
}

// Oracle: the recorded state hash and body states of every step. Definitions whose every
// optional field is set (a disabled body, motion locks, a sleep threshold, a user material id,
// a rolling resistance and a tangent speed, the pre-solve switch off, a joint's spring target
// and own tuning) replay as made: a field the codec left at its
// default would change the replayed world's hash at the first step.
BOOST_AUTO_TEST_CASE(every_definition_field_replays, *utf::label("determinism")) {
    World world;
    Recorder rec(world);
    BodyDef sd;
    sd.type = BodyType::static_body;
    const BodyId ground = rec.create_body(sd);
    rec.create_shape(ground, box_shape(40.0, 1.0));
    BodyDef a = dynamic_at({-2.0, 2.0});
    a.motion_locks = {true, false, false};
    a.sleep_threshold = 0.2;
    BodyDef b = dynamic_at({2.0, 2.0});
    b.motion_locks = {false, false, true};
    BodyDef off = dynamic_at({6.0, 2.0});
    off.enabled = false;
    const BodyId ba = rec.create_body(a);
    const BodyId bb = rec.create_body(b);
    rec.create_body(off);
    ShapeDef shape = box_shape(0.8, 0.8);
    shape.material.user_material_id = 42;
    shape.enable_pre_solve = false;
    rec.create_shape(ba, shape);
    Material rolling{.friction = 0.5};
    rolling.rolling_resistance = 0.1; // DD46, DD47: in the recorded definition too
    rolling.tangent_speed = -0.5;
    rec.create_shape(bb, circle_shape(0.4, rolling));
    RevoluteJointDef rj{.body_a = ba, .body_b = bb, .anchor = {0.0, 2.0}};
    rj.enable_spring = true;
    rj.hertz = 2.0;
    rj.damping_ratio = 0.5;
    rj.spring_target = 0.3;
    rj.constraint_tuning = ConstraintTuning{40.0, 2.0};
    rec.create_joint(rj);
    for (int k = 0; k < 30; ++k)
        rec.step(1.0 / 60.0);
    const ReplayReport r = replay(rec.bytes());
    BOOST_TEST(r.matched(), (r.divergence ? r.divergence->message : ""));
    BOOST_TEST(r.steps == 30u);
}

// Oracle: the documented refusal: callbacks cannot be recorded.
BOOST_AUTO_TEST_CASE(hook_functions_are_refused, *utf::label("reliability")) {
    World pre;
    pre.set_pre_solve([](const PreSolveContact&) { return true; });
    BOOST_CHECK_EXCEPTION(Recorder{pre}, ValidationError,
                          [](const ValidationError& e) { return e.field == "world.pre_solve"; });
    World mixed;
    mixed.set_friction_mixing([](double x, std::uint64_t, double, std::uint64_t) { return x; });
    BOOST_CHECK_EXCEPTION(Recorder{mixed}, ValidationError, [](const ValidationError& e) {
        return e.field == "world.friction_mixing";
    });
    World bouncy;
    bouncy.set_restitution_mixing([](double x, std::uint64_t, double, std::uint64_t) { return x; });
    BOOST_CHECK_EXCEPTION(Recorder{bouncy}, ValidationError, [](const ValidationError& e) {
        return e.field == "world.restitution_mixing";
    });
}

// Oracle: the recording's promise (recorder.hpp): it holds the world's snapshot as
// World::snapshot gives it, byte for byte, and replays with the recorded bits. Checked for every
// snapshot size from 4070 to 4120 bytes (a body's name sets it to the byte), around the end of
// the recorder's first block of storage, which the snapshot reaches as the block fills.
BOOST_AUTO_TEST_CASE(a_snapshot_of_any_size_near_a_block_end_is_recorded_whole,
                     *utf::label("determinism")) {
    const auto make = [](std::size_t name_length, World& w) {
        for (int k = 0; k < 3; ++k) {
            BodyDef d = dynamic_at({3.0 * k, 2.0});
            d.name = k == 0 ? std::string(name_length, 'n') : "";
            w.create_shape(w.create_body(d), circle_shape(0.5));
        }
    };
    World unnamed;
    make(0, unnamed);
    const std::size_t base = unnamed.snapshot().size();
    BOOST_TEST_REQUIRE(base < 4070u);
    for (std::size_t size = 4070; size <= 4120; ++size) {
        BOOST_TEST_CONTEXT("snapshot of " << size << " bytes") {
            World world;
            make(size - base, world);
            const Bytes snapshot = world.snapshot();
            BOOST_TEST_REQUIRE(snapshot.size() == size);
            Recorder rec(world);
            rec.step(1.0 / 60.0);
            const Bytes recording = rec.bytes();
            const auto at =
                std::search(recording.begin(), recording.end(), snapshot.begin(), snapshot.end());
            BOOST_TEST((at != recording.end()), "the snapshot, whole, in the recording");
            Replayer replay(recording);
            BOOST_TEST(!replay.advance().has_value());
            BOOST_TEST(replay.world().state_hash() == world.state_hash());
        }
    }
}

BOOST_AUTO_TEST_SUITE_END()
