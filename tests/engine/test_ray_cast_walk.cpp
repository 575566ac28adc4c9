// World::ray_cast walks the broad phase's trees along the ray, the ray clipped at each hit:
// a differential test on random worlds. Oracle: the brute-force answer, every live non-sensor
// shape tested with the shape's own ray cast (geometry/shape_queries.hpp) at its body's pose,
// the least fraction kept and at equal fractions the lowest shape index: the answer the world
// gave when it tested every proxy in the ray's bounding box. Whatever the walk skips must not
// change it, bit for bit.
#include <boost/test/unit_test.hpp>

#include <cstdint>
#include <optional>
#include <random>
#include <vector>

#include "tamias2d/geometry/shape_queries.hpp"
#include "tamias2d/world.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;

namespace {

struct Placed {
    ShapeId id;
    BodyId body;
    ShapeDef def;
};

struct Pose {
    Vec2d origin;
    double angle;
};

std::optional<RayCastHit> brute_force(const std::vector<Placed>& shapes,
                                      const std::vector<Pose>& poses, Vec2d origin,
                                      Vec2d translation) {
    std::optional<RayCastHit> best;
    for (const Placed& p : shapes) {
        if (p.def.is_sensor)
            continue; // a sensor is not there for rays (DD28)
        const Pose& pose = poses[p.body.index];
        const Transform xf{pose.origin, Rot::from_angle(pose.angle)};
        const auto hit = ray_cast(p.def.geometry, xf, origin, translation);
        if (hit && (!best || hit->fraction < best->fraction ||
                    (hit->fraction == best->fraction && p.id.index < best->shape.index)))
            best = RayCastHit{p.id, p.body, hit->point, hit->normal, hit->fraction};
    }
    return best;
}

ShapeDef random_shape(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> size(0.1, 3.0), off(-1.0, 1.0);
    ShapeDef s;
    switch (rng() % 4) {
    case 0:
        s = circle_shape(size(rng), {}, {off(rng), off(rng)});
        break;
    case 1:
        s = box_shape(size(rng), size(rng));
        break;
    case 2: {
        const Vec2d c1{off(rng), off(rng)};
        s = capsule_shape(c1, {c1.x + 0.5 + size(rng), c1.y + off(rng)}, 0.5 * size(rng));
        break;
    }
    default: {
        const Vec2d p1{off(rng), off(rng)};
        s = segment_shape(p1, {p1.x + 0.5 + size(rng), p1.y + off(rng)});
        break;
    }
    }
    s.is_sensor = rng() % 10 == 0;
    return s;
}

} // namespace

BOOST_AUTO_TEST_SUITE(ray_cast_walk)

