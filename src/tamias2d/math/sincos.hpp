// sin and cos of one argument, the same bits on every IEEE 754 platform: the project's own, so
// that a world's rotations (and so its state) do not depend on the C library's libm, which no
// standard requires to round sin and cos in any particular way (glibc and musl differ on a few
// per cent of arguments).
#pragma once

#include <cmath>

#include "tamias2d/export.hpp"
#include "tamias2d/math/sincos_kernels.hpp"

namespace tamias2d::math {

struct SinCos {
    double sin = 0.0;
    double cos = 1.0;
};

/// sin x and cos x for any x, the reduction to |r| <= pi/4 out of line; NaN for an infinite or
/// NaN x. Marked TAMIAS2D_EXPORT because the scene library's sinusoidal load calls sincos: a
/// shared libtamias2d exports it for libtamias2d_io beside the API, as it does validation.hpp's
/// functions; no public header declares it.
TAMIAS2D_EXPORT SinCos sincos_reduced(double x);

/// sin x and cos x for |x| <= pi/4 only (the caller checks): the kernels without a branch, so
/// that a loop over many small angles vectorises (joints/joint_rotations.cpp).
inline SinCos sincos_small(double x) {
    const double ax = std::fabs(x);
    const double s = kernels::sin_kernel(ax, 0.0);
    return {std::copysign(s, x), kernels::cos_kernel(ax, 0.0)}; // sin odd (s >= +0), cos even
}

/// sin x and cos x for a finite x, each within 1 ulp on every argument tested (random ones over
/// the whole range and each binade's nearest to a multiple of pi/2:
/// tests/model/test_dd32_rotation.cpp); NaN for an infinite or NaN x. |x| <= pi/4 is evaluated
/// inline, with sincos_reduced's bits (its own first case).
inline SinCos sincos(double x) {
    if (std::fabs(x) <= kernels::pi_over_4) // (false for NaN)
        return sincos_small(x);
    return sincos_reduced(x);
}

} // namespace tamias2d::math
