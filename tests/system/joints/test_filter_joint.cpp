// Filter joints (DD27's joint-filtered pair) in the engine: two bodies joined by one do not
// collide and feel no force from it; destroyed, they collide again. Oracles: free flight in
// closed form (IM1's semi-implicit Euler: a body nothing touches moves as if alone) and the
// rule's statement (a pair no filter refuses collides); the refusal tests compare the world's
// state hash before and after.
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "tamias2d/errors.hpp"
#include "tamias2d/world.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;

namespace {

constexpr double g = 10.0, dt = 1.0 / 60.0;

/// Two 1 m dynamic boxes overlapping by half their width, flying towards each other at 1 m/s
/// each under gravity.
struct Overlap {
    World world{WorldDef{.gravity = {0.0, -g}, .enable_sleep = false}};
    BodyId a, b;
    Overlap() {
        a = world.create_body(BodyDef{.position = {0.0, 0.0}, .linear_velocity = {1.0, 0.0}});
        b = world.create_body(BodyDef{.position = {0.5, 0.0}, .linear_velocity = {-1.0, 0.0}});
        world.create_shape(a, box_shape(1.0, 1.0));
        world.create_shape(b, box_shape(1.0, 1.0));
    }
    /// IM1's discrete free flight from (x0, 0) at (vx, 0) after n substeps of h = dt / 4.
    static Vec2d free_flight(double x0, double vx, int substeps_done) {
        const double h = dt / WorldDef{}.substeps, n = substeps_done;
        return {x0 + vx * h * n, -g * h * h * n * (n + 1.0) / 2.0};
    }
};

} // namespace

BOOST_AUTO_TEST_SUITE(filter_joint)

// Oracle: IM1's free flight in closed form and DD27's joint rule. Joined by a filter joint,
// the overlapping boxes pass through each other: no contact ever, each on its free path.
BOOST_AUTO_TEST_CASE(joined_bodies_pass_through_each_other, *utf::label("DD27")) {
    Overlap s;
    const JointId j = s.world.create_joint(FilterJointDef{.body_a = s.a, .body_b = s.b});
    const int substeps = WorldDef{}.substeps;
    for (int k = 1; k <= 60; ++k) {
        s.world.step(dt);
        BOOST_TEST_REQUIRE(s.world.contacts().size() == 0u);
        const Vec2d want_a = Overlap::free_flight(0.0, 1.0, k * substeps);
        const Vec2d want_b = Overlap::free_flight(0.5, -1.0, k * substeps);
        BOOST_TEST_REQUIRE(std::abs(s.world.position(s.a).x - want_a.x) <= 1e-12);
        BOOST_TEST_REQUIRE(std::abs(s.world.position(s.a).y - want_a.y) <= 1e-12);
        BOOST_TEST_REQUIRE(std::abs(s.world.position(s.b).x - want_b.x) <= 1e-12);
        BOOST_TEST_REQUIRE(std::abs(s.world.position(s.b).y - want_b.y) <= 1e-12);
        BOOST_TEST_REQUIRE(s.world.angular_velocity(s.a) == 0.0);
        BOOST_TEST_REQUIRE(s.world.angular_velocity(s.b) == 0.0);
    }
    // No constraint: no reaction.
    BOOST_TEST(s.world.joint_reaction_force(j).x == 0.0);
    BOOST_TEST(s.world.joint_reaction_force(j).y == 0.0);
    BOOST_TEST(s.world.joint_reaction_torque(j) == 0.0);
}

