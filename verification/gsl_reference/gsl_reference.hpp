// Reference solutions of IM1 and IM2 from GSL's rk8pd integrator, and the machinery to compare
// the engine's trajectories with them (errors over the whole history, observed order of
// convergence). Shared by the verification program verify_gsl_reference and the fast unit test
// tests/system/test_gsl_reference.cpp.
//
// GSL is GPL-3: this header is included only by verification programs and tests, never by the
// library (scripts/check_no_gsl.sh guards that).
//
// The oracle is independent of the engine: the ODEs are written here from the SRS text
//   IM1: dp/dt = v, dv/dt = g + F(t) / m
//   IM2: dphi/dt = omega, domega/dt = tau(t) / I
// with the *true* load F(t), tau(t) (the engine samples the load once per step at the step's
// start time, itself a first-order approximation; the comparison includes that error on purpose).
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include "tamias2d/world.hpp"

namespace tamias2d::verification {

/// A scalar function of time: zero, constant, sinusoid, step or saturating ramp.
/// `eval(t, branch)` evaluates the formula of the piece that contains time `branch` at time t:
/// the ODE integrator integrates each smooth piece separately and must not see the other side of
/// a jump when a stage lands exactly on a breakpoint.
struct Profile {
    enum class Kind { zero, constant, sine, step, ramp };
    Kind kind = Kind::zero;
    double a = 0.0; ///< constant value; sine amplitude; value before the step; ramp's final value
    double b = 0.0; ///< value after the step
    double w = 0.0; ///< sine angular frequency (rad s^-1)
    double phase = 0.0; ///< sine phase (rad)
    double t1 = 0.0;    ///< step time; ramp saturation time (s)

    static Profile zero() { return {}; }
    static Profile constant(double c) { return {Kind::constant, c}; }
    static Profile sine(double amp, double omega, double ph) {
        return {Kind::sine, amp, 0.0, omega, ph};
    }
    static Profile step(double before, double after, double at) {
        return {Kind::step, before, after, 0.0, 0.0, at};
    }
    /// a t / t1 for t < t1, then a.
    static Profile ramp(double final_value, double until) {
        return {Kind::ramp, final_value, 0.0, 0.0, 0.0, until};
    }

    double eval(double t, double branch) const {
        switch (kind) {
        case Kind::zero:
            return 0.0;
        case Kind::constant:
            return a;
        case Kind::sine:
            return a * std::sin(w * t + phase);
        case Kind::step:
            return branch < t1 ? a : b;
        case Kind::ramp:
            return branch < t1 ? a * t / t1 : a;
        }
        return 0.0;
    }
    double operator()(double t) const { return eval(t, t); }
    bool has_break() const { return kind == Kind::step || kind == Kind::ramp; }
};

/// The load of IM1/IM2: F(t) = (fx(t), fy(t)) N and tau(t) N m at the centre of mass.
struct LoadSpec {
    Profile fx, fy, tau;
    Load at(double t, double branch) const {
        return {{fx.eval(t, branch), fy.eval(t, branch)}, tau.eval(t, branch)};
    }
    Load operator()(double t) const { return at(t, t); }
    std::vector<double> breaks() const {
        std::vector<double> out;
        for (const Profile* p : {&fx, &fy, &tau}) {
            if (p->has_break())
                out.push_back(p->t1);
        }
        std::sort(out.begin(), out.end());
        out.erase(std::unique(out.begin(), out.end()), out.end());
        return out;
    }
};

/// One body under IM1 and IM2.
struct Scenario {
    std::string name;
    double mass = 1.0;    ///< kg
    double inertia = 1.0; ///< kg m^2
    Vec2d gravity{};      ///< m s^-2
    Vec2d p0{}, v0{};     ///< m, m s^-1 (centre of mass)
    double phi0 = 0.0, omega0 = 0.0;
    LoadSpec load;
    double duration = 2.0; ///< s
    /// Velocities are integrated exactly by the scheme (piecewise-constant load whose jumps lie
    /// on every step grid): their error must be round-off, not first order.
    bool exact_velocity = false;
};

/// State y = (px, py, vx, vy, phi, omega) at one time.
struct Sample {
    double t = 0.0;
    Vec2d p{}, v{};
    double phi = 0.0; ///< unwrapped for the reference; wrapped to [0, 2 pi) for the engine
    double omega = 0.0;
};

namespace detail {
struct OdeParams {
    const Scenario* s;
    double branch;
};

inline int rhs(double t, const double y[], double dydt[], void* params) {
    const auto* p = static_cast<const OdeParams*>(params);
    const Load l = p->s->load.at(t, p->branch);
    dydt[0] = y[2];
    dydt[1] = y[3];
    dydt[2] = p->s->gravity.x + l.force.x / p->s->mass; // IM1
    dydt[3] = p->s->gravity.y + l.force.y / p->s->mass;
    dydt[4] = y[5];
    dydt[5] = l.torque / p->s->inertia; // IM2
    return GSL_SUCCESS;
}
} // namespace detail

/// GSL rk8pd solution at t_k = k * dt_out, k = 0..n, with absolute and relative tolerance eps.
/// Each smooth piece of the load (between breakpoints) is integrated separately.
inline std::vector<Sample> gsl_reference(const Scenario& s, double dt_out, int n,
                                         double eps = 1e-12) {
    detail::OdeParams params{&s, 0.0};
    gsl_odeiv2_system sys{detail::rhs, nullptr, 6, &params};
    gsl_odeiv2_driver* d =
        gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk8pd, 1e-4, eps, eps);
    double y[6] = {s.p0.x, s.p0.y, s.v0.x, s.v0.y, s.phi0, s.omega0};
    double t = 0.0;
    const std::vector<double> breaks = s.load.breaks();
    std::vector<Sample> out;
    out.reserve(std::size_t(n) + 1);
    out.push_back({0.0, s.p0, s.v0, s.phi0, s.omega0});
    for (int k = 1; k <= n; ++k) {
        const double tk = k * dt_out;
        while (t < tk) {
            double end = tk;
            for (double b : breaks) {
                if (b > t && b < end)
                    end = b;
            }
            params.branch = 0.5 * (t + end);
            gsl_odeiv2_driver_reset(d);
            const int status = gsl_odeiv2_driver_apply(d, &t, end, y);
            if (status != GSL_SUCCESS) {
                gsl_odeiv2_driver_free(d);
                throw std::runtime_error("gsl_odeiv2_driver_apply failed: " +
                                         std::string(gsl_strerror(status)));
            }
            t = end; // exactly, so the breakpoint comparison is exact
        }
        out.push_back({tk, {y[0], y[1]}, {y[2], y[3]}, y[4], y[5]});
    }
    gsl_odeiv2_driver_free(d);
    return out;
}

