// The World's queries in a small level: a ground, three crates, a player's capsule and a
// pickup (a sensor). Each query prints what it found (docs/user-guide.md, "Queries").
#include <array>
#include <cstdio>

#include "tamias2d/world.hpp"

int main() {
    using namespace tamias2d;
    World world(WorldDef{});
    const BodyId ground = world.create_body({.type = BodyType::static_body});
    world.create_shape(ground, box_shape(40.0, 1.0)); // top face at y = 0.5 m

    // Crates on category 2, the player on category 4.
    constexpr std::uint32_t crates = 2, players = 4;
    std::array<BodyId, 3> crate{};
    for (int i = 0; i < 3; ++i) {
        crate[std::size_t(i)] = world.create_body({.position = {2.0 + 2.0 * i, 1.0}});
        ShapeDef box = box_shape(1.0, 1.0);
        box.filter.category_bits = crates;
        world.create_shape(crate[std::size_t(i)], box);
    }
    const BodyId player = world.create_body({.position = {-2.0, 1.5}});
    ShapeDef body = capsule_shape({0.0, -0.5}, {0.0, 0.5}, 0.5);
    body.filter.category_bits = players;
    world.create_shape(player, body);
    const BodyId pickup =
        world.create_body({.type = BodyType::static_body, .position = {0.0, 1.5}});
    ShapeDef coin = circle_shape(0.3);
    coin.is_sensor = true;
    world.create_shape(pickup, coin);

    // The closest hit straight down from 10 m: the ground's top at y = 0.5 m, 95 % of the way.
    if (const auto hit = world.ray_cast({0.0, 10.0}, {0.0, -10.0}, QueryFilter{}))
        std::printf("ray down: body %u at (%.3f, %.3f), fraction %.3f\n", hit->body.index,
                    hit->point.x, hit->point.y, hit->fraction);

    // Every hit along a line through the crates at half their height, from inside the player
    // (whose own capsule the ray starts in, so it is not hit; the filter leaves it out anyway).
    const QueryFilter not_me{.exclude_body = player};
    for (const RayCastHit& h : world.ray_cast_all({-2.0, 1.0}, {10.0, 0.0}, not_me))
        std::printf("ray along: body %u at x = %.3f\n", h.body.index, h.point.x);

    // The same without allocating: the nearest two hits into a buffer of the caller's.
    std::array<RayCastHit, 2> nearest{};
    const std::size_t n = world.ray_cast_all({-2.0, 1.0}, {10.0, 0.0}, not_me, nearest);
    std::printf("ray along: %zu hits, the nearest at x = %.3f\n", n, nearest[0].point.x);

    // Only crates (mask 2), through a callback that ignores those before x = 3 and clips the
    // ray at each other one, so that the last it keeps is the nearest beyond x = 3.
    double beyond = 0.0;
    world.ray_cast({-2.0, 1.0}, {10.0, 0.0}, {.mask_bits = crates}, [&](const RayCastHit& h) {
        if (h.point.x < 3.0)
            return -1.0; // ignore it and go on
        beyond = h.point.x;
        return h.fraction; // clip: only nearer hits from now on
    });
    std::printf("callback: the nearest crate beyond x = 3 at x = %.3f\n", beyond);

    // Line of sight from the player to a point: blocked by anything?
    std::printf("line of sight to (9, 1): %s\n",
                world.ray_cast_any({-2.0, 1.0}, {11.0, 0.0}, not_me) ? "blocked" : "clear");

    // A ball of radius 0.5 m dropped from 8 m: it touches the ground with its centre at 1 m.
    const Geometry ball = circle_shape(0.5).geometry;
    if (const auto hit = world.shape_cast(ball, {-6.0, 8.0}, 0.0, {0.0, -10.0}))
        std::printf("ball cast: touches body %u at fraction %.4f, point (%.3f, %.3f), normal "
                    "(%.3f, %.3f)\n",
                    hit->body.index, hit->fraction, hit->point.x, hit->point.y, hit->normal.x,
                    hit->normal.y);

    // Which crates a 3 m wide box around x = 3 overlaps, exactly; what contains a point.
    for (const ShapeId s :
         world.overlap_shape(box_shape(3.0, 0.5).geometry, {3.0, 1.0}, 0.0, {.mask_bits = crates}))
        std::printf("overlap: shape %u\n", s.index);
    for (const ShapeId s : world.query_point({0.0, 1.5}, QueryFilter{}))
        std::printf("point (0, 1.5): shape %u%s\n", s.index, s.index == 5 ? " (the pickup)" : "");

    // How far apart the first two crates are (1 m gaps), and the ground's nearest point.
    const ShapeId c0 = world.shapes(crate[0]).front(), c1 = world.shapes(crate[1]).front();
    const ClosestPoints d = world.distance(c0, c1);
    std::printf("distance crate 0 - crate 1: %.3f m\n", d.distance);
    const ClosestPoints g = world.closest_point(world.shapes(ground).front(), {5.0, 3.0});
    std::printf("ground's nearest point to (5, 3): (%.3f, %.3f), %.3f m away\n", g.point_a.x,
                g.point_a.y, g.distance);
}
