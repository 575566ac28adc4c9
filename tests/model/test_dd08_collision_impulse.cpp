// DD8 (impulse for collision response), checked against hand-derived values.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <utility>

#include "tamias2d/model/dd08_collision_impulse.hpp"

namespace utf = boost::unit_test;
namespace tt = boost::test_tools;
using namespace tamias2d::units;
namespace dd08 = tamias2d::model::dd08;

namespace {
const auto kg_m2 = kilogram * metre * metre / (radian * radian); // per-radian convention
Vec2<Length> L2(double x, double y) {
    return vec_from_values<Length>(x, y);
}
dd08::InverseInertia body(double m, double I) {
    return {1.0 / (m * kilogram), 1.0 / (I * kg_m2)};
}
dd08::InverseInertia particle(double m) { // no rotational term (r x n = 0 or I -> infinity)
    return {1.0 / (m * kilogram), 0.0 / (1.0 * kg_m2)};
}
const dd08::InverseInertia immovable{0.0 / (1.0 * kilogram), 0.0 / (1.0 * kg_m2)};
const auto m_s = metre / second;
} // namespace

BOOST_AUTO_TEST_SUITE(dd08_collision_impulse)

// Oracle: hand derivation. Head-on, centres on the normal (r x n = 0), m_A = 1, m_B = 3,
// v^AB . n = -4, C_R = 0.5: K = 1 + 1/3 = 4/3, j = -(1.5)(-4)/(4/3) = 4.5 N s.
BOOST_AUTO_TEST_CASE(head_on_unequal_masses, *utf::label("DD8")) {
    const dd08::InverseInertia A{1.0 / (1.0 * kilogram),
                                 0.0 / (1.0 * kilogram * metre * metre / (radian * radian))};
    const dd08::InverseInertia B{1.0 / (3.0 * kilogram),
                                 0.0 / (1.0 * kilogram * metre * metre / (radian * radian))};
    const Vec2<Length> r{0.0 * metre, 0.0 * metre};
    const auto K = dd08::effective_mass_inverse(A, B, r, r, dd08::Normal{1.0, 0.0});
    BOOST_TEST(K.value() == 4.0 / 3.0, boost::test_tools::tolerance(1e-15));
    const Impulse j = dd08::collision_impulse(0.5, -4.0 * metre / second, K);
    BOOST_TEST(j.value() == 4.5, boost::test_tools::tolerance(1e-15));
}

// Oracle: hand derivation. Lever arm r_AP = (0, 2) m with n = (1, 0): r x n = -2 m, so the
// rotational term is 4 / I_A = 4 / 8 = 0.5 kg^-1; K = 1/2 + 0 + 0.5 = 1.
BOOST_AUTO_TEST_CASE(off_centre_lever_arm, *utf::label("DD8")) {
    const auto per_I = 1.0 / (1.0 * kilogram * metre * metre / (radian * radian));
    const dd08::InverseInertia A{1.0 / (2.0 * kilogram), (1.0 / 8.0) * per_I};
    const dd08::InverseInertia B{0.0 / (1.0 * kilogram), 0.0 * per_I}; // static
    const Vec2<Length> rA{0.0 * metre, 2.0 * metre};
    const Vec2<Length> rB{5.0 * metre, 0.0 * metre}; // irrelevant: B is static
    const auto K = dd08::effective_mass_inverse(A, B, rA, rB, dd08::Normal{1.0, 0.0});
    BOOST_TEST(K.value() == 1.0, boost::test_tools::tolerance(1e-15));
}

// Oracle: textbook special case (ball on a fixed wall, the DD8 derivation with 1/m_B = 0 and no
// rotation): j = -(1 + C_R) m v_n. m = 2 kg, v_n = -3 m/s: C_R = 1 gives 12 N s (momentum
// reversed), C_R = 0.8 gives 10.8 N s, C_R = 0 gives 6 N s (stopped).
BOOST_AUTO_TEST_CASE(ball_on_fixed_wall, *utf::label("DD8")) {
    const auto K = dd08::effective_mass_inverse(particle(2.0), immovable, L2(0, 0), L2(0, 0),
                                                dd08::Normal{0.0, 1.0});
    BOOST_TEST(K.value() == 0.5);
    BOOST_TEST(dd08::collision_impulse(1.0, -3.0 * m_s, K).value() == 12.0, tt::tolerance(1e-15));
    BOOST_TEST(dd08::collision_impulse(0.8, -3.0 * m_s, K).value() == 10.8, tt::tolerance(1e-15));
    BOOST_TEST(dd08::collision_impulse(0.0, -3.0 * m_s, K).value() == 6.0, tt::tolerance(1e-15));
}

