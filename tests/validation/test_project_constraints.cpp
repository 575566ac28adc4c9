// R4 for the constraints the SRS forgot (srs/data_constraints.yaml DCX_*): finite inputs, a
// positive time step, non-degenerate shapes, positive density, non-negative friction. Each is
// enforced with a ValidationError naming the field and the label, and a rejected call leaves
// the world bit-for-bit unchanged (state_hash, body count and time).
#include <boost/test/unit_test.hpp>

#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "tamias2d/geometry/shape_factory.hpp"
#include "validation_support.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;
using namespace tamias2d::test;

BOOST_AUTO_TEST_SUITE(project_constraints)

// Oracle: positive control for the strong-guarantee check itself: a valid mutation of each kind
// the other tests reject must change state_hash (else "unchanged" would prove nothing).
BOOST_AUTO_TEST_CASE(state_hash_sees_every_kind_of_change, *utf::label("internals")) {
    const std::vector<std::function<void(MovingWorld&)>> changes = {
        [](MovingWorld& m) { m.world.create_body(BodyDef{}); },
        [](MovingWorld& m) { m.world.create_shape(m.box, circle_shape(0.1)); },
        [](MovingWorld& m) {
            m.world.set_velocity(m.ball, {1.0, 0.0});
        },
        [](MovingWorld& m) { m.world.set_angular_velocity(m.plate, 0.0); },
        [](MovingWorld& m) {
            m.world.set_transform(m.box, {0.0, 0.6}, 0.0);
        },
        [](MovingWorld& m) {
            m.world.set_force(m.box, {1.0, 0.0});
        },
        [](MovingWorld& m) { m.world.set_torque(m.box, 1.0); },
        [](MovingWorld& m) {
            m.world.apply_force(m.box, {1.0, 0.0}, {0.0, 1.0});
        },
        [](MovingWorld& m) { m.world.apply_torque(m.box, 1.0); },
        [](MovingWorld& m) {
            m.world.apply_impulse(m.ball, {1.0, 0.0}, {3.0, 2.0});
        },
        [](MovingWorld& m) {
            m.world.set_gravity({0.0, -9.81});
        },
        [](MovingWorld& m) { m.world.step(1.0 / 60.0); },
        [](MovingWorld& m) { m.world.destroy_body(m.ball); },
    };
    for (std::size_t i = 0; i < changes.size(); ++i) {
        BOOST_TEST_CONTEXT("change #" << i) {
            MovingWorld m;
            const auto before = m.world.state_hash();
            changes[i](m);
            BOOST_TEST(m.world.state_hash() != before);
        }
    }
}

// Oracle: DCX_finite (srs/data_constraints.yaml): every real input is finite. Here: the body
// definition's fields not covered by a Table 1 row (gravity scale), and mass and inertia,
// whose finiteness is checked before their sign.
BOOST_AUTO_TEST_CASE(body_definition_fields_must_be_finite,
                     *utf::label("R4") * utf::label("DCX_finite")) {
    MovingWorld m;
    for (const double bad : non_finite) {
        BOOST_TEST_CONTEXT("value = " << bad) {
            BodyDef a;
            a.gravity_scale = bad;
            expect_rejected_value(
                m.world, [&] { m.world.create_body(a); }, "gravity_scale", "DCX_finite", bad);
            BodyDef b;
            b.mass = bad;
            expect_rejected_value(
                m.world, [&] { m.world.create_body(b); }, "mass", "DCX_finite", bad);
            BodyDef c;
            c.inertia = bad;
            expect_rejected_value(
                m.world, [&] { m.world.create_body(c); }, "inertia", "DCX_finite", bad);
        }
    }
}

