// World::draw on every example scene: the primitives it hands a DebugDraw, by kind, against
// counts taken independently from the scene as loaded (its shapes' kinds, its joints' kinds,
// its bodies) and from the world's own contact report; what the flags and the bounds select.
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cstddef>
#include <filesystem>
#include <string>
#include <variant>
#include <vector>

#include "tamias2d/debug_draw.hpp"
#include "tamias2d/io/scene.hpp"
#include "tamias2d/world.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;

namespace {

/// Counts each primitive World::draw hands it.
struct CountingDraw : DebugDraw {
    std::size_t polygons = 0, solid_polygons = 0, circles = 0, capsules = 0, segments = 0,
                transforms = 0, points = 0;
    void polygon(std::span<const Vec2d> v, Color) override {
        BOOST_TEST(v.size() == 4u); // a box outline
        ++polygons;
    }
    void solid_polygon(std::span<const Vec2d> v, Color) override {
        BOOST_TEST(v.size() >= 3u);
        ++solid_polygons;
    }
    void solid_circle(Vec2d, double, double, Color) override { ++circles; }
    void solid_capsule(Vec2d, Vec2d, double, Color) override { ++capsules; }
    void segment(Vec2d, Vec2d, Color) override { ++segments; }
    void transform(Vec2d, double, double) override { ++transforms; }
    void point(Vec2d, double, Color) override { ++points; }
    std::size_t total() const {
        return polygons + solid_polygons + circles + capsules + segments + transforms + points;
    }
};

CountingDraw only(bool shapes, bool joints, bool contacts, bool normals, bool aabbs, bool centers) {
    CountingDraw d;
    d.draw_shapes = shapes;
    d.draw_joints = joints;
    d.draw_contacts = contacts;
    d.draw_contact_normals = normals;
    d.draw_aabbs = aabbs;
    d.draw_mass_centers = centers;
    return d;
}

/// What a scene holds, counted from the file as loaded (not from the world).
struct SceneCounts {
    std::size_t polygons = 0, circles = 0, capsules = 0, segments = 0, shapes = 0;
    std::size_t joint_segments = 0, bodies = 0;
};

SceneCounts count(const io::Scene& scene) {
    SceneCounts c;
    c.bodies = scene.bodies.size();
    for (const io::SceneBody& b : scene.bodies) {
        for (const ShapeDef& s : b.shapes) {
            ++c.shapes;
            switch (s.geometry.type) {
            case ShapeType::polygon:
                ++c.polygons;
                break;
            case ShapeType::circle:
                ++c.circles;
                break;
            case ShapeType::capsule:
                ++c.capsules;
                break;
            case ShapeType::segment:
            case ShapeType::chain_segment:
                ++c.segments;
                break;
            }
        }
    }
    // The documented drawing of a joint: a filter or motor joint one segment between the
    // bodies' centres, every other kind of a scene three (centre, anchor, anchor, centre).
    for (const io::SceneJoint& j : scene.joints) {
        const bool one = std::holds_alternative<FilterJointDef>(j.def) ||
                         std::holds_alternative<MotorJointDef>(j.def);
        c.joint_segments += one ? 1 : 3;
    }
    return c;
}

std::vector<std::filesystem::path> example_scenes() {
    std::vector<std::filesystem::path> out;
    for (const auto& e : std::filesystem::directory_iterator(TAMIAS_EXAMPLE_SCENES)) {
        if (e.path().extension() == ".json")
            out.push_back(e.path());
    }
    std::sort(out.begin(), out.end());
    return out;
}

} // namespace

BOOST_AUTO_TEST_SUITE(debug_draw)

