// The handle rules of docs/user-guide.md ("Threads, exceptions and handles"), one case each:
// what a destroyed, reused, moved or foreign handle gets. (That every call rejects a stale or
// never-issued handle, leaving the world unchanged, is tests/validation/test_handles.cpp.)
// Oracle: the rules as the guide states them.
#include <boost/test/unit_test.hpp>

#include <string>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "tamias2d/errors.hpp"
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

// Oracle: the handle rule of docs/user-guide.md: a handle to something destroyed stays invalid
// when its slot is reused, so the old body's and shape's handles are refused with InvalidHandle
// while the new body in the same slot keeps its own position (x = 5 m). Fails if the reused slot
// revives the old handle.
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

// Oracle: the handle rule of docs/user-guide.md: destroying a body destroys its joints, so the
// pin's handle is invalid, every call taking it throws InvalidHandle and no joint is left.
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

// Oracle: the handle rule of docs/user-guide.md: moving a world keeps its handles valid in the
// world moved to (the body keeps its given y = 2 m), and a moved-from world may be assigned to;
// the fresh world assigned there refuses the handle with InvalidHandle.
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

// Oracle: the handle rule of docs/user-guide.md and WrongWorld's contract in errors.hpp: a
// handle of another world (same index and generation, other tag) is refused with WrongWorld,
// naming the handle and both worlds' tags, and the world is left unchanged (its state_hash()
// before and after the refused call agree).
BOOST_AUTO_TEST_CASE(a_foreign_handle_is_refused_as_one_of_another_world,
                     *utf::label("reliability")) {
    // The first body of every world has the same index and generation; the tag tells them apart.
    World w1, w2;
    const BodyId in_w1 = add_ball(w1, {1.0, 0.0});
    const BodyId in_w2 = add_ball(w2, {7.0, 0.0});
    BOOST_TEST(w1.tag() != w2.tag());
    BOOST_TEST(w1.tag() != 0u);
    BOOST_TEST((in_w1.index == in_w2.index && in_w1.generation == in_w2.generation));
    BOOST_TEST(!(in_w1 == in_w2));
    BOOST_TEST(!w2.is_valid(in_w1));
    const std::uint64_t before = w2.state_hash();
    try {
        w2.set_velocity(in_w1, {1.0, 0.0});
        BOOST_FAIL("a handle of another world was taken");
    } catch (const WrongWorld& e) {
        BOOST_TEST(e.handle == "BodyId 0:1");
        BOOST_TEST(e.handle_world == w1.tag());
        BOOST_TEST(e.world == w2.tag());
        const std::string what = e.what();
        BOOST_TEST(what.find("BodyId 0:1") != std::string::npos);
        BOOST_TEST(what.find(std::to_string(w1.tag())) != std::string::npos);
        BOOST_TEST(what.find(std::to_string(w2.tag())) != std::string::npos);
    }
    BOOST_TEST(w2.state_hash() == before); // refused before anything changed
    BOOST_TEST(w2.velocity(in_w2).x == 0.0);
    const ShapeId shape_w1 = w1.shapes(in_w1).front();
    BOOST_CHECK_THROW(w2.destroy_shape(shape_w1), WrongWorld);
    BOOST_TEST(w2.shapes(in_w2).size() == 1u);
}

// Oracle: the handle rules of docs/user-guide.md and handles.hpp: a default-constructed handle
// names nothing, and a handle of no world (tag 0, which no world has) is an unknown handle,
// refused with InvalidHandle, not with WrongWorld.
BOOST_AUTO_TEST_CASE(a_default_handle_names_nothing_in_any_world, *utf::label("reliability")) {
    World w;
    add_ball(w, {0.0, 0.0});
    BOOST_TEST(!w.is_valid(BodyId{}));
    BOOST_TEST(!w.is_valid(ShapeId{}));
    BOOST_TEST(!w.is_valid(JointId{}));
    // A handle of no world (tag 0) is an unknown handle, not another world's.
    const BodyId untagged{0, 1, 0};
    BOOST_TEST(!w.is_valid(untagged));
    try {
        (void)w.position(untagged);
        BOOST_FAIL("an untagged handle was taken");
    } catch (const WrongWorld&) {
        BOOST_FAIL("an untagged handle was called another world's");
    } catch (const InvalidHandle&) {
    }
}

// Oracle: the handle rules of docs/user-guide.md: the tag is no part of the state, so two worlds
// built by the same calls hash equal while their tags differ; a moved world keeps its tag and
// its handles.
BOOST_AUTO_TEST_CASE(a_moved_world_keeps_its_tag_and_equal_worlds_hash_equal,
                     *utf::label("reliability")) {
    World a, b;
    const BodyId in_a = add_ball(a, {1.0, 2.0});
    add_ball(b, {1.0, 2.0});
    BOOST_TEST(a.tag() != b.tag());
    BOOST_TEST(a.state_hash() == b.state_hash());
    const std::uint32_t tag = a.tag();
    World moved = std::move(a);
    BOOST_TEST(moved.tag() == tag);
    BOOST_TEST(in_a.world == tag);
    BOOST_TEST(moved.is_valid(in_a));
}

// Oracle: the handle rule of docs/user-guide.md (handles are keys of std::unordered_map and
// std::unordered_set) with the containers' contract: distinct handles, one a reused slot's new
// generation, give one entry each, each found again by its own handle. Fails if == takes two
// distinct handles for one key or equal handles hash differently.
BOOST_AUTO_TEST_CASE(handles_key_unordered_maps, *utf::label("reliability")) {
    World w1, w2;
    std::vector<BodyId> ids;
    for (int k = 0; k < 40; ++k)
        ids.push_back(add_ball(k % 2 == 0 ? w1 : w2, {double(k), 0.0}));
    w1.destroy_body(ids[0]);
    ids.push_back(add_ball(w1, {-1.0, 0.0})); // same slot as ids[0], a new generation
    std::unordered_map<BodyId, int> of_body;
    for (std::size_t k = 0; k < ids.size(); ++k)
        of_body[ids[k]] = int(k);
    BOOST_TEST(of_body.size() == ids.size()); // no two handles collide as keys
    for (std::size_t k = 0; k < ids.size(); ++k)
        BOOST_TEST(of_body.at(ids[k]) == int(k));
    BOOST_TEST((std::hash<BodyId>{}(ids[1]) == std::hash<BodyId>{}(BodyId(ids[1]))));
    std::unordered_set<ShapeId> shapes;
    for (const BodyId b : {ids[1], ids[2]})
        shapes.insert((b.world == w1.tag() ? w1 : w2).shapes(b).front());
    BOOST_TEST(shapes.size() == 2u);
    World w3;
    const BodyId j_a = add_ball(w3, {0.0, 0.0}), j_b = add_ball(w3, {1.0, 0.0});
    std::unordered_map<JointId, BodyId> joints;
    joints[w3.create_joint(RevoluteJointDef{.body_a = j_a, .body_b = j_b, .anchor = {0.5, 0.0}})] =
        j_a;
    BOOST_TEST(joints.size() == 1u);
}

BOOST_AUTO_TEST_SUITE_END()
