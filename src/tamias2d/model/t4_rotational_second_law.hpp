#pragma once
#include "tamias2d/units/quantities.hpp"

namespace tamias2d::model::t4 {
using namespace tamias2d::units;

/// \srs{T4} Newton's second law for rotation: tau = I alpha, solved for alpha.
/// (The SRS's IM2 says it is "derived from T5"; it is derived from this, T4.)
inline AngularAcceleration angular_acceleration(Torque tau, MomentOfInertia I) {
    return tau / I;
}

/// \srs{T4} tau = I alpha.
inline Torque torque(MomentOfInertia I, AngularAcceleration alpha) {
    return I * alpha;
}

} // namespace tamias2d::model::t4