// Oracle: DCX_finite and DCX_shape: every coordinate and size of a shape is finite; the
// factories reject it, and so does the world for a hand-made Geometry that bypassed them.
BOOST_AUTO_TEST_CASE(shape_definition_fields_must_be_finite,
                     *utf::label("R4") * utf::label("DCX_finite")) {
    MovingWorld m;
    for (const double bad : non_finite) {
        BOOST_TEST_CONTEXT("value = " << bad) {
            // A non-finite size is not "> 0" either; both labels are defensible, the finite
            // check comes first.
            expect_validation_error([&] { (void)box_shape(bad, 1.0); }, "width", "DCX_finite");
            expect_validation_error([&] { (void)box_shape(1.0, bad); }, "height", "DCX_finite");
            expect_validation_error(
                [&] {
                    (void)box_shape(1.0, 1.0, {}, {bad, 0.0});
                },
                "center", "DCX_finite");
            expect_validation_error([&] { (void)box_shape(1.0, 1.0, {}, {}, bad); }, "angle",
                                    "DCX_finite");
            expect_validation_error([&] { (void)circle_shape(bad); }, "radius", "DCX_finite");
            expect_validation_error(
                [&] {
                    (void)circle_shape(1.0, {}, {0.0, bad});
                },
                "center", "DCX_finite");
            const std::array<Vec2d, 3> pts = {Vec2d{0.0, 0.0}, Vec2d{1.0, 0.0}, Vec2d{0.0, bad}};
            expect_validation_error([&] { (void)polygon_shape(pts); }, "points", "DCX_finite");

            ShapeDef circle;
            circle.geometry.type = ShapeType::circle;
            circle.geometry.circle = {{bad, 0.0}, 1.0};
            expect_rejected(
                m.world, [&] { m.world.create_shape(m.box, circle); }, "center", "DCX_finite");
            circle.geometry.circle = {{0.0, 0.0}, bad};
            expect_rejected(
                m.world, [&] { m.world.create_shape(m.box, circle); }, "radius", "DCX_finite");

            ShapeDef poly = box_shape(1.0, 1.0);
            poly.geometry.polygon.vertices[2].x = bad;
            expect_rejected(
                m.world, [&] { m.world.create_shape(m.box, poly); }, "vertices", "DCX_finite");
        }
    }
}

// Oracle: DCX_finite for the material's real fields (density, C_R, friction).
BOOST_AUTO_TEST_CASE(material_fields_must_be_finite, *utf::label("R4") * utf::label("DCX_finite")) {
    MovingWorld m;
    for (const double bad : non_finite) {
        BOOST_TEST_CONTEXT("value = " << bad) {
            for (const int field : {0, 1, 2}) {
                Material mat;
                const char* name = field == 0 ? "density" : field == 1 ? "restitution" : "friction";
                (field == 0 ? mat.density : field == 1 ? mat.restitution : mat.friction) = bad;
                BOOST_TEST_CONTEXT("field " << name) {
                    expect_rejected_value(
                        m.world, [&] { m.world.create_shape(m.box, circle_shape(0.2, mat)); }, name,
                        "DCX_finite", bad);
                }
            }
        }
    }
}

// Oracle: DCX_finite for the impulse call (J and its point of application), whose inputs no
// Table 1 row covers (J is DD10's impulse).
BOOST_AUTO_TEST_CASE(impulse_must_be_finite, *utf::label("R4") * utf::label("DCX_finite")) {
    MovingWorld m;
    for (const double bad : non_finite) {
        BOOST_TEST_CONTEXT("value = " << bad) {
            expect_rejected_value(
                m.world,
                [&] {
                    m.world.apply_impulse(m.ball, {bad, 0.0}, {3.0, 2.0});
                },
                "impulse", "DCX_finite", bad);
            expect_rejected_value(
                m.world,
                [&] {
                    m.world.apply_impulse(m.ball, {0.0, bad}, {3.0, 2.0});
                },
                "impulse", "DCX_finite", bad);
            expect_rejected_value(
                m.world,
                [&] {
                    m.world.apply_impulse(m.ball, {1.0, 0.0}, {bad, 2.0});
                },
                "world_point", "DCX_finite", bad);
        }
    }
}

