// The scene format (docs/scene-format.md): what a file says is what the Scene and the World
// get (R1, R2, R3), and canonical JSON round-trips.
#include <boost/test/unit_test.hpp>

#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include "tamias2d/io/scene.hpp"
#include "tamias2d/world.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;
using namespace tamias2d::io;

namespace {

const char* const full_scene = R"({
  "version": 1,
  "description": "every field",
  "world": { "gravity": [0.5, -10], "substeps": 8, "contact_hertz": 40,
             "contact_damping_ratio": 5, "contact_push_max_velocity": 2, "linear_slop": 0.004,
             "speculative_distance": 0.03, "manifold_reuse_distance": 0.01, "contact_regions": 3,
             "restitution_threshold": 0.5, "enable_sleep": true,
             "time_to_sleep": 0.75, "linear_sleep_tolerance": 0.02, "angular_sleep_tolerance": 0.01 },
  "dt": "1/120",
  "steps": 240,
  "output_every": 12,
  "materials": { "default": { "friction": 0.6 },
                 "rubber": { "density": 1.5, "restitution": 0.8, "friction": 0.9 } },
  "bodies": [
    { "name": "ground", "type": "static", "position": [0, -1],
      "shapes": [ { "type": "box", "width": 40, "height": 2 } ] },
    { "name": "crate", "type": "dynamic", "position": [1.5, 2.5], "angle": 0.25,
      "velocity": [2.51, -1], "angular_velocity": 2.1, "mass": 56.2, "inertia": 74.5,
      "gravity_scale": 0.5, "fixed_rotation": false, "enable_sleep": false, "awake": false,
      "force": [98.1, 0], "torque": 200,
      "loads": { "force_x": 3,
                 "force_y": { "kind": "sinusoid", "amplitude": 2, "omega": 3, "phase": 0.5, "offset": 1 },
                 "torque": { "kind": "ramp", "t0": 1, "t1": 3, "from": 0, "to": 4 } },
      "shapes": [ { "type": "box", "width": 2, "height": 1, "center": [0.5, 0], "angle": 0,
                    "material": "rubber" },
                  { "type": "circle", "radius": 0.25, "center": [-1, 0],
                    "material": { "density": 2, "restitution": 1 },
                    "filter": { "category_bits": 6, "mask_bits": 4294967293, "group_index": -3 },
                    "sensor": true } ] },
    { "name": "wedge", "type": "kinematic", "velocity": [1, 0],
      "loads": { "torque": { "kind": "step", "time": 2, "before": -1, "after": 1 } },
      "shapes": [ { "type": "polygon", "points": [[0, 0], [2, 0], [0, 1]] } ] }
  ]
})";

// Capsules, segments and chains, each key written out (docs/scene-format.md, "Shapes").
const char* const shapes_scene = R"({
  "dt": "1/60",
  "steps": 120,
  "materials": { "grip": { "friction": 0.9 } },
  "bodies": [
    { "name": "ground", "type": "static",
      "shapes": [ { "type": "chain", "points": [[8, 0], [4, 1], [0, 0], [-4, -1], [-8, 0]],
                    "material": "grip", "filter": { "category_bits": 2 }, "sensor": false },
                  { "type": "chain", "points": [[-2, 4], [2, 4], [2, 6], [-2, 6]], "loop": true },
                  { "type": "segment", "point1": [-6, 3], "point2": [-2, 2.5] },
                  { "type": "chain_segment", "ghost1": [10, 1], "point1": [10, 0],
                    "point2": [12, 0], "ghost2": [13, 1] } ] },
    { "name": "pill", "position": [-5, 5], "bullet": true, "velocity": [30, 0],
      "shapes": [ { "type": "capsule", "center1": [-0.5, 0], "center2": [0.5, 0.25],
                    "radius": 0.25, "material": { "density": 2 } } ] },
    { "name": "rod", "position": [5, 4], "mass": 1.5, "inertia": 0.2,
      "shapes": [ { "type": "segment", "point1": [-1, 0], "point2": [1, 0] } ] }
  ]
})";

