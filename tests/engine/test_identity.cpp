// Identity: user data on the world, bodies, shapes and joints, and the ways from one object to
// another (shape -> body, kind, geometry and boxes; body -> shapes' box, joints, contacts; joint
// -> bodies and kind). API behaviour, no SRS item: the oracles are the definitions the objects
// were made from, closed-form boxes of known shapes at known poses, contacts() itself, and
// state_hash() for "not simulation state".
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "tamias2d/errors.hpp"
#include "tamias2d/world.hpp"

using namespace tamias2d;

namespace {

constexpr double dt = 1.0 / 60.0;

struct Scene {
    World world;
    BodyId ground, box, ball;
    ShapeId ground_shape, box_shape_id, ball_shape;
    JointId hinge;
};

/// A ground, a unit box resting on it and a ball hanging from a revolute joint; user data
/// on everything when `tagged`.
Scene make_scene(bool tagged) {
    Scene s;
    s.world.set_user_data(tagged ? 7u : 0u);
    BodyDef g;
    g.type = BodyType::static_body;
    g.position = {0.0, -0.5};
    g.user_data = tagged ? 11u : 0u;
    s.ground = s.world.create_body(g);
    ShapeDef gs = box_shape(20.0, 1.0);
    gs.user_data = tagged ? 12u : 0u;
    s.ground_shape = s.world.create_shape(s.ground, gs);
    BodyDef b;
    b.position = {0.0, 0.5};
    b.user_data = tagged ? 21u : 0u;
    s.box = s.world.create_body(b);
    ShapeDef bs = box_shape(1.0, 1.0);
    bs.user_data = tagged ? 22u : 0u;
    s.box_shape_id = s.world.create_shape(s.box, bs);
    BodyDef c;
    c.position = {5.0, 5.0};
    s.ball = s.world.create_body(c);
    s.ball_shape = s.world.create_shape(s.ball, circle_shape(0.25));
    RevoluteJointDef r;
    r.body_a = s.ground;
    r.body_b = s.ball;
    r.anchor = {5.0, 6.0};
    r.user_data = tagged ? 31u : 0u;
    s.hinge = s.world.create_joint(r);
    return s;
}

} // namespace

BOOST_AUTO_TEST_SUITE(identity, *boost::unit_test::label("reliability"))

// Oracle: the values given in the definitions and to the setters.
BOOST_AUTO_TEST_CASE(user_data_is_kept_from_the_definitions_and_the_setters) {
    Scene s = make_scene(true);
    BOOST_TEST(s.world.user_data() == 7u);
    BOOST_TEST(s.world.user_data(s.ground) == 11u);
    BOOST_TEST(s.world.user_data(s.ground_shape) == 12u);
    BOOST_TEST(s.world.user_data(s.box) == 21u);
    BOOST_TEST(s.world.user_data(s.box_shape_id) == 22u);
    BOOST_TEST(s.world.user_data(s.ball) == 0u);
    BOOST_TEST(s.world.user_data(s.hinge) == 31u);
    int entity = 0;
    const auto pointer = reinterpret_cast<UserData>(&entity);
    s.world.set_user_data(s.ball, pointer);
    s.world.set_user_data(s.ball_shape, pointer + 1);
    s.world.set_user_data(s.hinge, pointer + 2);
    s.world.set_user_data(pointer + 3);
    for (int i = 0; i < 30; ++i)
        s.world.step(dt);
    BOOST_TEST(reinterpret_cast<int*>(s.world.user_data(s.ball)) == &entity);
    BOOST_TEST(s.world.user_data(s.ball_shape) == pointer + 1);
    BOOST_TEST(s.world.user_data(s.hinge) == pointer + 2);
    BOOST_TEST(s.world.user_data() == pointer + 3);
    BOOST_TEST(s.world.user_data(s.box) == 21u); // untouched by the others' setters
}

