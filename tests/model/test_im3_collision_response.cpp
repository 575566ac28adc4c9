// IM3 (collision response: impulse j n at the contact point applied to A and -j n to B),
// checked against hand values, the textbook two-body collision results, conservation of linear
// (GD1) and angular momentum, DD12's restitution law at the contact and the energy budget.
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "tamias2d/model/im3_collision_response.hpp"

namespace utf = boost::unit_test;
namespace tt = boost::test_tools;
using namespace tamias2d::units;
namespace im3 = tamias2d::model::im3;

namespace {
const auto kg_m2 = kilogram * metre * metre / (radian * radian);
const auto rad_s = radian / second;
Vec2<Length> L2(double x, double y) {
    return vec_from_values<Length>(x, y);
}
im3::Velocities state(double vx, double vy, double w) {
    return {vec_from_values<Velocity>(vx, vy), w * rad_s};
}
im3::InverseInertia body(double m, double I) {
    return {1.0 / (m * kilogram), 1.0 / (I * kg_m2)};
}
const im3::InverseInertia immovable{0.0 / (1.0 * kilogram), 0.0 / (1.0 * kg_m2)};

// An off-centre contact between two spinning bodies, used by the conservation tests.
struct Scene {
    double mA = 3.0, IA = 0.8, mB = 1.5, IB = 0.3;
    double pA[2] = {0.0, 0.0}, P[2] = {0.4, -0.9}, pB[2] = {1.0, -1.1}; // centres and contact
    double n[2] = {-0.8, 0.6};                                          // unit, from B into A
    im3::Velocities A = state(1.2, -0.5, 0.9), B = state(-0.7, 0.6, -1.4);
    Vec2<Length> rA() const { return L2(P[0] - pA[0], P[1] - pA[1]); }
    Vec2<Length> rB() const { return L2(P[0] - pB[0], P[1] - pB[1]); }
    im3::Normal normal() const { return {n[0], n[1]}; }
    // Hand-written Chasles (v + w x r = v + w (-r_y, r_x)) and DD11, independent of im3.
    double vn() const {
        const double rax = P[0] - pA[0], ray = P[1] - pA[1], rbx = P[0] - pB[0], rby = P[1] - pB[1];
        const double wa = A.omega.value(), wb = B.omega.value();
        const double ux = A.v.x.value() - wa * ray - (B.v.x.value() - wb * rby);
        const double uy = A.v.y.value() + wa * rax - (B.v.y.value() + wb * rbx);
        return ux * n[0] + uy * n[1];
    }
    double px() const { return mA * A.v.x.value() + mB * B.v.x.value(); }
    double py() const { return mA * A.v.y.value() + mB * B.v.y.value(); }
    // Angular momentum about the origin: I w + m (p x v) for each body.
    double L() const {
        return IA * A.omega.value() + mA * (pA[0] * A.v.y.value() - pA[1] * A.v.x.value()) +
               IB * B.omega.value() + mB * (pB[0] * B.v.y.value() - pB[1] * B.v.x.value());
    }
    double KE() const {
        const auto sq = [](const im3::Velocities& s) {
            return s.v.x.value() * s.v.x.value() + s.v.y.value() * s.v.y.value();
        };
        return 0.5 * (mA * sq(A) + IA * A.omega.value() * A.omega.value() + mB * sq(B) +
                      IB * B.omega.value() * B.omega.value());
    }
    Impulse resolve(double e) {
        return im3::resolve(A, B, body(mA, IA), body(mB, IB), rA(), rB(), normal(), e);
    }
};
} // namespace

BOOST_AUTO_TEST_SUITE(im3_collision_response)

