// The fuzz findings F1-F3 (docs/verification.md, "Findings (fixed)") as concrete cases: an
// anchor too many radii of gyration from its body's centre of mass is refused by name with the
// world unchanged, at the joint's creation and at a step after a shape moved the centre of mass
// (F1, F2, and F3's two seeds); a pin under a huge load per step stays finite (F3).
//
// Oracle: DCX_joint (srs/data_constraints.yaml): an anchor on a dynamic body that turns lies
// within 1e5 radii of gyration sqrt(I / m) of its centre of mass (the bound's value, checked on
// both sides of it), and the step's promise (docs/user-guide.md): a step refuses or leaves every
// state finite.
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "tamias2d/world.hpp"
#include "validation_support.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;
using namespace tamias2d::test;

namespace {

struct Pendulum {
    World world;
    BodyId pivot, bob;
    ShapeId disc;
    explicit Pendulum(Vec2d gravity = {0.0, -10.0}) : world(def(gravity)) {
        BodyDef s;
        s.type = BodyType::static_body;
        s.position = {-8.63, 0.0};
        pivot = world.create_body(s);
        BodyDef b;
        b.position = {12.72, -1.65};
        bob = world.create_body(b);
        disc = world.create_shape(bob, circle_shape(1.468));
    }
    static WorldDef def(Vec2d g) {
        WorldDef d;
        d.gravity = g;
        return d;
    }
};

bool finite(const World& w, BodyId b) {
    const Vec2d p = w.position(b), v = w.velocity(b);
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(v.x) && std::isfinite(v.y) &&
           std::isfinite(w.angular_velocity(b)) && std::isfinite(w.orientation(b));
}

} // namespace

BOOST_AUTO_TEST_SUITE(joint_levers)

// Oracle: DCX_joint's stated rule (srs/data_constraints.yaml): an anchor's lever over the
// body's radius of gyration is bounded, and a refused joint leaves the world unchanged.
// F1: the fuzzer's circle (r = 1.468 m, k = r / sqrt(2)) pinned at (3e8, -8), |r| / k = 4e8:
// without the rule, NaN after one step under g = 8.8e10 m s^-2 (under 10 m s^-2 this geometry
// happened to stay finite, with no digit of the pin's solve left).
BOOST_AUTO_TEST_CASE(a_far_anchor_is_refused, *utf::label("R4") * utf::label("DCX_joint")) {
    Pendulum p;
    const double k = 1.468 / std::sqrt(2.0);
    expect_rejected(
        p.world,
        [&] {
            p.world.create_joint(
                RevoluteJointDef{.body_a = p.pivot, .body_b = p.bob, .anchor = {3e8, -8.0}});
        },
        "joint.anchor (on body[1])", "DCX_joint");
    // Just beyond and just within the bound, along x from the centre of mass.
    const Vec2d c = p.world.position(p.bob);
    expect_rejected(
        p.world,
        [&] {
            p.world.create_joint(DistanceJointDef{.body_a = p.pivot,
                                                  .body_b = p.bob,
                                                  .anchor_a = {0.0, 0.0},
                                                  .anchor_b = {c.x + 1.0001e5 * k, c.y}});
        },
        "joint.anchor_b", "DCX_joint");
    BOOST_CHECK_NO_THROW(
        p.world.create_joint(DistanceJointDef{.body_a = p.pivot,
                                              .body_b = p.bob,
                                              .anchor_a = {0.0, 0.0},
                                              .anchor_b = {c.x + 0.9999e5 * k, c.y}}));
}

