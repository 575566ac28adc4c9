// A small game level written from docs/user-guide.md alone, driving the world at run time as a
// game does: a trapdoor crate turned from static to dynamic, an icy crate (its friction changed)
// sliding through a pickup zone, a ball that grows (its geometry changed), a piston locked to
// its axis, a door whose hinge gets a motor, wider limits and a spring, a hidden platform
// switched on, and a lamp whose body is destroyed. The game keeps its objects in an
// std::unordered_map keyed by body handles, finds them from a query through shape -> body ->
// user data, and reacts to hit, move, sensor and joint events. Every promise the guide makes
// that the level can observe is checked; the program exits with 1 if one is broken.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <unordered_map>

#include "tamias2d/tamias2d.hpp"

using namespace tamias2d;

namespace {

struct Entity {
    std::string name;
    int hits = 0;        // hit events it took part in
    int moves = 0;       // move events reported for it
    bool asleep = false; // a move event said it fell asleep
    bool in_zone = false;
};

int broken = 0, kept = 0;

void promise(bool ok, const char* what) {
    if (ok) {
        ++kept;
    } else {
        ++broken;
        std::printf("BROKEN: %s\n", what);
    }
}

constexpr double dt = 1.0 / 60.0;

} // namespace

int main() {
    World world(WorldDef{.enable_sleep = true});
    const double g = -world.gravity().y; // m/s^2, the default gravity's magnitude
    std::unordered_map<BodyId, Entity> entities;
    // The game's object for a body: kept in the map, and tied to the body through user data.
    const auto add = [&](BodyId body, const char* name) {
        Entity& e = entities[body];
        e.name = name;
        world.set_user_data(body, reinterpret_cast<UserData>(&e));
        return body;
    };
    const auto entity_of_shape = [&](ShapeId s) {
        return reinterpret_cast<Entity*>(world.user_data(world.body(s)));
    };
    const Material wood{1.0, 0.0, 0.6}; // density, restitution, friction

    BodyDef def;
    def.type = BodyType::static_body;
    def.position = {0.0, -0.5};
    const BodyId ground = add(world.create_body(def), "ground");
    world.create_shape(ground, box_shape(80.0, 1.0, wood)); // top face at y = 0

    // A pickup zone on the icy crate's path.
    def.position = {-30.0, 1.0};
    const BodyId zone_body = add(world.create_body(def), "zone");
    ShapeDef zone_shape = box_shape(1.0, 2.0);
    zone_shape.is_sensor = true;
    const ShapeId zone = world.create_shape(zone_body, zone_shape);

    // A hidden platform, made disabled: no query finds it until it is enabled.
    def.position = {-5.0, 3.0};
    def.enabled = false;
    const BodyId platform = add(world.create_body(def), "platform");
    world.create_shape(platform, box_shape(2.0, 0.2, wood));
    def.enabled = true;

    // The trapdoor crate: static (held in the air) until the game drops it.
    def.position = {15.0, 6.0};
    def.enable_move_events = true;
    const BodyId trapdoor = add(world.create_body(def), "trapdoor crate");
    ShapeDef crate_shape = box_shape(1.0, 1.0, wood);
    crate_shape.enable_hit_events = true;
    world.create_shape(trapdoor, crate_shape);
    def.enable_move_events = false;

    // Two crates sliding at 5 m/s; one of them is made icy.
    def.type = BodyType::dynamic;
    def.position = {-38.0, 0.5};
    def.linear_velocity = {5.0, 0.0};
    def.enable_move_events = true;
    const BodyId icy = add(world.create_body(def), "icy crate");
    const ShapeId icy_shape = world.create_shape(icy, box_shape(1.0, 1.0, wood));
    def.enable_move_events = false;
    def.position = {31.0, 0.5};
    const BodyId rough = add(world.create_body(def), "rough crate");
    world.create_shape(rough, box_shape(1.0, 1.0, wood));
    def.linear_velocity = {};

    // A ball that will grow.
    def.position = {28.0, 0.25};
    const BodyId grower = add(world.create_body(def), "growing ball");
    const ShapeId grower_shape = world.create_shape(grower, circle_shape(0.25, wood));

    // A piston that only moves up and down, and a ball thrown at it.
    def.position = {10.0, 0.5};
    def.motion_locks = MotionLocks{.linear_x = true, .angular = true};
    const BodyId piston = add(world.create_body(def), "piston");
    world.create_shape(piston, box_shape(1.0, 1.0, wood));
    def.motion_locks = {};
    def.position = {7.0, 0.25};
    def.linear_velocity = {6.0, 0.0};
    const BodyId ball = add(world.create_body(def), "ball");
    ShapeDef ball_shape = circle_shape(0.25, Material{1.0, 0.3, 0.2});
    ball_shape.enable_hit_events = true;
    world.create_shape(ball, ball_shape);
    def.linear_velocity = {};

    // A door on a hinge, floating (gravity scale 0), its angle limited to [-0.5, 0.5] rad.
    def.type = BodyType::static_body;
    def.position = {20.0, 5.0};
    const BodyId post = add(world.create_body(def), "door post");
    def.type = BodyType::dynamic;
    def.position = {21.0, 5.0};
    def.gravity_scale = 0.0;
    const BodyId door = add(world.create_body(def), "door");
    world.create_shape(door, box_shape(2.0, 0.2, wood));
    def.gravity_scale = 1.0;
    RevoluteJointDef hinge_def{.body_a = post, .body_b = door, .anchor = {20.0, 5.0}};
    hinge_def.enable_limit = true;
    hinge_def.lower_angle = -0.5;
    hinge_def.upper_angle = 0.5;
    hinge_def.torque_threshold = 10.0; // N m: report a hard push
    const JointId hinge = world.create_joint(hinge_def);

    // A lamp hanging from a beam.
    def.type = BodyType::static_body;
    def.position = {25.0, 8.0};
    const BodyId beam = add(world.create_body(def), "beam");
    world.create_shape(beam, box_shape(1.0, 0.2));
    def.type = BodyType::dynamic;
    def.position = {25.0, 7.0};
    const BodyId lamp = add(world.create_body(def), "lamp");
    world.create_shape(lamp, circle_shape(0.3));
    const JointId lamp_joint = world.create_joint(DistanceJointDef{
        .body_a = beam, .body_b = lamp, .anchor_a = {25.0, 8.0}, .anchor_b = {25.0, 7.0}});

    // Material: the icy crate's friction goes to 0 (the pair's is the geometric mean: 0).
    world.set_friction(icy_shape, 0.0);
    promise(world.friction(icy_shape) == 0.0, "the friction set is read back");

    // The hidden platform is out of every query.
    const Aabb platform_box{-5.5, 2.8, -4.5, 3.2};
    promise(world.query_aabb(platform_box).empty(), "a disabled body's shapes are not queried");

    bool zone_entered = false, zone_left = false, hinge_pushed = false, lamp_gone = false;
    int trapdoor_moves_while_static = 0;
    double trapdoor_hit_speed = 0.0;
    bool piston_hit = false;
    double grower_mass = 0.0;

    for (int step = 1; step <= 360; ++step) {
        // The game's actions at their times.
        if (step == 30) {
            grower_mass = world.mass(grower);
            world.set_circle(grower_shape, Circle{.center = {}, .radius = 0.5});
            // DD1: mass = density pi r^2, so twice the radius is four times the mass.
            promise(std::abs(world.mass(grower) / grower_mass - 4.0) < 1e-12,
                    "a circle twice as wide is four times as heavy (DD1)");
            promise(world.geometry(grower_shape).circle.radius == 0.5,
                    "the new geometry is read back");
            world.enable_joint_motor(hinge, true);
            world.set_joint_max_motor_torque(hinge, 50.0);
            world.set_joint_motor_speed(hinge, 2.0);
        }
        if (step == 60) {
            promise(world.origin(trapdoor).y == 6.0, "a static body does not move");
            world.set_body_type(trapdoor, BodyType::dynamic);
        }
        if (step == 100) {
            world.set_enabled(platform, true);
            bool found = false;
            for (const ShapeId s : world.query_aabb(platform_box))
                found = found || entity_of_shape(s)->name == "platform";
            promise(found, "an enabled platform is found by a query, shape -> body -> entity");
        }
        if (step == 120) {
            const double angle = world.joint_angle(hinge);
            promise(angle > 0.45 && angle < 0.55, "the motor drives the door to its upper limit");
            world.set_joint_limits(hinge, -0.5, 1.0);
        }
        if (step == 200) {
            const double angle = world.joint_angle(hinge);
            promise(angle > 0.95 && angle < 1.05, "the door opens to its wider limit");
            world.enable_joint_motor(hinge, false);
            world.set_joint_spring(hinge, 2.0, 1.0);
            world.set_joint_spring_target(hinge, 0.2);
            world.enable_joint_spring(hinge, true);
        }
        if (step == 250) {
            world.destroy_body(lamp);
            entities.erase(lamp);
            for (const JointEvent& e : world.joint_events())
                lamp_gone = lamp_gone ||
                            (e.joint == lamp_joint && e.kind == JointEventKind::body_destroyed);
            promise(lamp_gone, "a joint destroyed with its body is reported");
            promise(!world.is_valid(lamp_joint), "the lamp's joint is gone");
        }

        world.step(dt);

        for (const ContactHitEvent& e : world.contact_hit_events()) {
            ++entities[e.body_a].hits;
            ++entities[e.body_b].hits;
            if (e.body_a == trapdoor || e.body_b == trapdoor)
                trapdoor_hit_speed = std::max(trapdoor_hit_speed, e.approach_speed);
            piston_hit = piston_hit || ((e.body_a == ball && e.body_b == piston) ||
                                        (e.body_a == piston && e.body_b == ball));
        }
        for (const BodyMoveEvent& e : world.body_move_events()) {
            Entity& entity = entities.at(e.body);
            ++entity.moves;
            entity.asleep = entity.asleep || e.fell_asleep;
            if (e.body == trapdoor && step < 60)
                ++trapdoor_moves_while_static;
        }
        for (const SensorEvent& e : world.sensor_begin_events()) {
            if (e.sensor == zone) {
                entity_of_shape(e.visitor)->in_zone = true;
                zone_entered = zone_entered || e.visitor_body == icy;
            }
        }
        for (const SensorEvent& e : world.sensor_end_events()) {
            if (e.sensor == zone) {
                entity_of_shape(e.visitor)->in_zone = false;
                zone_left = zone_left || e.visitor_body == icy;
            }
        }
        for (const JointEvent& e : world.joint_events())
            hinge_pushed =
                hinge_pushed || (e.joint == hinge && e.kind == JointEventKind::threshold_exceeded);
    }

    // The icy crate slid freely (no friction: 5 m/s all along); the rough one stopped after
    // v^2 / (2 mu g) (LC2's Coulomb friction, mu = 0.6), give or take its first step.
    const double rough_slide = world.origin(rough).x - 31.0;
    const double stop_distance = 25.0 / (2.0 * 0.6 * g);
    promise(std::abs(world.velocity(icy).x - 5.0) < 1e-9, "an icy crate keeps its speed");
    promise(std::abs(rough_slide - stop_distance) < 0.1 * stop_distance,
            "a rough crate stops after v^2 / (2 mu g)");
    promise(zone_entered && zone_left, "the icy crate entered and left the pickup zone");
    promise(entities.at(icy).moves == 360, "a moving body reports a move every step");
    promise(!entities.at(icy).in_zone, "the zone's begin and end events pair up");
    // The trapdoor fell 5.5 m: it hit the ground at sqrt(2 g h), within the last step's g dt.
    const double impact = std::sqrt(2.0 * g * 5.5);
    promise(trapdoor_moves_while_static == 0, "a static body reports no moves");
    promise(std::abs(trapdoor_hit_speed - impact) < 0.05 * impact,
            "the dropped crate hits the ground at sqrt(2 g h)");
    promise(entities.at(trapdoor).asleep, "the crate fell asleep on the ground");
    promise(piston_hit, "the ball hit the piston");
    promise(world.origin(piston).x == 10.0 && world.orientation(piston) == 0.0,
            "a piston locked along x and in rotation neither slides nor turns (DD39)");
    promise(world.origin(ball).x < 10.0 - 0.5, "the ball did not pass the piston");
    promise(hinge_pushed, "the hinge reported the motor's push");
    promise(std::abs(world.joint_angle(hinge) - 0.2) < 0.02,
            "the door's spring holds it at its target angle");
    // Query -> shape -> body -> the game's object.
    bool piston_found = false;
    for (const ShapeId s : world.query_aabb(Aabb{9.6, 0.2, 10.4, 0.8}))
        piston_found = piston_found || entity_of_shape(s) == &entities.at(piston);
    promise(piston_found, "a query leads back to the piston's entity");

    std::printf("%d promises kept, %d broken\n", kept, broken);
    return broken == 0 ? 0 : 1;
}
