#pragma once
#include <cstddef>

#include "tamias2d/units/vec2.hpp"

namespace tamias2d::model::dcx_shape {
using namespace tamias2d::units;

/// \srs{DCX_shape} The signed area of the triangle (0, a, b): (a x b) / 2, positive when b lies
/// counter-clockwise of a (A4). A convex polygon is a fan of these; a shape's mass is its
/// density times its area (DCX_density), so the mass properties (DD1, DD14) weigh the fan's
/// triangles with it.
inline Area triangle_area(Vec2<Length> a, Vec2<Length> b) {
    return 0.5 * cross(a, b);
}

/// \srs{DCX_shape} The signed area of the polygon q_0 ... q_{n-1} (counter-clockwise positive),
/// A = (1/2) sum_k q_k x q_{k+1}, summed as the fan from q_0: (1/2) sum_k (q_k - q_0) x
/// (q_{k+1} - q_0), the same sum with every vertex taken relative to q_0, so that a polygon far
/// from the origin keeps its precision. A shape is non-degenerate only with A > 0. Plain SI
/// doubles in (the engine's vertices, m), quantities inside.
inline Area polygon_area(const Vec2d* q, std::size_t n) {
    const Vec2<Length> q0 = vec_from_values<Length>(q[0].x, q[0].y);
    Area twice{};
    for (std::size_t k = 1; k + 1 < n; ++k)
        twice += cross(vec_from_values<Length>(q[k].x, q[k].y) - q0,
                       vec_from_values<Length>(q[k + 1].x, q[k + 1].y) - q0);
    return 0.5 * twice;
}

} // namespace tamias2d::model::dcx_shape