// Oracle: state_hash() of the same scene without user data, step by step: user data is not
// simulation state, and setting it changes no bit of what follows.
BOOST_AUTO_TEST_CASE(user_data_is_not_simulation_state) {
    Scene tagged = make_scene(true);
    Scene plain = make_scene(false);
    BOOST_TEST(tagged.world.state_hash() == plain.world.state_hash());
    for (int i = 0; i < 60; ++i) {
        tagged.world.set_user_data(tagged.box, UserData(1000 + i));
        tagged.world.step(dt);
        plain.world.step(dt);
        BOOST_TEST_REQUIRE(tagged.world.state_hash() == plain.world.state_hash());
    }
}

// Oracle: a refused call changes nothing (state_hash) and names the handle's kind.
BOOST_AUTO_TEST_CASE(stale_handles_are_refused_and_change_nothing) {
    Scene s = make_scene(true);
    const BodyId gone = s.world.create_body(BodyDef{});
    const ShapeId gone_shape = s.world.create_shape(gone, circle_shape(0.1));
    s.world.destroy_body(gone);
    JointId gone_joint = s.hinge;
    s.world.destroy_joint(s.hinge);
    const std::uint64_t before = s.world.state_hash();
    BOOST_CHECK_THROW(s.world.set_user_data(gone, 1u), InvalidHandle);
    BOOST_CHECK_THROW(s.world.set_user_data(gone_shape, 1u), InvalidHandle);
    BOOST_CHECK_THROW(s.world.set_user_data(gone_joint, 1u), InvalidHandle);
    BOOST_CHECK_THROW((void)s.world.user_data(gone), InvalidHandle);
    BOOST_CHECK_THROW((void)s.world.body(gone_shape), InvalidHandle);
    BOOST_CHECK_THROW((void)s.world.shape_aabb(gone_shape), InvalidHandle);
    BOOST_CHECK_THROW((void)s.world.body_aabb(gone), InvalidHandle);
    BOOST_CHECK_THROW((void)s.world.joints(gone), InvalidHandle);
    BOOST_CHECK_THROW((void)s.world.contacts(gone), InvalidHandle);
    BOOST_CHECK_THROW((void)s.world.joint_kind(gone_joint), InvalidHandle);
    BOOST_CHECK_THROW((void)s.world.joint_body_a(gone_joint), InvalidHandle);
    BOOST_TEST(s.world.state_hash() == before);
}

// Oracle: the definitions the shapes and joints were made from.
BOOST_AUTO_TEST_CASE(shapes_and_joints_lead_to_their_bodies_and_kinds) {
    Scene s = make_scene(false);
    BOOST_TEST((s.world.body(s.ground_shape) == s.ground));
    BOOST_TEST((s.world.body(s.box_shape_id) == s.box));
    BOOST_TEST((s.world.body(s.ball_shape) == s.ball));
    BOOST_TEST((s.world.shape_type(s.ball_shape) == ShapeType::circle));
    BOOST_TEST((s.world.shape_type(s.box_shape_id) == ShapeType::polygon));
    const Geometry ball = s.world.geometry(s.ball_shape);
    BOOST_TEST(ball.circle.radius == 0.25);
    const Geometry box = s.world.geometry(s.box_shape_id);
    BOOST_TEST(box.polygon.count == 4);
    for (int k = 0; k < 4; ++k) {
        BOOST_TEST(std::abs(box.polygon.vertices[std::size_t(k)].x) == 0.5);
        BOOST_TEST(std::abs(box.polygon.vertices[std::size_t(k)].y) == 0.5);
    }
    BOOST_TEST((s.world.joint_kind(s.hinge) == JointKind::revolute));
    BOOST_TEST(to_string(s.world.joint_kind(s.hinge)) == "revolute");
    BOOST_TEST((s.world.joint_body_a(s.hinge) == s.ground));
    BOOST_TEST((s.world.joint_body_b(s.hinge) == s.ball));
    BOOST_TEST((s.world.joints(s.ball) == std::vector<JointId>{s.hinge}));
    BOOST_TEST((s.world.joints(s.ground) == std::vector<JointId>{s.hinge}));
    BOOST_TEST(s.world.joints(s.box).empty());
    TargetJointDef t;
    t.body = s.box;
    t.target = {0.0, 0.5};
    const JointId drag = s.world.create_joint(t);
    BOOST_TEST((s.world.joint_kind(drag) == JointKind::target));
    BOOST_TEST((s.world.joint_body_a(drag) == s.box));
    BOOST_TEST((s.world.joint_body_b(drag) == s.box));
    DistanceJointDef d;
    d.body_a = s.box;
    d.body_b = s.ball;
    d.anchor_a = {0.0, 0.5};
    d.anchor_b = {5.0, 5.0};
    const JointId rope = s.world.create_joint(d);
    BOOST_TEST((s.world.joint_kind(rope) == JointKind::distance));
    BOOST_TEST((s.world.joints(s.ball) == std::vector<JointId>{s.hinge, rope}));
}

