// A conveyor belt and rolling resistance, as the user guide's "Surface motion" section builds
// them: a belt (a static box whose surface moves at 2 m/s, Material::tangent_speed) carries
// balls and boxes to the right onto a gentle slope; the balls, whose surface resists rolling
// (Material::rolling_resistance), come to rest on it, where balls without resistance would roll
// on. Prints each body's speed while on the belt and where each ball rests.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "tamias2d/tamias2d.hpp"

using namespace tamias2d;

int main() {
    World world(WorldDef{});

    // The belt: 12 m long, its top at y = 0 from x = -12 to 0, its surface moving clockwise
    // around it at 2 m/s (so its top carries things towards +x).
    BodyDef belt_def;
    belt_def.type = BodyType::static_body;
    belt_def.position = {-6.0, -0.5};
    Material belt{.friction = 0.6};
    belt.tangent_speed = 2.0;
    world.create_shape(world.create_body(belt_def), box_shape(12.0, 1.0, belt));

    // The slope: 30 m falling 0.05 rad to the right, its top starting where the belt ends.
    const double theta = 0.05;
    BodyDef slope_def;
    slope_def.type = BodyType::static_body;
    slope_def.angle = -theta;
    slope_def.position = {15.0 * std::cos(theta) - 0.5 * std::sin(theta),
                          -15.0 * std::sin(theta) - 0.5 * std::cos(theta)};
    world.create_shape(world.create_body(slope_def),
                       box_shape(30.0, 1.0, Material{.friction = 0.6}));

    // Three balls at rest on the belt, the one ahead resisting rolling least (c = 0.1, 0.2,
    // 0.3: each more than tan(0.05), so the slope cannot keep any of them rolling, and each
    // stops before the one ahead of it), and three boxes behind them.
    std::vector<BodyId> boxes, balls;
    for (int k = 0; k < 3; ++k) {
        BodyDef d;
        d.position = {-4.0 - 2.0 * k, 0.25};
        balls.push_back(world.create_body(d));
        Material ball{.friction = 0.6};
        ball.rolling_resistance = 0.1 * (k + 1);
        world.create_shape(balls.back(), circle_shape(0.25, ball));
        d.position = {-9.5 - 1.0 * k, 0.25};
        boxes.push_back(world.create_body(d));
        world.create_shape(boxes.back(), box_shape(0.5, 0.5, Material{.friction = 0.6}));
    }

    // After 1 s every box rides with the belt (it reached 2 m/s at 0.6 g after 0.34 s). A ball
    // rolls on the belt from the first contact, at a third of its speed (a disc: v + omega r = 2
    // with m v = I omega / r), and the resistance's torque c r m g slows its turning, so it gains
    // (2/3) c g per second until it rides at 2 m/s.
    for (int i = 0; i < 60; ++i)
        world.step(1.0 / 60.0);
    const double g = -world.settings().gravity.y;
    for (std::size_t k = 0; k < boxes.size(); ++k) {
        const double c = 0.1 * double(k + 1);
        const double closed_form = std::min(2.0 / 3.0 + 2.0 / 3.0 * c * g * 1.0, 2.0);
        std::printf("on the belt: box %zu at %.2f m/s, ball %zu at %.2f m/s (closed form %.2f)\n",
                    k, world.velocity(boxes[k]).x, k, world.velocity(balls[k]).x, closed_form);
    }
    for (int i = 0; i < 20 * 60; ++i)
        world.step(1.0 / 60.0);
    for (std::size_t k = 0; k < balls.size(); ++k) {
        const Vec2d v = world.velocity(balls[k]);
        std::printf("ball %zu (c = %.1f) rests on the slope at x = %.2f m (speed %.4f m/s)\n", k,
                    0.1 * double(k + 1), world.position(balls[k]).x, std::hypot(v.x, v.y));
    }
}
