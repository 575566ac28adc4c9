// A capsule character walked over the terrain scene's ground (docs/user-guide.md,
// "Characters"): a kinematic body moved by the mover's queries. Each step the character asks
// for the planes of what it touches (collide_mover), the translation they allow towards where
// its velocity would take it (solve_planes), how much of that is free (cast_mover), moves
// there, clips its velocity against the planes (clip_vector) and sends its body to the new
// pose (set_target_transform). It walks right from the flat ground at x = -20 m down into the
// valley, over the hill and into the wall at x = 30 m; the scene's loose bodies are left out so
// that the walk is the character's own.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

#include "tamias2d/io/scene.hpp"
#include "tamias2d/plane_solver.hpp"
#include "tamias2d/world.hpp"

using namespace tamias2d;
using tamias2d::io::build_world;
using tamias2d::io::load_scene;
using tamias2d::io::Scene;
using tamias2d::io::SceneBody;

namespace {

constexpr double radius = 0.3;       // m
constexpr double height = 1.0;       // m, the core's length: the character is 1.6 m tall
constexpr double walk_speed = 4.0;   // m s^-1
constexpr std::uint32_t level = 0x2; // the category of the level's shapes

struct Character {
    BodyId body;
    Vec2d position; // m: the lower end of the capsule's core
    Vec2d velocity; // m s^-1
};

Capsule capsule_at(Vec2d p) {
    return {p, {p.x, p.y + height}, radius};
}

/// One step of the character: up to five passes of collide, solve, cast and move towards the
/// target, then the velocity clipped against the last planes.
void walk(World& world, Character& c, double dt) {
    const QueryFilter filter{.mask_bits = level, .exclude_body = c.body};
    c.velocity.x = walk_speed;
    c.velocity += dt * world.gravity();
    const Vec2d target = c.position + dt * c.velocity;
    std::vector<CollisionPlane> planes;
    for (int pass = 0; pass < 5; ++pass) {
        planes.clear();
        for (const MoverPlane& p : world.collide_mover(capsule_at(c.position), filter))
            planes.push_back(p.plane);
        const Vec2d wanted = solve_planes(target - c.position, planes).translation;
        const double fraction = world.cast_mover(capsule_at(c.position), wanted, filter);
        const Vec2d moved = fraction * wanted;
        c.position += moved;
        if (std::hypot(moved.x, moved.y) < 1e-6)
            break;
    }
    c.velocity = clip_vector(c.velocity, planes);
    world.set_target_transform(c.body, c.position, 0.0, dt);
    world.step(dt);
}

} // namespace

int main(int argc, char** argv) {
    Scene scene = load_scene(argc > 1 ? argv[1] : TAMIAS_TERRAIN_SCENE);
    std::erase_if(scene.bodies,
                  [](const SceneBody& b) { return b.def.type != BodyType::static_body; });
    for (SceneBody& b : scene.bodies)
        for (ShapeDef& s : b.shapes)
            s.filter.category_bits = level;
    World world(scene.world);
    build_world(scene, world);

    Character c;
    c.position = {-20.0, radius + 0.01};
    c.body = world.create_body({.type = BodyType::kinematic, .position = c.position});
    world.create_shape(c.body, capsule_shape({0.0, 0.0}, {0.0, height}, radius));

    const double dt = 1.0 / 60.0;
    double lowest = c.position.y, highest = c.position.y;
    for (int n = 1; n <= 900; ++n) {
        walk(world, c, dt);
        lowest = std::min(lowest, c.position.y);
        highest = std::max(highest, c.position.y);
        if (n % 150 == 0)
            std::printf("t=%.1f s: x = %.3f m, y = %.3f m\n", n * dt, c.position.x, c.position.y);
    }
    const Vec2d body = world.origin(c.body);
    std::printf("lowest y = %.3f m (the valley's floor is -2 m), highest y = %.3f m (the hill's "
                "top is 3.5 m)\n",
                lowest, highest);
    std::printf("stopped at x = %.3f m (the wall's face is 30 m, less the radius 0.3 m), "
                "velocity x = %.3f m/s\n",
                c.position.x, c.velocity.x);
    std::printf("body at (%.3f, %.3f)\n", body.x, body.y);
}
