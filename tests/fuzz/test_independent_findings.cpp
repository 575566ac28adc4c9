// The findings of an independent fuzzer (docs/verification.md, "Findings (fixed)": G1 to G5),
// each as the concrete input that found it; every case failed (G1 crashed) before its fix.
//
// G1: a circle whose unused polygon member had a count of 9 or 1e8 was accepted, and
//     World::state_hash() then read past the polygon's 8 vertices (a segfault at 1e8).
// G2: a hand-made polygon's centroid was checked for finiteness only: a box whose centroid was
//     1e155 m away turned the body NaN in its first step.
// G3: a pentagram turns left at every vertex, and was accepted as a convex polygon.
// G4: N shapes on one body cost O(N^2) to create (a list walk and a mass update per shape).
// G5: the broad phase fattened every box by 0.1 m, so a pyramid of 1e-12 m boxes made every
//     pair of its 5050 boxes a pair (12.7 million), even with a speculative distance of 1e-13 m.
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

#include "support/cpu_time.hpp"
#include "tamias2d/collision/broad_phase.hpp"
#include "tamias2d/errors.hpp"
#include "tamias2d/io/scene.hpp"
#include "tamias2d/memory.hpp"
#include "tamias2d/shape_def.hpp"
#include "tamias2d/world.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;

namespace {

/// A world with one dynamic body at (0, 2) over a static ground box, ready for a shape.
struct Scene1 {
    World world;
    BodyId ground, body;
    Scene1() : world(WorldDef{}) {
        BodyDef g;
        g.type = BodyType::static_body;
        ground = world.create_body(g);
        world.create_shape(ground, box_shape(10.0, 1.0));
        BodyDef d;
        d.position = {0.0, 2.0};
        body = world.create_body(d);
    }
};

/// Expects `create` to throw a ValidationError naming `field` and DCX_shape, and the world's
/// state hash to be as before the call (docs/user-guide.md, "Errors").
template <class F> void expect_refused(World& world, F create, const std::string& field) {
    const std::uint64_t before = world.state_hash();
    try {
        create();
        BOOST_ERROR("accepted; expected a ValidationError on " << field);
    } catch (const ValidationError& e) {
        BOOST_TEST(e.field == field, e.what());
        BOOST_TEST(e.constraint == "DCX_shape", e.what());
    }
    BOOST_TEST(world.state_hash() == before);
}

/// A regular pentagon of circumradius 1 m (counter-clockwise), its vertices in `order`, with
/// each edge's outward unit normal and the given centroid: a hand-made Polygon.
ShapeDef pentagon_in_order(const std::array<int, 5>& order) {
    std::array<Vec2d, 5> q;
    for (int k = 0; k < 5; ++k) {
        const double a = std::numbers::pi / 2.0 + 2.0 * std::numbers::pi * k / 5.0;
        q[std::size_t(k)] = {std::cos(a), std::sin(a)};
    }
    ShapeDef def;
    def.geometry.type = ShapeType::polygon;
    Polygon& p = def.geometry.polygon;
    p.count = 5;
    for (int k = 0; k < 5; ++k)
        p.vertices[std::size_t(k)] = q[std::size_t(order[std::size_t(k)])];
    for (int k = 0; k < 5; ++k) {
        const Vec2d e = p.vertices[std::size_t((k + 1) % 5)] - p.vertices[std::size_t(k)];
        const double len = std::hypot(e.x, e.y);
        p.normals[std::size_t(k)] = {e.y / len, -e.x / len};
    }
    p.centroid = {0.0, 0.0}; // both the pentagon's and the pentagram's, by symmetry
    return def;
}

} // namespace

BOOST_AUTO_TEST_SUITE(independent_findings)