// Oracle: DCX_finite for every real world setting (the solver's softness and tolerances).
BOOST_AUTO_TEST_CASE(world_settings_must_be_finite, *utf::label("R4") * utf::label("DCX_finite")) {
    using Field = double WorldDef::*;
    const std::vector<std::pair<Field, const char*>> fields = {
        {&WorldDef::contact_hertz, "contact_hertz"},
        {&WorldDef::contact_damping_ratio, "contact_damping_ratio"},
        {&WorldDef::contact_push_max_velocity, "contact_push_max_velocity"},
        {&WorldDef::linear_slop, "linear_slop"},
        {&WorldDef::speculative_distance, "speculative_distance"},
        {&WorldDef::manifold_reuse_distance, "manifold_reuse_distance"},
        {&WorldDef::restitution_threshold, "restitution_threshold"},
    };
    for (const double bad : non_finite) {
        for (const auto& [field, name] : fields) {
            BOOST_TEST_CONTEXT(name << " = " << bad) {
                WorldDef def;
                def.*field = bad;
                expect_validation_error([&] { World w(def); }, name, "DCX_finite");
            }
        }
    }
}

// Oracle: WorldDef::manifold_reuse_distance's stated range, >= 0 (0 turns reuse off); the
// world's settings that are lengths are checked as DCX_finite's finite, non-negative values.
BOOST_AUTO_TEST_CASE(manifold_reuse_distance_must_not_be_negative,
                     *utf::label("R4") * utf::label("DCX_finite")) {
    for (const double bad : {-1e-9, -0.005, -1.0}) {
        BOOST_TEST_CONTEXT("manifold_reuse_distance = " << bad) {
            WorldDef def;
            def.manifold_reuse_distance = bad;
            expect_validation_error([&] { World w(def); }, "manifold_reuse_distance", "DCX_finite");
        }
    }
    WorldDef off;
    off.manifold_reuse_distance = 0.0;
    World w(off); // 0 is valid
    BOOST_TEST(w.settings().manifold_reuse_distance == 0.0);
}

// Oracle: WorldDef::contact_regions's stated range, an integer in [1, 8]; the refusal names the
// field and the rule, and leaves no world behind.
BOOST_AUTO_TEST_CASE(contact_regions_must_be_in_one_to_eight, *utf::label("reliability")) {
    for (const int bad : {0, -1, 9, 1 << 30}) {
        BOOST_TEST_CONTEXT("contact_regions = " << bad) {
            WorldDef def;
            def.contact_regions = bad;
            expect_validation_error([&] { World w(def); }, "contact_regions", "threads");
        }
    }
    for (const int good : {1, 8}) {
        WorldDef def;
        def.contact_regions = good;
        World w(def);
        BOOST_TEST(w.settings().contact_regions == good);
    }
}

// Oracle: DCX_dt (srs/data_constraints.yaml): the time step is finite and > 0; substeps
// (h = dt / substeps) are a positive count.
BOOST_AUTO_TEST_CASE(time_step_must_be_positive_and_finite,
                     *utf::label("R4") * utf::label("DCX_dt")) {
    MovingWorld m;
    for (const double dt : {0.0, -0.0, -1.0 / 60.0, -1e-300}) {
        BOOST_TEST_CONTEXT("dt = " << dt) {
            expect_rejected_value(
                m.world, [&] { m.world.step(dt); }, "dt", "DCX_dt", dt);
        }
    }
    for (const double dt : non_finite) {
        BOOST_TEST_CONTEXT("dt = " << dt) {
            expect_rejected_value(
                m.world, [&] { m.world.step(dt); }, "dt", "DCX_finite", dt);
        }
    }
    for (const int substeps : {0, -1}) {
        BOOST_TEST_CONTEXT("substeps = " << substeps) {
            WorldDef def;
            def.substeps = substeps;
            expect_validation_error([&] { World w(def); }, "substeps", "DCX_dt");
        }
    }
    const double t0 = m.world.time();
    m.world.step(1e-6); // a tiny positive step is valid
    BOOST_TEST(m.world.time() == t0 + 1e-6);
}

