// The joint_control calls' promises (the user guide's "Changing joints"): a value out of its
// range is refused naming the field (ValidationError, DCX_joint), a joint of a kind the call
// does not apply to as WrongKind naming the joint, a stale handle as InvalidHandle, each with
// state_hash() unchanged; a value equal to the current one changes no bit of the simulation;
// the results are the same on 1 to 4 workers. Library guarantees: labelled "reliability" and
// "determinism" (the physics is test_joint_control_effects.cpp's).
#include <boost/test/unit_test.hpp>

#include <functional>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

#include "tamias2d/world.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;

namespace {

constexpr double dt = 1.0 / 60.0;
constexpr double not_a_number = std::numeric_limits<double>::quiet_NaN();
constexpr double infinity = std::numeric_limits<double>::infinity();

/// One joint of every kind on a few boxes hanging from a static frame, sleeping as asked.
struct Rig {
    World w;
    JointId revolute, distance, target, prismatic, weld, wheel, motor, filter;
    explicit Rig(bool sleeping = true, int workers = 1)
        : w([&] {
              WorldDef d;
              d.enable_sleep = sleeping;
              d.workers = workers;
              return d;
          }()) {
        BodyDef fd;
        fd.type = BodyType::static_body;
        const BodyId frame = w.create_body(fd);
        w.create_shape(frame, box_shape(30.0, 1.0, {}, {0.0, -5.0}));
        std::vector<BodyId> box;
        for (int i = 0; i < 8; ++i) {
            BodyDef bd;
            bd.position = {-10.0 + 2.5 * i, 0.0};
            box.push_back(w.create_body(bd));
            w.create_shape(box.back(), box_shape(0.5, 0.5));
        }
        const auto at = [&](int i) { return w.position(box[std::size_t(i)]); };
        RevoluteJointDef r;
        r.body_a = frame, r.body_b = box[0], r.anchor = at(0) + Vec2d{0.0, 1.0};
        r.enable_limit = true, r.lower_angle = -0.3, r.upper_angle = 0.3;
        r.enable_motor = true, r.max_motor_torque = 1.0;
        revolute = w.create_joint(r);
        DistanceJointDef d;
        d.body_a = frame, d.body_b = box[1], d.anchor_a = at(1) + Vec2d{0.0, 2.0};
        d.anchor_b = at(1);
        d.hertz = 2.0, d.damping_ratio = 0.3;
        distance = w.create_joint(d);
        TargetJointDef t;
        t.body = box[2], t.target = at(2);
        target = w.create_joint(t);
        PrismaticJointDef p;
        p.body_a = frame, p.body_b = box[3], p.anchor = at(3), p.axis = {0.0, 1.0};
        p.enable_spring = true, p.hertz = 1.0, p.damping_ratio = 0.2;
        prismatic = w.create_joint(p);
        WeldJointDef we;
        we.body_a = frame, we.body_b = box[4], we.anchor = at(4) + Vec2d{-0.25, 0.0};
        weld = w.create_joint(we);
        WheelJointDef wh;
        wh.body_a = box[6], wh.body_b = box[5], wh.anchor = at(5);
        wh.enable_motor = true, wh.max_motor_torque = 2.0, wh.motor_speed = 1.0;
        wheel = w.create_joint(wh);
        MotorJointDef m;
        m.body_a = frame, m.body_b = box[6];
        motor = w.create_joint(m);
        FilterJointDef f;
        f.body_a = box[7], f.body_b = frame;
        filter = w.create_joint(f);
    }
    void steps(int n) {
        for (int k = 0; k < n; ++k)
            w.step(dt);
    }
    std::vector<JointId> all() const {
        return {revolute, distance, target, prismatic, weld, wheel, motor, filter};
    }
};

/// Calls `call` expecting a refusal of type E naming `what` (a ValidationError's field, or in
/// a WrongKind's subject, or in an InvalidHandle's message); the hash must not change.
template <class E> void refused(World& w, const std::function<void()>& call, std::string what) {
    const std::uint64_t before = w.state_hash();
    bool thrown = false;
    try {
        call();
    } catch (const E& e) {
        thrown = true;
        if constexpr (std::is_same_v<E, ValidationError>) {
            BOOST_TEST(e.field == what);
            // A value's own rule, or a number's: not finite (DCX_finite), beyond 1e12 (DCX_range).
            BOOST_TEST((e.constraint == "DCX_joint" || e.constraint == "DCX_finite" ||
                        e.constraint == "DCX_range"),
                       e.what());
        } else if constexpr (std::is_same_v<E, WrongKind>) {
            BOOST_TEST(e.subject == what);
        } else {
            BOOST_TEST(std::string(e.what()).find(what) != std::string::npos);
        }
    }
    BOOST_TEST(thrown, "no " << what << " refusal");
    BOOST_TEST(w.state_hash() == before);
}

std::string name(JointId j) {
    return "joint[" + std::to_string(j.index) + "]";
}

} // namespace

BOOST_AUTO_TEST_SUITE(joint_control_guarantees)

