#pragma once
#include "tamias2d/model/dd06_angular_velocity.hpp"
#include "tamias2d/model/dd07_angular_acceleration.hpp"
#include "tamias2d/model/t4_rotational_second_law.hpp"

namespace tamias2d::model::im2 {
using namespace tamias2d::units;

/// \srs{IM2} The ODE of rotational motion: alpha_i(t) = d omega_i / dt = tau_i(t) / I_i (T4).
inline AngularAcceleration angular_acceleration(Torque tau, MomentOfInertia I) {
    return t4::angular_acceleration(tau, I);
}

struct RotationalState {
    Angle phi; ///< unwrapped; the API wraps to [0, 2 pi) on output (SRS Table 2)
    AngularVelocity omega;
};

/// \srs{IM2} The velocity half: omega(t + dt) = omega(t) + alpha dt (DD7).
inline AngularVelocity velocity_half(AngularVelocity omega, AngularAcceleration alpha, Time dt) {
    return omega + dd07::angular_velocity_change_over(alpha, dt);
}

/// \srs{IM2} The position half: phi(t + dt) = phi(t) + omega(t + dt) dt (DD6).
inline Angle position_half(Angle phi, AngularVelocity omega_end, Time dt) {
    return phi + dd06::angle_over(omega_end, dt);
}

/// \srs{IM2} One semi-implicit Euler step, the rotational twin of im1::step: the velocity
/// half, then the position half with the new angular velocity.
inline RotationalState step(RotationalState s, AngularAcceleration alpha, Time dt) {
    const AngularVelocity omega = velocity_half(s.omega, alpha, dt);
    return {position_half(s.phi, omega, dt), omega};
}

} // namespace tamias2d::model::im2