/// Bit for bit: -0 and 0 differ (the round trip is promised for the bits).
bool same_bits(double a, double b) {
    return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}
bool same_bits(Vec2d a, Vec2d b) {
    return same_bits(a.x, b.x) && same_bits(a.y, b.y);
}

/// The geometry of a capsule, segment or chain segment, bit for bit.
bool same_segment_kind(const Geometry& a, const Geometry& b) {
    if (a.type != b.type)
        return false;
    switch (a.type) {
    case ShapeType::capsule:
        return same_bits(a.capsule.center1, b.capsule.center1) &&
               same_bits(a.capsule.center2, b.capsule.center2) &&
               same_bits(a.capsule.radius, b.capsule.radius);
    case ShapeType::segment:
        return same_bits(a.segment.point1, b.segment.point1) &&
               same_bits(a.segment.point2, b.segment.point2);
    case ShapeType::chain_segment:
        return same_bits(a.chain_segment.ghost1, b.chain_segment.ghost1) &&
               same_bits(a.chain_segment.point1, b.chain_segment.point1) &&
               same_bits(a.chain_segment.point2, b.chain_segment.point2) &&
               same_bits(a.chain_segment.ghost2, b.chain_segment.ghost2);
    default:
        return false;
    }
}

bool same_polygon(const Polygon& a, const Polygon& b, double tol) {
    if (a.count != b.count)
        return false;
    // Same vertices in the same cyclic order, from any starting vertex.
    for (int shift = 0; shift < a.count; ++shift) {
        bool all = true;
        for (int i = 0; i < a.count && all; ++i) {
            const Vec2d p = a.vertices[std::size_t(i)];
            const Vec2d q = b.vertices[std::size_t((i + shift) % a.count)];
            all = std::abs(p.x - q.x) <= tol && std::abs(p.y - q.y) <= tol;
        }
        if (all)
            return true;
    }
    return false;
}

