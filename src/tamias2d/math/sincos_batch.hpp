// sin and cos of many arguments at once, each with sincos's bits (math/sincos.hpp): the step's
// rotations of every body, or of every jointed body after each substep, are one such batch.
#pragma once

#include <cstddef>

namespace tamias2d::math {

/// sin x[k] and cos x[k] into s[k] and c[k] for k < n (x must not overlap s or c). The
/// arguments below 1.6e6 in magnitude run Cody and Waite's reduction and the kernels in lanes
/// of a vector register, with the scalar's operations lane by lane (no branch, no contraction);
/// the others (and any infinite or NaN x) go through sincos one by one.
void sincos_batch(const double* x, double* s, double* c, std::size_t n);

} // namespace tamias2d::math
