// Loads a scene file with tamias2d::io, runs it for its own number of steps and prints the
// final states: the installed scene library works in a program of the user's.
#include <cstdio>

#include "tamias2d/io/scene.hpp"
#include "tamias2d/tamias2d.hpp"

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: scene_runner <scene.json>\n");
        return 2;
    }
    try {
        const tamias2d::io::Scene scene = tamias2d::io::load_scene(argv[1]);
        tamias2d::World world(scene.world);
        const std::vector<tamias2d::BodyId> ids = tamias2d::io::build_world(scene, world);
        for (int step = 0; step < scene.steps; ++step)
            world.step(scene.dt);
        std::printf("tamias2d %s (%s)\n", tamias2d::library_version(),
                    tamias2d::solver_instruction_set());
        for (const tamias2d::BodyId id : ids) {
            const tamias2d::BodyState s = world.state(id);
            std::printf("%s %a %a %a %a %a %a\n", world.name(id).c_str(), s.position.x,
                        s.position.y, s.velocity.x, s.velocity.y, s.orientation,
                        s.angular_velocity);
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "scene_runner: %s\n", e.what());
        return 1;
    }
}