void check_same(const Scene& a, const Scene& b) {
    BOOST_TEST(a.dt == b.dt);
    BOOST_TEST(a.steps == b.steps);
    BOOST_TEST(a.output_every == b.output_every);
    BOOST_TEST(a.world.gravity.x == b.world.gravity.x);
    BOOST_TEST(a.world.gravity.y == b.world.gravity.y);
    BOOST_TEST(a.world.substeps == b.world.substeps);
    BOOST_TEST(a.world.contact_hertz == b.world.contact_hertz);
    BOOST_TEST(a.world.linear_slop == b.world.linear_slop);
    BOOST_TEST(a.world.manifold_reuse_distance == b.world.manifold_reuse_distance);
    BOOST_TEST(a.world.contact_regions == b.world.contact_regions);
    BOOST_TEST(a.world.enable_sleep == b.world.enable_sleep);
    BOOST_TEST(a.world.time_to_sleep == b.world.time_to_sleep);
    BOOST_TEST(a.world.linear_sleep_tolerance == b.world.linear_sleep_tolerance);
    BOOST_TEST(a.world.angular_sleep_tolerance == b.world.angular_sleep_tolerance);
    BOOST_TEST_REQUIRE(a.joints.size() == b.joints.size());
    for (std::size_t i = 0; i < a.joints.size(); ++i) {
        BOOST_TEST_CONTEXT("joint " << i) {
            const SceneJoint& x = a.joints[i];
            const SceneJoint& y = b.joints[i];
            BOOST_TEST(x.body_a == y.body_a);
            BOOST_TEST(x.body_b == y.body_b);
            BOOST_TEST((x.def == y.def)); // every field of the definition, of the same kind
        }
    }
    BOOST_TEST_REQUIRE(a.bodies.size() == b.bodies.size());
    for (std::size_t i = 0; i < a.bodies.size(); ++i) {
        BOOST_TEST_CONTEXT("body " << i) {
            const BodyDef& x = a.bodies[i].def;
            const BodyDef& y = b.bodies[i].def;
            BOOST_TEST(x.name == y.name);
            BOOST_TEST((x.type == y.type));
            BOOST_TEST(x.position.x == y.position.x);
            BOOST_TEST(x.position.y == y.position.y);
            BOOST_TEST(x.angle == y.angle);
            BOOST_TEST(x.linear_velocity.x == y.linear_velocity.x);
            BOOST_TEST(x.linear_velocity.y == y.linear_velocity.y);
            BOOST_TEST(x.angular_velocity == y.angular_velocity);
            BOOST_TEST(x.force.x == y.force.x);
            BOOST_TEST(x.torque == y.torque);
            BOOST_TEST((x.mass == y.mass));
            BOOST_TEST((x.inertia == y.inertia));
            BOOST_TEST(x.gravity_scale == y.gravity_scale);
            BOOST_TEST(x.fixed_rotation == y.fixed_rotation);
            BOOST_TEST(x.bullet == y.bullet);
            BOOST_TEST(x.enable_sleep == y.enable_sleep);
            BOOST_TEST(x.awake == y.awake);
            BOOST_TEST((a.bodies[i].loads == b.bodies[i].loads));
            BOOST_TEST_REQUIRE(a.bodies[i].shapes.size() == b.bodies[i].shapes.size());
            for (std::size_t s = 0; s < a.bodies[i].shapes.size(); ++s) {
                const ShapeDef& p = a.bodies[i].shapes[s];
                const ShapeDef& q = b.bodies[i].shapes[s];
                BOOST_TEST((p.geometry.type == q.geometry.type));
                BOOST_TEST(p.material.density == q.material.density);
                BOOST_TEST(p.material.restitution == q.material.restitution);
                BOOST_TEST(p.material.friction == q.material.friction);
                BOOST_TEST((p.filter == q.filter));
                BOOST_TEST(p.is_sensor == q.is_sensor);
                if (p.geometry.type == ShapeType::circle) {
                    BOOST_TEST(p.geometry.circle.radius == q.geometry.circle.radius);
                    BOOST_TEST(p.geometry.circle.center.x == q.geometry.circle.center.x);
                    BOOST_TEST(p.geometry.circle.center.y == q.geometry.circle.center.y);
                } else if (p.geometry.type != ShapeType::polygon) {
                    BOOST_TEST(same_segment_kind(p.geometry, q.geometry), "shape " << s);
                } else {
                    BOOST_TEST(same_polygon(p.geometry.polygon, q.geometry.polygon, 0.0));
                }
            }
        }
    }
}

} // namespace

BOOST_AUTO_TEST_SUITE(scene_parse)

