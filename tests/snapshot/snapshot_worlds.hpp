// The worlds the snapshot tests take snapshots of: every example scene, and random worlds of
// every shape kind, joint kind, sensors, sleeping on or off, destroyed bodies and shapes (free
// slots), persistent and one-step loads, changed filters.
#pragma once

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "tamias2d/io/scene.hpp"
#include "tamias2d/world.hpp"

namespace snapshot_test {

using namespace tamias2d;
namespace fs = std::filesystem;

inline std::vector<fs::path> example_scenes() {
    std::vector<fs::path> scenes;
    for (const auto& e : fs::directory_iterator(TAMIAS_EXAMPLE_SCENES))
        if (e.path().extension() == ".json")
            scenes.push_back(e.path());
    std::sort(scenes.begin(), scenes.end());
    return scenes;
}

/// Steps of a scene the tests run: the two largest are cut short (as the golden hashes are).
inline int steps_for(const std::string& scene, int scene_steps) {
    if (scene == "large_pyramid")
        return std::min(scene_steps, 40);
    if (scene == "rain")
        return std::min(scene_steps, 120);
    return scene_steps;
}

/// A uniform double in [lo, hi) from the generator's raw output (the standard's distributions
/// are not fixed across libraries; this is).
inline double uniform(std::mt19937_64& r, double lo, double hi) {
    return lo + (hi - lo) * double(r() >> 11) * 0x1.0p-53;
}
inline int pick(std::mt19937_64& r, int n) {
    return int(r() % std::uint64_t(n));
}

/// A random world of `seed`: a ground, 6 to 30 bodies of every shape kind (some bullets, some
/// damped, some kinematic), joints of every kind between them, sensors, a few bodies and shapes
/// destroyed (their slots free), loads, filters; sleeping on for odd seeds. From a stream of
/// their own, the settings changed after creation, each of which changes later steps (so a
/// snapshot that lost one would not continue with the same bits): joints' break torques,
/// thresholds, own tuning, spring targets, limits and a distance joint's motor; shapes with hit
/// events and bodies with move events (the events of the step after the snapshot are part of
/// its state); bodies' gravity scales, motion locks, enabled flags, mass data and sleep
/// thresholds; the world's hit threshold and maximum linear speed; user data everywhere.
inline World random_world(std::uint64_t seed, int workers = 1) {
    std::mt19937_64 r(seed);
    std::mt19937_64 c(seed * 104729 + 17); // the controls' stream
    WorldDef def;
    def.enable_sleep = (seed & 1) != 0;
    def.workers = workers;
    def.substeps = 1 + pick(r, 4);
    if (pick(r, 3) == 0)
        def.manifold_reuse_distance = 0.0;
    if (pick(c, 2) == 0)
        def.hit_event_threshold = uniform(c, 0.1, 1.0);
    World w(def);
    w.set_user_data(UserData(seed));
    if (pick(c, 2) == 0)
        w.set_maximum_linear_speed(uniform(c, 2.0, 6.0));
    BodyDef ground_def;
    ground_def.type = BodyType::static_body;
    const BodyId ground = w.create_body(ground_def);
    w.create_shape(ground, segment_shape({-20.0, 0.0}, {20.0, 0.0}, {1.0, 0.1, 0.6}));
    const std::vector<Vec2d> chain = {{-20.0, 5.0}, {-19.0, 0.5}, {19.0, 0.5}, {20.0, 5.0}};
    w.create_chain(ground, chain_shapes(chain, false, {1.0, 0.0, 0.5}));
    std::vector<BodyId> bodies;
    const int n = 6 + pick(r, 25);
    for (int i = 0; i < n; ++i) {
        BodyDef b;
        b.type = pick(r, 10) == 0 ? BodyType::kinematic : BodyType::dynamic;
        b.position = {uniform(r, -8.0, 8.0), uniform(r, 0.8, 10.0)};
        b.angle = uniform(r, -3.0, 3.0);
        b.linear_velocity = {uniform(r, -2.0, 2.0), uniform(r, -2.0, 2.0)};
        b.angular_velocity = uniform(r, -2.0, 2.0);
        b.bullet = pick(r, 6) == 0;
        b.fixed_rotation = pick(r, 12) == 0;
        if (pick(r, 4) == 0) {
            b.linear_damping = uniform(r, 0.0, 0.5);
            b.angular_damping = uniform(r, 0.0, 0.5);
        }
        if (pick(r, 8) == 0)
            b.force = {uniform(r, -5.0, 5.0), 0.0};
        if (pick(r, 3) == 0)
            b.name = std::string("b").append(std::to_string(i));
        b.enable_move_events = pick(c, 3) == 0;
        b.user_data = UserData(1000 + i);
        const BodyId id = w.create_body(b);
        const Material m{uniform(r, 0.5, 2.0), pick(r, 3) == 0 ? uniform(r, 0.0, 0.8) : 0.0,
                         uniform(r, 0.0, 0.9)};
        switch (pick(r, 4)) {
        case 0:
            w.create_shape(id, circle_shape(uniform(r, 0.2, 0.6), m));
            break;
        case 1:
            w.create_shape(id, box_shape(uniform(r, 0.3, 1.2), uniform(r, 0.3, 1.2), m));
            break;
        case 2:
            w.create_shape(id, capsule_shape({-0.4, 0.0}, {0.4, 0.0}, uniform(r, 0.1, 0.3), m));
            break;
        default: {
            const std::vector<Vec2d> pts = {{-0.5, -0.3}, {0.6, -0.2}, {0.3, 0.5}, {-0.4, 0.4}};
            w.create_shape(id, polygon_shape(pts, m));
            w.create_shape(id, circle_shape(0.2, m, {0.6, 0.0}));
        }
        }
        if (pick(r, 7) == 0) {
            ShapeDef sensor = circle_shape(1.0);
            sensor.is_sensor = true;
            w.create_shape(id, sensor);
        }
        if (pick(c, 3) == 0) { // a shape with hit events, another with contact events off
            ShapeDef hit = circle_shape(0.15, m, {-0.3, 0.0});
            hit.enable_hit_events = true;
            hit.enable_contact_events = pick(c, 2) == 0;
            hit.user_data = UserData(2000 + i);
            w.create_shape(id, hit);
        }
        bodies.push_back(id);
    }
    // Joints of every kind, between neighbours (so that they hold, and some pile up).
    for (int i = 0; i + 1 < n; i += 1 + pick(r, 3)) {
        const BodyId a = bodies[std::size_t(i)], b = bodies[std::size_t(i) + 1];
        if (w.type(a) != BodyType::dynamic || w.type(b) != BodyType::dynamic)
            continue;
        const Vec2d pa = w.position(a), pb = w.position(b);
        const Vec2d mid = 0.5 * (pa + pb);
        JointId j{};
        switch (pick(r, 8)) {
        case 0:
            j = w.create_joint(RevoluteJointDef{.body_a = a, .body_b = b, .anchor = mid});
            break;
        case 1:
            j = w.create_joint(DistanceJointDef{
                .body_a = a, .body_b = b, .anchor_a = pa, .anchor_b = pb, .hertz = 2.0});
            break;
        case 2:
            j = w.create_joint(WeldJointDef{.body_a = a, .body_b = b, .anchor = mid});
            break;
        case 3:
            j = w.create_joint(PrismaticJointDef{.body_a = a,
                                                 .body_b = b,
                                                 .anchor = mid,
                                                 .enable_limit = true,
                                                 .lower_translation = -1.0,
                                                 .upper_translation = 1.0});
            break;
        case 4:
            j = w.create_joint(WheelJointDef{.body_a = a, .body_b = b, .anchor = pb});
            break;
        case 5:
            j = w.create_joint(
                MotorJointDef{.body_a = a, .body_b = b, .linear_offset = {1.0, 0.0}});
            break;
        case 6:
            j = w.create_joint(FilterJointDef{.body_a = a, .body_b = b});
            break;
        default:
            if (w.type(b) == BodyType::dynamic)
                j = w.create_joint(TargetJointDef{.body = b, .target = pb + Vec2d{0.5, 0.5}});
        }
        if (!w.is_valid(j))
            continue;
        // The joint's settings changed after creation, from the controls' stream.
        const JointKind kind = w.joint_kind(j);
        w.set_user_data(j, UserData(3000 + i));
        if (kind == JointKind::filter)
            continue;
        if (kind != JointKind::target && kind != JointKind::motor && pick(c, 3) == 0)
            w.set_constraint_tuning(j, uniform(c, 5.0, 40.0), uniform(c, 0.2, 2.0));
        if (kind != JointKind::distance && kind != JointKind::target && pick(c, 3) == 0)
            w.set_joint_break_torque(j, uniform(c, 5.0, 60.0));
        if (pick(c, 3) == 0)
            w.set_joint_event_thresholds(j, uniform(c, 1.0, 20.0), uniform(c, 1.0, 20.0));
        if (kind == JointKind::distance) {
            w.enable_joint_motor(j, true);
            w.set_joint_motor_speed(j, uniform(c, -1.0, 1.0));
            w.set_joint_max_motor_force(j, uniform(c, 1.0, 30.0));
            w.set_joint_limits(j, 0.5, 3.0);
        }
        if ((kind == JointKind::revolute || kind == JointKind::prismatic) && pick(c, 2) == 0) {
            w.set_joint_spring(j, uniform(c, 1.0, 5.0), 0.5);
            w.set_joint_spring_target(j, uniform(c, -0.5, 0.5));
        }
    }
    // Free slots: a few bodies and shapes destroyed, a filter changed.
    for (int k = 0; k < 2; ++k) {
        const std::size_t i = std::size_t(pick(r, int(bodies.size())));
        if (w.is_valid(bodies[i]))
            w.destroy_body(bodies[i]);
    }
    for (const BodyId b : bodies) {
        if (!w.is_valid(b))
            continue;
        const auto shapes = w.shapes(b);
        if (shapes.size() > 1 && pick(r, 2) == 0)
            w.destroy_shape(shapes.back());
        if (pick(r, 9) == 0)
            w.set_filter(shapes.front(), Filter{2, 0xFFFFFFFD, 0});
        if (w.type(b) == BodyType::dynamic && pick(r, 9) == 0)
            w.apply_force(b, {1.0, 2.0}, w.position(b) + Vec2d{0.1, 0.0});
        // Body controls, from the controls' stream.
        if (pick(c, 4) == 0)
            w.set_gravity_scale(b, uniform(c, -0.5, 2.0));
        if (pick(c, 6) == 0)
            w.set_motion_locks(b, MotionLocks{pick(c, 2) == 0, pick(c, 2) == 0, pick(c, 3) == 0});
        if (pick(c, 10) == 0)
            w.set_enabled(b, false);
        if (w.type(b) == BodyType::dynamic && pick(c, 6) == 0)
            w.set_mass_data(b, BodyMassData{uniform(c, 0.5, 3.0),
                                            {uniform(c, -0.2, 0.2), uniform(c, -0.2, 0.2)},
                                            uniform(c, 0.2, 1.0)});
        if (pick(c, 5) == 0)
            w.set_sleep_threshold(b, uniform(c, 0.01, 0.5));
    }
    return w;
}

} // namespace snapshot_test
