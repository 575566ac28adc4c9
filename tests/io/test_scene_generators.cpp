// The generators (docs/scene-format.md): body counts, geometry, determinism, and the elastic
// pair's physics (R1, R3, R8).
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "tamias2d/geometry/aabb.hpp"
#include "tamias2d/io/scene_generators.hpp"
#include "tamias2d/world.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;
using namespace tamias2d::io;

namespace {

/// World-frame AABB of a body's first shape (generated bodies have unrotated boxes).
Aabb box_of(const SceneBody& b, std::size_t shape = 0) {
    const Polygon& p = b.shapes[shape].geometry.polygon;
    Aabb a{1e300, 1e300, -1e300, -1e300};
    for (int i = 0; i < p.count; ++i) {
        const Vec2d v = p.vertices[std::size_t(i)] + b.def.position;
        a = union_of(a, Aabb{v.x, v.y, v.x, v.y});
    }
    return a;
}

/// Closed-interval overlap with a tolerance: touching within `tol` does not count.
bool overlap(const Aabb& a, const Aabb& b, double tol) {
    return a.min_x < b.max_x - tol && b.min_x < a.max_x - tol && a.min_y < b.max_y - tol &&
           b.min_y < a.max_y - tol;
}

} // namespace

BOOST_AUTO_TEST_SUITE(scene_generators)

// Oracle: arithmetic series: a pyramid of base N holds N + (N - 1) + ... + 1 = N (N + 1) / 2
// boxes (base 20: 210), plus one static ground; row r (from 0) has N - r boxes centred at
// y = gap + box / 2 + r (box + gap) on a ground whose top face is at y = 0; each row is offset
// by half a pitch from the one below and neighbours are `gap` apart (hand geometry).
BOOST_AUTO_TEST_CASE(pyramid_counts_and_rows, *utf::label("scene")) {
    for (const int base : {1, 2, 20, 40}) {
        BOOST_TEST_CONTEXT("base " << base) {
            PyramidParams p;
            p.base = base;
            p.box = 1.0;
            p.gap = 0.001;
            const std::vector<SceneBody> bodies = generate_pyramid(p);
            BOOST_TEST(bodies.size() == std::size_t(base * (base + 1) / 2 + 1));
            const SceneBody& ground = bodies.front();
            BOOST_TEST((ground.def.type == BodyType::static_body));
            BOOST_TEST(ground.def.name == "pyramid/ground");
            BOOST_TEST(box_of(ground).max_y == 0.0, boost::test_tools::tolerance(1e-15));
            std::size_t k = 1;
            for (int row = 0; row < base; ++row) {
                const double y = 0.001 + 0.5 + row * 1.001;
                double first_x = 0.0;
                for (int col = 0; col < base - row; ++col, ++k) {
                    const SceneBody& b = bodies.at(k);
                    BOOST_TEST((b.def.type == BodyType::dynamic));
                    BOOST_TEST(b.def.name ==
                               "pyramid/r" + std::to_string(row) + "c" + std::to_string(col));
                    BOOST_TEST(b.def.position.y == y, boost::test_tools::tolerance(1e-12));
                    if (col == 0)
                        first_x = b.def.position.x;
                    else
                        BOOST_TEST(b.def.position.x - bodies[k - 1].def.position.x == 1.001,
                                   boost::test_tools::tolerance(1e-12));
                    BOOST_TEST(b.shapes.size() == 1u);
                    BOOST_TEST(b.shapes[0].material.friction == 0.6);
                    BOOST_TEST(b.shapes[0].material.density == 1.0);
                }
                // Centred: the first box is (n - 1) / 2 pitches left of the origin, i.e. each
                // row starts half a pitch right of the row below.
                BOOST_TEST(first_x == -0.5 * (base - row - 1) * 1.001,
                           boost::test_tools::tolerance(1e-12));
                // The lowest row rests a gap above the ground; its bottom at y = gap.
                if (row == 0 && base > 0)
                    BOOST_TEST(box_of(bodies[1]).min_y == 0.001,
                               boost::test_tools::tolerance(1e-12));
            }
            // The ground spans the base with room to spare.
            BOOST_TEST(box_of(ground).max_x - box_of(ground).min_x >= base * 1.001);
        }
    }
}

