// The wide solver's loops over its packs: gather the lanes' bodies, run one contact iteration
// on four manifolds at once (contact_iteration.hpp), write the velocities back. Templates over
// the model adapter (bridge::Model in the engine; the benchmark instantiates them with plain
// doubles too, to measure the typing).
#pragma once

#include <cstddef>
#include <cstdint>

#include "tamias2d/dynamics/contact_iteration.hpp"
#include "tamias2d/dynamics/solver_body.hpp"
#include "tamias2d/dynamics/wide_contact_constraint.hpp"

// Functions running the pack loops are compiled twice, for AVX2 and for the x86-64 baseline, and
// the processor picks one at load time (GCC function multiversioning). Neither clone uses fused
// multiply-add, so both give the same bits. flatten inlines the whole iteration into each clone.
#if defined(__GNUC__) && defined(__x86_64__) && !defined(__clang__)
#define TAMIAS_WIDE_KERNEL __attribute__((target_clones("avx2", "default"), flatten))
#else
#define TAMIAS_WIDE_KERNEL
#endif

namespace tamias2d::wide {

using Lanes = const std::uint32_t (&)[wide_lanes];

/// Velocities of the lanes' bodies, with the inverse masses the pack holds for them.
inline WideBody gather_velocities(const SolverBody* bodies, Lanes index, Wide inv_m, Wide inv_I) {
    static_assert(wide_lanes == 4);
    const SolverBody& b0 = bodies[index[0]];
    const SolverBody& b1 = bodies[index[1]];
    const SolverBody& b2 = bodies[index[2]];
    const SolverBody& b3 = bodies[index[3]];
    WideBody w;
    w.v = {Wide{b0.v.x, b1.v.x, b2.v.x, b3.v.x}, Wide{b0.v.y, b1.v.y, b2.v.y, b3.v.y}};
    w.w = Wide{b0.w, b1.w, b2.w, b3.w};
    w.inv_m = inv_m;
    w.inv_I = inv_I;
    return w;
}

/// The same and the motions so far in the step (for the current separations).
inline WideBody gather_motions(const SolverBody* bodies, Lanes index, Wide inv_m, Wide inv_I) {
    WideBody w = gather_velocities(bodies, index, inv_m, inv_I);
    const SolverBody& b0 = bodies[index[0]];
    const SolverBody& b1 = bodies[index[1]];
    const SolverBody& b2 = bodies[index[2]];
    const SolverBody& b3 = bodies[index[3]];
    w.dp = {Wide{b0.dp.x, b1.dp.x, b2.dp.x, b3.dp.x}, Wide{b0.dp.y, b1.dp.y, b2.dp.y, b3.dp.y}};
    w.dq = Wide{b0.dq, b1.dq, b2.dq, b3.dq};
    return w;
}

/// Lanes naming the static body 0 write back its unchanged zeros (its inverse mass is 0); no
/// other body appears twice in a pack.
inline void scatter(SolverBody* bodies, Lanes index, const WideBody& w) {
    for (int l = 0; l < wide_lanes; ++l) {
        SolverBody& b = bodies[index[l]];
        b.v = {w.v.x[l], w.v.y[l]};
        b.w = w.w[l];
    }
}

template <class Model>
void warm_start_packs(WideContactConstraint* packs, std::size_t count, SolverBody* bodies) {
    for (std::size_t i = 0; i < count; ++i) {
        WideContactConstraint& c = packs[i];
        WideBody a = gather_velocities(bodies, c.body_a, c.inv_m_a, c.inv_I_a);
        WideBody b = gather_velocities(bodies, c.body_b, c.inv_m_b, c.inv_I_b);
        iteration::warm_start<Model>(c, a, b);
        scatter(bodies, c.body_a, a);
        scatter(bodies, c.body_b, b);
    }
}

template <class Model>
void solve_packs(WideContactConstraint* packs, std::size_t count, SolverBody* bodies,
                 const ContactSolverSettings& settings, bool use_bias) {
    const ContactSolverSettings st = settings; // a local copy: the body stores cannot touch it
    for (std::size_t i = 0; i < count; ++i) {
        WideContactConstraint& c = packs[i];
        WideBody a = gather_motions(bodies, c.body_a, c.inv_m_a, c.inv_I_a);
        WideBody b = gather_motions(bodies, c.body_b, c.inv_m_b, c.inv_I_b);
        iteration::solve<Model>(c, a, b, st, use_bias);
        scatter(bodies, c.body_a, a);
        scatter(bodies, c.body_b, b);
    }
}

} // namespace tamias2d::wide
