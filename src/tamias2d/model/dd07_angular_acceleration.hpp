#pragma once
#include "tamias2d/units/quantities.hpp"

namespace tamias2d::model::dd07 {
using namespace tamias2d::units;

/// \srs{DD7} Angular acceleration alpha = d omega / dt: over one step, d omega = alpha dt.
inline AngularVelocity angular_velocity_change_over(AngularAcceleration alpha, Time dt) {
    return alpha * dt;
}

/// \srs{DD7} The mean angular acceleration over an interval.
inline AngularAcceleration mean_angular_acceleration(AngularVelocity d_omega, Time dt) {
    return d_omega / dt;
}

} // namespace tamias2d::model::dd07