// Oracle: hand derivation of IM3's four update equations. m_A = 2 kg, I_A = 0.5 kg m^2,
// m_B = 4 kg, I_B = 1 kg m^2, r_AP = (1, 0), r_BP = (-1, 0), n = (0, 1), j = 2 N s:
// v_A += j n / m_A = (0, 1); v_B -= j n / m_B = (0, 0.5); w_A += (r_AP x j n) / I_A = 2 / 0.5 = 4;
// w_B -= (r_BP x j n) / I_B = -(-2) / 1 = +2 rad/s.
BOOST_AUTO_TEST_CASE(apply_impulse_hand_values, *utf::label("IM3")) {
    im3::Velocities A = state(0, 0, 0), B = state(0, 0, 0);
    im3::apply_impulse(A, B, body(2, 0.5), body(4, 1), L2(1, 0), L2(-1, 0), im3::Normal{0, 1},
                       2.0 * newton * second);
    BOOST_TEST(A.v.x.value() == 0.0);
    BOOST_TEST(A.v.y.value() == 1.0);
    BOOST_TEST(A.omega.value() == 4.0);
    BOOST_TEST(B.v.x.value() == 0.0);
    BOOST_TEST(B.v.y.value() == -0.5);
    BOOST_TEST(B.omega.value() == 2.0);
}

// Oracle: hand derivation (DD9 + DD11). Body A with v = (1, 0), w = 2 rad/s, r_AP = (0, 1)
// gives (-1, 0); body B with v = (0, -1), w = -1, r_BP = (1, 0) gives (0, -2); so
// v^AB = (-1, 2) and with n = (0.6, 0.8), v^AB . n = 1 m/s.
BOOST_AUTO_TEST_CASE(normal_relative_velocity_hand_value, *utf::label("IM3")) {
    const double vn = im3::normal_relative_velocity(state(1, 0, 2), state(0, -1, -1), L2(0, 1),
                                                    L2(1, 0), im3::Normal{0.6, 0.8})
                          .value();
    BOOST_TEST(vn == 1.0, tt::tolerance(1e-15));
}

// Oracle: textbook 1D collision results. Equal masses, head-on, elastic (C_R = 1): the bodies
// exchange velocities, A (2, 0) -> (-1, 0) and B (-1, 0) -> (2, 0) with n = (-1, 0) pointing
// from B (right) into A (left). Totally inelastic (C_R = 0), masses 1 and 3: both end at the
// centre-of-mass velocity (1 x 2 + 3 x (-2)) / 4 = -1 m/s. Centres on the normal: no spin.
BOOST_AUTO_TEST_CASE(head_on_textbook_cases, *utf::label("IM3")) {
    im3::Velocities A = state(2, 0, 0), B = state(-1, 0, 0);
    const Impulse j = im3::resolve(A, B, body(1, 1), body(1, 1), L2(0.5, 0), L2(-0.5, 0),
                                   im3::Normal{-1, 0}, 1.0);
    BOOST_TEST(j.value() == 3.0, tt::tolerance(1e-15));
    BOOST_TEST(A.v.x.value() == -1.0, tt::tolerance(1e-15));
    BOOST_TEST(B.v.x.value() == 2.0, tt::tolerance(1e-15));
    BOOST_TEST(A.omega.value() == 0.0);
    BOOST_TEST(B.omega.value() == 0.0);
    im3::Velocities C = state(2, 0, 0), D = state(-2, 0, 0);
    im3::resolve(C, D, body(1, 1), body(3, 1), L2(0.5, 0), L2(-0.5, 0), im3::Normal{-1, 0}, 0.0);
    BOOST_TEST(C.v.x.value() == -1.0, tt::tolerance(1e-15));
    BOOST_TEST(D.v.x.value() == -1.0, tt::tolerance(1e-15));
}

// Oracle: GD1 and the conservation of angular momentum (textbook: the impulses are equal and
// opposite, T2, and act at the same point P, so their moments about any point cancel). Off-
// centre contact between two spinning bodies, C_R = 0.8: total m v and sum (I w + m p x v)
// about the origin are unchanged. Terms below 10 N s with a dozen roundings: 1e-14 absolute.
BOOST_AUTO_TEST_CASE(conserves_linear_and_angular_momentum,
                     *utf::label("IM3") * utf::label("GD1")) {
    Scene s;
    const double px0 = s.px(), py0 = s.py(), L0 = s.L();
    BOOST_TEST_REQUIRE(s.vn() < 0.0); // approaching
    const Impulse j = s.resolve(0.8);
    BOOST_TEST(j.value() > 0.0);
    BOOST_TEST(std::abs(s.px() - px0) <= 1e-14);
    BOOST_TEST(std::abs(s.py() - py0) <= 1e-14);
    BOOST_TEST(std::abs(s.L() - L0) <= 1e-14);
}