// Oracle: the scene text above, read by hand against docs/scene-format.md: every value the file
// states reaches the Scene unchanged, omitted ones take the documented defaults.
BOOST_AUTO_TEST_CASE(every_field_reaches_the_scene, *utf::label("R2") * utf::label("R3")) {
    const Scene s = parse_scene(full_scene, "full");
    BOOST_TEST(s.description == "every field");
    BOOST_TEST(s.dt == 1.0 / 120.0); // "1/120" is the double nearest 1/120
    BOOST_TEST(s.steps == 240);
    BOOST_TEST(s.output_every == 12);
    BOOST_TEST(s.world.gravity.x == 0.5);
    BOOST_TEST(s.world.gravity.y == -10.0);
    BOOST_TEST(s.world.substeps == 8);
    BOOST_TEST(s.world.contact_hertz == 40.0);
    BOOST_TEST(s.world.contact_damping_ratio == 5.0);
    BOOST_TEST(s.world.contact_push_max_velocity == 2.0);
    BOOST_TEST(s.world.linear_slop == 0.004);
    BOOST_TEST(s.world.speculative_distance == 0.03);
    BOOST_TEST(s.world.manifold_reuse_distance == 0.01);
    BOOST_TEST(s.world.contact_regions == 3);
    BOOST_TEST(s.world.restitution_threshold == 0.5);
    BOOST_TEST(s.world.enable_sleep);
    BOOST_TEST(s.world.time_to_sleep == 0.75);
    BOOST_TEST(s.world.linear_sleep_tolerance == 0.02);
    BOOST_TEST(s.world.angular_sleep_tolerance == 0.01);
    BOOST_TEST(s.materials.size() == 2u);
    BOOST_TEST_REQUIRE(s.bodies.size() == 3u);

    const SceneBody& ground = s.bodies[0];
    BOOST_TEST(ground.def.name == "ground");
    BOOST_TEST((ground.def.type == BodyType::static_body));
    BOOST_TEST(ground.source == "/bodies/0");
    BOOST_TEST(!ground.generated);
    BOOST_TEST_REQUIRE(ground.shapes.size() == 1u);
    const Polygon& g = ground.shapes[0].geometry.polygon;
    BOOST_TEST(g.count == 4);
    BOOST_TEST(g.vertices[0].x == -20.0);
    BOOST_TEST(g.vertices[0].y == -1.0);
    BOOST_TEST(g.vertices[2].x == 20.0);
    BOOST_TEST(g.vertices[2].y == 1.0);
    // "default" material: friction 0.6, other fields the library's defaults (1, 0).
    BOOST_TEST(ground.shapes[0].material.friction == 0.6);
    BOOST_TEST(ground.shapes[0].material.density == 1.0);
    BOOST_TEST(ground.shapes[0].material.restitution == 0.0);

    const SceneBody& crate = s.bodies[1];
    const BodyDef& d = crate.def;
    BOOST_TEST((d.type == BodyType::dynamic));
    BOOST_TEST(d.position.x == 1.5);
    BOOST_TEST(d.position.y == 2.5);
    BOOST_TEST(d.angle == 0.25);
    BOOST_TEST(d.linear_velocity.x == 2.51);
    BOOST_TEST(d.linear_velocity.y == -1.0);
    BOOST_TEST(d.angular_velocity == 2.1);
    BOOST_TEST_REQUIRE(d.mass.has_value());
    BOOST_TEST(*d.mass == 56.2);
    BOOST_TEST_REQUIRE(d.inertia.has_value());
    BOOST_TEST(*d.inertia == 74.5);
    BOOST_TEST(d.gravity_scale == 0.5);
    BOOST_TEST(!d.fixed_rotation);
    BOOST_TEST(!d.enable_sleep);
    BOOST_TEST(!d.awake);
    BOOST_TEST(ground.def.enable_sleep); // omitted: the defaults
    BOOST_TEST(ground.def.awake);
    BOOST_TEST(d.force.x == 98.1);
    BOOST_TEST(d.torque == 200.0);
    BOOST_TEST(bool(d.load));
    BOOST_TEST_REQUIRE(crate.shapes.size() == 2u);
    const ShapeDef& box = crate.shapes[0];
    BOOST_TEST(box.material.density == 1.5); // named material
    BOOST_TEST(box.material.restitution == 0.8);
    BOOST_TEST(box.material.friction == 0.9);
    BOOST_TEST(box.geometry.polygon.vertices[0].x == -0.5); // centre 0.5, half width 1
    BOOST_TEST(box.geometry.polygon.vertices[1].x == 1.5);
    const ShapeDef& ball = crate.shapes[1];
    BOOST_TEST((ball.geometry.type == ShapeType::circle));
    BOOST_TEST(ball.geometry.circle.radius == 0.25);
    BOOST_TEST(ball.geometry.circle.center.x == -1.0);
    BOOST_TEST(ball.material.density == 2.0); // inline: missing friction from "default"
    BOOST_TEST(ball.material.restitution == 1.0);
    BOOST_TEST(ball.material.friction == 0.6);
    BOOST_TEST(ball.filter.category_bits == 6u); // the filter as written (DD27)
    BOOST_TEST(ball.filter.mask_bits == 0xFFFFFFFDu);
    BOOST_TEST(ball.filter.group_index == -3);
    BOOST_TEST(ball.is_sensor);
    BOOST_TEST(!box.is_sensor); // the defaults
    BOOST_TEST((box.filter == Filter{}));

    const SceneBody& wedge = s.bodies[2];
    BOOST_TEST((wedge.def.type == BodyType::kinematic));
    BOOST_TEST(wedge.shapes[0].geometry.polygon.count == 3);
    BOOST_TEST(!wedge.loads.force_x.has_value());
    BOOST_TEST(wedge.loads.torque.has_value());
}

