// A one-way platform, as the user guide's "Contact hooks" section builds it: a pre-solve
// callback lets a hero jump up through a ledge and land on it. Prints when the hero's feet rise
// above the ledge, the highest point of the jump, and where the hero comes to rest.
#include <cstdio>

#include "tamias2d/tamias2d.hpp"

using namespace tamias2d;

int main() {
    World world(WorldDef{});
    BodyDef ground_def;
    ground_def.type = BodyType::static_body;
    ground_def.position = {0.0, -0.5};
    world.create_shape(world.create_body(ground_def), box_shape(20.0, 1.0));

    // The ledge: 4 m wide, 0.2 m thick, its top at y = 3.1 m.
    BodyDef ledge_def;
    ledge_def.type = BodyType::static_body;
    ledge_def.position = {0.0, 3.0};
    const ShapeId ledge = world.create_shape(world.create_body(ledge_def), box_shape(4.0, 0.2));

    // The hero: a 0.5 m box standing on the ground.
    BodyDef hero_def;
    hero_def.position = {0.0, 0.25};
    const BodyId hero = world.create_body(hero_def);
    world.create_shape(hero, box_shape(0.5, 0.5, Material{.friction = 0.5}));

    // One way: a contact with the ledge is solved only while its normal pushes the other body
    // up (the normal runs from shape_a into shape_b).
    world.set_pre_solve([ledge](const PreSolveContact& c) {
        if (c.shape_a == ledge)
            return c.normal.y > 0.7;
        if (c.shape_b == ledge)
            return c.normal.y < -0.7;
        return true;
    });

    world.set_velocity(hero, {0.0, 10.0}); // jump
    bool above = false;
    double highest = 0.0;
    for (int i = 0; i < 300; ++i) {
        world.step(1.0 / 60.0);
        const double feet = world.position(hero).y - 0.25;
        if (!above && feet > 3.1) {
            above = true;
            std::printf("t=%.3f feet above the ledge, rising at %.2f m/s\n", world.time(),
                        world.velocity(hero).y);
        }
        if (world.position(hero).y > highest)
            highest = world.position(hero).y;
    }
    std::printf("highest: %.3f m\n", highest);
    std::printf("rests at y = %.4f m (ledge top + half height = 3.3500 m)\n",
                world.position(hero).y);
}
