// "Unit typing is free": the hot loop of the soft step, compiled twice (typing_bridge.cpp,
// typing_plain.cpp) with the same flags and the same run-time dispatch as the engine:
//   tamias2d::bridge::Model  the engine's adapters (plain doubles or 4-lane packs wrapped in
//                            Boost.Units quantities, the labelled model function, unwrapped);
//   PlainOps                 the same formulas written directly on doubles and packs, in the
//                            same operation order.
// The loop is not a copy: it is the engine's own pack loops
// (tamias2d/dynamics/contacts/wide_pack_loops.hpp, contact_iteration.hpp) instantiated with each,
// plus the substep integration (IM1/IM2), on a resting pyramid's contact graph packed by the
// engine. Same algorithm, same data, same order: the final states must be bitwise equal (checked),
// so the only difference left is the typing.
#pragma once

#include <cstdint>
#include <vector>

#include "tamias2d/dynamics/bridge/contacts.hpp"
#include "tamias2d/dynamics/bridge/motion.hpp"
#include "tamias2d/dynamics/contacts/contact_constraint.hpp"
#include "tamias2d/dynamics/contacts/wide_contact_constraint.hpp"
#include "tamias2d/dynamics/contacts/wide_pack_loops.hpp"
#include "tamias2d/dynamics/solver_body.hpp"

namespace tamias_bench::typing {

using tamias2d::SolverBody;
using tamias2d::Vec2d;

struct KernelData {
    std::vector<SolverBody> bodies; ///< 0 is the static ground
    std::vector<Vec2d> acc;
    std::vector<double> alpha;
    std::vector<tamias2d::WideContactConstraint> packs; ///< prepared and packed by the engine
    int constraints = 0;
};

/// A resting pyramid of unit boxes (base `base`): ground contacts, two supports per upper box
/// and side contacts between neighbours, two points each, friction 0.6.
KernelData make_kernel_data(int base);

/// Runs `steps` steps of dt with 4 substeps; defined in typing_bridge.cpp / typing_plain.cpp.
void run_bridge(KernelData& d, int steps, double dt);
void run_plain(KernelData& d, int steps, double dt);

// ----------------------------------------------------------------------------- arithmetic
/// The engine's adapters, for the integration as well as the contact iteration.
struct BridgeOps : tamias2d::bridge::Model {
    static Vec2d velocity_change(Vec2d a, double h) {
        return tamias2d::bridge::velocity_change(a, h);
    }
    static double angular_velocity_change(double al, double h) {
        return tamias2d::bridge::angular_velocity_change(al, h);
    }
    static Vec2d displacement(Vec2d v, double h) { return tamias2d::bridge::displacement(v, h); }
    static double rotation(double w, double h) { return tamias2d::bridge::rotation(w, h); }
};

/// The model's formulas on doubles or packs, operation for operation (see the model headers
/// cited): V is double or tamias2d::Wide, Body SolverBody or WideBody.
struct PlainOps {
    template <class V> using Vec = tamias2d::Vec2<V>;

