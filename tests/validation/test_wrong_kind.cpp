// A call that does not apply to what its handle names is refused with WrongKind (errors.hpp),
// naming the call, the body or joint and the rule, and leaves the world exactly as it was: a
// one-step force, torque or impulse on a static or kinematic body (which it would not move),
// and a joint reading or setter on a joint of a kind that has no such thing. Not an SRS data
// constraint (no value is wrong): the library's own guarantee, labelled "reliability".
#include <boost/test/unit_test.hpp>

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "validation_support.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;
using namespace tamias2d::test;

namespace {

/// `call` throws WrongKind whose what() is `what`, naming `subject`, and the world is unchanged.
void expect_wrong_kind(World& w, const std::function<void()>& call, const std::string& subject,
                       const std::string& what) {
    const Snapshot before = snapshot(w);
    try {
        call();
        BOOST_ERROR("accepted; expected WrongKind: " << what);
    } catch (const WrongKind& e) {
        BOOST_TEST(e.subject == subject);
        BOOST_TEST(std::string(e.what()) == what);
    } catch (const std::exception& e) {
        BOOST_ERROR("expected WrongKind, got another exception: " << e.what());
    }
    check_unchanged(before, w);
}

constexpr const char* not_moved = "must be a dynamic body (a static or kinematic body does not "
                                  "move under forces, torques or impulses)";

} // namespace

BOOST_AUTO_TEST_SUITE(wrong_kind)

// Oracle: World's contract (world.hpp, "loads"): forces, torques and impulses move dynamic
// bodies only (IM1, IM2 and DD10 act on a body of finite mass); a one-step one given to a
// static or kinematic body is refused, with the world's complete state hash unchanged, while
// the same call on a dynamic body is accepted. The persistent settings are kept by any body
// and move none but a dynamic one.
BOOST_AUTO_TEST_CASE(one_step_loads_on_a_body_no_load_moves_are_refused,
                     *utf::label("reliability")) {
    MovingWorld m; // body 0 is the static ground
    BodyDef lift_def;
    lift_def.type = BodyType::kinematic;
    lift_def.name = "lift";
    lift_def.position = {8.0, 1.0};
    lift_def.linear_velocity = {0.0, 0.5};
    const BodyId lift = m.world.create_body(lift_def); // body 4
    m.world.create_shape(lift, box_shape(2.0, 0.2));
    m.world.step(1.0 / 60.0);

    const std::vector<std::pair<BodyId, std::string>> immovable = {
        {m.ground, "body[0 'ground'] is a static body"},
        {lift, "body[4 'lift'] is a kinematic body"}};
    for (const auto& [id, is] : immovable) {
        const std::string subject = is.substr(0, is.find(" is "));
        BOOST_TEST_CONTEXT(subject) {
            expect_wrong_kind(
                m.world,
                [&, id = id] {
                    m.world.apply_impulse(id, {1.0, 0.0}, {0.0, 0.0});
                },
                subject, "apply_impulse: " + is + ": " + not_moved);
            expect_wrong_kind(
                m.world,
                [&, id = id] {
                    m.world.apply_force(id, {0.0, 5.0}, {1.0, 0.0});
                },
                subject, "apply_force: " + is + ": " + not_moved);
            expect_wrong_kind(
                m.world, [&, id = id] { m.world.apply_torque(id, 2.0); }, subject,
                "apply_torque: " + is + ": " + not_moved);
            // Refused before its numbers are looked at: the kind is the mistake to fix first.
            expect_wrong_kind(
                m.world,
                [&, id = id] {
                    m.world.apply_impulse(id, {test::nan, 0.0}, {});
                },
                subject, "apply_impulse: " + is + ": " + not_moved);
        }
    }
    BOOST_CHECK_NO_THROW(m.world.apply_impulse(m.ball, {1.0, 0.0}, m.world.position(m.ball)));
    BOOST_CHECK_NO_THROW(m.world.apply_force(m.box, {0.0, 5.0}, m.world.position(m.box)));
    BOOST_CHECK_NO_THROW(m.world.apply_torque(m.plate, 2.0));

    // The persistent loads are settings of the body, as BodyDef::force is: accepted, unused.
    const Vec2d lift_v = m.world.velocity(lift);
    const Vec2d ground_at = m.world.position(m.ground);
    BOOST_CHECK_NO_THROW(m.world.set_force(lift, {0.0, 1e3}));
    BOOST_CHECK_NO_THROW(m.world.set_torque(m.ground, 1e3));
    BOOST_CHECK_NO_THROW(m.world.set_load(lift, [](double) { return Load{{1e3, 0.0}, 1e3}; }));
    m.world.step(1.0 / 60.0);
    BOOST_TEST(m.world.velocity(lift).x == lift_v.x);
    BOOST_TEST(m.world.velocity(lift).y == lift_v.y);
    BOOST_TEST(m.world.angular_velocity(lift) == 0.0);
    BOOST_TEST(m.world.position(m.ground).x == ground_at.x);
    BOOST_TEST(m.world.position(m.ground).y == ground_at.y);
}