// Oracle: textbook totally inelastic collision (C_R = 0): j = -mu v_n with the reduced mass
// mu = m_A m_B / (m_A + m_B) = 2 x 6 / 8 = 1.5 kg, so v_n = -4 m/s gives j = 6 N s; after it
// both bodies move with the centre-of-mass velocity (m_A v_A + m_B v_B) / (m_A + m_B). With
// v_A = -1, v_B = 3 along n: v_cm = (-2 + 18) / 8 = 2 m/s = v_A + j / m_A = v_B - j / m_B.
BOOST_AUTO_TEST_CASE(totally_inelastic_reduced_mass, *utf::label("DD8") * utf::label("DD12")) {
    const auto K = dd08::effective_mass_inverse(particle(2.0), particle(6.0), L2(0, 0), L2(0, 0),
                                                dd08::Normal{1.0, 0.0});
    const Impulse j = dd08::collision_impulse(0.0, (-1.0 - 3.0) * m_s, K);
    BOOST_TEST(j.value() == 6.0, tt::tolerance(1e-15));
    BOOST_TEST(-1.0 + j.value() / 2.0 == 2.0, tt::tolerance(1e-15));
    BOOST_TEST(3.0 - j.value() / 6.0 == 2.0, tt::tolerance(1e-15));
}

// Oracle: hand derivation with every term of DD8's denominator present. m_A = 2 kg,
// m_B = 4 kg, I_A = 0.5 kg m^2, I_B = 2 kg m^2, r_AP = (1, 2) m, r_BP = (-1, 0.5) m,
// n = (0.6, 0.8): r_AP x n = 0.8 - 1.2 = -0.4 m, r_BP x n = -0.8 - 0.3 = -1.1 m, so
// K = 1/2 + 1/4 + 0.16 / 0.5 + 1.21 / 2 = 0.5 + 0.25 + 0.32 + 0.605 = 1.675 kg^-1 and, with
// C_R = 0.5 and v_n = -2 m/s, j = 1.5 x 2 / 1.675 = 1.7910447761194030 N s. About ten roundings
// of terms below 1: 1e-14 relative.
BOOST_AUTO_TEST_CASE(all_terms_hand_value, *utf::label("DD8")) {
    const auto K = dd08::effective_mass_inverse(body(2.0, 0.5), body(4.0, 2.0), L2(1.0, 2.0),
                                                L2(-1.0, 0.5), dd08::Normal{0.6, 0.8});
    BOOST_TEST(K.value() == 1.675, tt::tolerance(1e-14));
    BOOST_TEST(dd08::collision_impulse(0.5, -2.0 * m_s, K).value() == 3.0 / 1.675,
               tt::tolerance(1e-14));
}

// Oracle: the DD8 derivation read backwards (DD12 with DD9 and IM3's update written out by hand
// here): after applying j n to A and -j n to B at P, the normal relative velocity at P must be
// -C_R times its value before. Hand-written updates: v_A += j n / m_A, w_A += (r_AP x j n) / I_A
// and the opposite for B; point velocity v + w x r = v + w (-r_y, r_x). Round-off: sums of
// terms below 10 m/s, 1e-13 absolute.
BOOST_AUTO_TEST_CASE(impulse_restores_restitution_law, *utf::label("DD8") * utf::label("DD12")) {
    const double mA = 3.0, IA = 0.8, mB = 1.5, IB = 0.3, e = 0.7;
    const double rA[2] = {0.4, -0.9}, rB[2] = {-0.6, 0.2}, n[2] = {0.28, 0.96};
    double vA[2] = {1.2, -0.5}, wA = 0.9, vB[2] = {-0.7, 2.1}, wB = -1.4;
    const auto vn = [&] {
        const double pA[2] = {vA[0] - wA * rA[1], vA[1] + wA * rA[0]};
        const double pB[2] = {vB[0] - wB * rB[1], vB[1] + wB * rB[0]};
        return (pA[0] - pB[0]) * n[0] + (pA[1] - pB[1]) * n[1];
    };
    const double vn0 = vn();
    BOOST_TEST_REQUIRE(vn0 < 0.0); // approaching
    const auto K = dd08::effective_mass_inverse(body(mA, IA), body(mB, IB), L2(rA[0], rA[1]),
                                                L2(rB[0], rB[1]), dd08::Normal{n[0], n[1]});
    const double j = dd08::collision_impulse(e, vn0 * m_s, K).value();
    for (int k = 0; k < 2; ++k) {
        vA[k] += j * n[k] / mA;
        vB[k] -= j * n[k] / mB;
    }
    wA += (rA[0] * n[1] - rA[1] * n[0]) * j / IA;
    wB -= (rB[0] * n[1] - rB[1] * n[0]) * j / IB;
    BOOST_TEST(std::abs(vn() - -e * vn0) <= 1e-13);
}

