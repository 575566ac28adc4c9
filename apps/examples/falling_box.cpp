// A box dropped onto the ground falls, lands and comes to rest: the README's first program.
#include <cstdio>

#include "tamias2d/world.hpp"

int main() {
    using namespace tamias2d;
    World world(WorldDef{}); // gravity 9.81 m/s^2 downwards
    const Material material{.density = 1.0, .restitution = 0.0, .friction = 0.6};
    const BodyId ground = world.create_body({.type = BodyType::static_body});
    world.create_shape(ground, box_shape(20.0, 1.0, material)); // its top face at y = 0.5 m

    const BodyId box = world.create_body({.position = {0.0, 4.0}});
    world.create_shape(box, box_shape(1.0, 1.0, material)); // 1 m wide and high, 1 kg

    for (int step = 1; step <= 120; ++step) { // two seconds at 60 steps per second
        world.step(1.0 / 60.0);
        if (step % 30 == 0)
            std::printf("t=%.2f s  y=%.4f m  vy=%.4f m/s\n", world.time(),
                        world.state(box).position.y, world.state(box).velocity.y);
    }
}
