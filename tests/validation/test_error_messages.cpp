// R4's messages name what the caller wrote: a box's `width` and `height` as box_shape takes
// them (not the half extents it builds the box from), and the bodies of a joint by their
// labels and types with the rule they break (not a slot index given as the offending value).
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <string>

#include "validation_support.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;
using namespace tamias2d::test;

namespace {

/// The error `call` throws: a ValidationError whose field is exactly `field`, whose label is
/// `constraint` and whose what() is exactly `what`; the world is unchanged.
template <class F>
void expect_message(World& w, F&& call, const std::string& field, const std::string& constraint,
                    const std::string& what) {
    const auto e = expect_rejected(w, std::forward<F>(call), field, constraint);
    BOOST_REQUIRE(e.has_value());
    BOOST_TEST(e->field == field);
    BOOST_TEST(std::string(e->what()) == what);
}

/// A body of `type`, named `name`, without shapes.
BodyId named_body(World& w, const char* name, BodyType type) {
    BodyDef d;
    d.type = type;
    d.name = name;
    return w.create_body(d);
}

} // namespace

BOOST_AUTO_TEST_SUITE(error_messages)

// Oracle: box_shape's declaration (shape_def.hpp: box_shape(width, height, ...)) and DCX_shape
// (srs/data_constraints.yaml: a size is > 0) and DCX_finite: the message names the parameter
// the caller passed, with the value the caller passed, not the half extent derived from it.
BOOST_AUTO_TEST_CASE(box_sizes_are_named_as_box_shape_takes_them,
                     *utf::label("R4") * utf::label("DCX_shape") * utf::label("DCX_finite")) {
    const auto message = [](double width, double height) -> std::string {
        try {
            (void)box_shape(width, height);
        } catch (const ValidationError& e) {
            return e.field + " | " + e.what();
        }
        return "accepted";
    };
    BOOST_TEST(message(0.0, 1.0) == "shape.width | shape.width = 0: must be > 0 (DCX_shape)");
    BOOST_TEST(message(1.0, -2.0) == "shape.height | shape.height = -2: must be > 0 (DCX_shape)");
    BOOST_TEST(message(test::nan, 1.0) ==
               "shape.width | shape.width = nan: must be finite (DCX_finite)");
    BOOST_TEST(message(1.0, test::inf) ==
               "shape.height | shape.height = inf: must be finite (DCX_finite)");
    BOOST_TEST(message(2.0, 1.0) == "accepted");
}

// Oracle: DCX_joint (srs/data_constraints.yaml: two distinct bodies, not both immovable): the
// error names the definition's field, the bodies by their labels ("body[i 'name']", as every
// message of the World names a body) and types, and the rule; its value is no number (NaN),
// and what() states none. The world is unchanged.
BOOST_AUTO_TEST_CASE(a_joint_names_its_bodies_and_the_rule_they_break,
                     *utf::label("R4") * utf::label("DCX_joint")) {
    MovingWorld m; // bodies 0 to 3: ground (static), box, ball, plate
    const BodyId wall = named_body(m.world, "wall", BodyType::static_body);
    const BodyId lift = named_body(m.world, "lift", BodyType::kinematic);
    expect_message(
        m.world,
        [&] { m.world.create_joint(RevoluteJointDef{.body_a = m.ground, .body_b = wall}); },
        "joint.body_b", "DCX_joint",
        "joint.body_b: body[4 'wall'] is static and body_a, body[0 'ground'], static: one of a "
        "joint's two bodies must be dynamic (DCX_joint)");
    expect_message(
        m.world, [&] { m.world.create_joint(WeldJointDef{.body_a = m.ground, .body_b = lift}); },
        "joint.body_b", "DCX_joint",
        "joint.body_b: body[5 'lift'] is kinematic and body_a, body[0 'ground'], static: one of "
        "a joint's two bodies must be dynamic (DCX_joint)");
    expect_message(
        m.world,
        [&] {
            m.world.create_joint(
                DistanceJointDef{.body_a = m.ball, .body_b = m.ball, .anchor_b = {1.0, 0.0}});
        },
        "joint.body_b", "DCX_joint",
        "joint.body_b: must be another body than body_a, body[2 'ball'] (DCX_joint)");
    expect_message(
        m.world, [&] { m.world.create_joint(TargetJointDef{.body = lift}); }, "joint.body",
        "DCX_joint",
        "joint.body: body[5 'lift'] is kinematic: a target joint's body must be dynamic "
        "(DCX_joint)");
    // The value is no number: the index of a slot is not what the caller should change.
    try {
        m.world.create_joint(PrismaticJointDef{.body_a = wall, .body_b = lift});
        BOOST_ERROR("a prismatic joint between a static and a kinematic body was accepted");
    } catch (const ValidationError& e) {
        BOOST_TEST(std::isnan(e.value));
        BOOST_TEST(std::string(e.what()).find(" = ") == std::string::npos);
    }
    // Either body may be the dynamic one.
    BOOST_CHECK_NO_THROW(m.world.create_joint(RevoluteJointDef{.body_a = m.box, .body_b = wall}));
}

BOOST_AUTO_TEST_SUITE_END()