// Oracle: DCX_shape (srs/data_constraints.yaml): a convex polygon has 3 to 8 vertices, is
// convex and counter-clockwise and has positive area. Point clouds whose hull is degenerate are
// rejected by polygon_shape; hand-made polygons breaking an invariant by create_shape.
BOOST_AUTO_TEST_CASE(degenerate_polygons_are_rejected,
                     *utf::label("R4") * utf::label("DCX_shape")) {
    using Points = std::vector<Vec2d>;
    std::vector<std::pair<const char*, Points>> clouds = {
        {"two points", {{0.0, 0.0}, {1.0, 0.0}}},
        {"collinear", {{0.0, 0.0}, {1.0, 1.0}, {2.0, 2.0}, {3.0, 3.0}}},
        {"coincident", {{1.0, 1.0}, {1.0, 1.0}, {1.0, 1.0}}},
        {"sliver", {{0.0, 0.0}, {1.0, 0.0}, {0.5, 1e-9}}},
    };
    Points twelve; // a regular 12-gon: its hull has more than 8 vertices
    for (int k = 0; k < 12; ++k)
        twelve.push_back({std::cos(k * std::numbers::pi / 6), std::sin(k * std::numbers::pi / 6)});
    clouds.emplace_back("12-gon", twelve);
    for (const auto& [what, pts] : clouds) {
        BOOST_TEST_CONTEXT(what) {
            expect_validation_error([&pts = pts] { (void)polygon_shape(pts); }, "polygon",
                                    "DCX_shape");
        }
    }

    MovingWorld m;
    const ShapeDef square = box_shape(1.0, 1.0);
    std::vector<std::pair<const char*, ShapeDef>> hand_made;
    {
        ShapeDef cw = square; // clockwise: vertices reversed (normals re-derived accordingly)
        auto& p = cw.geometry.polygon;
        std::reverse(p.vertices.begin(), p.vertices.begin() + p.count);
        hand_made.emplace_back("clockwise", cw);
    }
    {
        ShapeDef concave = square; // a vertex pushed inside: a reflex angle
        concave.geometry.polygon.vertices[2] = {0.0, 0.0};
        hand_made.emplace_back("non-convex", concave);
    }
    {
        ShapeDef few = square;
        few.geometry.polygon.count = 2;
        hand_made.emplace_back("two vertices", few);
    }
    {
        ShapeDef many = square;
        many.geometry.polygon.count = max_polygon_vertices + 1;
        hand_made.emplace_back("nine vertices", many);
    }
    {
        ShapeDef flat = box_shape(1.0, 1.0);
        auto& p = flat.geometry.polygon; // all four vertices on the x axis: zero area
        for (int i = 0; i < p.count; ++i)
            p.vertices[std::size_t(i)].y = 0.0;
        hand_made.emplace_back("zero area", flat);
    }
    for (const auto& [what, def] : hand_made) {
        BOOST_TEST_CONTEXT(what) {
            expect_rejected(
                m.world, [&, &def = def] { m.world.create_shape(m.box, def); }, "polygon",
                "DCX_shape");
        }
    }
    // Positive control: a valid triangle through both paths.
    const std::array<Vec2d, 3> tri = {Vec2d{0.0, 0.0}, Vec2d{1.0, 0.0}, Vec2d{0.0, 1.0}};
    BOOST_CHECK_NO_THROW(m.world.create_shape(m.box, polygon_shape(tri)));
}

