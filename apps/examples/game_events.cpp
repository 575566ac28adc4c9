// The events a game reacts to, as the user guide's "Events" section shows them: a ball that
// hits the ground (a hit event with its approach speed), falls through a pickup zone (sensor
// overlaps), a sprite kept in step by move events until the ball falls asleep, and a lamp whose
// chain loses its ceiling (joint events). Prints one line per event.
#include <cstdio>
#include <unordered_map>

#include "tamias2d/tamias2d.hpp"

using namespace tamias2d;

int main() {
    World world(WorldDef{.enable_sleep = true});
    BodyDef ground_def;
    ground_def.type = BodyType::static_body;
    ground_def.position = {0.0, -0.5};
    const BodyId ground = world.create_body(ground_def);
    world.create_shape(ground, box_shape(20.0, 1.0));

    // A pickup zone the ball falls through.
    BodyDef zone_def;
    zone_def.type = BodyType::static_body;
    zone_def.position = {0.0, 2.0};
    ShapeDef zone_shape = box_shape(2.0, 1.0);
    zone_shape.is_sensor = true;
    const ShapeId zone = world.create_shape(world.create_body(zone_def), zone_shape);

    // The ball: hits and moves reported.
    BodyDef ball_def;
    ball_def.position = {0.0, 4.0};
    ball_def.enable_move_events = true;
    const BodyId ball = world.create_body(ball_def);
    ShapeDef ball_shape = circle_shape(0.25);
    ball_shape.enable_hit_events = true;
    world.create_shape(ball, ball_shape);

    // A lamp hanging from a ceiling beam, its joint reporting loads above 5 N.
    BodyDef beam_def;
    beam_def.type = BodyType::static_body;
    beam_def.position = {6.0, 5.0};
    const BodyId beam = world.create_body(beam_def);
    world.create_shape(beam, box_shape(1.0, 0.2));
    BodyDef lamp_def;
    lamp_def.position = {6.0, 4.0};
    const BodyId lamp = world.create_body(lamp_def);
    world.create_shape(lamp, circle_shape(0.3));
    world.create_joint(DistanceJointDef{.body_a = beam,
                                        .body_b = lamp,
                                        .anchor_a = {6.0, 5.0},
                                        .anchor_b = {6.0, 4.0},
                                        .force_threshold = 1e9});

    std::unordered_map<std::uint32_t, const char*> names{{ball.index, "ball"}};
    bool was_in_zone = false;
    int moves = 0;
    for (int step = 1; step <= 240; ++step) {
        world.step(1.0 / 60.0);
        for (const ContactHitEvent& e : world.contact_hit_events())
            std::printf("step %d: hit, approach speed %.2f m/s\n", step, e.approach_speed);
        const bool in_zone = !world.sensor_overlaps(zone).empty();
        if (in_zone != was_in_zone)
            std::printf("step %d: ball %s the zone\n", step, in_zone ? "entered" : "left");
        was_in_zone = in_zone;
        for (const BodyMoveEvent& e : world.body_move_events()) {
            ++moves; // a game would move the sprite to e.origin, e.angle here
            if (e.fell_asleep)
                std::printf("step %d: %s fell asleep at y = %.2f m\n", step, names[e.body.index],
                            e.origin.y);
        }
    }
    std::printf("%d move events\n", moves);
    world.destroy_body(beam); // the ceiling goes: the game hears of the lamp's chain
    for (const JointEvent& e : world.joint_events())
        std::printf("joint %u: %s\n", e.joint.index, to_string(e.kind).data());
    return 0;
}