// Oracle: textbook properties of the two-contact effective-mass matrix [[K11, K12], [K12, K22]]:
// it is symmetric (K12 = K21, exact: same products in another order), its diagonal is DD8's own
// denominator at each point, and it is positive semi-definite (K12^2 <= K11 K22, Cauchy-Schwarz).
// Hand value with m_A = 1, I_A = 1, m_B = 2, I_B = 4, n = (1, 0), r_A1 = (0, 1), r_A2 = (0, -1),
// r_B1 = (0, 2), r_B2 = (0, -2): r x n = -r_y, so K12 = 1 + 0.5 + (-1)(1)/1 + (-2)(2)/4 = -0.5,
// K11 = 1 + 0.5 + 1 + 1 = 3.5.
BOOST_AUTO_TEST_CASE(two_contact_coupling, *utf::label("DD8")) {
    const auto A = body(1.0, 1.0), B = body(2.0, 4.0);
    const dd08::Normal n{1.0, 0.0};
    const Vec2<Length> rA1 = L2(0, 1), rA2 = L2(0, -1), rB1 = L2(0, 2), rB2 = L2(0, -2);
    const double K12 = dd08::normal_mass_coupling(A, B, rA1, rB1, rA2, rB2, n).value();
    const double K21 = dd08::normal_mass_coupling(A, B, rA2, rB2, rA1, rB1, n).value();
    const double K11 = dd08::normal_mass_coupling(A, B, rA1, rB1, rA1, rB1, n).value();
    const double K22 = dd08::normal_mass_coupling(A, B, rA2, rB2, rA2, rB2, n).value();
    BOOST_TEST(K12 == -0.5, tt::tolerance(1e-15));
    BOOST_TEST(K21 == K12);
    BOOST_TEST(K11 == 3.5, tt::tolerance(1e-15));
    BOOST_TEST(K11 == dd08::effective_mass_inverse(A, B, rA1, rB1, n).value());
    BOOST_TEST(K12 * K12 <= K11 * K22);
}

// Oracle: textbook invariance. Rotating the whole contact (r_AP, r_BP and n by the same angle)
// leaves every 2D cross product and |n| unchanged, hence K and j. Rotations by 0.3 rad and
// 2.5 rad of the all-terms case: sin/cos and products round to ~1e-16, so 1e-14 relative.
BOOST_AUTO_TEST_CASE(invariant_under_rotation, *utf::label("DD8")) {
    const auto A = body(2.0, 0.5), B = body(4.0, 2.0);
    for (double t : {0.3, 2.5}) {
        const double c = std::cos(t), s = std::sin(t);
        const auto rot = [&](double x, double y) {
            return std::pair{c * x - s * y, s * x + c * y};
        };
        const auto [ax, ay] = rot(1.0, 2.0);
        const auto [bx, by] = rot(-1.0, 0.5);
        const auto [nx, ny] = rot(0.6, 0.8);
        const auto K =
            dd08::effective_mass_inverse(A, B, L2(ax, ay), L2(bx, by), dd08::Normal{nx, ny});
        BOOST_TEST(K.value() == 1.675, tt::tolerance(1e-14));
    }
}

// Oracle: DD8's closed form is linear in the approach speed and in (1 + C_R): doubling v_n
// doubles j, and j(C_R = 1) / j(C_R = 0) = 2 (a fully elastic impulse is twice the inelastic).
BOOST_AUTO_TEST_CASE(linear_in_speed_and_restitution, *utf::label("DD8")) {
    const InverseMass K = 0.75 / (1.0 * kilogram);
    const double j1 = dd08::collision_impulse(0.6, -1.3 * m_s, K).value();
    const double j2 = dd08::collision_impulse(0.6, -2.6 * m_s, K).value();
    BOOST_TEST(j2 == 2.0 * j1, tt::tolerance(1e-15));
    const double je = dd08::collision_impulse(1.0, -1.3 * m_s, K).value();
    const double ji = dd08::collision_impulse(0.0, -1.3 * m_s, K).value();
    BOOST_TEST(je == 2.0 * ji, tt::tolerance(1e-15));
}