// Oracle: closed-form boxes. A circle of radius r at c: [c - r, c + r]. A unit square turned by
// 45 degrees: half-width sqrt(2)/2 about its centre. The body's box is their union.
BOOST_AUTO_TEST_CASE(boxes_of_shapes_and_bodies_are_closed_form) {
    World w;
    BodyDef d;
    d.position = {2.0, 3.0};
    d.angle = std::numbers::pi / 4.0;
    d.type = BodyType::kinematic;
    const BodyId b = w.create_body(d);
    const ShapeId square = w.create_shape(b, box_shape(1.0, 1.0));
    const ShapeId disc = w.create_shape(b, circle_shape(0.5, {}, {3.0, 0.0}));
    const double h = std::sqrt(2.0) / 2.0;
    const Aabb sq = w.shape_aabb(square);
    BOOST_TEST(sq.min_x == 2.0 - h, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(sq.max_x == 2.0 + h, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(sq.min_y == 3.0 - h, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(sq.max_y == 3.0 + h, boost::test_tools::tolerance(1e-12));
    // The disc's centre: (3, 0) in the body frame, turned by 45 degrees: (3h, 3h) from (2, 3).
    const Aabb dc = w.shape_aabb(disc);
    BOOST_TEST(dc.min_x == 2.0 + 3.0 * h - 0.5, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(dc.max_y == 3.0 + 3.0 * h + 0.5, boost::test_tools::tolerance(1e-12));
    const Aabb all = w.body_aabb(b);
    BOOST_TEST(all.min_x == sq.min_x);
    BOOST_TEST(all.min_y == sq.min_y);
    BOOST_TEST(all.max_x == dc.max_x);
    BOOST_TEST(all.max_y == dc.max_y);
    const BodyId bare = w.create_body(BodyDef{.position = {-1.0, 4.0}});
    const Aabb none = w.body_aabb(bare);
    BOOST_TEST(none.min_x == -1.0);
    BOOST_TEST(none.max_x == -1.0);
    BOOST_TEST(none.min_y == 4.0);
    BOOST_TEST(none.max_y == 4.0);
    // The box follows the body.
    w.set_transform(b, {0.0, 0.0}, 0.0);
    const Aabb moved = w.shape_aabb(square);
    BOOST_TEST(moved.min_x == -0.5, boost::test_tools::tolerance(1e-15));
    BOOST_TEST(moved.max_y == 0.5, boost::test_tools::tolerance(1e-15));
}

// Oracle: contacts() filtered by hand; a box resting on the ground touches it, the ball does
// not touch anything.
BOOST_AUTO_TEST_CASE(a_bodys_contacts_are_those_of_contacts_naming_it) {
    Scene s = make_scene(false);
    for (int i = 0; i < 10; ++i)
        s.world.step(dt);
    const std::vector<ContactInfo> mine = s.world.contacts(s.box);
    BOOST_TEST_REQUIRE(mine.size() == 1u);
    BOOST_TEST((mine[0].shape_a == s.ground_shape));
    BOOST_TEST((mine[0].shape_b == s.box_shape_id));
    BOOST_TEST(s.world.contacts(s.ball).empty());
    BOOST_TEST(s.world.contacts(s.ground).size() == 1u);
}

BOOST_AUTO_TEST_SUITE_END()
