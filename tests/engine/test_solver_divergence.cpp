// A joint solve that turns non-finite refuses the step (SolverDivergence, errors.hpp): the
// bodies, the joints' readings and the clock stay as the last accepted step left them, and once
// the game removes the joint that drove the solver away the world steps on. The scene: a light
// disc (0.3 g) on a pin 0.5 m from its centre carries, on a prismatic joint, a slider without
// shapes (1 kg and no rotational inertia, so it never turns). The prismatic joint also fixes
// the pair's relative angle, so the disc cannot turn either while its pin asks it to: joints
// that fight on a light body, across a mass ratio of about 3000. The solve grows without bound
// within ten steps.
#include <boost/test/unit_test.hpp>

#include <bit>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "fuzz/fuzz_support.hpp"
#include "tamias2d/errors.hpp"
#include "tamias2d/world.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;

namespace {

constexpr double dt = 1.0 / 60.0;
constexpr double g = 10.0;

struct LightPendulum {
    World world{WorldDef{.gravity = {0.0, -g}, .enable_sleep = true}}; // sleep states restored too
    BodyId ground, disc, slider;
    JointId pin, slide;

    LightPendulum() {
        ground = world.create_body(BodyDef{.type = BodyType::static_body});
        disc = world.create_body(BodyDef{.position = {0.0, 0.0}});
        world.create_shape(disc, circle_shape(0.01));
        slider = world.create_body(BodyDef{.position = {0.5, -0.5}});
        pin = world.create_joint(
            RevoluteJointDef{.body_a = ground, .body_b = disc, .anchor = {0.5, 0.0}});
        slide = world.create_joint(PrismaticJointDef{
            .body_a = disc, .body_b = slider, .anchor = {0.5, -0.5}, .axis = {0.0, 1.0}});
    }

    std::vector<double> last_accepted; ///< readings() after the last step accepted below
    std::uint64_t last_hash = 0;       ///< and the world's state hash then

    /// Steps of dt until one is refused: the number accepted before it (at most `limit`).
    int steps_until_refused(int limit);
};

/// What the refusal promises to keep, bit for bit: every body's state, the clock and each
/// joint's reaction (fuzz::body_states, the promise the fuzzers check).
std::vector<double> readings(const LightPendulum& p) {
    const JointId joints[] = {p.pin, p.slide};
    return fuzz::body_states(p.world, joints);
}

int LightPendulum::steps_until_refused(int limit) {
    last_accepted = readings(*this);
    last_hash = world.state_hash();
    for (int n = 0; n < limit; ++n) {
        try {
            world.step(dt);
        } catch (const SolverDivergence&) {
            return n;
        }
        last_accepted = readings(*this);
        last_hash = world.state_hash();
    }
    return limit;
}

} // namespace

BOOST_AUTO_TEST_SUITE(solver_divergence)

// Oracle: the refusal's promise (errors.hpp, SolverDivergence; docs/user-guide.md, "Errors"):
// the bodies, the joints and the clock as they were, compared bit for bit with their readings
// after the last accepted step, once the step of 1/60 s is refused and again once a step of
// 1/30 s is: a reaction read with the refused step's rate, or with none, would differ (a
// reaction is an impulse times the rate of its step). The field names a body's velocity.
BOOST_AUTO_TEST_CASE(a_refused_step_keeps_the_bodies_the_reactions_and_the_clock,
                     *utf::label("reliability")) {
    LightPendulum p;
    // The scene diverges at all, with reactions to lose.
    BOOST_TEST_REQUIRE(p.steps_until_refused(600) < 600);
    const std::vector<double> before = p.last_accepted;
    BOOST_TEST(p.world.joint_reaction_force(p.slide).x != 0.0);
    auto same_as_before = [&](const char* when) {
        const std::vector<double> now = readings(p);
        BOOST_TEST_REQUIRE(now.size() == before.size());
        for (std::size_t k = 0; k < now.size(); ++k)
            BOOST_TEST(std::bit_cast<std::uint64_t>(now[k]) ==
                           std::bit_cast<std::uint64_t>(before[k]),
                       when << ", reading " << k << ": " << now[k] << ", before " << before[k]);
        // No shape touches another here, so the contacts (which the hash covers too, and which
        // a refused step leaves brought up to date) are none: the whole state is as it was.
        BOOST_TEST(p.world.state_hash() == p.last_hash, when);
    };
    same_as_before("refused at 1/60 s");

    std::string field;
    try {
        p.world.step(2.0 * dt);
    } catch (const SolverDivergence& e) {
        field = e.field;
    }
    BOOST_TEST_REQUIRE(!field.empty()); // refused with the longer step too
    BOOST_TEST(field.find("body[") == 0);
    BOOST_TEST(field.find("].velocity") != std::string::npos);
    same_as_before("refused at 1/30 s");
}

// Oracle: docs/user-guide.md ("Errors": remove or soften the conflicting joints before stepping
// again) and IM1. With the prismatic joint destroyed the slider is a free body: the next step is
// accepted although the world still solves a joint (the disc's pin), and the slider's velocity
// gains -g dt as free flight gives (it has no shape and no joint; 1e-12 m/s covers the
// substeps' rounding).
BOOST_AUTO_TEST_CASE(the_world_steps_on_once_the_conflicting_joint_is_gone,
                     *utf::label("reliability")) {
    LightPendulum p;
    BOOST_TEST_REQUIRE(p.steps_until_refused(600) < 600);
    p.world.destroy_joint(p.slide);
    const Vec2d v0 = p.world.velocity(p.slider);
    const double t0 = p.world.time();
    BOOST_CHECK_NO_THROW(p.world.step(dt));
    BOOST_TEST(p.world.time() == t0 + dt);
    BOOST_TEST(std::abs(p.world.velocity(p.slider).x - v0.x) <= 1e-12);
    BOOST_TEST(std::abs(p.world.velocity(p.slider).y - (v0.y - g * dt)) <= 1e-12);
    BOOST_TEST(fuzz::non_finite_state(p.world).empty(), fuzz::non_finite_state(p.world));
}

BOOST_AUTO_TEST_SUITE_END()
