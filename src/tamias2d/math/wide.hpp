// A pack of four doubles for the contact solver's hot loop: one contact constraint per lane, so
// four constraints that share no body are solved at once (graph colouring, constraint_graph.hpp).
// GCC/Clang vector extensions: the same source compiles to AVX2 (one 256-bit register) or to
// two SSE2 registers, chosen at run time (wide_contact_solver.cpp). Every operation is
// lane-wise IEEE arithmetic without fused multiply-add, so each lane computes bit for bit what
// the scalar solver computes for that constraint, whichever instruction set runs it. Without
// the extensions (MSVC), or with TAMIAS_PORTABLE_LANES, the packs are plain structures of four
// lanes doing the same operations lane by lane (math/lanes.hpp): the same bits again.
#pragma once

#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <utility>

#include "tamias2d/math/lanes.hpp"

namespace tamias2d {

inline constexpr int wide_lanes = 4;

#if TAMIAS_GNU_LANES
using Wide = double __attribute__((vector_size(wide_lanes * sizeof(double))));
/// Lane-wise comparison results: all bits set (true) or clear (false) per lane. The type a
/// comparison yields: 64-bit lanes of long for GCC, of long long for Clang.
using WideMask = decltype(Wide{} < Wide{});
#else
using Wide = lanes::Doubles<wide_lanes>;
using WideMask = lanes::Mask<wide_lanes>;
#endif
/// Without AVX enabled GCC aligns Wide to 16 bytes only, while the AVX2 code reads it with
/// aligned 32-byte loads: every structure holding packs is declared alignas(wide_alignment).
inline constexpr std::size_t wide_alignment = sizeof(Wide);
static_assert(sizeof(Wide) == wide_lanes * sizeof(double) && sizeof(WideMask) == sizeof(Wide));

/// Every lane x, exactly (Wide{} + x would turn -0.0 into +0.0).
inline Wide splat(double x) {
    static_assert(wide_lanes == 4);
    return Wide{x, x, x, x};
}
/// Lane by lane for a pack (mask: WideMask), plain for one lane (V = double, mask: bool);
/// min and max keep std::min's and std::max's tie and signed-zero behaviour.
template <class M, class V> V select(M m, V if_true, V if_false) {
    return m ? if_true : if_false;
}
template <class V> V min(V a, V b) {
    return b < a ? b : a;
}
template <class V> V max(V a, V b) {
    return a < b ? b : a;
}
#if !TAMIAS_GNU_LANES
// The same for the portable packs, whose masks cannot be the condition of ?: (exact matches,
// so these win over the templates above).
inline Wide select(WideMask m, Wide if_true, Wide if_false) {
    return lanes::select(m, if_true, if_false);
}
inline Wide min(Wide a, Wide b) {
    return select(b < a, b, a);
}
inline Wide max(Wide a, Wide b) {
    return select(a < b, b, a);
}
#endif
inline bool any(WideMask m) {
    std::int64_t r = 0;
    for (int l = 0; l < wide_lanes; ++l)
        r |= m[l];
    return r != 0;
}
inline bool all(WideMask m) {
    std::int64_t r = -1;
    for (int l = 0; l < wide_lanes; ++l)
        r &= m[l];
    return r != 0;
}

// The mask vocabulary for one lane (V = double), so that the contact iteration is written once
// as a template over V (dynamics/contacts/contact_iteration.hpp).
inline bool any(bool m) {
    return m;
}
inline bool all(bool m) {
    return m;
}
inline bool both(bool a, bool b) {
    return a && b;
}
inline WideMask both(WideMask a, WideMask b) {
    return a & b;
}
inline bool and_not(bool a, bool b) {
    return a && !b;
}
inline WideMask and_not(WideMask a, WideMask b) {
    return a & ~b;
}
inline bool either(bool a, bool b) {
    return a || b;
}
inline WideMask either(WideMask a, WideMask b) {
    return a | b;
}

/// The type of a comparison of two V: bool for one lane, WideMask for a pack.
template <class V> using mask_of = decltype(std::declval<V>() < std::declval<V>());
static_assert(std::is_same_v<mask_of<Wide>, WideMask>);

template <class V> V broadcast(double x) {
    if constexpr (std::is_same_v<V, double>)
        return x;
    else
        return splat(x);
}

} // namespace tamias2d
