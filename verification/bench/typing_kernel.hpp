// "Unit typing is free": the contact solver and integration hot loop of the soft step, written
// once as a template over its arithmetic (Ops) and compiled twice (typing_bridge.cpp,
// typing_plain.cpp) with the same flags:
//   BridgeOps  calls tamias2d::bridge (the engine's adapters: plain doubles wrapped in
//              Boost.Units quantities, the labelled model function, unwrapped again);
//   PlainOps   the same formulas written directly on doubles, in the same operation order.
// Same algorithm, same data, same evaluation order: the final states must be bitwise equal
// (checked), so the only difference left is the typing layer, which must compile away.
//
// The loop mirrors src/tamias2d/dynamics/contact_solver.cpp and World::solve (warm start,
// biased soft iteration, position update, rigid relax iteration per substep, block solver for
// two-point manifolds, friction) on a synthetic pyramid contact graph.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "tamias2d/dynamics/model_bridge.hpp"
#include "tamias2d/dynamics/softness.hpp"
#include "tamias2d/dynamics/solver_body.hpp"
#include "tamias2d/dynamics/two_point_lcp.hpp"

namespace tamias_bench::typing {

using tamias2d::SolverBody;
using tamias2d::Vec2d;

struct KPoint {
    Vec2d r_a{}, r_b{};
    double base_separation = 0.0;
    double normal_mass = 0.0, tangent_mass = 0.0;
    double normal_impulse = 0.0, tangent_impulse = 0.0;
    double relative_velocity = 0.0;
};

struct KConstraint {
    std::uint32_t a = 0, b = 0;
    Vec2d normal{};
    double friction = 0.6, restitution = 0.0;
    int count = 0;
    KPoint points[2]{};
    double k11 = 0.0, k12 = 0.0, k22 = 0.0, inv11 = 0.0, inv12 = 0.0, inv22 = 0.0;
    bool use_block = false;
};

struct KernelData {
    std::vector<SolverBody> bodies; ///< 0 is the static ground
    std::vector<Vec2d> acc;
    std::vector<double> alpha;
    std::vector<KConstraint> constraints;
};

/// A resting pyramid of unit boxes (base `base`): ground contacts, two supports per upper box
/// and side contacts between neighbours, two points each, friction 0.6.
KernelData make_kernel_data(int base);

/// Runs `steps` steps of dt with 4 substeps; defined in typing_bridge.cpp / typing_plain.cpp.
void run_bridge(KernelData& d, int steps, double dt);
void run_plain(KernelData& d, int steps, double dt);

// ----------------------------------------------------------------------------- arithmetic
struct BridgeOps {
    static Vec2d velocity_change(Vec2d a, double h) {
        return tamias2d::bridge::velocity_change(a, h);
    }
    static double angular_velocity_change(double al, double h) {
        return tamias2d::bridge::angular_velocity_change(al, h);
    }
    static Vec2d displacement(Vec2d v, double h) { return tamias2d::bridge::displacement(v, h); }
    static double rotation(double w, double h) { return tamias2d::bridge::rotation(w, h); }
    static double inverse_effective_mass(const SolverBody& a, const SolverBody& b, Vec2d ra,
                                         Vec2d rb, Vec2d n) {
        return tamias2d::bridge::inverse_effective_mass(a, b, ra, rb, n);
    }
    static double normal_mass_coupling(const SolverBody& a, const SolverBody& b, Vec2d ra1,
                                       Vec2d rb1, Vec2d ra2, Vec2d rb2, Vec2d n) {
        return tamias2d::bridge::normal_mass_coupling(a, b, ra1, rb1, ra2, rb2, n);
    }
    static double relative_velocity(const SolverBody& a, const SolverBody& b, Vec2d ra, Vec2d rb,
                                    Vec2d dir) {
        return tamias2d::bridge::relative_velocity(a, b, ra, rb, dir);
    }
    static void apply_impulse(SolverBody& a, SolverBody& b, Vec2d ra, Vec2d rb, Vec2d dir,
                              double lambda) {
        tamias2d::bridge::apply_impulse(a, b, ra, rb, dir, lambda);
    }
    static double impulse_to_reach(double vn, double target, double m) {
        return tamias2d::bridge::impulse_to_reach(vn, target, m);
    }
};

/// The model's formulas on doubles, operation for operation (see the model headers cited).
struct PlainOps {
    static Vec2d velocity_change(Vec2d a, double h) { return {a.x * h, a.y * h}; } // DD4
    static double angular_velocity_change(double al, double h) { return al * h; }  // DD7
    static Vec2d displacement(Vec2d v, double h) { return {v.x * h, v.y * h}; }    // DD3
    static double rotation(double w, double h) { return w * h; }                   // DD6
    static double normal_mass_coupling(const SolverBody& a, const SolverBody& b, Vec2d ra1,
                                       Vec2d rb1, Vec2d ra2, Vec2d rb2, Vec2d n) { // DD8's K12
        const double a1 = ra1.x * n.y - ra1.y * n.x, a2 = ra2.x * n.y - ra2.y * n.x;
        const double b1 = rb1.x * n.y - rb1.y * n.x, b2 = rb2.x * n.y - rb2.y * n.x;
        return a.inv_m + b.inv_m + a.inv_I * a1 * a2 + b.inv_I * b1 * b2;
    }
    static double inverse_effective_mass(const SolverBody& a, const SolverBody& b, Vec2d ra,
                                         Vec2d rb, Vec2d n) {
        return normal_mass_coupling(a, b, ra, rb, ra, rb, n);
    }
    static double relative_velocity(const SolverBody& a, const SolverBody& b, Vec2d ra, Vec2d rb,
                                    Vec2d dir) { // IM3 with DD9, DD11: B's point minus A's
        const double bx = b.v.x + -b.w * rb.y, by = b.v.y + b.w * rb.x;
        const double ax = a.v.x + -a.w * ra.y, ay = a.v.y + a.w * ra.x;
        return (bx - ax) * dir.x + (by - ay) * dir.y;
    }
    static void apply_impulse(SolverBody& a, SolverBody& b, Vec2d ra, Vec2d rb, Vec2d dir,
                              double lambda) { // IM3: +J on B, -J on A
        const double jx = lambda * dir.x, jy = lambda * dir.y;
        b.v.x = b.v.x + b.inv_m * jx;
        b.v.y = b.v.y + b.inv_m * jy;
        a.v.x = a.v.x - a.inv_m * jx;
        a.v.y = a.v.y - a.inv_m * jy;
        b.w = b.w + b.inv_I * (rb.x * jy - rb.y * jx);
        a.w = a.w - a.inv_I * (ra.x * jy - ra.y * jx);
    }
    static double impulse_to_reach(double vn, double target, double m) {
        return -(vn - target) * m; // DD8
    }
};

// ------------------------------------------------------------------------------- the loop
template <class Ops> struct Kernel {
    static constexpr int substeps = 4;

    static double separation(const KPoint& p, const SolverBody& a, const SolverBody& b, Vec2d n) {
        const Vec2d da = a.dp + a.dq * tamias2d::left_perp(p.r_a);
        const Vec2d db = b.dp + b.dq * tamias2d::left_perp(p.r_b);
        return p.base_separation + dot(db - da, n);
    }

    static void prepare(KernelData& d) {
        for (KConstraint& c : d.constraints) {
            const SolverBody& a = d.bodies[c.a];
            const SolverBody& b = d.bodies[c.b];
            const Vec2d t = tamias2d::right_perp(c.normal);
            for (int j = 0; j < c.count; ++j) {
                KPoint& p = c.points[j];
                const double k = Ops::inverse_effective_mass(a, b, p.r_a, p.r_b, c.normal);
                const double kt = Ops::inverse_effective_mass(a, b, p.r_a, p.r_b, t);
                p.normal_mass = k > 0.0 ? 1.0 / k : 0.0;
                p.tangent_mass = kt > 0.0 ? 1.0 / kt : 0.0;
                p.relative_velocity = Ops::relative_velocity(a, b, p.r_a, p.r_b, c.normal);
            }
            c.use_block = false;
            if (c.count == 2) {
                const KPoint& p1 = c.points[0];
                const KPoint& p2 = c.points[1];
                c.k11 = Ops::inverse_effective_mass(a, b, p1.r_a, p1.r_b, c.normal);
                c.k22 = Ops::inverse_effective_mass(a, b, p2.r_a, p2.r_b, c.normal);
                c.k12 = Ops::normal_mass_coupling(a, b, p1.r_a, p1.r_b, p2.r_a, p2.r_b, c.normal);
                const double det = c.k11 * c.k22 - c.k12 * c.k12;
                if (c.k11 > 0.0 && c.k22 > 0.0 && c.k11 * c.k11 < 1000.0 * det) {
                    c.use_block = true;
                    const double inv_det = 1.0 / det;
                    c.inv11 = c.k22 * inv_det;
                    c.inv12 = -c.k12 * inv_det;
                    c.inv22 = c.k11 * inv_det;
                }
            }
        }
    }

    static void warm_start(KernelData& d) {
        for (KConstraint& c : d.constraints) {
            SolverBody& a = d.bodies[c.a];
            SolverBody& b = d.bodies[c.b];
            const Vec2d t = tamias2d::right_perp(c.normal);
            for (int j = 0; j < c.count; ++j) {
                const KPoint& p = c.points[j];
                Ops::apply_impulse(a, b, p.r_a, p.r_b, c.normal, p.normal_impulse);
                Ops::apply_impulse(a, b, p.r_a, p.r_b, t, p.tangent_impulse);
            }
        }
    }

    static void apply_normal(KConstraint& c, int j, SolverBody& a, SolverBody& b, double updated) {
        KPoint& p = c.points[j];
        const double delta = updated - p.normal_impulse;
        p.normal_impulse = updated;
        Ops::apply_impulse(a, b, p.r_a, p.r_b, c.normal, delta);
    }

    static void solve(KernelData& d, const tamias2d::Softness& soft, double inv_h, bool use_bias) {
        constexpr double slop = 0.005, push_max = 3.0;
        for (KConstraint& c : d.constraints) {
            SolverBody& a = d.bodies[c.a];
            SolverBody& b = d.bodies[c.b];
            double target[2] = {0.0, 0.0}, mass_scale[2] = {1.0, 1.0}, impulse_scale[2] = {};
            bool is_soft = false;
            for (int j = 0; j < c.count; ++j) {
                const double s = separation(c.points[j], a, b, c.normal);
                if (s > 0.0) {
                    target[j] = -s * inv_h;
                } else if (use_bias) {
                    target[j] = -std::max(soft.bias_rate * std::min(s + slop, 0.0), -push_max);
                    mass_scale[j] = soft.mass_scale;
                    impulse_scale[j] = soft.impulse_scale;
                }
                is_soft = is_soft || mass_scale[j] != 1.0;
            }
            if (c.use_block && !is_soft) {
                KPoint& p1 = c.points[0];
                KPoint& p2 = c.points[1];
                const double vn1 = Ops::relative_velocity(a, b, p1.r_a, p1.r_b, c.normal);
                const double vn2 = Ops::relative_velocity(a, b, p2.r_a, p2.r_b, c.normal);
                const double b1 =
                    vn1 - target[0] - (c.k11 * p1.normal_impulse + c.k12 * p2.normal_impulse);
                const double b2 =
                    vn2 - target[1] - (c.k12 * p1.normal_impulse + c.k22 * p2.normal_impulse);
                const tamias2d::TwoPointSolution x = tamias2d::solve_two_point_lcp(
                    c.k11, c.k12, c.k22, c.inv11, c.inv12, c.inv22, b1, b2);
                apply_normal(c, 0, a, b, x.x1);
                apply_normal(c, 1, a, b, x.x2);
            } else {
                for (int j = 0; j < c.count; ++j) {
                    KPoint& p = c.points[j];
                    const double vn = Ops::relative_velocity(a, b, p.r_a, p.r_b, c.normal);
                    const double lambda =
                        mass_scale[j] * Ops::impulse_to_reach(vn, target[j], p.normal_mass) -
                        impulse_scale[j] * p.normal_impulse;
                    apply_normal(c, j, a, b, std::max(p.normal_impulse + lambda, 0.0));
                }
            }
            const Vec2d t = tamias2d::right_perp(c.normal);
            for (int j = 0; j < c.count; ++j) {
                KPoint& p = c.points[j];
                const double vt = Ops::relative_velocity(a, b, p.r_a, p.r_b, t);
                const double max_f = c.friction * p.normal_impulse;
                const double lambda = Ops::impulse_to_reach(vt, 0.0, p.tangent_mass);
                const double updated = std::clamp(p.tangent_impulse + lambda, -max_f, max_f);
                const double delta = updated - p.tangent_impulse;
                p.tangent_impulse = updated;
                Ops::apply_impulse(a, b, p.r_a, p.r_b, t, delta);
            }
        }
    }

    static void run(KernelData& d, int steps, double dt) {
        const double h = dt / substeps;
        const tamias2d::Softness soft = tamias2d::make_softness(30.0, 10.0, h);
        const std::size_t nb = d.bodies.size();
        for (int s = 0; s < steps; ++s) {
            prepare(d);
            for (int sub = 0; sub < substeps; ++sub) {
                for (std::size_t k = 1; k < nb; ++k) {
                    SolverBody& sb = d.bodies[k];
                    sb.v += Ops::velocity_change(d.acc[k], h);
                    sb.w += Ops::angular_velocity_change(d.alpha[k], h);
                }
                warm_start(d);
                solve(d, soft, 1.0 / h, true);
                for (std::size_t k = 1; k < nb; ++k) {
                    SolverBody& sb = d.bodies[k];
                    sb.dp += Ops::displacement(sb.v, h);
                    sb.dq += Ops::rotation(sb.w, h);
                }
                solve(d, soft, 1.0 / h, false);
            }
            // The geometry moves with the bodies (a narrow phase would recompute it): fold the
            // step's motion into the separations and start the next step from there.
            for (KConstraint& c : d.constraints) {
                for (int j = 0; j < c.count; ++j) {
                    KPoint& p = c.points[j];
                    p.base_separation = separation(p, d.bodies[c.a], d.bodies[c.b], c.normal);
                }
            }
            for (SolverBody& sb : d.bodies) {
                sb.dp = {};
                sb.dq = 0.0;
            }
        }
    }
};

} // namespace tamias_bench::typing