// Oracle: the gaps make every pair of boxes disjoint (no initial overlap, so the stack settles
// without being pushed apart); checked pairwise for base 20 (22 155 pairs).
BOOST_AUTO_TEST_CASE(pyramid_boxes_do_not_overlap, *utf::label("scene")) {
    const std::vector<SceneBody> bodies = generate_pyramid(PyramidParams{});
    BOOST_TEST_REQUIRE(bodies.size() == 211u);
    std::size_t overlaps = 0;
    for (std::size_t i = 0; i < bodies.size(); ++i)
        for (std::size_t j = i + 1; j < bodies.size(); ++j)
            overlaps += overlap(box_of(bodies[i]), box_of(bodies[j]), 1e-9) ? 1 : 0;
    BOOST_TEST(overlaps == 0u);
}

// Oracle: the rain's specification: count boxes + 1 container body of 3 boxes (floor and two
// walls, inner floor at the origin, inner width 40, wall height 20); every box starts above the
// walls and inside the inner width, on a grid of pitch 1.5 box with |jitter| <= 0.2 box.
BOOST_AUTO_TEST_CASE(rain_counts_and_geometry, *utf::label("scene")) {
    RainParams p; // the defaults: 2000 boxes of 0.5 m, seed 1
    const std::vector<SceneBody> bodies = generate_rain(p);
    BOOST_TEST_REQUIRE(bodies.size() == 2001u);
    const SceneBody& c = bodies.front();
    BOOST_TEST((c.def.type == BodyType::static_body));
    BOOST_TEST_REQUIRE(c.shapes.size() == 3u);
    const Aabb floor = box_of(c, 0), left = box_of(c, 1), right = box_of(c, 2);
    BOOST_TEST(floor.max_y == 0.0);
    BOOST_TEST(floor.min_y == -1.0);
    BOOST_TEST(left.max_x == -20.0);
    BOOST_TEST(right.min_x == 20.0);
    BOOST_TEST(left.max_y == 20.0);
    BOOST_TEST(right.max_y == 20.0);
    BOOST_TEST(left.min_y == 0.0);
    const int columns = 53; // floor(40 / 0.75)
    for (std::size_t i = 1; i < bodies.size(); ++i) {
        const SceneBody& b = bodies[i];
        const Aabb a = box_of(b);
        const std::size_t n = i - 1;
        BOOST_TEST_REQUIRE((b.def.type == BodyType::dynamic));
        BOOST_TEST_REQUIRE(a.min_y >= 21.0 - 1e-12); // drop height 1 above the walls
        BOOST_TEST_REQUIRE(a.min_x > -20.0);
        BOOST_TEST_REQUIRE(a.max_x < 20.0);
        BOOST_TEST_REQUIRE(b.def.position.y == 21.25 + 0.75 * double(n / std::size_t(columns)));
        const double grid_x = (double(n % std::size_t(columns)) - 26.0) * 0.75;
        BOOST_TEST_REQUIRE(std::abs(b.def.position.x - grid_x) <= 0.1 + 1e-12);
        BOOST_TEST_REQUIRE(std::abs(a.max_x - a.min_x - 0.5) < 1e-12);
    }
    // Boxes in the same row and in neighbouring rows never overlap (pitch - 2 jitter > box).
    for (std::size_t i = 1; i + 1 < bodies.size(); ++i)
        BOOST_TEST_REQUIRE(!overlap(box_of(bodies[i]), box_of(bodies[i + 1]), 0.0));
}

