#include "tamias2d/dynamics/contacts/restitution.hpp"

#include <algorithm>

#include "tamias2d/dynamics/bridge/contacts.hpp"
#include "tamias2d/dynamics/contacts/contact_iteration.hpp"
#include "tamias2d/dynamics/contacts/contact_preparation.hpp"

namespace tamias2d {

namespace {

/// Passes of the restitution solve over all manifolds (Gauss-Seidel on the step's totals): a
/// body that bounces on two manifolds at once (a box in a corner) needs both solved together
/// for the energy balance to hold; one pass left 1 of 1000 seeded piles above the bound, two
/// or more none (tests/properties, finding E1).
constexpr int restitution_iterations = 4;

/// The restitution pass clamps the impulse of the whole step, not of the last substep: an
/// impact's impulse is non-negative over the impact, and only then does the energy balance
/// sum_j P_j (v_before_j + v_after_j) / 2 hold with the targets chosen in restitute()
/// (an impulse given in an earlier substep can be taken back when the bounce makes it
/// unnecessary). The warm-start impulse is left alone: the bounce belongs to this step's
/// impact, and warm-started into the next step a soft iteration would not take all of it back
/// (that added energy in multi-contact piles, finding E1).
void apply_total_delta(ContactConstraint& c, int j, SolverBody& a, SolverBody& b,
                       double updated_total) {
    ContactConstraintPoint& cp = c.points[j];
    const double delta = updated_total - cp.total_normal_impulse;
    cp.total_normal_impulse = updated_total;
    bridge::apply_impulse(a, b, cp.normal_arm_a, cp.normal_arm_b, c.normal, delta);
}

/// DD12 for one manifold: each pushed point driven to its energy-safe target (see below).
/// Returns whether the manifold bounces (false: nothing was applied).
bool restitute(ContactConstraint& c, std::span<SolverBody> bodies,
               const ContactSolverSettings& st) {
    if (c.restitution == 0.0)
        return false;
    bool pushed[2] = {false, false};
    bool any_bounce = false;
    double target[2] = {0.0, 0.0};
    for (int j = 0; j < c.count; ++j) {
        const ContactConstraintPoint& cp = c.points[j];
        const double v_before = cp.relative_velocity;
        pushed[j] = cp.max_normal_impulse > 0.0;
        const bool bounce = pushed[j] && v_before < -st.restitution_threshold;
        any_bounce = any_bounce || bounce;
        // Energy: over the step, the pair's kinetic energy changes by
        // sum_j P_j (v_before_j + v_after_j) / 2 for the total impulses P_j >= 0. A point
        // that bounces ends at -C_R v_before (its share is <= 0); a point that was
        // separating before but took an impulse must end no faster than -v_before (share
        // 0), or the impulse it received would add energy; a slow point is held at 0.
        if (bounce)
            target[j] = bridge::separating_normal_velocity(c.restitution, v_before);
        else if (v_before > 0.0)
            target[j] = bridge::separating_normal_velocity(1.0, v_before);
    }
    if (!any_bounce)
        return false;
    SolverBody& a = bodies[c.body_a];
    SolverBody& b = bodies[c.body_b];
    if (c.count == 2 && c.invertible && pushed[0] && pushed[1]) {
        const bridge::TwoPointSolution<double> x =
            iteration::block_update(c, a, b, target[0], target[1], c.points[0].total_normal_impulse,
                                    c.points[1].total_normal_impulse);
        // Both deltas applied from the same state: exact for the linear system.
        apply_total_delta(c, 0, a, b, x.x1);
        apply_total_delta(c, 1, a, b, x.x2);
        return true;
    }
    for (int j = 0; j < c.count; ++j) {
        if (!pushed[j])
            continue;
        ContactConstraintPoint& cp = c.points[j];
        const double vn =
            bridge::relative_velocity(a, b, cp.normal_arm_a, cp.normal_arm_b, c.normal);
        const double lambda = bridge::impulse_to_reach(vn, target[j], cp.normal_mass);
        apply_total_delta(c, j, a, b, std::max(cp.total_normal_impulse + lambda, 0.0));
    }
    return true;
}

} // namespace

void prepare_contact(ContactConstraint& c, std::span<const SolverBody> bodies) {
    const SolverBody& a = bodies[c.body_a];
    const SolverBody& b = bodies[c.body_b];
    for (int j = 0; j < c.count; ++j) {
        ContactConstraintPoint& cp = c.points[j];
        const preparation::PreparedPoint<double> p =
            preparation::prepare_point(a, b, cp.r_a, cp.r_b, c.normal);
        cp.normal_arm_a = p.normal_arm_a;
        cp.normal_arm_b = p.normal_arm_b;
        cp.tangent_arm_a = p.tangent_arm_a;
        cp.tangent_arm_b = p.tangent_arm_b;
        cp.normal_mass = p.normal_mass;
        cp.tangent_mass = p.tangent_mass;
        cp.relative_velocity =
            bridge::relative_velocity(a, b, cp.normal_arm_a, cp.normal_arm_b, c.normal);
        cp.max_normal_impulse = 0.0;
        cp.total_normal_impulse = 0.0;
        cp.total_tangent_impulse = 0.0;
    }
    preparation::PreparedBlock<double> k{};
    if (c.count == 2) {
        const ContactConstraintPoint& p1 = c.points[0];
        const ContactConstraintPoint& p2 = c.points[1];
        k = preparation::prepare_block(a, b, p1.normal_arm_a, p1.normal_arm_b, p2.normal_arm_a,
                                       p2.normal_arm_b);
    }
    c.k11 = k.k11;
    c.k12 = k.k12;
    c.k22 = k.k22;
    c.inv_k11 = k.inv_k11;
    c.inv_k12 = k.inv_k12;
    c.inv_k22 = k.inv_k22;
    c.invertible = k.invertible;
    c.use_block = k.use_block;
}

void apply_restitution(std::span<ContactConstraint> bouncing, std::span<SolverBody> bodies,
                       const ContactSolverSettings& st) {
    for (int pass = 0; pass < restitution_iterations; ++pass) {
        bool bounced = false;
        for (ContactConstraint& c : bouncing)
            bounced = restitute(c, bodies, st) || bounced;
        if (!bounced) // the same manifolds bounce in every pass: none now, none later
            break;
    }
}

} // namespace tamias2d
