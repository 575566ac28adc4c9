#pragma once
#include "tamias2d/units/vec2.hpp"

namespace tamias2d::model::dd15 {
using namespace tamias2d::units;

/// \srs{DD15} Kinetic energy of translation KE = m |v|^2 / 2.
inline Energy translational(Mass m, Vec2<Velocity> v) {
    return 0.5 * m * norm_squared(v);
}

/// \srs{DD15} Kinetic energy of rotation I omega^2 / 2, which the SRS omits (erratum) but
/// section 5.2.7's energy property needs for spinning bodies.
inline Energy rotational(MomentOfInertia I, AngularVelocity omega) {
    return 0.5 * I * omega * omega;
}

/// \srs{DD15} Total kinetic energy of a rigid body.
inline Energy kinetic_energy(Mass m, Vec2<Velocity> v, MomentOfInertia I, AngularVelocity omega) {
    return translational(m, v) + rotational(I, omega);
}

} // namespace tamias2d::model::dd15