// Oracle: DD27's rule without the joint (a pair no filter refuses collides) against IM1's free
// flight. Destroyed after a step, the joint no longer filters the still-overlapping boxes: a
// contact appears at the next step and pushes them off their free paths.
BOOST_AUTO_TEST_CASE(destroyed_the_bodies_collide_again, *utf::label("DD27")) {
    Overlap s;
    const JointId j = s.world.create_joint(FilterJointDef{.body_a = s.a, .body_b = s.b});
    s.world.step(dt);
    BOOST_TEST_REQUIRE(s.world.contacts().size() == 0u);
    s.world.destroy_joint(j);
    BOOST_TEST(!s.world.is_valid(j));
    s.world.step(dt);
    BOOST_TEST(s.world.contacts().size() == 1u);
    BOOST_TEST(s.world.contact_begin_events().size() == 1u);
    const int substeps = WorldDef{}.substeps;
    const Vec2d free_a = Overlap::free_flight(0.0, 1.0, 2 * substeps);
    // The contact pushes a back (towards -x) from where free flight would have taken it.
    BOOST_TEST(s.world.position(s.a).x < free_a.x - 1e-6);
    BOOST_TEST(s.world.velocity(s.a).x < 1.0);
}

// Oracle: DD27's statement, a filter joint refuses only its own pair: a third box overlapping
// both still collides with each of them.
BOOST_AUTO_TEST_CASE(filters_only_its_pair, *utf::label("DD27")) {
    Overlap s;
    s.world.create_joint(FilterJointDef{.body_a = s.a, .body_b = s.b});
    const BodyId c = s.world.create_body(BodyDef{.position = {0.25, 0.5}});
    s.world.create_shape(c, box_shape(1.0, 1.0));
    s.world.step(dt);
    BOOST_TEST(s.world.contacts().size() == 2u);
    for (const ContactInfo& ci : s.world.contacts())
        BOOST_TEST((ci.body_a == c || ci.body_b == c));
}

// Oracle: the API's strong guarantee. A bad filter joint (one body twice, two static bodies, a
// stale handle) is refused and the world is bit for bit as before (state hash, joint count).
BOOST_AUTO_TEST_CASE(bad_definitions_leave_the_world_unchanged, *utf::label("reliability")) {
    Overlap s;
    BodyDef sd;
    sd.type = BodyType::static_body;
    const BodyId ground = s.world.create_body(sd);
    const BodyId wall = s.world.create_body(sd);
    const BodyId gone = s.world.create_body(BodyDef{});
    s.world.destroy_body(gone);
    s.world.step(dt);
    const std::uint64_t before = s.world.state_hash();
    BOOST_CHECK_THROW(s.world.create_joint(FilterJointDef{.body_a = s.a, .body_b = s.a}),
                      ValidationError);
    BOOST_CHECK_THROW(s.world.create_joint(FilterJointDef{.body_a = ground, .body_b = wall}),
                      ValidationError);
    BOOST_CHECK_THROW(s.world.create_joint(FilterJointDef{.body_a = s.a, .body_b = gone}),
                      InvalidHandle);
    BOOST_TEST(s.world.state_hash() == before);
    BOOST_TEST(s.world.joint_count() == 0u);
    try {
        s.world.create_joint(FilterJointDef{.body_a = s.a, .body_b = s.a});
    } catch (const ValidationError& e) {
        BOOST_TEST(std::string(e.what()).find("joint.body_b") != std::string::npos);
    }
}

// Oracle: the state hash's contract (every live joint is part of the state) and the kinds'
// readings: a filter joint changes the hash, holds no angle (WrongKind), and its destruction
// gives back a world that hashes as one that never had it.
BOOST_AUTO_TEST_CASE(counted_in_the_state_and_refused_where_it_has_no_meaning,
                     *utf::label("internals")) {
    Overlap with, without;
    const std::uint64_t plain = with.world.state_hash();
    BOOST_TEST(plain == without.world.state_hash());
    const JointId j = with.world.create_joint(FilterJointDef{.body_a = with.a, .body_b = with.b});
    BOOST_TEST(with.world.state_hash() != plain);
    BOOST_TEST(with.world.joint_count() == 1u);
    BOOST_CHECK_THROW((void)with.world.joint_angle(j), WrongKind);
    BOOST_CHECK_THROW(with.world.set_joint_motor_speed(j, 1.0), WrongKind);
}

BOOST_AUTO_TEST_SUITE_END()
