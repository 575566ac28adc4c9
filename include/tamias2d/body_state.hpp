/// \file
/// A body's state as the SRS outputs it (Table 2).
#pragma once

#include "tamias2d/vec2.hpp"

namespace tamias2d {

/// \srs{R8} Position, velocity, orientation and angular velocity of one body after a step.
struct BodyState {
    Vec2d position{};              ///< m, centre of mass p (DD1), world frame
    Vec2d velocity{};              ///< m s^-1, of the centre of mass
    double orientation = 0.0;      ///< rad, phi wrapped to [0, 2 pi) (SRS Table 2)
    double angular_velocity = 0.0; ///< rad s^-1, CCW positive
};

} // namespace tamias2d