    static Vec2d velocity_change(Vec2d a, double h) { return {a.x * h, a.y * h}; } // DD4
    static double angular_velocity_change(double al, double h) { return al * h; }  // DD7
    static Vec2d displacement(Vec2d v, double h) { return {v.x * h, v.y * h}; }    // DD3
    static double rotation(double w, double h) { return w * h; }                   // DD6
    template <class Body, class V = tamias2d::bridge::value_of<Body>>
    static V relative_velocity(const Body& a, const Body& b, V arm_a, V arm_b,
                               Vec<V> dir) { // IM3: DD9 along dir (dd09), B's minus A's (DD11)
        const V vb = (b.v.x * dir.x + b.v.y * dir.y) + b.w * arm_b;
        const V va = (a.v.x * dir.x + a.v.y * dir.y) + a.w * arm_a;
        return vb - va;
    }
    template <class Body, class V = tamias2d::bridge::value_of<Body>>
    static void apply_impulse(Body& a, Body& b, V arm_a, V arm_b, Vec<V> dir,
                              V lambda) { // IM3: +J on B, -J on A
        const V jx = lambda * dir.x, jy = lambda * dir.y;
        b.v.x = b.v.x + b.inv_m * jx;
        b.v.y = b.v.y + b.inv_m * jy;
        a.v.x = a.v.x - a.inv_m * jx;
        a.v.y = a.v.y - a.inv_m * jy;
        b.w = b.w + b.inv_I * (lambda * arm_b);
        a.w = a.w - a.inv_I * (lambda * arm_a);
    }
    template <class V> static V impulse_to_reach(V vn, V target, V m) {
        return -(vn - target) * m; // DD8
    }
    template <class V> static V soft_impulse(V mass_scale, V rigid, V impulse_scale, V acc) {
        return rigid * mass_scale - acc * impulse_scale; // IM7
    }
    template <bool soft, class V>
    static tamias2d::bridge::Target<V> target(V s, const tamias2d::ContactSolverSettings& st) {
        using tamias2d::broadcast, tamias2d::select, tamias2d::min, tamias2d::max; // IM7's target
        const V zero = broadcast<V>(0.0);
        const V one = broadcast<V>(1.0);
        const auto speculative = s > zero;
        const V closing = -(s * broadcast<V>(st.inv_h));
        if constexpr (!soft) {
            return {select(speculative, closing, zero), one, zero};
        } else {
            const V bias = max(broadcast<V>(st.softness.bias_rate) *
                                   min(s + broadcast<V>(st.linear_slop), zero),
                               -broadcast<V>(st.push_max_velocity));
            return {select(speculative, closing, -bias),
                    select(speculative, one, broadcast<V>(st.softness.mass_scale)),
                    select(speculative, zero, broadcast<V>(st.softness.impulse_scale))};
        }
    }
    template <class V>
    static tamias2d::bridge::TwoPointSolution<V>
    two_point_impulses(V k11, V k12, V k22, V inv11, V inv12, V inv22, V m1, V m2, V vn1, V vn2,
                       V t1, V t2, V x1, V x2) { // IM7's two_point_impulses
        using tamias2d::both, tamias2d::select;
        const V zero = tamias2d::broadcast<V>(0.0);
        const V b1 = vn1 - t1 - (k11 * x1 + k12 * x2);
        const V b2 = vn2 - t2 - (k12 * x1 + k22 * x2);
        const V both1 = -(inv11 * b1 + inv12 * b2);
        const V both2 = -(inv12 * b1 + inv22 * b2);
        const auto both_active = both(both1 >= zero, both2 >= zero);
        const V only1 = -b1 * m1;
        const auto first_active = both(only1 >= zero, k12 * only1 + b2 >= zero);
        const V only2 = -b2 * m2;
        const auto second_active = both(only2 >= zero, k12 * only2 + b1 >= zero);
        return {select(both_active, both1, select(first_active, only1, zero)),
                select(both_active, both2,
                       select(first_active, zero, select(second_active, only2, zero)))};
    }
};

// ------------------------------------------------------------------------------- the loop
/// Each translation unit instantiates this in a function marked like the engine's pack loops
/// (TAMIAS_WIDE_KERNEL: AVX2 or baseline chosen at run time, everything inlined).
template <class Ops> struct Kernel {
    static constexpr int substeps = 4;

    static void run(KernelData& d, int steps, double dt) {
        const double h = dt / substeps;
        tamias2d::ContactSolverSettings st;
        st.inv_h = 1.0 / h;
        st.softness = tamias2d::make_softness(30.0, 10.0, h);
        st.linear_slop = 0.005;
        st.push_max_velocity = 3.0;
        const std::size_t nb = d.bodies.size();
        tamias2d::WideContactConstraint* packs = d.packs.data();
        const std::size_t np = d.packs.size();
        for (int s = 0; s < steps; ++s) {
            for (int sub = 0; sub < substeps; ++sub) {
                for (std::size_t k = 1; k < nb; ++k) {
                    SolverBody& sb = d.bodies[k];
                    sb.v += Ops::velocity_change(d.acc[k], h);
                    sb.w += Ops::angular_velocity_change(d.alpha[k], h);
                }
                tamias2d::wide::warm_start_packs<Ops>(packs, np, d.bodies.data());
                tamias2d::wide::solve_packs<Ops>(packs, np, d.bodies.data(), st, true);
                for (std::size_t k = 1; k < nb; ++k) {
                    SolverBody& sb = d.bodies[k];
                    sb.dp += Ops::displacement(sb.v, h);
                    sb.dq += Ops::rotation(sb.w, h);
                }
                tamias2d::wide::solve_packs<Ops>(packs, np, d.bodies.data(), st, false);
            }
            // The geometry moves with the bodies (a narrow phase would recompute it): fold the
            // step's motion into the separations and start the next step from there.
            for (std::size_t i = 0; i < np; ++i) {
                tamias2d::WideContactConstraint& c = packs[i];
                const tamias2d::WideBody a = tamias2d::wide::gather(d.bodies.data(), c.body_a);
                const tamias2d::WideBody b = tamias2d::wide::gather(d.bodies.data(), c.body_b);
                for (auto& p : c.points)
                    p.base_separation = tamias2d::iteration::current_separation(p, a, b, c.normal);
            }
            for (SolverBody& sb : d.bodies) {
                sb.dp = {};
                sb.dq = 0.0;
            }
        }
    }
};

} // namespace tamias_bench::typing
