#include "tamias2d/dynamics/wide_contact_solver.hpp"

#include "tamias2d/dynamics/contact_iteration.hpp"

// The pack loops are compiled twice, for AVX2 and for the x86-64 baseline, and the processor
// picks one at load time (GCC function multiversioning). Neither clone uses fused multiply-add,
// so both give the same bits. flatten inlines the whole iteration into each clone.
#if defined(__GNUC__) && defined(__x86_64__) && !defined(__clang__)
#define TAMIAS_WIDE_KERNEL __attribute__((target_clones("avx2", "default"), flatten))
#else
#define TAMIAS_WIDE_KERNEL
#endif

namespace tamias2d {

namespace {

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

TAMIAS_WIDE_KERNEL void warm_start_packs(WideContactConstraint* packs, std::size_t count,
                                         SolverBody* bodies) {
    for (std::size_t i = 0; i < count; ++i) {
        WideContactConstraint& c = packs[i];
        WideBody a = gather_velocities(bodies, c.body_a, c.inv_m_a, c.inv_I_a);
        WideBody b = gather_velocities(bodies, c.body_b, c.inv_m_b, c.inv_I_b);
        iteration::warm_start(c, a, b);
        scatter(bodies, c.body_a, a);
        scatter(bodies, c.body_b, b);
    }
}

TAMIAS_WIDE_KERNEL void solve_packs(WideContactConstraint* packs, std::size_t count,
                                    SolverBody* bodies, const ContactSolverSettings& settings,
                                    bool use_bias) {
    const ContactSolverSettings st = settings; // a local copy: the body stores cannot touch it
    for (std::size_t i = 0; i < count; ++i) {
        WideContactConstraint& c = packs[i];
        WideBody a = gather_motions(bodies, c.body_a, c.inv_m_a, c.inv_I_a);
        WideBody b = gather_motions(bodies, c.body_b, c.inv_m_b, c.inv_I_b);
        iteration::solve(c, a, b, st, use_bias);
        scatter(bodies, c.body_a, a);
        scatter(bodies, c.body_b, b);
    }
}

} // namespace

void WideContactSolver::load(std::span<const ContactConstraint> constraints,
                             std::span<const SolverBody> bodies) {
    const std::size_t body_count = bodies.size();
    graph_.colour(constraints, body_count);
    const auto order = graph_.packs();
    packs_.resize(order.size());
    // Every field of every lane is written (an empty lane, or a one-point manifold's second
    // point, from zeros): clearing the packs first cost as much again.
    static const ContactConstraint empty{};
    for (std::size_t i = 0; i < order.size(); ++i) {
        WideContactConstraint& w = packs_[i];
        for (int l = 0; l < wide_lanes; ++l) {
            const std::uint32_t k = order[i][l];
            const ContactConstraint& c =
                k == ConstraintGraph::no_constraint ? empty : constraints[k];
            w.body_a[l] = c.body_a;
            w.body_b[l] = c.body_b;
            w.normal.x[l] = c.normal.x;
            w.normal.y[l] = c.normal.y;
            w.friction[l] = c.friction;
            w.inv_m_a[l] = bodies[c.body_a].inv_m;
            w.inv_I_a[l] = bodies[c.body_a].inv_I;
            w.inv_m_b[l] = bodies[c.body_b].inv_m;
            w.inv_I_b[l] = bodies[c.body_b].inv_I;
            w.k11[l] = c.k11;
            w.k12[l] = c.k12;
            w.k22[l] = c.k22;
            w.inv_k11[l] = c.inv_k11;
            w.inv_k12[l] = c.inv_k12;
            w.inv_k22[l] = c.inv_k22;
            w.use_block[l] = c.use_block ? -1 : 0;
            for (int j = 0; j < 2; ++j) {
                const ContactConstraintPoint& p = j < c.count ? c.points[j] : empty.points[1];
                WideContactConstraintPoint& q = w.points[j];
                q.r_a.x[l] = p.r_a.x;
                q.r_a.y[l] = p.r_a.y;
                q.r_b.x[l] = p.r_b.x;
                q.r_b.y[l] = p.r_b.y;
                q.base_separation[l] = p.base_separation;
                q.normal_mass[l] = p.normal_mass;
                q.tangent_mass[l] = p.tangent_mass;
                q.normal_impulse[l] = p.normal_impulse;
                q.tangent_impulse[l] = p.tangent_impulse;
                q.max_normal_impulse[l] = p.max_normal_impulse;
                q.total_normal_impulse[l] = p.total_normal_impulse;
                q.total_tangent_impulse[l] = p.total_tangent_impulse;
            }
        }
    }
}

void WideContactSolver::warm_start(std::span<SolverBody> bodies) {
    warm_start_packs(packs_.data(), packs_.size(), bodies.data());
}

void WideContactSolver::solve(std::span<SolverBody> bodies, const ContactSolverSettings& settings,
                              bool use_bias) {
    solve_packs(packs_.data(), packs_.size(), bodies.data(), settings, use_bias);
}

void WideContactSolver::store(std::span<ContactConstraint> constraints) const {
    const auto order = graph_.packs();
    for (std::size_t i = 0; i < order.size(); ++i) {
        const WideContactConstraint& w = packs_[i];
        for (int l = 0; l < wide_lanes; ++l) {
            if (order[i][l] == ConstraintGraph::no_constraint)
                continue;
            ContactConstraint& c = constraints[order[i][l]];
            for (int j = 0; j < c.count; ++j) {
                ContactConstraintPoint& p = c.points[j];
                const WideContactConstraintPoint& q = w.points[j];
                p.normal_impulse = q.normal_impulse[l];
                p.tangent_impulse = q.tangent_impulse[l];
                p.max_normal_impulse = q.max_normal_impulse[l];
                p.total_normal_impulse = q.total_normal_impulse[l];
                p.total_tangent_impulse = q.total_tangent_impulse[l];
            }
        }
    }
}

bool WideContactSolver::uses_avx2() {
#if defined(__GNUC__) && defined(__x86_64__) && !defined(__clang__)
    return __builtin_cpu_supports("avx2");
#else
    return false;
#endif
}

} // namespace tamias2d
