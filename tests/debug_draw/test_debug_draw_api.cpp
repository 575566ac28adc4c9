// World::draw's guarantees: colours by state as DrawColors documents them, the geometry of
// what it hands over, nothing changed by drawing, and bad settings refused before any call.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <vector>

#include "tamias2d/debug_draw.hpp"
#include "tamias2d/errors.hpp"
#include "tamias2d/world.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;

namespace {

struct DrawnCircle {
    Vec2d center;
    double radius;
    Color color;
};

/// Keeps what it is handed.
struct Recorder : DebugDraw {
    std::vector<Color> polygon_colors;
    std::vector<std::vector<Vec2d>> polygons;
    std::vector<DrawnCircle> circles;
    int calls = 0;
    void solid_polygon(std::span<const Vec2d> v, Color c) override {
        polygons.emplace_back(v.begin(), v.end());
        polygon_colors.push_back(c);
        ++calls;
    }
    void solid_circle(Vec2d p, double r, double, Color c) override {
        circles.push_back({p, r, c});
        ++calls;
    }
    void segment(Vec2d, Vec2d, Color) override { ++calls; }
    void polygon(std::span<const Vec2d>, Color) override { ++calls; }
    void point(Vec2d, double, Color) override { ++calls; }
    void transform(Vec2d, double, double) override { ++calls; }
};

} // namespace

BOOST_AUTO_TEST_SUITE(debug_draw_api)

// Oracle: DrawColors' documented precedence (sensor, bullet, static, kinematic, sleeping,
// awake), one body of each state, each with one 1 m box, drawn in creation order.
BOOST_AUTO_TEST_CASE(colours_by_state, *utf::label("reliability")) {
    World world(WorldDef{.enable_sleep = true});
    BodyDef st;
    st.type = BodyType::static_body;
    world.create_shape(world.create_body(st), box_shape(1.0, 1.0));
    BodyDef kin;
    kin.type = BodyType::kinematic;
    kin.position = {2.0, 0.0};
    world.create_shape(world.create_body(kin), box_shape(1.0, 1.0));
    BodyDef awake;
    awake.position = {4.0, 0.0};
    world.create_shape(world.create_body(awake), box_shape(1.0, 1.0));
    BodyDef asleep;
    asleep.position = {6.0, 0.0};
    asleep.awake = false;
    world.create_shape(world.create_body(asleep), box_shape(1.0, 1.0));
    BodyDef sensor_body;
    sensor_body.position = {8.0, 0.0};
    ShapeDef sensor = box_shape(1.0, 1.0);
    sensor.is_sensor = true;
    world.create_shape(world.create_body(sensor_body), sensor);
    BodyDef bullet;
    bullet.position = {10.0, 0.0};
    bullet.bullet = true;
    world.create_shape(world.create_body(bullet), box_shape(1.0, 1.0));

    Recorder r;
    r.colors.static_body = Color{0x000001};
    r.colors.kinematic = Color{0x000002};
    r.colors.awake = Color{0x000003};
    r.colors.sleeping = Color{0x000004};
    r.colors.sensor = Color{0x000005};
    r.colors.bullet = Color{0x000006};
    world.draw(r);
    const std::vector<Color> want{Color{1}, Color{2}, Color{3}, Color{4}, Color{5}, Color{6}};
    BOOST_TEST_REQUIRE(r.polygon_colors.size() == want.size());
    for (std::size_t k = 0; k < want.size(); ++k)
        BOOST_TEST(r.polygon_colors[k].rgb == want[k].rgb);
}

// Oracle: hand placement: a 2 m x 1 m box whose body stands at (3, 4) turned by pi/2 has its
// corners at (3 -/+ 0.5, 4 -/+ 1), counter-clockwise from (3.5, 3); a circle of radius 0.5
// centred 1 m along the body's x axis lies at (3, 5).
BOOST_AUTO_TEST_CASE(primitives_in_world_coordinates, *utf::label("reliability")) {
    World world(WorldDef{.gravity = {0.0, 0.0}});
    BodyDef d;
    d.position = {3.0, 4.0};
    d.angle = std::acos(-1.0) / 2.0;
    const BodyId b = world.create_body(d);
    world.create_shape(b, box_shape(2.0, 1.0));
    world.create_shape(b, circle_shape(0.5, {}, {1.0, 0.0}));
    Recorder r;
    world.draw(r);
    BOOST_TEST_REQUIRE(r.polygons.size() == 1u);
    BOOST_TEST_REQUIRE(r.polygons[0].size() == 4u);
    const Vec2d want[4] = {{3.5, 3.0}, {3.5, 5.0}, {2.5, 5.0}, {2.5, 3.0}};
    for (int k = 0; k < 4; ++k) {
        BOOST_TEST(r.polygons[0][k].x == want[k].x, boost::test_tools::tolerance(1e-12));
        BOOST_TEST(r.polygons[0][k].y == want[k].y, boost::test_tools::tolerance(1e-12));
    }
    BOOST_TEST_REQUIRE(r.circles.size() == 1u);
    BOOST_TEST(std::abs(r.circles[0].center.x - 3.0) < 1e-12);
    BOOST_TEST(std::abs(r.circles[0].center.y - 5.0) < 1e-12);
    BOOST_TEST(r.circles[0].radius == 0.5);
}

// Oracle: the strong guarantee (state_hash before and after): drawing changes nothing, and a
// bad setting is refused, naming its field, before any primitive is handed over.
BOOST_AUTO_TEST_CASE(draws_nothing_wrong_and_changes_nothing, *utf::label("reliability")) {
    World world;
    BodyDef g;
    g.type = BodyType::static_body;
    world.create_shape(world.create_body(g), box_shape(10.0, 1.0));
    BodyDef d;
    d.position = {0.0, 1.0};
    world.create_shape(world.create_body(d), box_shape(1.0, 1.0));
    for (int k = 0; k < 30; ++k)
        world.step(1.0 / 60.0);
    const auto before = world.state_hash();
    Recorder ok;
    ok.draw_contacts = ok.draw_contact_normals = ok.draw_aabbs = ok.draw_mass_centers = true;
    world.draw(ok);
    BOOST_TEST(ok.calls > 0);
    BOOST_TEST(world.state_hash() == before);

    const auto refused = [&](auto set, const char* field) {
        Recorder r;
        r.draw_contacts = true;
        set(r);
        try {
            world.draw(r);
            BOOST_ERROR("accepted a bad " << field);
        } catch (const ValidationError& e) {
            BOOST_TEST(e.field == field);
        }
        BOOST_TEST(r.calls == 0);
        BOOST_TEST(world.state_hash() == before);
    };
    const double nan = std::nan("");
    refused([](Recorder& r) { r.contact_normal_length = 0.0; }, "draw.contact_normal_length");
    refused([&](Recorder& r) { r.contact_normal_length = nan; }, "draw.contact_normal_length");
    refused([](Recorder& r) { r.axis_length = -1.0; }, "draw.axis_length");
    refused([](Recorder& r) { r.bounds = Aabb{1.0, 0.0, 0.0, 1.0}; }, "draw.bounds.max_x");
    refused([](Recorder& r) { r.bounds = Aabb{0.0, 1.0, 1.0, 0.0}; }, "draw.bounds.max_y");
    refused([&](Recorder& r) { r.bounds = Aabb{nan, 0.0, 1.0, 1.0}; }, "draw.bounds.min_x");
}

BOOST_AUTO_TEST_SUITE_END()
