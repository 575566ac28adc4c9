// NFR3 (usability): a complete program that simulates two bodies over time. It is the program
// the user guide quotes; CTest builds and runs it, so the quoted code always compiles and works.
#include <cstdio>

#include "tamias2d/world.hpp"

int main() {
    using namespace tamias2d;
    WorldDef settings;
    settings.gravity = {0.0, -10.0}; // m/s^2
    World world(settings);
    const Material material{.density = 1.0, .restitution = 0.0, .friction = 0.6};

    BodyDef box_def; // a 1 m box at the origin, pushed right by a constant 10 N
    box_def.name = "box";
    box_def.force = {10.0, 0.0};
    const BodyId box = world.create_body(box_def);
    world.create_shape(box, box_shape(1.0, 1.0, material));

    BodyDef ball_def; // a ball 3 m to the right, moving left, spun up by 0.5 N m
    ball_def.name = "ball";
    ball_def.position = {3.0, 0.0};
    ball_def.linear_velocity = {-1.0, 0.0};
    ball_def.torque = 0.5;
    const BodyId ball = world.create_body(ball_def);
    world.create_shape(ball, circle_shape(0.5, material));

    for (int step = 1; step <= 60; ++step) { // one second at 60 Hz
        world.step(1.0 / 60.0);
        if (step % 20 != 0)
            continue;
        for (const BodyId id : {box, ball}) {
            const BodyState s = world.state(id); // SI units; phi in [0, 2 pi)
            std::printf("t=%.3f %-4s x=%7.3f y=%7.3f vx=%7.3f vy=%7.3f phi=%.3f omega=%.3f\n",
                        world.time(), world.name(id).c_str(), s.position.x, s.position.y,
                        s.velocity.x, s.velocity.y, s.orientation, s.angular_velocity);
        }
    }
}
