#include "tamias2d/dynamics/contacts/wide_contact_solver.hpp"

#include "tamias2d/dynamics/contacts/contact_preparation.hpp"
#include "tamias2d/dynamics/contacts/wide_pack_loops.hpp"
#include "tamias2d/math/prefetch.hpp"

namespace tamias2d {

namespace {

// Each kernel takes the packs' surface motion (DD46, DD47) or nullptr in a step without any:
// the loops without it are those of a world without surface motion.

TAMIAS_WIDE_KERNEL void warm_start_packs(WideContactConstraint* packs, std::size_t count,
                                         SolverBody* bodies, WideSurfaceMotion* surfaces) {
    if (surfaces == nullptr)
        wide::warm_start_packs<bridge::Model>(packs, count, bodies);
    else
        wide::warm_start_packs<bridge::Model, false, true>(packs, count, bodies, nullptr, surfaces);
}

TAMIAS_WIDE_KERNEL void solve_packs(WideContactConstraint* packs, std::size_t count,
                                    SolverBody* bodies, const ContactSolverSettings& settings,
                                    bool use_bias, WideSurfaceMotion* surfaces) {
    if (surfaces == nullptr)
        wide::solve_packs<bridge::Model>(packs, count, bodies, settings, use_bias);
    else
        wide::solve_packs<bridge::Model, false, true>(packs, count, bodies, settings, use_bias,
                                                      nullptr, surfaces);
}

TAMIAS_WIDE_KERNEL void warm_start_packs_apart(WideContactConstraint* packs, std::size_t count,
                                               SolverBody* bodies, SolverBody* sink,
                                               WideSurfaceMotion* surfaces) {
    if (surfaces == nullptr)
        wide::warm_start_packs<bridge::Model, true>(packs, count, bodies, sink);
    else
        wide::warm_start_packs<bridge::Model, true, true>(packs, count, bodies, sink, surfaces);
}

TAMIAS_WIDE_KERNEL void solve_packs_apart(WideContactConstraint* packs, std::size_t count,
                                          SolverBody* bodies, const ContactSolverSettings& settings,
                                          bool use_bias, SolverBody* sink,
                                          WideSurfaceMotion* surfaces) {
    if (surfaces == nullptr)
        wide::solve_packs<bridge::Model, true>(packs, count, bodies, settings, use_bias, sink);
    else
        wide::solve_packs<bridge::Model, true, true>(packs, count, bodies, settings, use_bias, sink,
                                                     surfaces);
}

/// Prepares the pack from its lanes' bodies (gathered by the caller). Inlined into the kernels
/// below (flatten), so that each clone has its own copy.
inline void prepare_from(WideContactConstraint& w, const WideManifoldInput& in, const WideBody& a,
                         const WideBody& b) {
    for (int l = 0; l < wide_lanes; ++l) {
        w.body_a[l] = in.body_a[l];
        w.body_b[l] = in.body_b[l];
        w.contact[l] = in.contact[l];
        w.restitution_slot[l] = in.restitution_slot[l];
        w.count[l] = in.count[l];
    }
    const Wide zero = splat(0.0);
    const Wide count{double(in.count[0]), double(in.count[1]), double(in.count[2]),
                     double(in.count[3])};
    const WideMask empty = count == zero;
    const WideMask valid[2] = {count >= splat(1.0), count == splat(2.0)};
    w.normal = in.normal;
    w.friction = in.friction;
    for (int j = 0; j < 2; ++j) {
        // A point past its lane's count is all zeros, so that solving it changes nothing.
        const preparation::PreparedPoint<Wide> p =
            preparation::prepare_point(a, b, in.r_a[j], in.r_b[j], in.normal);
        WideContactConstraintPoint& q = w.points[j];
        q.normal_arm_a = select(valid[j], p.normal_arm_a, zero);
        q.normal_arm_b = select(valid[j], p.normal_arm_b, zero);
        q.tangent_arm_a = select(valid[j], p.tangent_arm_a, zero);
        q.tangent_arm_b = select(valid[j], p.tangent_arm_b, zero);
        q.normal_mass = select(valid[j], p.normal_mass, zero);
        q.tangent_mass = select(valid[j], p.tangent_mass, zero);
        q.base_separation = in.separation[j];
        q.normal_impulse = in.normal_impulse[j];
        q.tangent_impulse = in.tangent_impulse[j];
        q.max_normal_impulse = zero;
        q.total_normal_impulse = zero;
        q.total_tangent_impulse = zero;
    }
    const preparation::PreparedBlock<Wide> k =
        preparation::prepare_block(a, b, w.points[0].normal_arm_a, w.points[0].normal_arm_b,
                                   w.points[1].normal_arm_a, w.points[1].normal_arm_b);
    const WideMask two = valid[1];
    w.k11 = select(two, k.k11, zero);
    w.k12 = select(two, k.k12, zero);
    w.k22 = select(two, k.k22, zero);
    w.inv_k11 = select(two, k.inv_k11, zero);
    w.inv_k12 = select(two, k.inv_k12, zero);
    w.inv_k22 = select(two, k.inv_k22, zero);
    // An empty lane takes the block path, which gives it zero impulses too, so that a part-filled
    // pack of two-point manifolds does not also take the point-by-point path for it.
    w.use_block = either(both(two, k.use_block), empty);
}

TAMIAS_WIDE_KERNEL void prepare_lanes(WideContactConstraint& w, const WideManifoldInput& in,
                                      const SolverBody* bodies) {
    prepare_from(w, in, wide::gather(bodies, in.body_a), wide::gather(bodies, in.body_b));
}

/// prepare_lanes, then the warm start of the pack from the same gathered rows: the pack is still
/// in registers and cache, where a later warm_start pass reads it back from memory.
TAMIAS_WIDE_KERNEL void prepare_and_warm_start_lanes(WideContactConstraint& w,
                                                     const WideManifoldInput& in,
                                                     SolverBody* bodies,
                                                     WideSurfaceMotion* surface) {
    WideBody a = wide::gather(bodies, in.body_a);
    WideBody b = wide::gather(bodies, in.body_b);
    prepare_from(w, in, a, b);
    if (surface == nullptr)
        iteration::warm_start<bridge::Model>(w, a, b);
    else
        iteration::warm_start<bridge::Model>(w, a, b, surface);
    wide::scatter(bodies, w.body_a, a);
    wide::scatter(bodies, w.body_b, b);
}

/// Point j of lane l: anchors, separation and warm-start impulses.
void set_input_point(WideManifoldInput& in, int l, int j, Vec2d r_a, Vec2d r_b, double separation,
                     double normal_impulse, double tangent_impulse) {
    in.r_a[j].x[l] = r_a.x;
    in.r_a[j].y[l] = r_a.y;
    in.r_b[j].x[l] = r_b.x;
    in.r_b[j].y[l] = r_b.y;
    in.separation[j][l] = separation;
    in.normal_impulse[j][l] = normal_impulse;
    in.tangent_impulse[j][l] = tangent_impulse;
}

/// Lane l's manifold-wide fields.
void set_input_manifold(WideManifoldInput& in, int l, std::uint32_t body_a, std::uint32_t body_b,
                        std::uint32_t contact, std::uint32_t slot, int count, Vec2d normal,
                        double friction) {
    in.body_a[l] = body_a;
    in.body_b[l] = body_b;
    in.contact[l] = contact;
    in.restitution_slot[l] = slot;
    in.count[l] = static_cast<std::uint8_t>(count);
    in.normal.x[l] = normal.x;
    in.normal.y[l] = normal.y;
    in.friction[l] = friction;
}

} // namespace

void set_input_lane(WideManifoldInput& in, int l, const GraphEdge& edge, std::uint32_t contact,
                    const Contact& c, const ContactImpulses& warm, std::uint32_t slot) {
    const Manifold& m = c.manifold;
    set_input_manifold(in, l, edge.body_a, edge.body_b, contact, slot, m.count, m.normal,
                       c.friction);
    for (int j = 0; j < 2; ++j) {
        if (j < m.count) {
            const ManifoldPoint& p = m.points[j];
            set_input_point(in, l, j, p.anchor_a, p.anchor_b, p.separation, warm.normal[j],
                            warm.tangent[j]);
        } else {
            set_input_point(in, l, j, {}, {}, 0.0, 0.0, 0.0); // solving it changes nothing
        }
    }
}

void set_input_lane(WideManifoldInput& in, int l, const ContactConstraint& c, std::uint32_t slot) {
    set_input_manifold(in, l, c.body_a, c.body_b, c.contact, slot, c.count, c.normal, c.friction);
    for (int j = 0; j < 2; ++j) {
        if (j < c.count) {
            const ContactConstraintPoint& p = c.points[j];
            set_input_point(in, l, j, p.r_a, p.r_b, p.base_separation, p.normal_impulse,
                            p.tangent_impulse);
        } else {
            set_input_point(in, l, j, {}, {}, 0.0, 0.0, 0.0); // solving it changes nothing
        }
    }
}

void clear_input_lane(WideManifoldInput& in, int l) {
    static constexpr ContactConstraint none{}; // no points, the static body 0 twice, all zeros
    set_input_lane(in, l, none, 0);
}

void WideContactSolver::colour(std::span<const GraphEdge> edges, std::size_t body_count,
                               std::uint32_t regions, std::span<const double> cut) {
    graph_.colour(edges, body_count, regions, cut);
    packs_.resize(graph_.packs().size()); // never shrinks its capacity: no allocation per step
}

void WideContactSolver::prepare_pack(std::size_t i, const WideManifoldInput& in,
                                     std::span<const SolverBody> bodies) {
    prefetch_pack_after(i);
    prepare_lanes(packs_[i], in, bodies.data());
}

void WideContactSolver::prepare_pack_and_warm_start(std::size_t i, const WideManifoldInput& in,
                                                    std::span<SolverBody> bodies) {
    prefetch_pack_after(i);
    prepare_and_warm_start_lanes(packs_[i], in, bodies.data(), surface(i));
}

void WideContactSolver::prefetch_pack_after(std::size_t i) const {
    constexpr std::size_t ahead = 2; // 1 and 4 were slower
    if (i + ahead >= packs_.size())
        return;
    const char* p = reinterpret_cast<const char*>(&packs_[i + ahead]);
    for (std::size_t line = 0; line < sizeof(WideContactConstraint); line += 64)
        prefetch_for_write(p + line);
}

void WideContactSolver::warm_start(std::span<SolverBody> bodies) {
    warm_start_packs(packs_.data(), packs_.size(), bodies.data(), surface(0));
}

void WideContactSolver::solve(std::span<SolverBody> bodies, const ContactSolverSettings& settings,
                              bool use_bias) {
    solve_packs(packs_.data(), packs_.size(), bodies.data(), settings, use_bias, surface(0));
}

void WideContactSolver::warm_start_run(std::size_t first, std::size_t count, std::uint32_t stream,
                                       std::span<SolverBody> bodies) {
    warm_start_packs_apart(packs_.data() + first, count, bodies.data(), &sinks_[stream].body,
                           surface(first));
}

void WideContactSolver::solve_run(std::size_t first, std::size_t count, std::uint32_t stream,
                                  std::span<SolverBody> bodies,
                                  const ContactSolverSettings& settings, bool use_bias) {
    solve_packs_apart(packs_.data() + first, count, bodies.data(), settings, use_bias,
                      &sinks_[stream].body, surface(first));
}

void WideContactSolver::use_surfaces(bool on) {
    with_surfaces_ = on;
    if (on)
        surfaces_.resize(packs_.size()); // never shrinks its capacity
}

void WideContactSolver::set_surface_lane(std::size_t i, int l, double tangent_speed,
                                         double rolling_resistance, double rolling_impulse) {
    WideSurfaceMotion& s = surfaces_[i];
    s.tangent_speed[l] = tangent_speed;
    s.rolling_resistance[l] = rolling_resistance;
    s.rolling_impulse[l] = rolling_impulse;
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

void WideContactSolver::store(std::span<ContactImpulses> warm, std::span<ContactImpulses> totals,
                              std::span<ContactConstraint> bouncing, std::size_t begin,
                              std::size_t end, std::span<double> rolling) const {
    if (with_surfaces_ && !rolling.empty()) { // \srs{DD46} the next step's warm start
        for (std::size_t i = begin; i < end; ++i)
            for (int l = 0; l < wide_lanes; ++l)
                if (packs_[i].count[l] != 0)
                    rolling[packs_[i].contact[l]] = surfaces_[i].rolling_impulse[l];
    }
    // The packs name their contacts level by level, scattered: ask for the records four packs
    // ahead (dense arrays, mostly in cache even at 16k boxes).
    constexpr std::size_t ahead = 4;
    for (std::size_t i = begin; i < end; ++i) {
        if (i + ahead < end) {
            const WideContactConstraint& next = packs_[i + ahead];
            for (int l = 0; l < wide_lanes; ++l) {
                if (next.count[l] != 0) {
                    prefetch_for_write(&warm[next.contact[l]]);
                    prefetch_for_write(&totals[next.contact[l]]);
                }
            }
        }
        const WideContactConstraint& w = packs_[i];
        for (int l = 0; l < wide_lanes; ++l) {
            if (w.count[l] == 0)
                continue;
            ContactImpulses& accumulated = warm[w.contact[l]];
            ContactImpulses& total = totals[w.contact[l]];
            for (int j = 0; j < w.count[l]; ++j) {
                const WideContactConstraintPoint& q = w.points[j];
                accumulated.normal[j] = q.normal_impulse[l];
                accumulated.tangent[j] = q.tangent_impulse[l];
                total.tangent[j] = q.total_tangent_impulse[l];
                if (w.restitution_slot[l] == no_slot)
                    total.normal[j] = q.total_normal_impulse[l];
                else // the normal total after the restitution pass, from its copy
                    copy_out(q, l, bouncing[w.restitution_slot[l]].points[j]);
            }
        }
    }
}

const char* WideContactSolver::instruction_set() {
#if TAMIAS_WIDE_CLONES
#if TAMIAS_WIDE_X86_64_V4
    if (__builtin_cpu_supports("x86-64-v4"))
        return "x86-64-v4";
#endif
    if (__builtin_cpu_supports("avx2"))
        return "avx2";
#endif
    return nullptr;
}

} // namespace tamias2d
