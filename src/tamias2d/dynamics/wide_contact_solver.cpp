#include "tamias2d/dynamics/wide_contact_solver.hpp"

#include "tamias2d/dynamics/wide_pack_loops.hpp"

namespace tamias2d {

namespace {

TAMIAS_WIDE_KERNEL void warm_start_packs(WideContactConstraint* packs, std::size_t count,
                                         SolverBody* bodies) {
    wide::warm_start_packs<bridge::Model>(packs, count, bodies);
}

TAMIAS_WIDE_KERNEL void solve_packs(WideContactConstraint* packs, std::size_t count,
                                    SolverBody* bodies, const ContactSolverSettings& settings,
                                    bool use_bias) {
    wide::solve_packs<bridge::Model>(packs, count, bodies, settings, use_bias);
}

} // namespace

void WideContactSolver::colour(std::span<const GraphEdge> edges, std::size_t body_count) {
    graph_.colour(edges, body_count);
    packs_.resize(graph_.packs().size()); // never shrinks its capacity: no allocation per step
}

void WideContactSolver::set_lane(std::size_t i, int l, const ContactConstraint& c,
                                 std::uint32_t slot) {
    // Every field of the lane is written (a one-point manifold's second point from zeros):
    // clearing the packs first cost as much again.
    static const ContactConstraintPoint unused{};
    WideContactConstraint& w = packs_[i];
    w.body_a[l] = c.body_a;
    w.body_b[l] = c.body_b;
    w.normal.x[l] = c.normal.x;
    w.normal.y[l] = c.normal.y;
    w.friction[l] = c.friction;
    w.k11[l] = c.k11;
    w.k12[l] = c.k12;
    w.k22[l] = c.k22;
    w.inv_k11[l] = c.inv_k11;
    w.inv_k12[l] = c.inv_k12;
    w.inv_k22[l] = c.inv_k22;
    w.use_block[l] = c.use_block ? -1 : 0;
    w.contact[l] = c.contact;
    w.count[l] = static_cast<std::uint8_t>(c.count);
    w.restitution_slot[l] = slot;
    for (int j = 0; j < 2; ++j) {
        const ContactConstraintPoint& p = j < c.count ? c.points[j] : unused;
        WideContactConstraintPoint& q = w.points[j];
        q.normal_arm_a[l] = p.normal_arm_a;
        q.normal_arm_b[l] = p.normal_arm_b;
        q.tangent_arm_a[l] = p.tangent_arm_a;
        q.tangent_arm_b[l] = p.tangent_arm_b;
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

void WideContactSolver::clear_lane(std::size_t i, int l) {
    // All zeros on the static body 0: solving it changes nothing. Marked for the block path,
    // which gives it zero impulses too, so that a part-filled pack of two-point manifolds
    // does not also take the point-by-point path for its empty lanes.
    static const ContactConstraint empty = [] {
        ContactConstraint c;
        c.use_block = true;
        return c;
    }();
    set_lane(i, l, empty, no_slot);
}

void WideContactSolver::load(std::span<const ContactConstraint> constraints,
                             std::size_t body_count) {
    edges_.clear();
    for (const ContactConstraint& c : constraints)
        edges_.push_back({c.body_a, c.body_b,
                          path_group(c.count, c.points[0].base_separation,
                                     c.points[1].base_separation, c.use_block)});
    colour(edges_, body_count);
    const auto lanes = order();
    for (std::size_t i = 0; i < lanes.size(); ++i) {
        for (int l = 0; l < wide_lanes; ++l) {
            const std::uint32_t k = lanes[i][l];
            if (k == ConstraintGraph::no_constraint)
                clear_lane(i, l);
            else
                set_lane(i, l, constraints[k], no_slot);
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

namespace {

/// Copies lane l's point j results into a constraint point or a contact's arrays.
inline void copy_out(const WideContactConstraintPoint& q, int l, ContactConstraintPoint& p) {
    p.normal_impulse = q.normal_impulse[l];
    p.tangent_impulse = q.tangent_impulse[l];
    p.max_normal_impulse = q.max_normal_impulse[l];
    p.total_normal_impulse = q.total_normal_impulse[l];
    p.total_tangent_impulse = q.total_tangent_impulse[l];
}

} // namespace

void WideContactSolver::store(std::span<ContactConstraint> constraints) const {
    const auto order = graph_.packs();
    for (std::size_t i = 0; i < order.size(); ++i) {
        const WideContactConstraint& w = packs_[i];
        for (int l = 0; l < wide_lanes; ++l) {
            for (int j = 0; j < w.count[l]; ++j)
                copy_out(w.points[j], l, constraints[order[i][l]].points[j]);
        }
    }
}

void WideContactSolver::store(std::span<Contact> contacts,
                              std::span<ContactConstraint> bouncing) const {
    for (const WideContactConstraint& w : packs_) {
        for (int l = 0; l < wide_lanes; ++l) {
            if (w.count[l] == 0)
                continue;
            Contact& c = contacts[w.contact[l]];
            for (int j = 0; j < w.count[l]; ++j) {
                const WideContactConstraintPoint& q = w.points[j];
                c.normal_impulse[j] = q.normal_impulse[l];
                c.tangent_impulse[j] = q.tangent_impulse[l];
                c.total_normal_impulse[j] = q.total_normal_impulse[l];
                c.total_tangent_impulse[j] = q.total_tangent_impulse[l];
                if (w.restitution_slot[l] != no_slot)
                    copy_out(q, l, bouncing[w.restitution_slot[l]].points[j]);
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
