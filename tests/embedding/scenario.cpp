#include "embedding/scenario.hpp"

#include <array>
#include <cmath>

#include "tamias2d/joint_def.hpp"
#include "tamias2d/recorder.hpp"
#include "tamias2d/replay.hpp"
#include "tamias2d/world.hpp"

namespace tamias2d::test {

ScenarioInput scenario_input(int workers) {
    ScenarioInput in;
    in.workers = workers;
    // A wavy chain ground right of the flat one (both sides of a chain are exercised by the
    // bodies resting and rolling on it).
    std::array<Vec2d, 12> points{};
    for (std::size_t i = 0; i < points.size(); ++i)
        points[i] = {10.0 + 2.0 * double(i), 0.3 * std::sin(0.7 * double(i))};
    in.chain = chain_shapes(points, false);
    in.buffer.reserve(std::size_t(1) << 20);
    return in;
}

namespace {

constexpr double dt = 1.0 / 60.0;

BodyDef at(Vec2d p, BodyType type = BodyType::dynamic) {
    BodyDef d;
    d.type = type;
    d.position = p;
    return d;
}

void count_events(const World& world, ScenarioResult& r) {
    r.begin_events += world.contact_begin_events().size();
    r.end_events += world.contact_end_events().size();
    r.sensor_begins += world.sensor_begin_events().size();
    r.hit_events += world.contact_hit_events().size();
    r.move_events += world.body_move_events().size();
    r.joint_events += world.joint_events().size();
}

void note_hash(const World& world, ScenarioResult& r) {
    if (r.hash_count < r.hashes.size())
        r.hashes[r.hash_count++] = world.state_hash();
}

} // namespace

ScenarioResult run_scenario(ScenarioInput& in) {
    ScenarioResult r;
    WorldDef def;
    def.workers = in.workers;
    def.task_system = in.task_system;
    def.enable_sleep = true;
    World world(def);

    // Ground: a flat box, a chain, a thin static wall (a segment) for the bullet, a sensor.
    const BodyId ground = world.create_body(at({0.0, 0.0}, BodyType::static_body));
    const Material wood{1.0, 0.0, 0.6};
    world.create_shape(ground, box_shape(20.0, 1.0, wood, {0.0, -0.5}));
    r.chain_ids = world.create_chain(ground, in.chain).size();
    const ShapeId wall = world.create_shape(ground, segment_shape({-8.0, 0.0}, {-8.0, 6.0}));
    ShapeDef sensor_def = box_shape(2.0, 2.0, {}, {4.0, 1.0});
    sensor_def.is_sensor = true;
    world.create_shape(ground, sensor_def);

    // Every shape kind on dynamic bodies: a crate (polygon), a ball (circle), a capsule; the
    // ball reports hits and moves.
    const BodyId crate = world.create_body(at({0.0, 0.5}));
    const ShapeId crate_shape = world.create_shape(crate, box_shape(1.0, 1.0, wood));
    BodyDef ball_def = at({4.0, 3.0});
    ball_def.enable_move_events = true;
    const BodyId ball = world.create_body(ball_def);
    ShapeDef ball_shape = circle_shape(0.4, wood);
    ball_shape.enable_hit_events = true;
    world.create_shape(ball, ball_shape);
    const BodyId pill = world.create_body(at({2.0, 1.0}));
    world.create_shape(pill, capsule_shape({-0.4, 0.0}, {0.4, 0.0}, 0.25, wood));
    // The roller resists rolling and drives its contacts (DD46, DD47): the per-contact arrays
    // of surface motion come from the hook too.
    Material rubber = wood;
    rubber.rolling_resistance = 0.2;
    rubber.tangent_speed = 0.5;
    const BodyId roller = world.create_body(at({14.0, 2.0}));
    world.create_shape(roller, circle_shape(0.3, rubber));

    // A bullet fired at the thin wall: continuous collision must hold it in front.
    BodyDef bullet_def = at({-4.0, 3.0});
    bullet_def.linear_velocity = {-300.0, 0.0};
    bullet_def.gravity_scale = 0.0;
    bullet_def.bullet = true;
    const BodyId bullet = world.create_body(bullet_def);
    world.create_shape(bullet, circle_shape(0.05, wood));

    // Every joint kind, on a rig of its own above the ground.
    std::array<BodyId, 9> links{};
    for (std::size_t k = 0; k < links.size(); ++k) {
        links[k] = world.create_body(at({-6.0 + 0.6 * double(k), 8.0}));
        world.create_shape(links[k], box_shape(0.4, 0.2, wood));
    }
    std::array<JointId, 8> joints{};
    const BodyId anchor = ground;
    joints[0] = world.create_joint(
        RevoluteJointDef{.body_a = anchor, .body_b = links[0], .anchor = {-6.0, 8.0}});
    joints[1] = world.create_joint(DistanceJointDef{
        .body_a = links[0], .body_b = links[1], .anchor_a = {-6.0, 8.0}, .anchor_b = {-5.4, 8.0}});
    joints[2] = world.create_joint(TargetJointDef{.body = links[2], .target = {-4.8, 8.5}});
    joints[3] = world.create_joint(
        PrismaticJointDef{.body_a = links[2], .body_b = links[3], .anchor = {-4.5, 8.0}});
    joints[4] = world.create_joint(
        WeldJointDef{.body_a = links[3], .body_b = links[4], .anchor = {-3.9, 8.0}});
    joints[5] = world.create_joint(
        WheelJointDef{.body_a = links[4], .body_b = links[5], .anchor = {-3.0, 8.0}});
    joints[6] = world.create_joint(MotorJointDef{.body_a = links[5], .body_b = links[6]});
    joints[7] = world.create_joint(FilterJointDef{.body_a = links[6], .body_b = links[7]});

    // Stored callbacks, small enough for std::function to keep in itself (a pointer).
    std::size_t* pre_solves = &r.pre_solve_calls;
    world.set_pre_solve([pre_solves](const PreSolveContact&) {
        ++*pre_solves;
        return true;
    });
    std::size_t* filters = &r.filter_calls;
    world.set_custom_filter([filters](ShapeId, ShapeId) {
        ++*filters;
        return true;
    });

    // Contacts, events, joints, continuous collision: one second.
    for (int i = 0; i < 60; ++i) {
        world.step(dt);
        count_events(world, r);
    }
    note_hash(world, r);
    r.bullet_held = world.position(bullet).x > -8.0;
    // Half the rig's joints destroyed, then its bodies with the other half (joint events).
    for (std::size_t k = 0; k < joints.size() / 2; ++k)
        world.destroy_joint(joints[k]);
    for (const BodyId b : links)
        world.destroy_body(b);
    r.joint_events += world.joint_events().size();
    world.destroy_body(bullet);
    // Sleeping: three more seconds.
    for (int i = 0; i < 180; ++i) {
        world.step(dt);
        count_events(world, r);
    }
    note_hash(world, r);
    r.crate_slept = !world.is_awake(crate);

    // Queries, in their callback and into-a-buffer forms.
    const QueryFilter all{};
    world.ray_cast({0.0, 5.0}, {0.0, -10.0}, all, [&](const RayCastHit& h) {
        ++r.ray_hits;
        return h.fraction;
    });
    world.query_aabb(Aabb{-10.0, -1.0, 10.0, 3.0}, all, [&](ShapeId) {
        ++r.aabb_hits;
        return true;
    });
    world.query_point({0.0, 0.5}, all, [&](ShapeId) {
        ++r.point_hits;
        return true;
    });
    world.overlap_shape(circle_shape(1.0).geometry, {0.0, 0.5}, 0.0, all, [&](ShapeId) {
        ++r.overlap_hits;
        return true;
    });
    world.shape_cast(circle_shape(0.2).geometry, {0.0, 5.0}, 0.0, {0.0, -10.0}, all,
                     [&](const ShapeCastHit& h) {
                         ++r.cast_hits;
                         return h.fraction;
                     });
    std::array<RayCastHit, 8> hits{};
    r.span_hits = world.ray_cast_all({-10.0, 0.5}, {30.0, 0.0}, all, hits);
    r.distance = world.distance(crate_shape, wall).distance;

    // A snapshot into the caller's reserved vector, some steps, the restore.
    world.snapshot(in.buffer);
    r.snapshot_size = in.buffer.size();
    const std::uint64_t at_snapshot = world.state_hash();
    for (int i = 0; i < 10; ++i)
        world.step(dt);
    world.restore(in.buffer);
    r.restored_equal = world.state_hash() == at_snapshot;
    note_hash(world, r);

    // A Recorder (it refuses a world holding functions): a few recorded steps.
    world.set_pre_solve({});
    world.set_custom_filter({});
    world.set_awake(crate, true);
    {
        Recorder recorder(world);
        for (int i = 0; i < 10; ++i)
            recorder.step(dt);
        r.recorder_steps = recorder.steps();
        // The recording (by value: the caller's), replayed step by step.
        const std::vector<std::byte> recording = recorder.bytes();
        Replayer replayer(recording, in.workers, in.task_system);
        while (!replayer.done())
            if (!replayer.advance())
                ++r.replayed_steps;
    }
    note_hash(world, r);

    world.destroy_body(ball);
    world.destroy_body(pill);
    world.step(dt);
    note_hash(world, r);
    return r;
}

} // namespace tamias2d::test