// Oracle: determinism by construction (splitmix64, no platform RNG): the same seed gives the
// same scene bit for bit, another seed other jitters; count 0 leaves just the container.
BOOST_AUTO_TEST_CASE(rain_is_deterministic_in_its_seed, *utf::label("scene")) {
    RainParams p;
    p.count = 300;
    const auto a = generate_rain(p);
    const auto b = generate_rain(p);
    p.seed = 2;
    const auto c = generate_rain(p);
    std::size_t same_as_a = 0, differs_from_c = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        same_as_a += a[i].def.position.x == b[i].def.position.x ? 1 : 0;
        differs_from_c += a[i].def.position.x != c[i].def.position.x ? 1 : 0;
    }
    BOOST_TEST(same_as_a == a.size());
    BOOST_TEST(differs_from_c >= 299u); // all boxes, the container aside
    p.count = 0;
    BOOST_TEST(generate_rain(p).size() == 1u);
}

// Oracle: Vigna's reference splitmix64.c test vector for seed 1234567 (also used by the
// rand_xoshiro crate): 6457827717110365317, 3203168211198807973, 9817491932198370423.
BOOST_AUTO_TEST_CASE(splitmix64_matches_the_reference) {
    SplitMix64 rng{1234567};
    BOOST_TEST(rng.next() == 6457827717110365317ULL);
    BOOST_TEST(rng.next() == 3203168211198807973ULL);
    BOOST_TEST(rng.next() == 9817491932198370423ULL);
    SplitMix64 u{42};
    for (int i = 0; i < 1000; ++i) {
        const double x = u.uniform();
        BOOST_TEST_REQUIRE((x >= 0.0 && x < 1.0));
    }
}

// Oracle: GD1 and DD12 for a head-on collision of equal masses with C_R = 1: the bodies
// exchange velocities (v_left: +1 -> -1, v_right: -1 -> +1 m/s), total momentum stays 0 and
// kinetic energy stays m v^2 = 1 J (m = 1 kg each: 1 m^2 at 1 kg m^-2); no gravity.
BOOST_AUTO_TEST_CASE(elastic_pair_exchanges_velocities,
                     *utf::label("R1") * utf::label("R3") * utf::label("R8")) {
    const std::vector<SceneBody> pair = generate_elastic_pair(ElasticPairParams{});
    BOOST_TEST_REQUIRE(pair.size() == 2u);
    BOOST_TEST(pair[0].def.position.x == -1.5);
    BOOST_TEST(pair[1].def.position.x == 1.5);
    BOOST_TEST(pair[0].def.linear_velocity.x == 1.0);
    BOOST_TEST(pair[1].def.linear_velocity.x == -1.0);
    for (const SceneBody& b : pair) {
        BOOST_TEST(b.def.gravity_scale == 0.0);
        BOOST_TEST(b.shapes[0].material.restitution == 1.0);
        BOOST_TEST(b.shapes[0].material.friction == 0.0);
    }
    WorldDef def;
    def.gravity = {0.0, -10.0}; // gravity_scale 0 makes them ignore it
    World world(def);
    std::vector<BodyId> ids;
    for (const SceneBody& b : pair) {
        ids.push_back(world.create_body(b.def));
        world.create_shape(ids.back(), b.shapes[0]);
    }
    BOOST_TEST(world.kinetic_energy() == 1.0, boost::test_tools::tolerance(1e-12));
    for (int i = 0; i < 120; ++i) // 2 s; contact at t = 1 s
        world.step(1.0 / 60.0);
    BOOST_TEST(world.velocity(ids[0]).x == -1.0, boost::test_tools::tolerance(1e-9));
    BOOST_TEST(world.velocity(ids[1]).x == 1.0, boost::test_tools::tolerance(1e-9));
    BOOST_TEST(std::abs(world.velocity(ids[0]).y) < 1e-9);
    BOOST_TEST(std::abs(world.linear_momentum().x) < 1e-12);
    BOOST_TEST(world.kinetic_energy() == 1.0, boost::test_tools::tolerance(1e-9));
}

BOOST_AUTO_TEST_SUITE_END()