// Oracle: hand derivation of the solved form j = -(v_n - v_target) m_eff (the impulse along n
// changes v_n by j / m_eff). A 2 kg ball on a fixed wall (m_eff = 2 kg) approaching at
// v_n = -3 m/s: stopping it (target 0) takes 6 N s; bouncing it with C_R = 0.8 (DD12 target
// 2.4 m/s) takes -(-3 - 2.4) x 2 = 10.8 N s, DD8's closed form (1 + C_R) m |v_n| again; and
// with v_n already at the target no impulse is needed.
BOOST_AUTO_TEST_CASE(impulse_to_reach_target, *utf::label("DD8") * utf::label("DD12")) {
    const Mass m_eff = 2.0 * kilogram;
    BOOST_TEST(dd08::impulse_to_reach(-3.0 * m_s, 0.0 * m_s, m_eff).value() == 6.0);
    BOOST_TEST(dd08::impulse_to_reach(-3.0 * m_s, 2.4 * m_s, m_eff).value() == 10.8,
               tt::tolerance(1e-15));
    BOOST_TEST(dd08::impulse_to_reach(-3.0 * m_s, 2.4 * m_s, m_eff).value() ==
                   dd08::collision_impulse(0.8, -3.0 * m_s, 1.0 / m_eff).value(),
               tt::tolerance(1e-15));
    BOOST_TEST(dd08::impulse_to_reach(1.5 * m_s, 1.5 * m_s, m_eff).value() == 0.0);
}

// Oracle: geometry. |r x n| is the distance from the centre of mass to the line of action
// through P along n, |r - (r . n) n| computed without a cross product; its sign is the sense of
// the turn (counter-clockwise positive, A4): P = (0, 1) pushed along +x turns the body
// clockwise. Round-off bound: a few roundings of terms below 2 m, 1e-15 m.
BOOST_AUTO_TEST_CASE(moment_arm_is_the_distance_to_the_line_of_action, *utf::label("DD8")) {
    BOOST_TEST(dd08::moment_arm(L2(0, 1), dd08::Normal{1, 0}).value() == -1.0);
    BOOST_TEST(dd08::moment_arm(L2(1, 0), dd08::Normal{0, 1}).value() == 1.0);
    for (double ang : {0.2, 1.6, 3.3, 5.0}) {
        const dd08::Normal n{std::cos(ang), std::sin(ang)};
        const double rx = 1.2, ry = -0.4;
        const double along = rx * n.x + ry * n.y;
        const double dx = rx - along * n.x, dy = ry - along * n.y;
        const double arm = dd08::moment_arm(L2(rx, ry), n).value();
        BOOST_TEST(std::abs(std::abs(arm) - std::hypot(dx, dy)) <= 1e-15);
    }
}

// Oracle: hand derivation. m_A = 2 kg, I_A = 0.5 kg m^2, m_B = 4 kg, I_B = 2 kg m^2,
// r_A = (1, 2), r_B = (-0.5, 1), n = (0.6, 0.8): r_A x n = 0.8 - 1.2 = -0.4 m,
// r_B x n = -0.4 - 0.6 = -1 m, K = 1/2 + 1/4 + 0.16 / 0.5 + 1 / 2 = 1.57 kg^-1. The anchors'
// form must give the same bits (it computes the arms, then this).
BOOST_AUTO_TEST_CASE(effective_mass_from_arms_hand_value, *utf::label("DD8")) {
    const dd08::Normal n{0.6, 0.8};
    const auto A = body(2.0, 0.5);
    const auto B = body(4.0, 2.0);
    const Length arm_a = dd08::moment_arm(L2(1.0, 2.0), n);
    const Length arm_b = dd08::moment_arm(L2(-0.5, 1.0), n);
    BOOST_TEST(arm_a.value() == -0.4, tt::tolerance(1e-15));
    BOOST_TEST(arm_b.value() == -1.0, tt::tolerance(1e-15));
    const double K = dd08::effective_mass_inverse(A, B, arm_a, arm_b).value();
    BOOST_TEST(K == 1.57, tt::tolerance(1e-15));
    BOOST_TEST(K == dd08::effective_mass_inverse(A, B, L2(1.0, 2.0), L2(-0.5, 1.0), n).value());
}

BOOST_AUTO_TEST_SUITE_END()
