/// \file
/// A body's mass properties as a whole (World::set_mass_data, World::mass_data).
#pragma once

#include "tamias2d/vec2.hpp"

namespace tamias2d {

/// \srs{R2} The mass, the centre of mass and the moment of inertia of a body.
struct BodyMassData {
    double mass = 0.0;    ///< kg (DD1's M)
    Vec2d center{};       ///< m, centre of mass in the body frame (from the body origin)
    double inertia = 0.0; ///< kg m^2 about the centre of mass (DD14)
    /// Field by field.
    friend bool operator==(const BodyMassData&, const BodyMassData&) = default;
};

} // namespace tamias2d
