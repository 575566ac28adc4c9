#pragma once
#include <algorithm>
#include <cmath>

#include "tamias2d/units/quantities.hpp"

namespace tamias2d::model::dd42 {
using namespace tamias2d::units;

/// \srs{DD42} The default friction of a contact: the geometric mean mu = sqrt(mu_a mu_b) of its
/// two shapes' Coulomb coefficients (LC2), so that a frictionless shape (mu = 0, A6) slides on
/// anything.
inline Dimensionless mixed_friction(Dimensionless mu_a, Dimensionless mu_b) {
    return Dimensionless{std::sqrt((mu_a * mu_b).value())};
}

/// \srs{DD42} The default restitution of a contact: the larger, C_R = max(C_R,a, C_R,b), of
/// its two shapes' coefficients (DD12), so that a bouncy ball bounces on any floor.
inline Dimensionless mixed_restitution(Dimensionless e_a, Dimensionless e_b) {
    return std::max(e_a, e_b);
}

/// \srs{DD42} A mixed friction is a Coulomb coefficient (LC2, DCX_friction): finite, >= 0.
inline bool valid_friction(Dimensionless mu) {
    return std::isfinite(mu.value()) && mu.value() >= 0.0;
}

/// \srs{DD42} A mixed restitution is a coefficient of restitution (DD12, DCI_CR): in [0, 1].
inline bool valid_restitution(Dimensionless e) {
    return e.value() >= 0.0 && e.value() <= 1.0;
}

} // namespace tamias2d::model::dd42