// Oracle: DCX_joint's stated rule, whose lever runs from the centre of mass, not the body's
// origin. A disc centred 6e4 m from its body's origin (k = 1.468 / sqrt(2) m, bound 1e5 k):
// anchors just within the bound on either side of the centre of mass are accepted, and just
// beyond it on the origin's side is refused, though that anchor lies within the bound of the
// origin.
BOOST_AUTO_TEST_CASE(the_lever_runs_from_the_centre_of_mass, *utf::label("DCX_joint")) {
    const double k = 1.468 / std::sqrt(2.0), offset = 6e4;
    // A static pivot at the origin and a body whose disc lies `offset` along x from its origin.
    struct OffCentre {
        World world{WorldDef{}};
        BodyId pivot, bob;
        explicit OffCentre(double offset) {
            BodyDef s;
            s.type = BodyType::static_body;
            pivot = world.create_body(s);
            bob = world.create_body(BodyDef{});
            world.create_shape(bob, circle_shape(1.468, {}, {offset, 0.0}));
        }
        void join(Vec2d anchor_b) {
            world.create_joint(DistanceJointDef{
                .body_a = pivot, .body_b = bob, .anchor_a = {0.0, 0.0}, .anchor_b = anchor_b});
        }
    };
    for (const double side : {1.0, -1.0}) {
        BOOST_TEST_CONTEXT("side " << side) {
            OffCentre w(offset);
            const Vec2d c = w.world.position(w.bob);
            BOOST_TEST_REQUIRE(std::abs(c.x - offset) < 1e-6); // the disc's centre, to rounding
            BOOST_CHECK_NO_THROW(w.join({c.x + side * 0.9999e5 * k, c.y}));
        }
    }
    OffCentre w(offset);
    const double beyond = offset - 1.0001e5 * k; // 4.4e4 m from the origin: within 1e5 k of it
    BOOST_TEST_REQUIRE(std::abs(beyond) < 1e5 * k);
    expect_rejected(
        w.world,
        [&] {
            w.join({beyond, 0.0});
        },
        "joint.anchor_b", "DCX_joint");
}

// Oracle: DCX_joint's stated rule, checked again at the step (as a_shapeless_jointed_body...).
// F1 after the joint: the centre of mass moves when a shape comes or goes (API seed 20287469
// reached it with a circle centred 3e8 m off). Here a second disc 3e8 m off makes a dumbbell whose
// radius of gyration is as long as its anchor's lever (accepted); with the first disc destroyed
// the anchor is 3e8 m from the centre of mass of a 1 m disc: the next step is refused, naming
// the joint's anchor, with the world unchanged.
BOOST_AUTO_TEST_CASE(an_anchor_made_far_by_a_shape_refuses_the_step,
                     *utf::label("R4") * utf::label("DCX_joint")) {
    Pendulum p;
    p.world.create_shape(p.bob, circle_shape(1.468, {}, {3e8, 0.0}));
    p.world.create_joint(
        RevoluteJointDef{.body_a = p.pivot, .body_b = p.bob, .anchor = {12.72, -1.65}});
    p.world.step(1.0 / 60.0);
    BOOST_TEST(finite(p.world, p.bob));
    p.world.destroy_shape(p.disc);
    expect_rejected(
        p.world, [&] { p.world.step(1.0 / 60.0); }, "joint[0].anchor (on body[1])", "DCX_joint");
}

// Oracle: DCX_joint's stated rule: the radius of gyration k = sqrt(I / m) against the anchor's
// lever, here k from the inertia override.
// F2: API seed 20264405, a body of 3.45e8 kg with an inertia override of 1e-13 kg m^2
// (k = 1.7e-11 m) pinned about 20 m from its centre by two revolute joints: without the rule,
// NaN after one step. A circle of radius 1e-12 m as a ragdoll's head (scene seeds 50007199,
// 50013103) is the same from a shape (tests/fuzz/test_fuzz_findings.cpp loads it).
BOOST_AUTO_TEST_CASE(a_tiny_radius_of_gyration_is_refused,
                     *utf::label("R4") * utf::label("DCX_joint")) {
    Pendulum p({-8.57, -9.18});
    BodyDef heavy;
    heavy.position = {-18.85, 9.41};
    heavy.mass = 3.45e8;
    heavy.inertia = 1e-13;
    heavy.linear_velocity = {7.04, 2.08};
    heavy.angular_velocity = 9.08;
    const BodyId b = p.world.create_body(heavy);
    BodyDef other_def;
    other_def.position = {11.89, 0.44};
    const BodyId other = p.world.create_body(other_def);
    expect_rejected(
        p.world,
        [&] {
            p.world.create_joint(
                RevoluteJointDef{.body_a = other, .body_b = b, .anchor = {-1.44, 0.84}});
        },
        "joint.anchor (on body[2])", "DCX_joint");
    BodyDef head;
    head.position = {0.0, 8.0};
    const BodyId h = p.world.create_body(head);
    p.world.create_shape(h, circle_shape(1e-12));
    expect_rejected(
        p.world,
        [&] {
            p.world.create_joint(
                RevoluteJointDef{.body_a = p.bob, .body_b = h, .anchor = {0.0, 7.75}});
        },
        "joint.anchor (on body[4])", "DCX_joint");
    // Pinned at its own centre, the same body is well posed: r = 0.
    BOOST_CHECK_NO_THROW(p.world.create_joint(
        RevoluteJointDef{.body_a = other, .body_b = b, .anchor = {-18.85, 9.41}}));
}