// Oracle: hand evaluation of docs/scene-format.md's load formulas: constant 3; sinusoid
// 1 + 2 sin(3 t + 0.5); ramp 0 -> 4 over t in [1, 3]; step -1 before t = 2, 1 from t = 2 on.
BOOST_AUTO_TEST_CASE(time_varying_loads_follow_their_formulas, *utf::label("R2")) {
    const Scene s = parse_scene(full_scene, "full");
    const BodyDef& d = s.bodies[1].def;
    for (const double t : {0.0, 0.5, 1.0, 2.0, 2.5, 3.0, 10.0}) {
        BOOST_TEST_CONTEXT("t = " << t) {
            const Load l = d.load(t);
            BOOST_TEST(l.force.x == 3.0);
            BOOST_TEST(l.force.y == 1.0 + 2.0 * std::sin(3.0 * t + 0.5),
                       boost::test_tools::tolerance(1e-15));
            const double ramp = t <= 1.0 ? 0.0 : t >= 3.0 ? 4.0 : 2.0 * (t - 1.0);
            BOOST_TEST(l.torque == ramp, boost::test_tools::tolerance(1e-15));
        }
    }
    const SceneLoads& w = s.bodies[2].loads;
    BOOST_TEST((*w.torque)(1.999) == -1.0);
    BOOST_TEST((*w.torque)(2.0) == 1.0);
    BOOST_TEST((*w.torque)(5.0) == 1.0);
}

// Oracle: IM1 for a constant load: with g = 0, m = 2 kg and F_x(t) = 4 N (a load, not the
// persistent force), v_x(t) = (F / m) t = 2 t exactly for a constant acceleration, so after
// 60 steps of 1/60 s v_x = 2 m/s (to round-off) and the body has not turned.
BOOST_AUTO_TEST_CASE(loads_reach_the_world, *utf::label("R2") * utf::label("R5")) {
    const Scene s = parse_scene(R"({"world": {"gravity": [0, 0]}, "dt": "1/60", "steps": 60,
        "bodies": [{"name": "b", "mass": 2, "loads": {"force_x": {"kind": "constant", "value": 4}},
                    "shapes": [{"type": "circle", "radius": 0.5}]}]})",
                                "loads");
    World world(s.world);
    const std::vector<BodyId> ids = build_world(s, world);
    BOOST_TEST_REQUIRE(ids.size() == 1u);
    BOOST_TEST(world.mass(ids[0]) == 2.0);
    for (int i = 0; i < s.steps; ++i)
        world.step(s.dt);
    BOOST_TEST(world.velocity(ids[0]).x == 2.0, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(world.velocity(ids[0]).y == 0.0);
    BOOST_TEST(world.angular_velocity(ids[0]) == 0.0);
}

// Oracle: the scene text: build_world creates the bodies in file order with their names, types
// and shapes (R1: the world is the space holding them).
BOOST_AUTO_TEST_CASE(build_world_creates_the_scene_in_order, *utf::label("R1")) {
    const Scene s = parse_scene(full_scene, "full");
    World world(s.world);
    const std::vector<BodyId> ids = build_world(s, world);
    BOOST_TEST_REQUIRE(ids.size() == 3u);
    BOOST_TEST(world.body_count() == 3u);
    BOOST_TEST(world.name(ids[0]) == "ground");
    BOOST_TEST(world.name(ids[1]) == "crate");
    BOOST_TEST(world.name(ids[2]) == "wedge");
    BOOST_TEST((world.type(ids[0]) == BodyType::static_body));
    BOOST_TEST((world.type(ids[2]) == BodyType::kinematic));
    BOOST_TEST(world.shapes(ids[1]).size() == 2u);
    BOOST_TEST(world.mass(ids[1]) == 56.2); // the override, not rho A
    BOOST_TEST(world.gravity().x == 0.5);
    BOOST_TEST(world.settings().substeps == 8);
}

