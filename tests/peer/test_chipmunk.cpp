// NFR2 ("compared to Pymunk"): Tamias2D against Chipmunk2D 7.0.3, the engine behind Pymunk, on
// the same scenes; the fast part of verify_chipmunk (docs/peer-differences.md).
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <numbers>

#include "peer_chipmunk/peer_scenes.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;
using namespace tamias2d::peer;

BOOST_AUTO_TEST_SUITE(peer_chipmunk)

// Oracle: Chipmunk 7.0.3's integrator (cpSpaceStep: cpBodyUpdatePosition, then
// cpBodyUpdateVelocity), started one position update behind: with one substep Tamias runs the
// same symplectic Euler sequence, so free flight, constant loads and a time-varying load agree
// to round-off (1e-12 of the largest magnitude) at every step.
BOOST_AUTO_TEST_CASE(integrator_matches_chipmunk_step_for_step, *utf::label("NFR2")) {
    for (IntegratorScene sc : integrator_scenes()) {
        sc.steps = 240;
        const IntegratorResult r = compare_integrators(sc);
        BOOST_TEST_CONTEXT(sc.name) {
            BOOST_TEST(r.p <= 1e-12 * r.p_scale);
            BOOST_TEST(r.v <= 1e-12 * r.v_scale);
            BOOST_TEST(r.phi <= 1e-12 * std::max(1.0, r.phi_scale));
            BOOST_TEST(r.omega <= 1e-12 * std::max(1.0, r.omega_scale));
        }
    }
}

// Oracle: the 1-D elastic collision closed form (GD1 and kinetic energy), evaluated here, for
// 1 kg against 100 kg head-on with C_R = 1; Chipmunk must give the same velocities.
BOOST_AUTO_TEST_CASE(head_on_elastic_collision_as_chipmunk,
                     *utf::label("NFR2") * utf::label("IM3") * utf::label("GD1") *
                         utf::label("R8")) {
    CollisionScene sc{"head-on", {0.0, 0.0}, {}, {}, true, 60, 1.0 / 60.0};
    sc.a = {true, 0.5, 0.0, 1.0, {-3.0, 0.0}, {4.0, 0.0}};
    sc.a.restitution = 1.0;
    sc.b = {true, 1.0, 0.0, 100.0, {0.0, 0.0}, {0.0, 0.0}};
    sc.b.restitution = 1.0;
    const CollisionOutcome t = run_tamias(sc), c = run_chipmunk(sc);
    const double w1 = (1.0 - 100.0) * 4.0 / 101.0, w2 = 2.0 * 4.0 / 101.0;
    for (const CollisionOutcome& o : {t, c}) {
        BOOST_TEST(std::abs(o.a.v.x - w1) <= 1e-9);
        BOOST_TEST(std::abs(o.b.v.x - w2) <= 1e-9);
        BOOST_TEST(o.contact_points == 1);
    }
    // The impact is resolved in the same step or one step apart: Chipmunk moves, then detects
    // (overlap) and solves in the same step; Tamias detects at the start of a step, within its
    // 0.02 m speculative distance, which a body closing at 4 m/s (0.067 m per step) may skip.
    BOOST_TEST(std::abs(t.step - c.step) <= 1);
}

// Oracle: IM3 with DD8 against an immovable body, by hand: a 1 x 0.6 m box (2 kg, turned
// 0.5 rad, no spin) falls on its lowest corner (A5) at (0.5, -3) m/s with C_R = 0.5; both
// engines must give the closed-form velocities.
BOOST_AUTO_TEST_CASE(box_corner_impact_as_chipmunk, *utf::label("NFR2") * utf::label("IM3") *
                                                        utf::label("DD8") * utf::label("A5")) {
    CollisionScene sc{"corner", {0.0, 0.0}, {}, {}, false, 60, 1.0 / 60.0};
    sc.a = {false, 1.0, 0.6, 2.0, {0.0, 1.5}, {0.5, -3.0}, 0.5, 0.0};
    sc.a.restitution = 0.5;
    // r: from the centre to the lowest of the four corners turned by 0.5 rad.
    const Rot q = Rot::from_angle(0.5);
    Vec2d r{0.0, 1e9};
    for (const Vec2d c : {Vec2d{0.5, 0.3}, Vec2d{-0.5, 0.3}, Vec2d{0.5, -0.3}, Vec2d{-0.5, -0.3}}) {
        const Vec2d w = rotate(q, c);
        if (w.y < r.y)
            r = w;
    }
    const double m = 2.0, I = m * (1.0 + 0.36) / 12.0, e = 0.5, vn = -3.0;
    const double rn = r.x; // r x n for n = (0, 1)
    const double j = -(1.0 + e) * vn / (1.0 / m + rn * rn / I);
    const Vec2d v_after{0.5, vn + j / m};
    const double w_after = rn * j / I;
    const CollisionOutcome t = run_tamias(sc), c = run_chipmunk(sc);
    for (const CollisionOutcome& o : {t, c}) {
        BOOST_TEST(std::abs(o.a.v.x - v_after.x) <= 1e-9);
        BOOST_TEST(std::abs(o.a.v.y - v_after.y) <= 1e-9);
        BOOST_TEST(std::abs(o.a.omega - w_after) <= 1e-9);
        BOOST_TEST(o.contact_points == 1);
    }
}

// Oracle: DD12 (v' = -C_R v on the velocity at the start of the impact step) in both engines,
// and Chipmunk's impact speed within g dt of Tamias's (the contact is seen at most one step
// apart).
BOOST_AUTO_TEST_CASE(dropped_ball_bounces_as_in_chipmunk,
                     *utf::label("NFR2") * utf::label("DD12") * utf::label("R8")) {
    const DropOutcome t = drop_tamias(0.8, 2.0), c = drop_chipmunk(0.8, 2.0);
    BOOST_TEST(std::abs(t.rebound + 0.8 * t.impact) <= 1e-9 * std::abs(t.impact));
    BOOST_TEST(std::abs(c.rebound + 0.8 * c.impact) <= 1e-9 * std::abs(c.impact));
    BOOST_TEST(std::abs(t.impact - c.impact) <= 9.81 / 60.0);
}

// Oracle: Chipmunk on the same stack of 6 boxes (0.5 m, 1 kg, mu = 0.6): both settle with the 6
// touching pairs and no motion, the heights agreeing within the contacts' slops and the soft
// contact's static deflection (see verify_chipmunk).
BOOST_AUTO_TEST_CASE(stack_settles_as_in_chipmunk, *utf::label("NFR2")) {
    const SettleScene sc = stack_scene(6, 0.5, 0.6);
    const SettledFigures t = settle_tamias(sc), c = settle_chipmunk(sc);
    BOOST_TEST(t.contacts == 6);
    BOOST_TEST(c.contacts == 6);
    BOOST_TEST(t.kinetic < 1e-3);
    BOOST_TEST(c.kinetic < 1e-3);
    const double omega = 2.0 * std::numbers::pi * WorldDef{}.contact_hertz;
    double bound = 0.0;
    for (std::size_t k = 0; k < t.heights.size(); ++k) {
        bound +=
            0.01 + double(t.heights.size() - k) * 9.81 / ((k == 0 ? 1.0 : 0.5) * omega * omega);
        BOOST_TEST(std::abs(t.heights[k] - c.heights[k]) <= bound);
    }
}

BOOST_AUTO_TEST_SUITE_END()
