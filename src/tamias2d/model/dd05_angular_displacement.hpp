#pragma once
#include "tamias2d/units/quantities.hpp"

namespace tamias2d::model::dd05 {
using namespace tamias2d::units;

/// \srs{DD5} Angular displacement theta(t) = phi(t) - phi(t0) (rad), unwrapped. The SRS writes
/// theta = d phi / dt, an angular velocity (erratum; compile-fail test in tests/compile_fail).
inline Angle angular_displacement(Angle phi_t, Angle phi_t0) {
    return phi_t - phi_t0;
}

} // namespace tamias2d::model::dd05