// Oracle: R4's promise (docs/user-guide.md, "Errors"): each value out of its data constraint
// (DCX_joint, DCX_finite, DCX_range, as the definition's field is checked) is refused naming
// the field, and the world's hash is unchanged.
BOOST_AUTO_TEST_CASE(bad_values_are_refused_and_change_nothing, *utf::label("R4")) {
    Rig r;
    r.steps(10);
    World& w = r.w;
    using VE = ValidationError;
    refused<VE>(
        w, [&] { w.set_joint_limits(r.revolute, 0.5, 0.1); }, "joint.upper_angle");
    refused<VE>(
        w, [&] { w.set_joint_limits(r.revolute, not_a_number, 0.1); }, "joint.lower_angle");
    refused<VE>(
        w, [&] { w.set_joint_limits(r.prismatic, 1.0, -1.0); }, "joint.upper_translation");
    refused<VE>(
        w, [&] { w.set_joint_limits(r.distance, -1.0, 2.0); }, "joint.min_length");
    refused<VE>(
        w, [&] { w.set_joint_limits(r.distance, 2.0, 1.0); }, "joint.max_length");
    refused<VE>(
        w, [&] { w.set_joint_max_motor_torque(r.revolute, -1.0); }, "joint.max_motor_torque");
    refused<VE>(
        w, [&] { w.set_joint_max_motor_force(r.distance, not_a_number); }, "joint.max_motor_force");
    refused<VE>(
        w, [&] { w.set_joint_motor_speed(r.distance, infinity); }, "joint.motor_speed");
    refused<VE>(
        w, [&] { w.set_joint_spring(r.prismatic, 0.0, 0.1); }, "joint.hertz");
    refused<VE>(
        w, [&] { w.set_joint_spring(r.distance, -1.0, 0.1); }, "joint.hertz");
    refused<VE>(
        w, [&] { w.set_joint_spring(r.target, 0.0, 0.7); }, "joint.hertz");
    refused<VE>(
        w, [&] { w.set_joint_spring(r.revolute, 1.0, -0.5); }, "joint.damping_ratio");
    refused<VE>(
        w, [&] { w.set_joint_spring_target(r.wheel, 1e13); }, "joint.spring_target");
    refused<VE>(
        w, [&] { w.set_distance_joint_length(r.distance, 0.0); }, "joint.length");
    refused<VE>(
        w, [&] { w.set_constraint_tuning(r.weld, 0.0, 1.0); }, "joint.tuning_hertz");
    refused<VE>(
        w, [&] { w.set_constraint_tuning(r.weld, 10.0, -1.0); }, "joint.tuning_damping_ratio");
    refused<VE>(
        w, [&] { w.set_joint_break_force(r.weld, 0.0); }, "joint.break_force");
    refused<VE>(
        w, [&] { w.set_joint_break_torque(r.weld, -1.0); }, "joint.break_torque");
    refused<VE>(
        w, [&] { w.set_joint_break_torque(r.weld, not_a_number); }, "joint.break_torque");
    // Turning a spring on needs its hertz > 0 (the revolute joint's is 0).
    refused<VE>(
        w, [&] { w.enable_joint_spring(r.revolute, true); }, "joint.hertz");
}

// Oracle: R4's promise for programming mistakes (errors.hpp's WrongKind): a call that does not
// apply to the joint's kind names the joint, and a stale handle is refused as InvalidHandle.
BOOST_AUTO_TEST_CASE(wrong_kinds_and_stale_handles_are_refused, *utf::label("reliability")) {
    Rig r;
    World& w = r.w;
    refused<WrongKind>(
        w, [&] { w.enable_joint_limit(r.weld, true); }, name(r.weld));
    refused<WrongKind>(
        w, [&] { w.set_joint_limits(r.motor, 0.0, 1.0); }, name(r.motor));
    refused<WrongKind>(
        w, [&] { w.enable_joint_motor(r.target, true); }, name(r.target));
    refused<WrongKind>(
        w, [&] { w.set_joint_max_motor_torque(r.prismatic, 1.0); }, name(r.prismatic));
    refused<WrongKind>(
        w, [&] { w.set_joint_max_motor_force(r.wheel, 1.0); }, name(r.wheel));
    refused<WrongKind>(
        w, [&] { w.enable_joint_spring(r.distance, true); }, name(r.distance));
    refused<WrongKind>(
        w, [&] { w.set_joint_spring(r.weld, 1.0, 0.0); }, name(r.weld));
    refused<WrongKind>(
        w, [&] { w.set_joint_spring_target(r.distance, 0.1); }, name(r.distance));
    refused<WrongKind>(
        w, [&] { w.set_distance_joint_length(r.revolute, 1.0); }, name(r.revolute));
    refused<WrongKind>(
        w, [&] { w.set_constraint_tuning(r.filter, 1.0, 1.0); }, name(r.filter));
    refused<WrongKind>(
        w, [&] { w.set_constraint_tuning(r.motor, 1.0, 1.0); }, name(r.motor));
    refused<WrongKind>(
        w, [&] { w.set_joint_collide_connected(r.filter, true); }, name(r.filter));
    refused<WrongKind>(
        w, [&] { w.set_joint_collide_connected(r.target, true); }, name(r.target));
    refused<WrongKind>(
        w, [&] { w.set_joint_break_force(r.target, 1.0); }, name(r.target));
    refused<WrongKind>(
        w, [&] { w.set_joint_break_torque(r.distance, 1.0); }, name(r.distance));
    refused<WrongKind>(
        w, [&] { (void)w.joint_motor_speed(r.weld); }, name(r.weld));
    refused<WrongKind>(
        w, [&] { (void)w.joint_limits(r.target); }, name(r.target));
    const JointId stale{r.weld.index, r.weld.generation + 3};
    refused<InvalidHandle>(
        w, [&] { w.set_joint_break_torque(stale, 1.0); }, "JointId");
    refused<InvalidHandle>(
        w, [&] { (void)w.joint_kind(stale); }, "JointId");
    refused<InvalidHandle>(
        w, [&] { w.set_constraint_tuning(stale, 1.0, 1.0); }, "JointId");
}