// Oracle: DD12's restitution law at the contact, with the relative normal velocity recomputed
// by hand (not by im3): after the response v_f . n = -C_R v_i . n for every C_R in [0, 1].
// Values below 5 m/s: 1e-14 absolute.
BOOST_AUTO_TEST_CASE(satisfies_restitution_law_at_contact,
                     *utf::label("IM3") * utf::label("DD12")) {
    for (double e : {0.0, 0.3, 0.8, 1.0}) {
        Scene s;
        const double vi = s.vn();
        s.resolve(e);
        BOOST_TEST(std::abs(s.vn() - -e * vi) <= 1e-14, "C_R = " << e);
    }
}

// Oracle: textbook energy budget of a frictionless impulsive collision (SRS 5.2.7): kinetic
// energy (translational + rotational, DD15's full form) is conserved when C_R = 1 and drops by
// exactly (1 - C_R^2) v_n^2 / (2 K) otherwise, K the DD8 denominator
// 1/m_A + 1/m_B + (r_AP x n)^2 / I_A + (r_BP x n)^2 / I_B (hand-computed here). 1e-14 absolute.
BOOST_AUTO_TEST_CASE(energy_budget, *utf::label("IM3") * utf::label("DD15")) {
    for (double e : {1.0, 0.8, 0.0}) {
        Scene s;
        const double ca = s.rA().x.value() * s.n[1] - s.rA().y.value() * s.n[0];
        const double cb = s.rB().x.value() * s.n[1] - s.rB().y.value() * s.n[0];
        const double K = 1 / s.mA + 1 / s.mB + ca * ca / s.IA + cb * cb / s.IB;
        const double vi = s.vn(), E0 = s.KE();
        s.resolve(e);
        BOOST_TEST(std::abs((E0 - s.KE()) - (1 - e * e) * vi * vi / (2 * K)) <= 1e-14,
                   "C_R = " << e);
    }
}

// Oracle: IM3's precondition (A5 collisions only between approaching bodies): bodies already
// separating (v^AB . n >= 0) or sliding tangentially get no impulse and keep their velocities.
BOOST_AUTO_TEST_CASE(separating_bodies_untouched, *utf::label("IM3")) {
    for (double vx : {1.0, 0.0}) { // separating along n = (1, 0), then exactly tangential
        im3::Velocities A = state(vx, 0.5, 0.25), B = state(0, -0.5, 0);
        const Impulse j =
            im3::resolve(A, B, body(1, 1), body(2, 2), L2(-1, 0), L2(1, 0), im3::Normal{1, 0}, 0.8);
        BOOST_TEST(j.value() == 0.0);
        BOOST_TEST(A.v.x.value() == vx);
        BOOST_TEST(A.v.y.value() == 0.5);
        BOOST_TEST(A.omega.value() == 0.25);
        BOOST_TEST(B.v.y.value() == -0.5);
        BOOST_TEST(B.omega.value() == 0.0);
    }
}

// Oracle: textbook ball on a fixed floor (1/m_B = 1/I_B = 0): the floor does not move and the
// ball's normal velocity is reversed and scaled by C_R: (1, -5) m/s with C_R = 0.8 leaves at
// (1, 4) m/s; j = (1 + 0.8) x 2 kg x 5 m/s = 18 N s. A centre-line contact adds no spin.
BOOST_AUTO_TEST_CASE(ball_on_fixed_floor, *utf::label("IM3")) {
    im3::Velocities ball = state(1, -5, 0), floor = state(0, 0, 0);
    const Impulse j = im3::resolve(ball, floor, body(2, 0.1), immovable, L2(0, -0.5), L2(3, 0),
                                   im3::Normal{0, 1}, 0.8);
    BOOST_TEST(j.value() == 18.0, tt::tolerance(1e-15));
    BOOST_TEST(ball.v.x.value() == 1.0);
    BOOST_TEST(ball.v.y.value() == 4.0, tt::tolerance(1e-15));
    BOOST_TEST(ball.omega.value() == 0.0);
    BOOST_TEST((floor.v == Vec2<Velocity>{}));
    BOOST_TEST(floor.omega.value() == 0.0);
}

BOOST_AUTO_TEST_SUITE_END()
