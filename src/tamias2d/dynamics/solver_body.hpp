// The per-step velocity state the solver works on: contiguous, plain doubles.
#pragma once

#include "tamias2d/math/vec2d.hpp"

namespace tamias2d {

struct SolverBody {
    Vec2d v{};          ///< m s^-1, centre of mass
    double w = 0.0;     ///< rad s^-1
    double inv_m = 0.0; ///< kg^-1 (0: static or kinematic)
    double inv_I = 0.0; ///< kg^-1 m^-2 (0: no rotation from impulses)
    Vec2d dp{};         ///< m, displacement so far in this step
    double dq = 0.0;    ///< rad, rotation so far in this step
};

} // namespace tamias2d