// G1. Oracle: the promise that a shape is its kind's member alone (shapes.hpp: "which of the
// members holds the shape"): the world with the scribbled definition hashes exactly as the one
// made with circle_shape, before and after a step.
BOOST_AUTO_TEST_CASE(a_shapes_unused_members_carry_nothing,
                     *utf::label("R4") * utf::label("DCX_shape")) {
    for (const int count : {9, 100000000, -7}) {
        BOOST_TEST_CONTEXT("polygon.count " << count) {
            Scene1 clean, scribbled;
            clean.world.create_shape(clean.body, circle_shape(0.5));
            ShapeDef def = circle_shape(0.5);
            def.geometry.polygon.count = count;
            def.geometry.polygon.vertices.fill({3.0, 4.0});
            def.geometry.polygon.centroid = {1e300, 0.0};
            def.geometry.capsule = {{1.0, 1.0}, {1.0, 1.0}, -1.0};
            def.geometry.segment = {{7.0, 0.0}, {7.0, 0.0}};
            def.geometry.chain_segment.point1 = {std::nan(""), 0.0};
            BOOST_CHECK_NO_THROW(scribbled.world.create_shape(scribbled.body, def));
            BOOST_TEST(scribbled.world.state_hash() == clean.world.state_hash());
            clean.world.step(1.0 / 60.0);
            scribbled.world.step(1.0 / 60.0);
            BOOST_TEST(scribbled.world.state_hash() == clean.world.state_hash());
        }
    }
    // A polygon's vertices and normals past its count, and the other kinds' members, likewise.
    Scene1 clean, scribbled;
    clean.world.create_shape(clean.body, box_shape(1.0, 0.5));
    ShapeDef def = box_shape(1.0, 0.5);
    def.geometry.polygon.vertices[6] = {1e300, -1e300};
    def.geometry.polygon.normals[7] = {std::nan(""), 2.0};
    def.geometry.circle = {{5.0, 5.0}, -3.0};
    BOOST_CHECK_NO_THROW(scribbled.world.create_shape(scribbled.body, def));
    BOOST_TEST(scribbled.world.state_hash() == clean.world.state_hash());
}

// G2. Oracle: the closed form centroid of a rectangle, its centre; a polygon whose centroid is
// not its vertices' (1e155 m away, or 0.1 m off on a 1 m box) is refused, the world unchanged.
BOOST_AUTO_TEST_CASE(a_polygons_centroid_is_its_vertices,
                     *utf::label("R4") * utf::label("DCX_shape")) {
    Scene1 s;
    for (const Vec2d c : {Vec2d{1.3e155, 0.0}, Vec2d{0.0, -1e20}, Vec2d{0.1, 0.0}}) {
        ShapeDef def = box_shape(1.0, 1.0);
        def.geometry.polygon.centroid = c;
        expect_refused(
            s.world, [&] { s.world.create_shape(s.body, def); }, "polygon.centroid.error");
    }
    // A rotated box far from the body origin, its centroid its exact centre: accepted, and its
    // body's centre of mass is that centre (to the rounding of its rotated vertices).
    const Vec2d center{1234.5, -678.25};
    BOOST_CHECK_NO_THROW(
        s.world.create_shape(s.body, box_shape(0.3, 2.0, Material{}, center, 0.7)));
    const Vec2d lc = s.world.local_center(s.body);
    BOOST_TEST(std::abs(lc.x - center.x) <= 1e-12 * 1234.5);
    BOOST_TEST(std::abs(lc.y - center.y) <= 1e-12 * 1234.5);
}