// Oracle: DCX_density (srs/data_constraints.yaml): rho > 0, so that m = rho A > 0 (DD1).
BOOST_AUTO_TEST_CASE(non_positive_density_is_rejected,
                     *utf::label("R4") * utf::label("DCX_density")) {
    MovingWorld m;
    for (const double rho : {0.0, -0.0, -1e-300, -1.0}) {
        BOOST_TEST_CONTEXT("density = " << rho) {
            expect_rejected_value(
                m.world,
                [&] {
                    m.world.create_shape(m.box, box_shape(0.5, 0.5, {rho, 0.0, 0.0}));
                },
                "density", "DCX_density", rho);
        }
    }
    BOOST_CHECK_NO_THROW(m.world.create_shape(m.box, circle_shape(0.1, {1e-6, 0.0, 0.0})));
}

// Oracle: DCX_friction (srs/data_constraints.yaml): mu >= 0 (0, the SRS regime A6, is valid).
BOOST_AUTO_TEST_CASE(negative_friction_is_rejected,
                     *utf::label("R4") * utf::label("DCX_friction")) {
    MovingWorld m;
    for (const double mu : {-1e-300, -0.1, -1.0}) {
        BOOST_TEST_CONTEXT("friction = " << mu) {
            expect_rejected_value(
                m.world,
                [&] {
                    m.world.create_shape(m.box, circle_shape(0.2, {1.0, 0.0, mu}));
                },
                "friction", "DCX_friction", mu);
        }
    }
    for (const double mu : {0.0, 0.6, 1e3})
        BOOST_CHECK_NO_THROW(m.world.create_shape(m.box, circle_shape(0.2, {1.0, 0.0, mu})));
}

// Oracle: DCX_damping (srs/data_constraints.yaml): c_v, c_omega >= 0 and finite (0, A6's
// regime, is valid); a rejected body leaves the world as it was.
BOOST_AUTO_TEST_CASE(negative_or_non_finite_damping_is_rejected,
                     *utf::label("R4") * utf::label("DCX_damping")) {
    MovingWorld m;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (const double c : {-1e-300, -0.5, nan, std::numeric_limits<double>::infinity()}) {
        BOOST_TEST_CONTEXT("damping = " << c) {
            BodyDef linear;
            linear.linear_damping = c;
            BodyDef angular;
            angular.angular_damping = c;
            const char* label = std::isfinite(c) ? "DCX_damping" : "DCX_finite";
            expect_rejected_value(
                m.world, [&] { m.world.create_body(linear); }, "linear_damping", label, c);
            expect_rejected_value(
                m.world, [&] { m.world.create_body(angular); }, "angular_damping", label, c);
        }
    }
    for (const double c : {0.0, 0.1, 1e3}) {
        BodyDef def;
        def.linear_damping = c;
        def.angular_damping = c;
        BOOST_CHECK_NO_THROW(m.world.create_body(def));
    }
    // The same constraint on a living body, and the rates read back once accepted.
    for (const double c : {-0.5, nan}) {
        const char* label = std::isfinite(c) ? "DCX_damping" : "DCX_finite";
        expect_rejected_value(
            m.world, [&] { m.world.set_damping(m.box, c, 0.0); }, "linear_damping", label, c);
        expect_rejected_value(
            m.world, [&] { m.world.set_damping(m.box, 0.0, c); }, "angular_damping", label, c);
    }
    m.world.set_damping(m.box, 0.25, 4.0);
    BOOST_TEST(m.world.linear_damping(m.box) == 0.25);
    BOOST_TEST(m.world.angular_damping(m.box) == 4.0);
}

