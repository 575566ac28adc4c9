// World::draw in a game's loop: a DebugDraw that a renderer would turn into lines and fills,
// here one that writes each primitive as a line of text. A ground, a stack of two boxes, a ball
// on a pendulum pin and a capsule fall and settle for one second; then the world is drawn with
// its shapes, joints, contact points and centres of mass. CTest builds and runs it.
#include <cstdio>

#include "tamias2d/tamias2d.hpp"

namespace {

using namespace tamias2d;

/// Prints each primitive it is handed (a game would draw them with its own renderer).
struct PrintDraw : DebugDraw {
    void solid_polygon(std::span<const Vec2d> v, Color c) override {
        std::printf("polygon  %zu vertices, first (%.2f, %.2f), colour #%06x\n", v.size(), v[0].x,
                    v[0].y, unsigned(c.rgb));
    }
    void solid_circle(Vec2d p, double r, double /*angle*/, Color c) override {
        std::printf("circle   centre (%.2f, %.2f), radius %.2f, colour #%06x\n", p.x, p.y, r,
                    unsigned(c.rgb));
    }
    void solid_capsule(Vec2d p1, Vec2d p2, double r, Color c) override {
        std::printf("capsule  (%.2f, %.2f) - (%.2f, %.2f), radius %.2f, colour #%06x\n", p1.x, p1.y,
                    p2.x, p2.y, r, unsigned(c.rgb));
    }
    void segment(Vec2d p1, Vec2d p2, Color c) override {
        std::printf("segment  (%.2f, %.2f) - (%.2f, %.2f), colour #%06x\n", p1.x, p1.y, p2.x, p2.y,
                    unsigned(c.rgb));
    }
    void point(Vec2d p, double /*size*/, Color c) override {
        std::printf("point    (%.2f, %.2f), colour #%06x\n", p.x, p.y, unsigned(c.rgb));
    }
    void transform(Vec2d p, double angle, double /*length*/) override {
        std::printf("frame    (%.2f, %.2f), angle %.2f\n", p.x, p.y, angle);
    }
};

} // namespace

int main() {
    World world(WorldDef{.gravity = {0.0, -10.0}});
    const Material m{.density = 1.0, .restitution = 0.0, .friction = 0.6};

    BodyDef ground_def;
    ground_def.type = BodyType::static_body;
    const BodyId ground = world.create_body(ground_def);
    world.create_shape(ground, box_shape(20.0, 1.0, m, {0.0, -0.5}));

    for (int k = 0; k < 2; ++k) { // two boxes stacked, resting after a second
        BodyDef d;
        d.position = {-3.0, 0.5 + 1.0 * k};
        world.create_shape(world.create_body(d), box_shape(1.0, 1.0, m));
    }
    BodyDef ball_def; // a ball swinging on a pin 2 m above it
    ball_def.position = {2.0, 2.0};
    const BodyId ball = world.create_body(ball_def);
    world.create_shape(ball, circle_shape(0.3, m));
    world.create_joint(RevoluteJointDef{.body_a = ground, .body_b = ball, .anchor = {0.0, 4.0}});

    BodyDef capsule_def; // a capsule lying on the ground
    capsule_def.position = {5.0, 0.3};
    world.create_shape(world.create_body(capsule_def),
                       capsule_shape({-0.5, 0.0}, {0.5, 0.0}, 0.25, m));

    for (int step = 0; step < 60; ++step)
        world.step(1.0 / 60.0);

    PrintDraw draw;
    draw.draw_contacts = true;
    draw.draw_mass_centers = true;
    world.draw(draw);
}