// Oracle: World's contract (world.hpp, "joints"): joint_angle applies to the revolute,
// prismatic, weld and wheel joints, joint_translation to the prismatic and wheel joints,
// set_joint_motor_speed to the revolute, prismatic, wheel and distance joints, set_joint_target
// to the target joint and set_motor_joint_offsets to the motor joint; asked of another kind,
// each names the joint and its kind and leaves the world unchanged.
BOOST_AUTO_TEST_CASE(a_joint_call_on_a_joint_of_another_kind_is_refused,
                     *utf::label("reliability")) {
    MovingWorld m;
    const JointId rope = m.world.create_joint(DistanceJointDef{
        .body_a = m.ground, .body_b = m.ball, .anchor_a = {3.0, 6.0}, .anchor_b = {3.0, 2.0}});
    const JointId pin = m.world.create_joint(RevoluteJointDef{
        .body_a = m.ground, .body_b = m.plate, .anchor = m.world.position(m.plate)});
    const JointId drag = m.world.create_joint(TargetJointDef{.body = m.box, .target = {0.0, 1.0}});
    m.world.step(1.0 / 60.0);

    expect_wrong_kind(
        m.world, [&] { (void)m.world.joint_angle(rope); }, "joint[0]",
        "joint_angle: joint[0] is a distance joint: must be a revolute, prismatic, weld or wheel "
        "joint (the kinds that hold an angle)");
    expect_wrong_kind(
        m.world, [&] { (void)m.world.joint_translation(pin); }, "joint[1]",
        "joint_translation: joint[1] is a revolute joint: must be a prismatic or wheel joint (the "
        "kinds with an axis)");
    expect_wrong_kind(
        m.world, [&] { m.world.set_joint_motor_speed(drag, 1.0); }, "joint[2]",
        "set_joint_motor_speed: joint[2] is a target joint: must be a revolute, prismatic, wheel "
        "or distance joint (the kinds with a motor)");
    expect_wrong_kind(
        m.world,
        [&] {
            m.world.set_joint_target(pin, {1.0, 0.0});
        },
        "joint[1]", "set_joint_target: joint[1] is a revolute joint: must be a target joint");
    expect_wrong_kind(
        m.world,
        [&] {
            m.world.set_motor_joint_offsets(rope, {1.0, 0.0}, 0.0);
        },
        "joint[0]", "set_motor_joint_offsets: joint[0] is a distance joint: must be a motor joint");
    // The kind is checked before the numbers, and a stale handle before the kind.
    expect_wrong_kind(
        m.world,
        [&] {
            m.world.set_joint_target(pin, {test::nan, 0.0});
        },
        "joint[1]", "set_joint_target: joint[1] is a revolute joint: must be a target joint");
    m.world.destroy_joint(rope);
    const Snapshot before = snapshot(m.world);
    BOOST_CHECK_THROW((void)m.world.joint_angle(rope), InvalidHandle);
    check_unchanged(before, m.world);
    // The kinds each call applies to are accepted.
    BOOST_CHECK_NO_THROW((void)m.world.joint_angle(pin));
    BOOST_CHECK_NO_THROW(m.world.set_joint_motor_speed(pin, 1.0));
    BOOST_CHECK_NO_THROW(m.world.set_joint_target(drag, {0.5, 1.0}));
}

BOOST_AUTO_TEST_SUITE_END()
