// R5, R6 (IM1, IM2): the engine against GSL rk8pd reference solutions under time-varying loads,
// a fast version of verify_gsl_reference (two step sizes instead of six).
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "gsl_reference/gsl_reference.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;
using namespace tamias2d::verification;

namespace {

const Scenario& scenario(const std::string& name) {
    static const std::vector<Scenario> all = standard_scenarios();
    for (const Scenario& s : all) {
        if (s.name == name)
            return s;
    }
    throw std::logic_error("no scenario " + name);
}

/// Errors for dt = 1/60 and 1/120 s against one reference sampled every 1/120 s.
std::pair<RunErrors, RunErrors> two_runs(const Scenario& s) {
    const int n = int(std::lround(s.duration * 120));
    const std::vector<Sample> ref = gsl_reference(s, 1.0 / 120.0, n);
    const RunErrors coarse =
        compare(engine_trajectory(s, 1.0 / 60.0, n / 2), ref, 2, 1.0 / 60.0, {1.0, 2.0});
    const RunErrors fine =
        compare(engine_trajectory(s, 1.0 / 120.0, n), ref, 1, 1.0 / 120.0, {1.0, 2.0});
    return {coarse, fine};
}

double order(double coarse, double fine) {
    return std::log2(coarse / fine);
}

} // namespace

BOOST_AUTO_TEST_SUITE(system_gsl_reference)

// Oracle: the closed-form integrals of sinusoidal loads and of gravity, evaluated here
// independently of GSL: the GSL reference itself must be accurate to 1e-9.
BOOST_AUTO_TEST_CASE(reference_matches_closed_form, *utf::label("IM1") * utf::label("IM2")) {
    const Scenario& s = scenario("sine load, gravity");
    const std::vector<Sample> ref = gsl_reference(s, 1.0 / 60.0, 120);
    for (const Sample& r : ref) {
        const Sample c = closed_form_smooth(s, r.t);
        BOOST_TEST(norm2(r.p - c.p) < 1e-9);
        BOOST_TEST(norm2(r.v - c.v) < 1e-9);
        BOOST_TEST(std::abs(r.phi - c.phi) < 1e-9);
        BOOST_TEST(std::abs(r.omega - c.omega) < 1e-9);
    }
}

// Oracle: GSL rk8pd (1e-12) solution of IM1/IM2 with the true sinusoidal F(t), tau(t) and
// gravity; the engine is first order, so halving dt halves every error (order in [0.9, 1.1]).
BOOST_AUTO_TEST_CASE(sine_load_converges_at_first_order,
                     *utf::label("IM1") * utf::label("IM2") * utf::label("R5") * utf::label("R6")) {
    const auto [c, f] = two_runs(scenario("sine load, gravity"));
    for (const double q :
         {order(c.p, f.p), order(c.v, f.v), order(c.phi, f.phi), order(c.omega, f.omega)}) {
        BOOST_TEST(q >= 0.9);
        BOOST_TEST(q <= 1.1);
    }
    // The absolute errors at dt = 1/120 s (verify_gsl_reference tabulates the whole study).
    BOOST_TEST(f.p < 0.03);
    BOOST_TEST(f.phi < 0.003);
    BOOST_TEST_MESSAGE("sine: p err " << c.p << " -> " << f.p << ", phi err " << c.phi << " -> "
                                      << f.phi);
}

// Oracle: GSL rk8pd solution with a step load switching at 0.5 s (on the step grid): the
// velocities are integrated exactly (round-off), the positions at first order.
BOOST_AUTO_TEST_CASE(step_load_velocity_exact_position_first_order,
                     *utf::label("IM1") * utf::label("IM2") * utf::label("R5") * utf::label("R6")) {
    const auto [c, f] = two_runs(scenario("step load, gravity"));
    BOOST_TEST(c.v < 1e-10);
    BOOST_TEST(f.v < 1e-10);
    BOOST_TEST(c.omega < 1e-10);
    BOOST_TEST(f.omega < 1e-10);
    for (const double q : {order(c.p, f.p), order(c.phi, f.phi), order(c.p_at[1], f.p_at[1])}) {
        BOOST_TEST(q >= 0.9);
        BOOST_TEST(q <= 1.1);
    }
}

// Oracle: GSL rk8pd solution with a ramp load (saturating at 1 s), no gravity: first order in
// every quantity.
BOOST_AUTO_TEST_CASE(ramp_load_converges_at_first_order,
                     *utf::label("IM1") * utf::label("IM2") * utf::label("R5") * utf::label("R6")) {
    const auto [c, f] = two_runs(scenario("ramp load, no gravity"));
    for (const double q :
         {order(c.p, f.p), order(c.v, f.v), order(c.phi, f.phi), order(c.omega, f.omega)}) {
        BOOST_TEST(q >= 0.9);
        BOOST_TEST(q <= 1.1);
    }
}

BOOST_AUTO_TEST_SUITE_END()
