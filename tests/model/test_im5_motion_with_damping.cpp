// IM5 (motion with damping, integrated implicitly in the damping), checked against the scheme's
// closed form (geometric decay), the ODE's exact solution (first-order convergence), the ODE's
// terminal velocity (the scheme's fixed point) and the backward-Euler relation with DD17/DD18.
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "tamias2d/model/im5_motion_with_damping.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d::units;
namespace im5 = tamias2d::model::im5;

namespace {
Vec2<Velocity> V2(double x, double y) {
    return vec_from_values<Velocity>(x, y);
}
Vec2<Acceleration> A2(double x, double y) {
    return vec_from_values<Acceleration>(x, y);
}

/// v after n steps of h from v0 under a constant applied acceleration a at rate c.
double integrate(double v0, double a, double c, double h, int n) {
    const Dimensionless f = im5::linear_decay_factor(c / second, h * second);
    Vec2<Velocity> v = V2(v0, 0.0);
    for (int k = 0; k < n; ++k)
        v = im5::velocity_step(v, A2(a, 0.0), h * second, f);
    return v.x.value();
}
} // namespace

BOOST_AUTO_TEST_SUITE(im5_motion_with_damping)

// Oracle: the scheme's closed form with no applied acceleration, v_n = v_0 (1 + h c)^(-n).
// h c = 1 gives the factor 1/2 exactly: 8 -> 4 -> 2 -> 1 m s^-1, bit for bit; and for
// h c = 0.3 (factor not exact in binary) 50 steps agree with the power to 50 roundings.
BOOST_AUTO_TEST_CASE(geometric_decay, *utf::label("IM5") * utf::label("LC2")) {
    BOOST_TEST(integrate(8.0, 0.0, 2.0, 0.5, 1) == 4.0);
    BOOST_TEST(integrate(8.0, 0.0, 2.0, 0.5, 3) == 1.0);
    const double expected = 8.0 * std::pow(1.0 + 0.3, -50);
    BOOST_TEST(integrate(8.0, 0.0, 3.0, 0.1, 50) == expected,
               boost::test_tools::tolerance(100 * 2.2e-16));
    // c = 0 is A6's regime: the factor is exactly 1 and the step is IM1's.
    BOOST_TEST(im5::linear_decay_factor(0.0 / second, 0.01 * second).value() == 1.0);
    BOOST_TEST(integrate(1.5, -9.81, 0.0, 0.25, 1) == 1.5 + (-9.81 * 0.25));
}

// Oracle: hand derivation. DD17's a_d = -c_v v and DD18's alpha_d = -c_omega omega are linear,
// with slopes -c_v and -c_omega; backward Euler then scales by 1 / (1 + h c): c = 2 s^-1 over
// h = 0.5 s gives exactly 1/2, c = 0.8 s^-1 over h = 1.25 s exactly 1/2 too.
BOOST_AUTO_TEST_CASE(decay_factors_are_backward_euler_of_dd17_and_dd18,
                     *utf::label("IM5") * utf::label("DD17") * utf::label("DD18")) {
    BOOST_TEST(im5::linear_damping_slope(2.0 / second).value() == -2.0);
    BOOST_TEST(im5::angular_damping_slope(0.8 / second).value() == -0.8);
    BOOST_TEST(im5::linear_decay_factor(2.0 / second, 0.5 * second).value() == 0.5);
    BOOST_TEST(im5::angular_decay_factor(0.8 / second, 1.25 * second).value() == 0.5);
    BOOST_TEST(im5::angular_decay_factor(0.0 / second, 0.01 * second).value() == 1.0);
}

// Oracle: the exact solution of dv/dt = a - c v, v(t) = a/c + (v0 - a/c) e^(-c t). The scheme
// is first order: halving h halves the error at t = 2 s (ratio 2 within 5 % at these h), and
// the error at h = 1/240 s is below c t h (a/c - v0) c / 2 ~ bound of the local truncation.
BOOST_AUTO_TEST_CASE(first_order_convergence_to_exact_decay, *utf::label("IM5")) {
    const double v0 = 3.0, a = -9.81, c = 1.5, t = 2.0;
    const double exact = a / c + (v0 - a / c) * std::exp(-c * t);
    double previous = 0.0;
    for (int n : {480, 960, 1920}) {
        const double error = std::abs(integrate(v0, a, c, t / n, n) - exact);
        if (previous > 0.0)
            BOOST_TEST(previous / error == 2.0, boost::test_tools::tolerance(0.05));
        previous = error;
        // Global error of backward Euler for a linear decay: <= t h c^2 |v0 - a/c| / 2 (the
        // local error h^2 c^2 |v - a/c| / 2 summed over t / h steps, each damped).
        BOOST_TEST(error <= t * (t / n) * c * c * std::abs(v0 - a / c) / 2.0);
    }
}

// Oracle: the ODE's terminal velocity a / c. It is the scheme's fixed point exactly, so from
// rest the velocity approaches it monotonically (never overshoots, even with h c = 10 where an
// explicit damping factor would reverse the velocity) and is within 1e-12 of it after 400 steps.
BOOST_AUTO_TEST_CASE(terminal_velocity_is_the_fixed_point, *utf::label("IM5") * utf::label("LC2")) {
    const double a = -9.81, c = 2.0;
    for (double h : {1.0 / 240.0, 1.0 / 60.0, 5.0}) {
        double v = 0.0;
        for (int k = 0; k < 400 * 240; ++k) {
            const double next = integrate(v, a, c, h, 1);
            BOOST_TEST_REQUIRE(next <= v); // monotone towards a / c < 0
            BOOST_TEST_REQUIRE(next >= a / c - 1e-12);
            v = next;
            if (k >= 400 && std::abs(v - a / c) <= 1e-12)
                break;
        }
        BOOST_TEST(std::abs(v - a / c) <= 1e-12);
    }
}

// Oracle: backward Euler's defining relation with DD17 and DD18 evaluated at the new velocity:
// v' - v = h (a - c_v v'), omega' - omega = h (alpha - c_omega omega'), to rounding.
BOOST_AUTO_TEST_CASE(step_solves_the_implicit_relation,
                     *utf::label("IM5") * utf::label("DD17") * utf::label("DD18")) {
    const Time h = (1.0 / 240.0) * second;
    const Vec2<Velocity> v = V2(2.5, -1.25);
    const Vec2<Acceleration> a = A2(0.75, -9.81);
    const Rate c = 3.0 / second;
    const Vec2<Velocity> next = im5::velocity_step(v, a, h, im5::linear_decay_factor(c, h));
    const Vec2<Acceleration> total = im5::acceleration(a, c, next);
    BOOST_TEST((next.x - v.x).value() == (total.x * h).value(),
               boost::test_tools::tolerance(1e-12));
    BOOST_TEST((next.y - v.y).value() == (total.y * h).value(),
               boost::test_tools::tolerance(1e-12));

    const AngularVelocity w = -4.0 * radian / second,
                          w_next = im5::angular_velocity_step(
                              w, 2.0 * radian / second / second, h,
                              im5::angular_decay_factor(0.8 / second, h));
    const AngularAcceleration alpha =
        im5::angular_acceleration(2.0 * radian / second / second, 0.8 / second, w_next);
    BOOST_TEST((w_next - w).value() == (alpha * h).value(), boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_SUITE_END()
