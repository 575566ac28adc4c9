#pragma once
#include "tamias2d/units/quantities.hpp"

namespace tamias2d::model::dd06 {
using namespace tamias2d::units;

/// \srs{DD6} Angular velocity omega = d theta / dt: over one step, theta = omega dt.
inline Angle angle_over(AngularVelocity omega, Time dt) {
    return omega * dt;
}

/// \srs{DD6} The mean angular velocity over an interval.
inline AngularVelocity mean_angular_velocity(Angle theta, Time dt) {
    return theta / dt;
}

} // namespace tamias2d::model::dd06