// Oracle: the promise that a value set to what it already is changes nothing. Two rigs step
// alike; one is given every setter with each joint's current value after part of the run
// (sleeping bodies must not be woken): their hashes agree after every step.
BOOST_AUTO_TEST_CASE(setting_the_current_value_changes_no_bit, *utf::label("reliability")) {
    Rig a, b;
    a.steps(150);
    b.steps(150);
    World& w = b.w;
    for (const JointId j : b.all()) {
        const JointKind k = w.joint_kind(j);
        const bool limited = k == JointKind::revolute || k == JointKind::prismatic ||
                             k == JointKind::wheel || k == JointKind::distance;
        if (limited) {
            w.enable_joint_limit(j, w.is_joint_limit_enabled(j));
            w.set_joint_limits(j, w.joint_limits(j).lower, w.joint_limits(j).upper);
            w.enable_joint_motor(j, w.is_joint_motor_enabled(j));
            w.set_joint_motor_speed(j, w.joint_motor_speed(j));
            if (k == JointKind::revolute || k == JointKind::wheel)
                w.set_joint_max_motor_torque(j, w.joint_max_motor_torque(j));
            else
                w.set_joint_max_motor_force(j, w.joint_max_motor_force(j));
        }
        if (limited || k == JointKind::target)
            w.set_joint_spring(j, w.joint_spring_hertz(j), w.joint_spring_damping_ratio(j));
        if (k == JointKind::revolute || k == JointKind::prismatic || k == JointKind::wheel) {
            w.enable_joint_spring(j, w.is_joint_spring_enabled(j));
            w.set_joint_spring_target(j, w.joint_spring_target(j));
            w.set_joint_spring_target(j, -0.0); // a zero of either sign is the same target
        }
        if (k == JointKind::distance)
            w.set_distance_joint_length(j, w.distance_joint_length(j));
        if (k != JointKind::target && k != JointKind::filter) {
            w.set_joint_collide_connected(j, w.joint_collide_connected(j));
            w.set_joint_break_force(j, w.joint_break_force(j));
        }
        if (k != JointKind::target && k != JointKind::filter && k != JointKind::distance)
            w.set_joint_break_torque(j, w.joint_break_torque(j));
    }
    BOOST_TEST(a.w.state_hash() == w.state_hash());
    for (int k = 0; k < 90; ++k) {
        a.w.step(dt);
        w.step(dt);
        BOOST_TEST_REQUIRE(a.w.state_hash() == w.state_hash());
    }
}

// Oracle: determinism (docs/design.md, "Determinism"): the same calls give the same hash on 1
// to 4 workers.
BOOST_AUTO_TEST_CASE(changes_give_equal_results_on_1_to_4_workers, *utf::label("determinism")) {
    std::vector<std::uint64_t> hashes;
    for (int workers = 1; workers <= 4; ++workers) {
        Rig r(true, workers);
        World& w = r.w;
        r.steps(10);
        w.set_joint_limits(r.revolute, -0.1, 0.2);
        w.set_joint_motor_speed(r.revolute, 3.0);
        w.set_joint_spring(r.revolute, 2.0, 0.1);
        w.enable_joint_spring(r.revolute, true);
        w.set_joint_spring_target(r.revolute, 0.4);
        w.set_joint_max_motor_force(r.distance, 5.0);
        w.set_joint_motor_speed(r.distance, 0.5);
        w.enable_joint_motor(r.distance, true);
        w.set_joint_limits(r.distance, 1.0, 3.0);
        w.enable_joint_limit(r.distance, true);
        w.set_joint_spring_target(r.prismatic, -0.5);
        w.set_constraint_tuning(r.weld, 5.0, 0.5);
        w.set_joint_break_torque(r.wheel, 1e6);
        w.set_joint_collide_connected(r.prismatic, true);
        r.steps(60);
        w.set_joint_collide_connected(r.prismatic, false);
        w.set_distance_joint_length(r.distance, 1.5);
        r.steps(60);
        hashes.push_back(w.state_hash());
    }
    for (std::size_t k = 1; k < hashes.size(); ++k)
        BOOST_TEST(hashes[k] == hashes[0]);
}

BOOST_AUTO_TEST_SUITE_END()