// Oracle: the strong guarantee (R4): a hand-made Scene whose third body is invalid is rejected
// by build_world before anything is created, with the body's source pointer in the message.
BOOST_AUTO_TEST_CASE(build_world_is_all_or_nothing, *utf::label("R4") * utf::label("DCI_m")) {
    Scene s = parse_scene(full_scene, "full");
    s.bodies[2].def.mass = -1.0;
    World world(s.world);
    world.create_body(BodyDef{});
    const auto hash = world.state_hash();
    try {
        build_world(s, world);
        BOOST_ERROR("build_world accepted a body of mass -1");
    } catch (const SceneError& e) {
        BOOST_TEST(e.pointer == "/bodies/2");
        BOOST_TEST(e.constraint == "DCI_m");
        BOOST_TEST(std::string(e.what()).find("mass") != std::string::npos);
    }
    BOOST_TEST(world.state_hash() == hash);
    BOOST_TEST(world.body_count() == 1u);
}

// Oracle: the library's own factories (shape_def.hpp): each capsule, segment and chain the
// file states is the ShapeDef capsule_shape, segment_shape and chain_shapes make from the same
// numbers, bit for bit (a chain of n points: n - 1 segments, n for a loop); a chain entry's
// filter and sensor flag reach each of its segments; a chain_segment entry keeps its ghosts.
BOOST_AUTO_TEST_CASE(capsules_segments_and_chains_reach_the_scene, *utf::label("scene")) {
    const Scene s = parse_scene(shapes_scene, "shapes");
    BOOST_TEST_REQUIRE(s.bodies.size() == 3u);
    const std::vector<ShapeDef>& ground = s.bodies[0].shapes;
    BOOST_TEST_REQUIRE(ground.size() == 4u + 4u + 1u + 1u);
    const Material grip{1.0, 0.0, 0.9};
    const std::vector<Vec2d> open{{8, 0}, {4, 1}, {0, 0}, {-4, -1}, {-8, 0}};
    const std::vector<ShapeDef> open_chain = chain_shapes(open, false, grip);
    const std::vector<Vec2d> box{{-2, 4}, {2, 4}, {2, 6}, {-2, 6}};
    const std::vector<ShapeDef> loop_chain = chain_shapes(box, true);
    for (std::size_t k = 0; k < 4; ++k) {
        BOOST_TEST_CONTEXT("segment " << k) {
            BOOST_TEST(same_segment_kind(ground[k].geometry, open_chain[k].geometry));
            BOOST_TEST(ground[k].material.friction == 0.9);
            BOOST_TEST(ground[k].filter.category_bits == 2u);
            BOOST_TEST(!ground[k].is_sensor);
            BOOST_TEST(same_segment_kind(ground[4 + k].geometry, loop_chain[k].geometry));
            BOOST_TEST((ground[4 + k].filter == Filter{}));
        }
    }
    // The loop's last segment closes it: from the last point back to the first.
    BOOST_TEST(ground[7].geometry.chain_segment.point1.x == -2.0);
    BOOST_TEST(ground[7].geometry.chain_segment.point2.y == 4.0);
    BOOST_TEST(same_segment_kind(ground[8].geometry, segment_shape({-6, 3}, {-2, 2.5}).geometry));
    const ChainSegment& alone = ground[9].geometry.chain_segment;
    BOOST_TEST((ground[9].geometry.type == ShapeType::chain_segment));
    BOOST_TEST(alone.ghost1.x == 10.0);
    BOOST_TEST(alone.ghost1.y == 1.0);
    BOOST_TEST(alone.ghost2.x == 13.0);

    const SceneBody& pill = s.bodies[1];
    BOOST_TEST(pill.def.bullet);
    BOOST_TEST(!s.bodies[0].def.bullet); // the default
    BOOST_TEST_REQUIRE(pill.shapes.size() == 1u);
    BOOST_TEST(same_segment_kind(pill.shapes[0].geometry,
                                 capsule_shape({-0.5, 0}, {0.5, 0.25}, 0.25).geometry));
    BOOST_TEST(pill.shapes[0].material.density == 2.0);
    BOOST_TEST(*s.bodies[2].def.mass == 1.5); // a segment has no mass: the body states one
}

