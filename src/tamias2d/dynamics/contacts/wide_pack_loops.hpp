// The wide solver's loops over its packs: gather the lanes' bodies, run one contact iteration
// on four manifolds at once (contact_iteration.hpp), write the velocities back. Templates over
// the model adapter (bridge::Model in the engine; the benchmark instantiates them with plain
// doubles too, to measure the typing).
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>

#include "tamias2d/dynamics/contacts/contact_iteration.hpp"
#include "tamias2d/dynamics/contacts/wide_contact_constraint.hpp"
#include "tamias2d/dynamics/solver_body.hpp"
#include "tamias2d/math/wide_kernel.hpp"

namespace tamias2d::wide {

using Lanes = const std::uint32_t (&)[wide_lanes];

/// Row 0 or 1 of a solver body as one pack (SolverBody's layout: two aligned rows of four).
inline Wide load_row(const SolverBody& b, int row) {
    Wide r;
    std::memcpy(&r, reinterpret_cast<const unsigned char*>(&b) + row * sizeof(Wide), sizeof r);
    return r;
}
inline void store_row(SolverBody& b, Wide r) {
    std::memcpy(reinterpret_cast<unsigned char*>(&b), &r, sizeof r);
}

/// 4 x 4 transpose: rows r0..r3 (one body each) into c0..c3 (one field each, a lane per body),
/// or back. Eight shuffles instead of sixteen scalar loads and their inserts.
inline void transpose(Wide r0, Wide r1, Wide r2, Wide r3, Wide& c0, Wide& c1, Wide& c2, Wide& c3) {
    static_assert(wide_lanes == 4);
#if TAMIAS_GNU_LANES
    const Wide t0 = __builtin_shufflevector(r0, r1, 0, 4, 2, 6);
    const Wide t1 = __builtin_shufflevector(r0, r1, 1, 5, 3, 7);
    const Wide t2 = __builtin_shufflevector(r2, r3, 0, 4, 2, 6);
    const Wide t3 = __builtin_shufflevector(r2, r3, 1, 5, 3, 7);
    c0 = __builtin_shufflevector(t0, t2, 0, 1, 4, 5);
    c1 = __builtin_shufflevector(t1, t3, 0, 1, 4, 5);
    c2 = __builtin_shufflevector(t0, t2, 2, 3, 6, 7);
    c3 = __builtin_shufflevector(t1, t3, 2, 3, 6, 7);
#else
    // Without shuffles (portable packs): lane i of column k is lane k of row i.
    c0 = Wide{r0[0], r1[0], r2[0], r3[0]};
    c1 = Wide{r0[1], r1[1], r2[1], r3[1]};
    c2 = Wide{r0[2], r1[2], r2[2], r3[2]};
    c3 = Wide{r0[3], r1[3], r2[3], r3[3]};
#endif
}

/// The lanes' bodies: velocities, inverse masses and the motions so far in the step.
inline WideBody gather(const SolverBody* bodies, Lanes index) {
    const SolverBody& b0 = bodies[index[0]];
    const SolverBody& b1 = bodies[index[1]];
    const SolverBody& b2 = bodies[index[2]];
    const SolverBody& b3 = bodies[index[3]];
    WideBody w;
    transpose(load_row(b0, 0), load_row(b1, 0), load_row(b2, 0), load_row(b3, 0), w.v.x, w.v.y, w.w,
              w.inv_m);
    transpose(load_row(b0, 1), load_row(b1, 1), load_row(b2, 1), load_row(b3, 1), w.inv_I, w.dp.x,
              w.dp.y, w.dq);
    return w;
}

/// Writes the velocity row back. Lanes naming the static body 0 write back its unchanged zeros
/// (its inverse mass is 0); no other body appears twice in a pack. With `apart`, those lanes
/// write into `sink` instead, a zero body of the stream's own: packs of different streams run
/// at once on different threads, and body 0 is then only read.
template <bool apart = false>
inline void scatter(SolverBody* bodies, Lanes index, const WideBody& w,
                    SolverBody* sink = nullptr) {
    Wide r0, r1, r2, r3;
    transpose(w.v.x, w.v.y, w.w, w.inv_m, r0, r1, r2, r3);
    const auto row = [&](std::uint32_t k) -> SolverBody& {
        if constexpr (apart)
            return k != 0 ? bodies[k] : *sink;
        else
            return bodies[k];
    };
    store_row(row(index[0]), r0);
    store_row(row(index[1]), r1);
    store_row(row(index[2]), r2);
    store_row(row(index[3]), r3);
}

/// Pack i's surface motion for the iteration: surfaces[i] in a loop `with_surface`, else none
/// (nullptr: the iteration without surface motion, operation for operation).
template <bool with_surface> inline auto surface_of(WideSurfaceMotion* surfaces, std::size_t i) {
    if constexpr (with_surface)
        return &surfaces[i];
    else
        return nullptr;
}

template <class Model, bool apart = false, bool with_surface = false>
void warm_start_packs(WideContactConstraint* packs, std::size_t count, SolverBody* bodies,
                      SolverBody* sink = nullptr, WideSurfaceMotion* surfaces = nullptr) {
    for (std::size_t i = 0; i < count; ++i) {
        WideContactConstraint& c = packs[i];
        WideBody a = gather(bodies, c.body_a);
        WideBody b = gather(bodies, c.body_b);
        iteration::warm_start<Model>(c, a, b, surface_of<with_surface>(surfaces, i));
        scatter<apart>(bodies, c.body_a, a, sink);
        scatter<apart>(bodies, c.body_b, b, sink);
    }
}

template <bool use_bias, class Model, bool apart = false, bool with_surface = false>
void solve_packs(WideContactConstraint* packs, std::size_t count, SolverBody* bodies,
                 const ContactSolverSettings& settings, SolverBody* sink = nullptr,
                 WideSurfaceMotion* surfaces = nullptr) {
    const ContactSolverSettings st = settings; // a local copy: the body stores cannot touch it
    for (std::size_t i = 0; i < count; ++i) {
        WideContactConstraint& c = packs[i];
        WideBody a = gather(bodies, c.body_a);
        WideBody b = gather(bodies, c.body_b);
        iteration::solve<use_bias, Model>(c, a, b, st, surface_of<with_surface>(surfaces, i));
        scatter<apart>(bodies, c.body_a, a, sink);
        scatter<apart>(bodies, c.body_b, b, sink);
    }
}

template <class Model, bool apart = false, bool with_surface = false>
void solve_packs(WideContactConstraint* packs, std::size_t count, SolverBody* bodies,
                 const ContactSolverSettings& settings, bool use_bias, SolverBody* sink = nullptr,
                 WideSurfaceMotion* surfaces = nullptr) {
    if (use_bias)
        solve_packs<true, Model, apart, with_surface>(packs, count, bodies, settings, sink,
                                                      surfaces);
    else
        solve_packs<false, Model, apart, with_surface>(packs, count, bodies, settings, sink,
                                                       surfaces);
}

} // namespace tamias2d::wide
