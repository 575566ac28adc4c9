// sin and cos of one argument, the same bits on every IEEE 754 platform: the project's own, so
// that a world's rotations (and so its state) do not depend on the C library's libm, which no
// standard requires to round sin and cos in any particular way (glibc and musl differ on a few
// per cent of arguments).
#pragma once

#include "tamias2d/export.hpp"

namespace tamias2d::math {

struct SinCos {
    double sin = 0.0;
    double cos = 1.0;
};

/// sin x and cos x, each within 1 ulp (tests/model/test_dd32_rotation.cpp), for every finite x;
/// NaN for an infinite or NaN x. Exported for the scene reader (tamias2d_io).
TAMIAS2D_EXPORT SinCos sincos(double x);

} // namespace tamias2d::math
