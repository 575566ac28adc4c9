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

/// sin x and cos x for a finite x, each within 1 ulp on every argument tested (random ones over
/// the whole range and each binade's nearest to a multiple of pi/2:
/// tests/model/test_dd32_rotation.cpp); NaN for an infinite or NaN x. Marked TAMIAS2D_EXPORT
/// because the scene library's sinusoidal load calls it: a shared libtamias2d exports it for
/// libtamias2d_io beside the API, as it does validation.hpp's functions; no public header
/// declares it.
TAMIAS2D_EXPORT SinCos sincos(double x);

} // namespace tamias2d::math