// Oracle: a brute-force search written in the test, apart from the broad phase's trees: every
// live non-sensor shape ray-cast on its own (the shape-level ray_cast of shape_queries.hpp) at
// its body's pose as the test set it, the least fraction kept and at equal fractions the lowest
// shape index. The walk's hit must equal it bit for bit on 12 random worlds; hits and misses
// both occur often.
BOOST_AUTO_TEST_CASE(ray_cast_walk_matches_brute_force_on_random_worlds, *utf::label("internals")) {
    int hits = 0, misses = 0;
    for (std::uint64_t seed = 1; seed <= 12; ++seed) {
        std::mt19937_64 rng(seed);
        std::uniform_real_distribution<double> pos(-25.0, 25.0), turn(-3.0, 3.0), ray(-60.0, 60.0);
        World world(WorldDef{.gravity = {0.0, 0.0}});
        std::vector<Placed> shapes;
        std::vector<Pose> poses;
        for (int i = 0; i < 80; ++i) {
            BodyDef bd;
            bd.type = i % 3 == 0 ? BodyType::static_body
                                 : (i % 7 == 0 ? BodyType::kinematic : BodyType::dynamic);
            bd.position = {pos(rng), pos(rng)};
            bd.angle = turn(rng);
            const BodyId b = world.create_body(bd);
            poses.resize(b.index + 1);
            poses[b.index] = {bd.position, bd.angle};
            for (int k = 0, n = 1 + int(rng() % 2); k < n; ++k) {
                const ShapeDef s = random_shape(rng);
                shapes.push_back({world.create_shape(b, s), b, s});
            }
        }
        // Half the bodies placed again (their fat boxes moved in the trees), a step taken
        // first so that the trees have seen a step's updates too; every pose then known.
        world.step(1.0 / 60.0);
        for (const BodyId b : world.bodies()) {
            const Pose p{{pos(rng), pos(rng)}, turn(rng)};
            if (b.index % 2 == 0 || world.type(b) != BodyType::static_body) {
                world.set_transform(b, p.origin, p.angle);
                poses[b.index] = p;
            }
        }
        for (int r = 0; r < 300; ++r) {
            const Vec2d origin{pos(rng), pos(rng)};
            Vec2d translation{ray(rng), ray(rng)};
            if (r % 10 == 0)
                translation.y = 0.0; // along an axis: the walk's boxes met edge-on
            if (r % 10 == 1)
                translation.x = 0.0;
            const auto got = world.ray_cast(origin, translation);
            const auto want = brute_force(shapes, poses, origin, translation);
            BOOST_TEST_REQUIRE(got.has_value() == want.has_value());
            if (!want) {
                ++misses;
                continue;
            }
            ++hits;
            BOOST_TEST((got->shape == want->shape));
            BOOST_TEST((got->body == want->body));
            BOOST_TEST(got->fraction == want->fraction);
            BOOST_TEST(got->point.x == want->point.x);
            BOOST_TEST(got->point.y == want->point.y);
            BOOST_TEST(got->normal.x == want->normal.x);
            BOOST_TEST(got->normal.y == want->normal.y);
        }
    }
    // The worlds are dense enough that both answers occur often.
    BOOST_TEST(hits > 500);
    BOOST_TEST(misses > 100);
}

// Oracle: the tie rule of World::ray_cast ("ties go to the lower shape index"), by the same
// brute force: four equal boxes on one spot, on bodies created in turn (one shape destroyed and
// its slot given to a later one, so that creation order and index order differ), are hit at
// the same fraction by rays from every side; the answer is the lowest live index.
BOOST_AUTO_TEST_CASE(shapes_hit_at_one_fraction_go_to_the_lowest_index, *utf::label("internals")) {
    World world(WorldDef{.gravity = {0.0, 0.0}});
    std::vector<Placed> shapes;
    std::vector<Pose> poses;
    const ShapeDef box = box_shape(1.0, 1.0);
    for (int i = 0; i < 4; ++i) {
        BodyDef bd;
        bd.type = BodyType::static_body;
        bd.position = {2.0, 1.0};
        const BodyId b = world.create_body(bd);
        poses.resize(b.index + 1);
        poses[b.index] = {bd.position, 0.0};
        shapes.push_back({world.create_shape(b, box), b, box});
    }
    world.destroy_shape(shapes[0].id);
    shapes.erase(shapes.begin());
    shapes.push_back({world.create_shape(shapes[1].body, box), shapes[1].body, box});
    const std::pair<Vec2d, Vec2d> rays[] = {{{-3.0, 1.0}, {10.0, 0.0}},
                                            {{7.0, 1.0}, {-10.0, 0.0}},
                                            {{2.0, -4.0}, {0.0, 10.0}},
                                            {{2.0, 6.0}, {0.0, -10.0}},
                                            {{-3.0, -3.0}, {10.0, 8.0}}};
    for (const auto& ray : rays) {
        const auto got = world.ray_cast(ray.first, ray.second);
        const auto want = brute_force(shapes, poses, ray.first, ray.second);
        BOOST_TEST_REQUIRE(want.has_value());
        BOOST_TEST_REQUIRE(got.has_value());
        BOOST_TEST((got->shape == want->shape), "ray from " << ray.first.x << ", " << ray.first.y);
        BOOST_TEST(got->fraction == want->fraction);
    }
}

BOOST_AUTO_TEST_SUITE_END()