// G3. Oracle: a pentagram (the pentagon's vertices taken two at a time) turns round twice, so
// it is not a simple polygon and is refused (the world unchanged); the pentagon itself is
// accepted with the closed form mass rho (5 / 2) R^2 sin(72 deg) of a regular pentagon.
BOOST_AUTO_TEST_CASE(self_intersecting_polygons_are_refused,
                     *utf::label("R4") * utf::label("DCX_shape")) {
    Scene1 s;
    const ShapeDef star = pentagon_in_order({0, 2, 4, 1, 3});
    expect_refused(
        s.world, [&] { s.world.create_shape(s.body, star); }, "polygon.winding_number");
    const double pentagon_mass = 2.5 * std::sin(2.0 * std::numbers::pi / 5.0);
    BOOST_CHECK_NO_THROW(s.world.create_shape(s.body, pentagon_in_order({0, 1, 2, 3, 4})));
    BOOST_TEST(s.world.mass(s.body) == pentagon_mass, boost::test_tools::tolerance(1e-14));

    // Through a scene (the CLI's path): the pentagram's points listed in the star's order are
    // refused by the scene's own check of the outline, which names the crossing edges.
    std::string points;
    for (const int k : {0, 2, 4, 1, 3}) {
        const double a = std::numbers::pi / 2.0 + 2.0 * std::numbers::pi * k / 5.0;
        points += (points.empty() ? "[" : ", [") + std::to_string(std::cos(a)) + ", " +
                  std::to_string(std::sin(a)) + "]";
    }
    try {
        (void)io::parse_scene(
            R"({"version": 1, "dt": 0.01, "steps": 1, "bodies": [{"name": "star", "shapes": [
                {"type": "polygon", "points": [)" +
            points + "]}]}]}");
        BOOST_ERROR("a pentagram's outline was accepted by the scene loader");
    } catch (const io::SceneError& e) {
        BOOST_TEST(e.constraint == "DCX_shape", e.what());
        BOOST_TEST(std::string(e.what()).find("crosses itself") != std::string::npos, e.what());
    }
}

namespace {
/// CPU seconds to create a body with `n` boxes of a tile map (n / 100 rows of 100), in a child
/// process of its own, or -1 if the child failed (the mass of N unit boxes of density 1 is N kg,
/// checked there). A fresh process for every trial: in one process a small size reuses the heap
/// memory a larger one freed, while a larger one's arrays are fresh mappings (LargeArray), whose
/// first touch the kernel, and on a virtual machine the host, may charge microseconds a page for.
/// A ratio of two sizes then measures what memory was touched before, not the code under test.
double seconds_for_shapes_once(int n, BodyType type) {
    int fd[2];
    if (pipe(fd) != 0)
        return -1.0;
    const pid_t child = fork();
    if (child < 0)
        return -1.0;
    if (child == 0) {
        close(fd[0]);
        double seconds = -1.0;
        try { // nothing may leave the child: Boost.Test would go on running cases in it
            World w{WorldDef{}};
            BodyDef d;
            d.type = type;
            const BodyId b = w.create_body(d);
            const double t0 = test::process_cpu_seconds();
            for (int i = 0; i < n; ++i)
                w.create_shape(b,
                               box_shape(1.0, 1.0, Material{}, {double(i % 100), double(i / 100)}));
            // The mass is read once: a dynamic body's sum over its shapes is part of the cost.
            const bool mass_right = w.mass(b) == (type == BodyType::dynamic ? double(n) : 0.0);
            if (mass_right)
                seconds = test::process_cpu_seconds() - t0;
        } catch (...) {
            seconds = -1.0;
        }
        const bool written = write(fd[1], &seconds, sizeof seconds) == ssize_t(sizeof seconds);
        _exit(written ? 0 : 1); // no Boost.Test teardown in the child
    }
    close(fd[1]);
    double seconds = -1.0;
    if (read(fd[0], &seconds, sizeof seconds) != ssize_t(sizeof seconds))
        seconds = -1.0;
    close(fd[0]);
    int status = 0;
    waitpid(child, &status, 0);
    return WIFEXITED(status) && WEXITSTATUS(status) == 0 ? seconds : -1.0;
}

/// The best of three trials.
double seconds_for_shapes(int n, BodyType type) {
    double best = 1e300;
    for (int trial = 0; trial < 3; ++trial) {
        const double t = seconds_for_shapes_once(n, type);
        BOOST_TEST_REQUIRE(t >= 0.0, "the trial of " << n << " shapes failed or got a wrong mass");
        best = std::min(best, t);
    }
    return best;
}
} // namespace

// G4. Oracle: linear cost, stated as a ratio of CPU times (no absolute time): 8N shapes on one
// body take less than 24 times as long as N (8 for linear cost; 64 for the quadratic cost it
// had: the bound lies between them with room for a shared machine's and a sanitizer's noise),
// each size timed in fresh processes. The mass of N unit boxes of density 1 is N kg.
BOOST_AUTO_TEST_CASE(shapes_attach_to_one_body_in_linear_time, *utf::label("performance")) {
    for (const BodyType type : {BodyType::static_body, BodyType::dynamic}) {
        BOOST_TEST_CONTEXT((type == BodyType::dynamic ? "dynamic" : "static")) {
            const int n = 5000;
            const double t1 = seconds_for_shapes(n, type);
            const double t8 = seconds_for_shapes(8 * n, type);
            BOOST_TEST_MESSAGE(n << " shapes: " << t1 << " s; " << 8 * n << ": " << t8 << " s");
            BOOST_TEST(t8 < 24.0 * t1, t8 << " s for 8N against " << t1 << " s for N");
        }
    }
}

// G5 in the broad phase. Oracle: the geometry of the pyramid: a box's fat box is grown by at
// most its own size (the broad phase's least margin is 0 here), so it can only pair with the boxes
// whose centres lie within three sizes of its own in each axis (counted here by brute force,
// to 3.25: the pyramid's centres are half a size apart, so no rounding decides): a handful per box,
// not all 5050.
BOOST_AUTO_TEST_CASE(small_boxes_pair_only_with_their_neighbours, *utf::label("reliability")) {
    const double size = 1e-12;
    std::vector<Aabb> boxes;
    for (int row = 0; row < 100; ++row)
        for (int col = 0; col < 100 - row; ++col) {
            const double x = (col - 0.5 * (99 - row)) * size, y = (row + 0.5) * size;
            boxes.push_back({x - 0.5 * size, y - 0.5 * size, x + 0.5 * size, y + 0.5 * size});
        }
    BroadPhase bp;
    for (std::size_t i = 0; i < boxes.size(); ++i)
        bp.create_proxy(boxes[i], std::uint32_t(i));
    memory::vector<BroadPhase::Pair> pairs;
    bp.update_pairs(pairs);
    std::size_t near = 0; // pairs of centres within 3.25 sizes in each axis
    for (std::size_t i = 0; i < boxes.size(); ++i)
        for (std::size_t j = i + 1; j < boxes.size(); ++j)
            if (std::abs(boxes[i].min_x - boxes[j].min_x) <= 3.25 * size &&
                std::abs(boxes[i].min_y - boxes[j].min_y) <= 3.25 * size)
                ++near;
    BOOST_TEST_MESSAGE(pairs.size() << " pairs of " << boxes.size() << " boxes; " << near
                                    << " within 3.25 sizes");
    BOOST_TEST(pairs.size() >= boxes.size()); // each box touches its neighbours
    BOOST_TEST(pairs.size() <= near);
    BOOST_TEST(near <= 25 * boxes.size()); // (at most 49 centres in a 7 x 7 neighbourhood)
}

// G5 through a scene. Oracle: the fuzzer's 80-byte scene with its tolerances scaled to its
// boxes (a speculative distance of 1e-13 m; the fixed margin still made every pair a pair)
// steps once, its touching pairs a few per box and the library's large blocks (contacts, tree
// nodes, solver packs) far below the gigabytes it took.
BOOST_AUTO_TEST_CASE(a_pyramid_of_tiny_boxes_steps_in_bounded_memory, *utf::label("reliability")) {
    const io::Scene scene = io::parse_scene(
        R"({"version":1,"dt":"1/60","steps":1,"world":{"speculative_distance":1e-13},)"
        R"("bodies":[{"generator":"pyramid","base":100,"box":1e-12,"gap":0}]})");
    World world(scene.world);
    io::build_world(scene, world);
    const std::size_t before = large_array_stats().mapped_bytes;
    world.step(scene.dt);
    const std::size_t after = large_array_stats().mapped_bytes;
    BOOST_TEST_MESSAGE(world.contacts().size() << " touching pairs; large blocks " << before
                                               << " -> " << after << " bytes");
    BOOST_TEST(world.contacts().size() >= world.body_count() - 1); // every box rests on one
    BOOST_TEST(world.contacts().size() <= 10 * world.body_count());
    BOOST_TEST(after <= before + (std::size_t(256) << 20));
}

BOOST_AUTO_TEST_SUITE_END()