// Oracle: DCX_joint (srs/data_constraints.yaml): two distinct bodies, one of them dynamic, a
// finite anchor, a break force > 0; a rejected joint leaves the world as it was, and a handle
// to no body is an InvalidHandle.
BOOST_AUTO_TEST_CASE(invalid_joints_are_rejected, *utf::label("R4") * utf::label("DCX_joint")) {
    MovingWorld m;
    BodyDef ground_def;
    ground_def.type = BodyType::static_body;
    const BodyId ground = m.world.create_body(ground_def);
    const BodyId ground2 = m.world.create_body(ground_def);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    expect_rejected(
        m.world, [&] { m.world.create_joint(RevoluteJointDef{.body_a = m.box, .body_b = m.box}); },
        "body_b", "DCX_joint");
    expect_rejected(
        m.world,
        [&] { m.world.create_joint(RevoluteJointDef{.body_a = ground, .body_b = ground2}); },
        "body_b", "DCX_joint");
    expect_rejected(
        m.world,
        [&] {
            m.world.create_joint(
                RevoluteJointDef{.body_a = ground, .body_b = m.box, .anchor = {nan, 0.0}});
        },
        "anchor", "DCX_finite");
    for (const double f : {0.0, -1.0, nan}) {
        expect_rejected_value(
            m.world,
            [&] {
                m.world.create_joint(
                    RevoluteJointDef{.body_a = ground, .body_b = m.box, .break_force = f});
            },
            "break_force", "DCX_joint", f);
    }
    const auto before = snapshot(m.world);
    BOOST_CHECK_THROW(m.world.create_joint(RevoluteJointDef{.body_a = ground, .body_b = BodyId{}}),
                      InvalidHandle);
    check_unchanged(before, m.world);
    // The distance joint's own fields: a rest length > 0 (given, or the anchors' distance),
    // hertz and damping ratio >= 0.
    expect_rejected_value(
        m.world,
        [&] {
            m.world.create_joint(
                DistanceJointDef{.body_a = ground, .body_b = m.box, .length = -1.0});
        },
        "length", "DCX_joint", -1.0);
    expect_rejected(
        m.world, [&] { m.world.create_joint(DistanceJointDef{.body_a = ground, .body_b = m.box}); },
        "length", "DCX_joint"); // coincident anchors, no length given
    expect_rejected_value(
        m.world,
        [&] {
            m.world.create_joint(
                DistanceJointDef{.body_a = ground, .body_b = m.box, .length = 1.0, .hertz = -2.0});
        },
        "hertz", "DCX_joint", -2.0);
    expect_rejected_value(
        m.world,
        [&] {
            m.world.create_joint(DistanceJointDef{
                .body_a = ground, .body_b = m.box, .length = 1.0, .damping_ratio = nan});
        },
        "damping_ratio", "DCX_finite", nan);
    // The target joint's: a dynamic body, hertz > 0, max force > 0; its target moves only
    // for a target joint, to a finite point.
    expect_rejected(
        m.world, [&] { m.world.create_joint(TargetJointDef{.body = ground}); }, "body",
        "DCX_joint");
    expect_rejected_value(
        m.world, [&] { m.world.create_joint(TargetJointDef{.body = m.box, .hertz = 0.0}); },
        "hertz", "DCX_joint", 0.0);
    expect_rejected_value(
        m.world, [&] { m.world.create_joint(TargetJointDef{.body = m.box, .max_force = -1.0}); },
        "max_force", "DCX_joint", -1.0);
    const JointId drag = m.world.create_joint(TargetJointDef{.body = m.box});
    expect_rejected(
        m.world,
        [&] {
            m.world.set_joint_target(drag, {nan, 0.0});
        },
        "target", "DCX_finite");
    m.world.destroy_joint(drag);
    const JointId j = m.world.create_joint(RevoluteJointDef{.body_a = ground, .body_b = m.box});
    BOOST_TEST(m.world.is_valid(j));
    m.world.destroy_body(m.box); // takes its joints with it
    BOOST_TEST(!m.world.is_valid(j));
    BOOST_CHECK_THROW(m.world.destroy_joint(j), InvalidHandle);
    // A revolute joint's limits in order and its motor torque >= 0.
    expect_rejected_value(
        m.world,
        [&] {
            m.world.create_joint(RevoluteJointDef{
                .body_a = ground, .body_b = m.plate, .lower_angle = 0.5, .upper_angle = -0.5});
        },
        "upper_angle", "DCX_joint", -0.5);
    expect_rejected_value(
        m.world,
        [&] {
            m.world.create_joint(
                RevoluteJointDef{.body_a = ground, .body_b = m.plate, .max_motor_torque = -1.0});
        },
        "max_motor_torque", "DCX_joint", -1.0);
    // (A setter called on a joint of another kind is a WrongKind: test_wrong_kind.cpp.)
}