// Oracle: the same world made through the API (world.hpp): a body with bullet set, a capsule,
// chains by World::create_chain: build_world gives the same World::state_hash() (every body's
// state, mass and flags, every shape's geometry and material), so the file means what the API
// means. The capsule's mass is DD30's, as World computes it.
BOOST_AUTO_TEST_CASE(capsules_segments_and_chains_reach_the_world,
                     *utf::label("R1") * utf::label("R2") * utf::label("R3")) {
    const Scene s = parse_scene(shapes_scene, "shapes");
    World from_file(s.world);
    const std::vector<BodyId> ids = build_world(s, from_file);

    World by_hand(s.world);
    BodyDef ground_def;
    ground_def.type = BodyType::static_body;
    ground_def.name = "ground";
    const BodyId ground = by_hand.create_body(ground_def);
    std::vector<ShapeDef> open =
        chain_shapes(std::vector<Vec2d>{{8, 0}, {4, 1}, {0, 0}, {-4, -1}, {-8, 0}}, false,
                     Material{1.0, 0.0, 0.9});
    for (ShapeDef& d : open)
        d.filter.category_bits = 2;
    by_hand.create_chain(ground, open);
    by_hand.create_chain(ground,
                         chain_shapes(std::vector<Vec2d>{{-2, 4}, {2, 4}, {2, 6}, {-2, 6}}, true));
    by_hand.create_shape(ground, segment_shape({-6, 3}, {-2, 2.5}));
    ShapeDef alone;
    alone.geometry.type = ShapeType::chain_segment;
    alone.geometry.chain_segment = {{10, 1}, {10, 0}, {12, 0}, {13, 1}};
    by_hand.create_shape(ground, alone);
    BodyDef pill_def;
    pill_def.name = "pill";
    pill_def.position = {-5, 5};
    pill_def.linear_velocity = {30, 0};
    pill_def.bullet = true;
    const BodyId pill = by_hand.create_body(pill_def);
    by_hand.create_shape(pill, capsule_shape({-0.5, 0}, {0.5, 0.25}, 0.25, Material{2.0}));
    BodyDef rod_def;
    rod_def.name = "rod";
    rod_def.position = {5, 4};
    rod_def.mass = 1.5;
    rod_def.inertia = 0.2;
    by_hand.create_shape(by_hand.create_body(rod_def), segment_shape({-1, 0}, {1, 0}));

    BOOST_TEST(from_file.state_hash() == by_hand.state_hash());
    BOOST_TEST_REQUIRE(ids.size() == 3u);
    BOOST_TEST(from_file.shapes(ids[0]).size() == 10u);
    BOOST_TEST(from_file.mass(ids[1]) == by_hand.mass(pill));
    // DD30 by hand: rectangle 2 r l plus disc pi r^2, l = |(1, 0.25)|, density 2.
    const double l = std::hypot(1.0, 0.25);
    BOOST_TEST(from_file.mass(ids[1]) == 2.0 * (2 * 0.25 * l + std::numbers::pi * 0.0625),
               boost::test_tools::tolerance(1e-14));
    for (int i = 0; i < 30; ++i) {
        from_file.step(s.dt);
        by_hand.step(s.dt);
    }
    BOOST_TEST(from_file.state_hash() == by_hand.state_hash());
}

// Oracle: the documented round-trip property: parse(scene_to_json(s)) reproduces s (values
// bit for bit, polygons up to the starting vertex) and scene_to_json is then a fixed point.
BOOST_AUTO_TEST_CASE(canonical_json_round_trips, *utf::label("R2")) {
    std::vector<std::pair<std::string, Scene>> scenes;
    scenes.emplace_back("full", parse_scene(full_scene, "full"));
    scenes.emplace_back("shapes", parse_scene(shapes_scene, "shapes"));
    for (const char* name :
         {"two_bodies", "free_fall", "projectile", "spinning", "collision_im3", "elastic2",
          "pyramid20", "rain", "damped", "pendulum", "chain", "double_pendulum", "bridge", "car",
          "ragdoll", "machines", "terrain"}) {
        const std::filesystem::path p =
            std::filesystem::path(TAMIAS_EXAMPLE_SCENES) / (std::string(name) + ".json");
        scenes.emplace_back(name, load_scene(p));
    }
    for (const auto& [name, s] : scenes) {
        BOOST_TEST_CONTEXT(name) {
            const std::string once = scene_to_json(s);
            const Scene back = parse_scene(once, name + " (canonical)");
            check_same(s, back);
            BOOST_TEST(scene_to_json(back) == once);
        }
    }
}