// Oracle: the scene file as loaded: each shape's kind counted from its definition, each
// joint's segments from its kind, one frame per body, one box per shape; after ten steps the
// contact points counted from World::contacts(). Every example scene.
BOOST_AUTO_TEST_CASE(every_example_scene_draws_what_it_holds, *utf::label("internals")) {
    const std::vector<std::filesystem::path> scenes = example_scenes();
    BOOST_TEST_REQUIRE(scenes.size() >= 19u);
    std::size_t scenes_with_joints = 0, scenes_with_contacts = 0;
    for (const std::filesystem::path& path : scenes) {
        BOOST_TEST_CONTEXT(path.filename().string()) {
            const io::Scene scene = io::load_scene(path);
            const SceneCounts want = count(scene);
            World world(scene.world);
            io::build_world(scene, world);
            BOOST_TEST_REQUIRE(world.joint_count() == scene.joints.size());
            scenes_with_joints += scene.joints.empty() ? 0 : 1;

            CountingDraw shapes = only(true, false, false, false, false, false);
            world.draw(shapes);
            BOOST_TEST(shapes.solid_polygons == want.polygons);
            BOOST_TEST(shapes.circles == want.circles);
            BOOST_TEST(shapes.capsules == want.capsules);
            BOOST_TEST(shapes.segments == want.segments);
            BOOST_TEST(shapes.total() == want.shapes);

            CountingDraw joints = only(false, true, false, false, false, false);
            world.draw(joints);
            BOOST_TEST(joints.segments == want.joint_segments);
            BOOST_TEST(joints.total() == want.joint_segments);

            CountingDraw boxes = only(false, false, false, false, true, true);
            world.draw(boxes);
            BOOST_TEST(boxes.polygons == want.shapes);
            BOOST_TEST(boxes.transforms == want.bodies);
            BOOST_TEST(boxes.total() == want.shapes + want.bodies);

            for (int k = 0; k < 10; ++k)
                world.step(scene.dt);
            std::size_t points = 0;
            for (const ContactInfo& c : world.contacts())
                points += std::size_t(c.point_count);
            scenes_with_contacts += points > 0 ? 1 : 0;
            CountingDraw contacts = only(false, false, true, true, false, false);
            world.draw(contacts);
            BOOST_TEST(contacts.points == points);
            BOOST_TEST(contacts.segments == points); // one normal per point
            BOOST_TEST(contacts.total() == 2 * points);
        }
    }
    // The scenes exercise what is counted: joints and contacts in several of them.
    BOOST_TEST(scenes_with_joints >= 3u);
    BOOST_TEST(scenes_with_contacts >= 5u);
}

// Oracle: the definition of the bounds: a box holding the whole scene draws what no bounds
// draws; a box far from every shape draws nothing; a box around one resting box of
// pyramid20's bottom row draws it and its neighbours only (the fattened boxes of the row's
// boxes 1 m apart overlap it at most in the box itself, its two neighbours, the ground and the
// three boxes above it), never the whole pyramid.
BOOST_AUTO_TEST_CASE(bounds_select_through_the_broad_phase, *utf::label("internals")) {
    const io::Scene scene =
        io::load_scene(std::filesystem::path(TAMIAS_EXAMPLE_SCENES) / "pyramid20.json");
    World world(scene.world);
    const std::vector<BodyId> ids = io::build_world(scene, world);
    CountingDraw all = only(true, true, false, false, true, true);
    world.draw(all);
    CountingDraw wide = only(true, true, false, false, true, true);
    wide.bounds = Aabb{-1e6, -1e6, 1e6, 1e6};
    world.draw(wide);
    BOOST_TEST(wide.total() == all.total());
    BOOST_TEST(wide.solid_polygons == 211u);

    CountingDraw far = only(true, true, true, true, true, true);
    far.bounds = Aabb{1e5, 1e5, 1e5 + 1.0, 1e5 + 1.0};
    world.draw(far);
    BOOST_TEST(far.total() == 0u);

    // A small box around the centre of a bottom-row box (the pyramid's second body).
    const Vec2d c = world.position(ids[1]);
    CountingDraw one = only(true, false, false, false, false, true);
    one.bounds = Aabb{c.x - 0.01, c.y - 0.01, c.x + 0.01, c.y + 0.01};
    world.draw(one);
    BOOST_TEST(one.solid_polygons >= 1u);
    BOOST_TEST(one.solid_polygons <= 6u);
    BOOST_TEST(one.transforms == 1u); // only its own centre lies in the box
}

BOOST_AUTO_TEST_SUITE_END()