// Oracle: DCX_joint (srs/data_constraints.yaml) for the prismatic, weld, wheel and motor
// joints and the revolute spring and distance limits: each out-of-range field is named with the
// constraint it breaks, and the world is left exactly as it was.
BOOST_AUTO_TEST_CASE(invalid_joint_options_are_rejected,
                     *utf::label("R4") * utf::label("DCX_joint")) {
    MovingWorld m;
    BodyDef ground_def;
    ground_def.type = BodyType::static_body;
    const BodyId ground = m.world.create_body(ground_def);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const auto reject = [&](auto def, const char* field, const char* label, double value) {
        def.body_a = ground;
        def.body_b = m.box;
        expect_rejected_value(
            m.world, [&] { m.world.create_joint(def); }, field, label, value);
    };
    reject(RevoluteJointDef{.enable_spring = true, .hertz = 0.0}, "hertz", "DCX_joint", 0.0);
    reject(RevoluteJointDef{.damping_ratio = -1.0}, "damping_ratio", "DCX_joint", -1.0);
    reject(DistanceJointDef{.length = 1.0, .min_length = -0.5}, "min_length", "DCX_joint", -0.5);
    reject(DistanceJointDef{.length = 1.0, .min_length = 2.0, .max_length = 1.0}, "max_length",
           "DCX_joint", 1.0);
    reject(PrismaticJointDef{.axis = {0.0, 0.0}}, "axis", "DCX_joint", 0.0);
    expect_rejected(
        m.world,
        [&] {
            m.world.create_joint(
                PrismaticJointDef{.body_a = ground, .body_b = m.box, .axis = {nan, 1.0}});
        },
        "axis", "DCX_finite");
    reject(PrismaticJointDef{.lower_translation = 1.0, .upper_translation = 0.0},
           "upper_translation", "DCX_joint", 0.0);
    reject(PrismaticJointDef{.max_motor_force = -2.0}, "max_motor_force", "DCX_joint", -2.0);
    reject(PrismaticJointDef{.enable_spring = true, .hertz = 0.0}, "hertz", "DCX_joint", 0.0);
    reject(WeldJointDef{.linear_hertz = -1.0}, "linear_hertz", "DCX_joint", -1.0);
    reject(WeldJointDef{.angular_damping_ratio = -0.1}, "angular_damping_ratio", "DCX_joint", -0.1);
    reject(WheelJointDef{.hertz = 0.0}, "hertz", "DCX_joint", 0.0); // the spring is on by default
    reject(WheelJointDef{.enable_limit = true, .lower_translation = 0.2, .upper_translation = -0.2},
           "upper_translation", "DCX_joint", -0.2);
    reject(WheelJointDef{.max_motor_torque = -1.0}, "max_motor_torque", "DCX_joint", -1.0);
    reject(MotorJointDef{.max_force = -1.0}, "max_force", "DCX_joint", -1.0);
    reject(MotorJointDef{.max_torque = -1.0}, "max_torque", "DCX_joint", -1.0);
    reject(MotorJointDef{.correction_factor = 1.5}, "correction_factor", "DCX_joint", 1.5);
    reject(MotorJointDef{.angular_offset = nan}, "angular_offset", "DCX_finite", nan);
}

BOOST_AUTO_TEST_SUITE_END()
