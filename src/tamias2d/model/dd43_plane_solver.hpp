#pragma once
#include <algorithm>

#include "tamias2d/units/vec2.hpp"

namespace tamias2d::model::dd43 {
using namespace tamias2d::units;

/// \srs{DD43} The problem the plane solver solves: the translation d closest to the target t
/// with n_i . d >= o_i for every plane i, each pushing at most L_i,
///   minimise |d - t|^2 / 2  subject to  n_i . d >= o_i,
/// whose solution is d = t + sum_i p_i n_i with pushes 0 <= p_i <= L_i (the multipliers of the
/// planes: zero for a plane the target already satisfies). A plane's separation of d is
/// s_i = n_i . d - o_i (>= 0: satisfied).
inline Length separation(Vec2<double> n, Length o, Vec2<Length> d) {
    return dot(n, d) - o;
}

/// \srs{DD43} One projected Gauss-Seidel update of plane i's push: the push that brings its
/// separation to zero with the others held, clamped to [0, L]:
///   p_i' = clamp(p_i - s_i, 0, L_i)   (unit normals: n_i . n_i = 1).
/// The translation then moves by (p_i' - p_i) n_i (translation_after).
inline Length updated_push(Length push, Length separation, Length limit) {
    return std::clamp(push - separation, Length::from_value(0.0), limit);
}

/// \srs{DD43} d' = d + (p_i' - p_i) n_i: the translation after plane i's push changed.
inline Vec2<Length> translation_after(Vec2<Length> d, Vec2<double> n, Length dp) {
    return d + dp * n;
}

/// \srs{DD43} A velocity clipped against a plane the solve pressed against:
/// v' = v - min(0, v . n) n, its part into the plane removed, the rest kept.
inline Vec2<Velocity> clipped(Vec2<Velocity> v, Vec2<double> n) {
    return v - std::min(Velocity::from_value(0.0), dot(v, n)) * n;
}

} // namespace tamias2d::model::dd43
