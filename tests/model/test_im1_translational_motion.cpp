// IM1 (translational motion a = g + F / m, integrated by semi-implicit Euler), checked against
// hand-computed step sequences, the scheme's exact closed form under constant acceleration
// (velocity exact, position off by the known first-order term), and its conserved quantity for
// a linear spring.
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "tamias2d/model/im1_translational_motion.hpp"

namespace utf = boost::unit_test;
namespace tt = boost::test_tools;
using namespace tamias2d::units;
namespace im1 = tamias2d::model::im1;

namespace {
Vec2<Length> L2(double x, double y) {
    return vec_from_values<Length>(x, y);
}
Vec2<Velocity> V2(double x, double y) {
    return vec_from_values<Velocity>(x, y);
}
Vec2<Acceleration> A2(double x, double y) {
    return vec_from_values<Acceleration>(x, y);
}
} // namespace

BOOST_AUTO_TEST_SUITE(im1_translational_motion)

// Oracle: hand derivation. g = (0, -9.81) m s^-2, F = (4, 0) N on 2 kg: a = (2, -9.81) m s^-2;
// with F = m (0, 9.81) gravity is cancelled exactly (a body held at rest).
BOOST_AUTO_TEST_CASE(acceleration_hand_value, *utf::label("IM1")) {
    const Vec2<Acceleration> a =
        im1::acceleration(A2(0.0, -9.81), vec_from_values<Force>(4.0, 0.0), 2.0 * kilogram);
    BOOST_TEST(a.x.value() == 2.0);
    BOOST_TEST(a.y.value() == -9.81);
    const Vec2<Acceleration> held =
        im1::acceleration(A2(0.0, -9.81), vec_from_values<Force>(0.0, 19.62), 2.0 * kilogram);
    BOOST_TEST(held.y.value() == 0.0);
}

// Oracle: hand-computed semi-implicit Euler sequence (v first, then p with the new v).
// p0 = (0, 0), v0 = (1, 0), a = (0, -2), dt = 0.5: v1 = (1, -1), p1 = (0.5, -0.5);
// v2 = (1, -2), p2 = (1, -1.5); v3 = (1, -3), p3 = (1.5, -3). Every value is exact in binary.
BOOST_AUTO_TEST_CASE(hand_computed_steps, *utf::label("IM1")) {
    im1::TranslationalState s{L2(0, 0), V2(1, 0)};
    const double expected[3][4] = {{0.5, -0.5, 1, -1}, {1, -1.5, 1, -2}, {1.5, -3, 1, -3}};
    for (const auto& e : expected) {
        s = im1::step(s, A2(0, -2), 0.5 * second);
        BOOST_TEST(s.p.x.value() == e[0]);
        BOOST_TEST(s.p.y.value() == e[1]);
        BOOST_TEST(s.v.x.value() == e[2]);
        BOOST_TEST(s.v.y.value() == e[3]);
    }
}

// Oracle: closed form of semi-implicit Euler under constant acceleration (sum of an arithmetic
// series): after n steps, v_n = v0 + a t_n exactly, and p_n = p0 + sum_k v_k dt =
// p0 + v0 t + a t^2 / 2 + a dt t / 2: the exact solution plus the first-order error a dt t / 2
// (0.5 a dt^2 per step, accumulated). Also the single-step local error is exactly
// 0.5 a dt^2. Falling body (SRS g) pushed sideways by F = (3, 0) N, m = 1.5 kg, dt = 1/60 s,
// 120 steps. Round-off: 120 additions of terms below 40 m, <= 120 eps relative = 2.7e-14:
// bound 1e-12 relative.
BOOST_AUTO_TEST_CASE(constant_acceleration_closed_form, *utf::label("IM1")) {
    const Vec2<Acceleration> a =
        im1::acceleration(A2(0.0, -9.81), vec_from_values<Force>(3.0, 0.0), 1.5 * kilogram);
    const double ax = 2.0, ay = -9.81, dt = 1.0 / 60.0;
    const double p0[2] = {0.412, 0.502}, v0[2] = {2.51, 4.0}; // SRS typical p and speed
    im1::TranslationalState s{L2(p0[0], p0[1]), V2(v0[0], v0[1])};
    const im1::TranslationalState one = im1::step(s, a, dt * second);
    BOOST_TEST(one.p.y.value() - (p0[1] + v0[1] * dt + 0.5 * ay * dt * dt) == 0.5 * ay * dt * dt,
               tt::tolerance(1e-11)); // ~0.6 m values, a few 1e-16 m roundings over 1.4e-3 m
    for (int n = 1; n <= 120; ++n) {
        s = im1::step(s, a, dt * second);
        const double t = n * dt;
        BOOST_TEST(s.v.x.value() == v0[0] + ax * t, tt::tolerance(1e-12));
        BOOST_TEST(s.v.y.value() == v0[1] + ay * t, tt::tolerance(1e-12));
        BOOST_TEST(s.p.x.value() == p0[0] + v0[0] * t + 0.5 * ax * t * t + 0.5 * ax * dt * t,
                   tt::tolerance(1e-12));
        BOOST_TEST(s.p.y.value() == p0[1] + v0[1] * t + 0.5 * ay * t * t + 0.5 * ay * dt * t,
                   tt::tolerance(1e-12));
    }
}

// Oracle: the same closed form read as a convergence statement: the position error against
// the exact parabola at t = 1 s is a dt t / 2, so halving dt halves it (first order).
BOOST_AUTO_TEST_CASE(first_order_position_error, *utf::label("IM1")) {
    const auto error_at_1s = [](int steps) {
        const double dt = 1.0 / steps;
        im1::TranslationalState s{L2(0, 0), V2(0, 0)};
        for (int n = 0; n < steps; ++n)
            s = im1::step(s, A2(0, -9.81), dt * second);
        return s.p.y.value() - 0.5 * -9.81;
    };
    const double e1 = error_at_1s(50), e2 = error_at_1s(100);
    BOOST_TEST(e1 == 0.5 * -9.81 / 50, tt::tolerance(1e-11));
    BOOST_TEST(e1 / e2 == 2.0, tt::tolerance(1e-10));
}

// Oracle: textbook property of semi-implicit (symplectic) Euler. For a spring a = -k x the map
// v' = v - k dt x, x' = x + dt v' is linear with determinant 1 and preserves exactly
// H = v^2 + k x^2 - k dt x v (expand H(x', v'): the dt terms cancel), so over 10000 steps H
// stays constant to round-off (each step rounds a few terms of size ~H: random-walk
// growth, ~sqrt(1e4) x 1e-15 ~ 1e-13; bound 1e-11 relative) while the true energy only
// oscillates within a bounded band instead of drifting.
BOOST_AUTO_TEST_CASE(spring_preserves_modified_energy, *utf::label("IM1")) {
    const double k = 4.0, dt = 0.05;
    im1::TranslationalState s{L2(1.0, 0.0), V2(0.0, 0.3)};
    const auto H = [&](const im1::TranslationalState& q) {
        const double x = q.p.x.value(), v = q.v.x.value();
        return v * v + k * x * x - k * dt * x * v;
    };
    const double H0 = H(s);
    for (int n = 0; n < 10000; ++n) {
        const Vec2<Acceleration> a = A2(-k * s.p.x.value(), -k * s.p.y.value());
        s = im1::step(s, a, dt * second);
    }
    BOOST_TEST(H(s) == H0, tt::tolerance(1e-11));
}

BOOST_AUTO_TEST_SUITE_END()