/// How often `needle` occurs in `text`.
std::size_t occurrences(const std::string& text, const std::string& needle) {
    std::size_t n = 0;
    for (std::size_t at = text.find(needle); at != std::string::npos;
         at = text.find(needle, at + 1))
        ++n;
    return n;
}

// Oracle: docs/scene-format.md, "Chains in the written form": a chain read from a file is
// written back as one "chain" entry with its points; a chain segment that is not exactly
// the segment chain_shapes makes (here an open end's ghost moved, and a lone segment with its
// own ghosts) is written with its ghosts, as a "chain_segment" entry, run and all. Either way
// the written form reads back bit for bit (-0 included).
BOOST_AUTO_TEST_CASE(chains_are_written_as_chains, *utf::label("scene")) {
    const std::string written = scene_to_json(parse_scene(shapes_scene, "shapes"));
    BOOST_TEST(occurrences(written, R"("type": "chain")") == 2u);
    BOOST_TEST(occurrences(written, R"("type": "chain_segment")") == 1u);
    BOOST_TEST(occurrences(written, R"("loop": true)") == 1u);

    Scene s = parse_scene(R"({"dt": 0.01, "steps": 1, "bodies": [{"type": "static", "shapes": [
        {"type": "chain", "points": [[-0.0, 0], [1, -0.0], [2, 0.5], [3, 0]]}]}]})",
                          "signed zeros");
    BOOST_TEST(std::signbit(s.bodies[0].shapes[0].geometry.chain_segment.point1.x));
    Scene moved = s;
    moved.bodies[0].shapes[0].geometry.chain_segment.ghost1 = {-1.0, 0.0}; // not a right angle
    for (const auto& [name, scene] : {std::pair{"as read", s}, std::pair{"ghost moved", moved}}) {
        BOOST_TEST_CONTEXT(name) {
            const std::string once = scene_to_json(scene);
            const bool as_read = std::string(name) == "as read";
            BOOST_TEST(occurrences(once, R"("type": "chain")") == (as_read ? 1u : 0u));
            BOOST_TEST(occurrences(once, R"("type": "chain_segment")") == (as_read ? 0u : 3u));
            const Scene back = parse_scene(once, "written");
            check_same(scene, back);
            BOOST_TEST(scene_to_json(back) == once);
        }
    }
}

// Oracle: the example scenes' descriptions (docs/scene-format.md): body counts by hand and by
// the generators' formulas (pyramid N: N (N + 1) / 2 + 1; rain n: n + 1).
BOOST_AUTO_TEST_CASE(example_scenes_load, *utf::label("scene")) {
    const std::vector<std::pair<const char*, std::size_t>> expected = {
        {"two_bodies", 2},       {"free_fall", 1},       {"projectile", 1},  {"spinning", 3},
        {"collision_im3", 2},    {"elastic2", 2},        {"pyramid20", 211}, {"pyramid40", 821},
        {"large_pyramid", 5051}, {"rain", 2001},         {"damped", 3},      {"pendulum", 5},
        {"chain", 23},           {"double_pendulum", 3}, {"bridge", 26},     {"car", 4},
        {"ragdoll", 11},         {"machines", 9},        {"terrain", 14}};
    for (const auto& [name, count] : expected) {
        BOOST_TEST_CONTEXT(name) {
            const Scene s = load_scene(std::filesystem::path(TAMIAS_EXAMPLE_SCENES) /
                                       (std::string(name) + ".json"));
            BOOST_TEST(s.bodies.size() == count);
            BOOST_TEST(s.dt == 1.0 / 60.0);
        }
    }
}

BOOST_AUTO_TEST_SUITE_END()