/// The closed form of IM1/IM2 for sinusoidal or constant loads (used to check the reference
/// itself): with f(t) = A sin(w t + c), the integral of f is A (cos c - cos(w t + c)) / w and
/// its double integral A (t cos c - (sin(w t + c) - sin c) / w) / w; a constant a gives a t and
/// a t^2 / 2.
inline Sample closed_form_smooth(const Scenario& s, double t) {
    const auto integrals = [t](const Profile& f) -> std::pair<double, double> {
        switch (f.kind) {
        case Profile::Kind::zero:
            return {0.0, 0.0};
        case Profile::Kind::constant:
            return {f.a * t, 0.5 * f.a * t * t};
        case Profile::Kind::sine:
            return {f.a * (std::cos(f.phase) - std::cos(f.w * t + f.phase)) / f.w,
                    f.a *
                        (t * std::cos(f.phase) -
                         (std::sin(f.w * t + f.phase) - std::sin(f.phase)) / f.w) /
                        f.w};
        default:
            throw std::logic_error("closed_form_smooth: only zero, constant and sine profiles");
        }
    };
    const auto [ix, iix] = integrals(s.load.fx);
    const auto [iy, iiy] = integrals(s.load.fy);
    const auto [it, iit] = integrals(s.load.tau);
    Sample r;
    r.t = t;
    r.v = {s.v0.x + s.gravity.x * t + ix / s.mass, s.v0.y + s.gravity.y * t + iy / s.mass};
    r.p = {s.p0.x + s.v0.x * t + 0.5 * s.gravity.x * t * t + iix / s.mass,
           s.p0.y + s.v0.y * t + 0.5 * s.gravity.y * t * t + iiy / s.mass};
    r.omega = s.omega0 + it / s.inertia;
    r.phi = s.phi0 + s.omega0 * t + iit / s.inertia;
    return r;
}

/// Time (s) by which the engine-side load looks ahead when choosing the piece of a piecewise load.
inline constexpr double clock_guard = 1e-9;

/// The engine's trajectory for dt: the body is a unit box whose mass and moment of inertia are
/// set to the scenario's (BodyDef overrides), loaded through BodyDef::load.
inline std::vector<Sample> engine_trajectory(const Scenario& s, double dt, int steps,
                                             int substeps = 4) {
    WorldDef wd;
    wd.gravity = s.gravity;
    wd.substeps = substeps;
    World world(wd);
    BodyDef def;
    def.position = s.p0;
    def.linear_velocity = s.v0;
    def.angle = s.phi0;
    def.angular_velocity = s.omega0;
    def.mass = s.mass;
    def.inertia = s.inertia;
    // The engine's clock accumulates t += dt, so a grid time such as 0.5 s arrives as
    // 0.49999999999999994 after 15 steps of 1/30 s: a load that jumps exactly there would be seen
    // one step late or on time depending on round-off. The piece is therefore chosen at
    // t + clock_guard (1 ns, seven orders below the smallest dt); the formula is evaluated at t.
    const LoadSpec load = s.load;
    def.load = [load](double t) { return load.at(t, t + clock_guard); };
    const BodyId b = world.create_body(def);
    world.create_shape(b, box_shape(1.0, 1.0));
    std::vector<Sample> out;
    out.reserve(std::size_t(steps) + 1);
    const auto sample = [&](double t) {
        const BodyState st = world.state(b);
        out.push_back({t, st.position, st.velocity, st.orientation, st.angular_velocity});
    };
    sample(0.0);
    for (int n = 1; n <= steps; ++n) {
        world.step(dt);
        sample(n * dt);
    }
    return out;
}