// Oracle: DCX_joint's stated rule, checked again at the step: a joint whose lever became too
// long for its body's radius of gyration refuses the step, naming the anchor, world unchanged.
// F3's seeds 20275047 (g = 8.8e10) and 20280323 (dt = 8.5 s), and F1's 20287469: the joint was
// made on a shapeless body, which does not turn (no lever applies), and a circle centred far off,
// added later, made it turn about a centre of mass far from the anchor (2.8e11 radii of gyration
// here): without the step's check, NaN after the next step.
BOOST_AUTO_TEST_CASE(a_shapeless_jointed_body_given_a_far_shape_refuses_the_step,
                     *utf::label("R4") * utf::label("DCX_joint")) {
    Pendulum p({0.0, 8.8e10});
    BodyDef bare;
    bare.position = {14.09, 10.78};
    const BodyId b = p.world.create_body(bare);
    p.world.create_joint(RevoluteJointDef{.body_a = p.pivot, .body_b = b, .anchor = {0.73, 8.97}});
    p.world.step(1.0 / 60.0);
    p.world.create_shape(b, circle_shape(1.3376, {}, {-3e11, 0.0}));
    expect_rejected(
        p.world, [&] { p.world.step(1.0 / 60.0); }, "joint[0].anchor (on body[2])", "DCX_joint");
}

// Oracle: DCX_range's stated bound (docs/design.md, "Supported ranges"): every accepted state
// is finite, and a step that would leave the supported range is refused.
// F3's load itself: a 1 m circle pinned 16 m from its centre under g = 1e7, 8.8e10 and 1e9 m s^-2,
// and under g = 10 with steps of 8.5 s. The joint stretches (a soft joint's physics), but every
// state stays finite or the step is refused at a state beyond the supported range.
BOOST_AUTO_TEST_CASE(a_pin_under_a_huge_load_stays_finite, *utf::label("R4")) {
    for (const auto& [g, dt] : {std::pair{1e7, 1.0 / 60.0}, std::pair{8.8e10, 1.0 / 60.0},
                                std::pair{10.0, 8.5}, std::pair{1e9, 1.0}}) {
        World w(Pendulum::def({0.0, -g}));
        BodyDef s;
        s.type = BodyType::static_body;
        const BodyId pivot = w.create_body(s);
        BodyDef b;
        b.position = {16.0, 0.0};
        const BodyId bob = w.create_body(b);
        w.create_shape(bob, circle_shape(1.0));
        w.create_joint(RevoluteJointDef{.body_a = pivot, .body_b = bob, .anchor = {0.0, 0.0}});
        for (int i = 0; i < 100; ++i) {
            try {
                w.step(dt);
            } catch (const ValidationError&) {
                break; // a state beyond the supported range is refused: allowed
            }
            BOOST_TEST_REQUIRE(finite(w, bob), "g " << g << ", dt " << dt << ", step " << i + 1);
        }
    }
}

BOOST_AUTO_TEST_SUITE_END()
