// The handle rules of docs/user-guide.md ("Threads, exceptions and handles"), one case each:
// what a destroyed, reused, moved or foreign handle gets. (That every call rejects a stale or
// never-issued handle, leaving the world unchanged, is tests/validation/test_handles.cpp.)
// Oracle: the rules as the guide states them.
#include <boost/test/unit_test.hpp>

#include <utility>

#include "tamias2d/world.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;

namespace {

BodyId add_ball(World& w, Vec2d at) {
    BodyDef d;
    d.position = at;
    const BodyId b = w.create_body(d);
    w.create_shape(b, circle_shape(0.5));
    return b;
}

} // namespace

BOOST_AUTO_TEST_SUITE(handle_rules)

BOOST_AUTO_TEST_CASE(a_destroyed_body_s_handle_stays_invalid_when_its_slot_is_reused,
                     *utf::label("reliability")) {
    World w;
    const BodyId old = add_ball(w, {0.0, 0.0});
    const ShapeId old_shape = w.shapes(old).front();
    w.destroy_body(old);
    const BodyId reuse = add_ball(w, {5.0, 0.0});
    BOOST_TEST(reuse.index == old.index); // the slot is reused ...
    BOOST_TEST(!w.is_valid(old));         // ... but the old handle names nothing
    BOOST_CHECK_THROW(w.position(old), InvalidHandle);
    BOOST_CHECK_THROW(w.set_velocity(old, {1.0, 0.0}), InvalidHandle);
    BOOST_TEST(!w.is_valid(old_shape));
    BOOST_CHECK_THROW(w.destroy_shape(old_shape), InvalidHandle);
    BOOST_TEST(w.position(reuse).x == 5.0);
}

BOOST_AUTO_TEST_CASE(a_destroyed_body_takes_its_joints_handles_with_it,
                     *utf::label("reliability")) {
    World w;
    const BodyId a = add_ball(w, {0.0, 0.0}), b = add_ball(w, {2.0, 0.0});
    RevoluteJointDef pin;
    pin.body_a = a;
    pin.body_b = b;
    pin.anchor = {1.0, 0.0};
    const JointId j = w.create_joint(pin);
    w.destroy_body(b);
    BOOST_TEST(!w.is_valid(j));
    BOOST_CHECK_THROW(w.joint_reaction_force(j), InvalidHandle);
    BOOST_CHECK_THROW(w.destroy_joint(j), InvalidHandle);
    BOOST_TEST(w.joint_count() == 0u);
}

BOOST_AUTO_TEST_CASE(handles_follow_a_moved_world_and_the_moved_from_world_can_be_reused,
                     *utf::label("reliability")) {
    World w;
    const BodyId b = add_ball(w, {1.0, 2.0});
    World moved = std::move(w);
    BOOST_TEST(moved.is_valid(b));
    BOOST_TEST(moved.position(b).y == 2.0);
    w = World(); // assigning to (or destroying) a moved-from world is all it allows
    BOOST_TEST(!w.is_valid(b));
    BOOST_CHECK_THROW(w.position(b), InvalidHandle);
}

BOOST_AUTO_TEST_CASE(a_foreign_handle_is_not_detected_it_names_the_same_slot,
                     *utf::label("reliability")) {
    // Handles carry no world: the first body of every world is the same handle.
    World w1, w2;
    const BodyId in_w1 = add_ball(w1, {1.0, 0.0});
    const BodyId in_w2 = add_ball(w2, {7.0, 0.0});
    BOOST_TEST((in_w1 == in_w2));
    BOOST_TEST(w2.position(in_w1).x == 7.0); // w2's body, not w1's
    // With no body in that slot and generation, the foreign handle is rejected.
    const BodyId second_in_w1 = add_ball(w1, {3.0, 0.0});
    BOOST_TEST(!w2.is_valid(second_in_w1));
    BOOST_CHECK_THROW(w2.position(second_in_w1), InvalidHandle);
}

BOOST_AUTO_TEST_SUITE_END()
