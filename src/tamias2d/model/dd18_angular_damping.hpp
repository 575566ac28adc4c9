#pragma once
#include "tamias2d/units/quantities.hpp"

namespace tamias2d::model::dd18 {
using namespace tamias2d::units;

/// \srs{DD18} Angular damping: alpha_d = -c_omega omega, at rate c_omega (s^-1), whatever the
/// moment of inertia (the torque is -I c_omega omega).
inline AngularAcceleration angular_acceleration(Rate c_omega, AngularVelocity omega) {
    return -(c_omega * omega);
}

} // namespace tamias2d::model::dd18
