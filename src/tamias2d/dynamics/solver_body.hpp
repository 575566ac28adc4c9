// The per-step velocity state the solver works on: contiguous, plain doubles.
#pragma once

#include <cstddef>

#include "tamias2d/math/vec2d.hpp"

namespace tamias2d {

/// Two rows of four doubles, each 32-byte aligned: the wide solver loads four bodies' rows as
/// whole packs and transposes them into one pack per field (wide_pack_loops.hpp), and writes the
/// first row back the same way. The field order is that layout.
struct alignas(32) SolverBody {
    Vec2d v{};          ///< m s^-1, centre of mass
    double w = 0.0;     ///< rad s^-1
    double inv_m = 0.0; ///< kg^-1 (0: static or kinematic)
    double inv_I = 0.0; ///< kg^-1 m^-2 (0: no rotation from impulses)
    Vec2d dp{};         ///< m, displacement so far in this step
    double dq = 0.0;    ///< rad, rotation so far in this step
};

static_assert(sizeof(SolverBody) == 64);
static_assert(offsetof(SolverBody, v) == 0 && offsetof(SolverBody, w) == 16 &&
              offsetof(SolverBody, inv_m) == 24); // row 0: v.x v.y w inv_m
static_assert(offsetof(SolverBody, inv_I) == 32 && offsetof(SolverBody, dp) == 40 &&
              offsetof(SolverBody, dq) == 56); // row 1: inv_I dp.x dp.y dq

} // namespace tamias2d