/// Distance between two orientations on the circle (the engine reports phi in [0, 2 pi)).
inline double angle_error(double a, double b) {
    return std::abs(std::remainder(a - b, 2.0 * std::numbers::pi));
}

inline double norm2(Vec2d v) {
    return std::sqrt(v.x * v.x + v.y * v.y);
}

/// Errors of one engine run against the reference.
struct RunErrors {
    double dt = 0.0;
    // max over the history of |engine - reference|
    double p = 0.0, v = 0.0, phi = 0.0, omega = 0.0;
    // at the fixed times (one entry per requested time)
    std::vector<double> p_at, v_at, phi_at, omega_at;
};

/// Compares an engine run of step dt with a reference sampled every dt_ref (dt = stride dt_ref).
inline RunErrors compare(const std::vector<Sample>& engine, const std::vector<Sample>& ref,
                         int stride, double dt, const std::vector<double>& fixed_times) {
    RunErrors e;
    e.dt = dt;
    for (std::size_t n = 0; n < engine.size(); ++n) {
        const Sample& r = ref.at(n * std::size_t(stride));
        const Sample& g = engine[n];
        e.p = std::max(e.p, norm2(g.p - r.p));
        e.v = std::max(e.v, norm2(g.v - r.v));
        e.phi = std::max(e.phi, angle_error(g.phi, r.phi));
        e.omega = std::max(e.omega, std::abs(g.omega - r.omega));
    }
    for (double tf : fixed_times) {
        const auto n = std::size_t(std::llround(tf / dt));
        const Sample& r = ref.at(n * std::size_t(stride));
        const Sample& g = engine.at(n);
        e.p_at.push_back(norm2(g.p - r.p));
        e.v_at.push_back(norm2(g.v - r.v));
        e.phi_at.push_back(angle_error(g.phi, r.phi));
        e.omega_at.push_back(std::abs(g.omega - r.omega));
    }
    return e;
}

/// Least-squares slope of log(err) against log(dt): the observed order of convergence.
inline double observed_order(const std::vector<double>& dts, const std::vector<double>& errs) {
    const std::size_t n = dts.size();
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const double x = std::log(dts[i]), y = std::log(errs[i]);
        sx += x;
        sy += y;
        sxx += x * x;
        sxy += x * y;
    }
    const double m = double(n);
    return (m * sxy - sx * sy) / (m * sxx - sx * sx);
}

/// The scenarios of the convergence study: sinusoidal, step and ramp loads, gravity off and on.
/// Step and ramp breakpoints (0.5 s and 1 s) lie on every grid dt = 1/30 ... 1/960 s.
inline std::vector<Scenario> standard_scenarios() {
    const Vec2d g{0.0, -9.81};
    std::vector<Scenario> out;
    const auto base = [](std::string name, Vec2d grav, LoadSpec load, bool exact_v) {
        Scenario s;
        s.name = std::move(name);
        s.mass = 2.5;
        s.inertia = 0.8;
        s.gravity = grav;
        s.p0 = {1.0, 2.0};
        s.v0 = {1.5, -0.5};
        s.phi0 = 0.3;
        s.omega0 = 0.7;
        s.load = load;
        s.duration = 2.0;
        s.exact_velocity = exact_v;
        return s;
    };
    const LoadSpec sine{Profile::sine(3.0, 2.0, 0.3),
                        Profile::sine(-2.0, 3.0, 0.5 * std::numbers::pi),
                        Profile::sine(1.5, 4.0, 0.1)};
    const LoadSpec step{Profile::step(2.0, -3.0, 0.5), Profile::step(-1.0, 4.0, 0.5),
                        Profile::step(1.0, -2.0, 0.5)};
    const LoadSpec ramp{Profile::ramp(4.0, 1.0), Profile::ramp(-2.0, 1.0), Profile::ramp(1.2, 1.0)};
    out.push_back(base("sine load, no gravity", {}, sine, false));
    out.push_back(base("sine load, gravity", g, sine, false));
    out.push_back(base("step load, no gravity", {}, step, true));
    out.push_back(base("step load, gravity", g, step, true));
    out.push_back(base("ramp load, no gravity", {}, ramp, false));
    out.push_back(base("ramp load, gravity", g, ramp, false));
    return out;
}

} // namespace tamias2d::verification
