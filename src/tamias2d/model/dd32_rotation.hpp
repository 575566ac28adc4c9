#pragma once
#include <cstddef>

#include "tamias2d/math/sincos.hpp"
#include "tamias2d/math/sincos_batch.hpp"
#include "tamias2d/units/quantities.hpp"

namespace tamias2d::model::dd32 {
using namespace tamias2d::units;

/// A rotation as its matrix's first column: R(phi) = [[cos, -sin], [sin, cos]].
struct Rotation {
    Dimensionless cos;
    Dimensionless sin;
};

/// \srs{DD32} The rotation of a body of orientation phi, R(phi) = (cos phi, sin phi), from the
/// project's own sincos (math/sincos.hpp: within 1 ulp, and the same bits on every IEEE 754
/// platform, which the C library's sin and cos are not).
inline Rotation rotation(Angle phi) {
    const math::SinCos r = math::sincos(phi.value());
    return {Dimensionless::from_value(r.cos), Dimensionless::from_value(r.sin)};
}

/// \srs{DD32} rotation(phi) of n orientations at once, phi[k] (rad) to cos[k] and sin[k], each
/// with rotation's bits: the sincos of many arguments in the lanes of a vector register
/// (math/sincos_batch.hpp). Plain doubles: a batch is an array, not one quantity.
inline void rotations(const double* phi, double* cos, double* sin, std::size_t n) {
    math::sincos_batch(phi, sin, cos, n);
}

} // namespace tamias2d::model::dd32
