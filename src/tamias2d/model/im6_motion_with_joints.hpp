#pragma once
#include "tamias2d/model/im7_soft_contact.hpp"
#include "tamias2d/units/quantities.hpp"

namespace tamias2d::model::im6 {
using namespace tamias2d::units;

/// The soft constraint's coefficients over a substep: bias rate beta, mass and impulse scales.
using Softness = im7::Softness;

/// \srs{IM6} The joints' spring frequency f_J, capped at a quarter of the substep rate n / dt
/// as the contacts' is (IM7): the implicit step resolves no faster spring.
inline Rate frequency(Rate requested, int substeps, Time dt) {
    return im7::frequency(requested, substeps, dt);
}

/// \srs{IM6} A joint's softness over the substep h: beta = omega / (2 zeta + h omega) with
/// omega = 2 pi f, and the mass and impulse scales of J u + beta C + gamma lambda = 0 solved
/// by backward Euler, the same damped spring as IM7's contacts (f = 0: rigid).
inline Softness softness(Rate f, Dimensionless zeta, Time h) {
    return im7::softness(f, zeta, h);
}

/// \srs{IM6} The velocity error a soft joint drives to zero: Cdot + beta C, the constraint's
/// rate plus its position error C pulled back at the bias rate beta (a vector or a scalar,
/// linear or angular).
template <class E, class R, class C>
E biased_velocity_error(E velocity_error, R bias_rate, C position_error) {
    return velocity_error + bias_rate * position_error;
}

/// \srs{IM6} A joint's impulse in the soft form: the rigid impulse -K^-1 (Cdot + beta C) scaled
/// by the mass scale, minus the impulse scale's share of the impulse accumulated so far (rigid:
/// mass scale 1, impulse scale 0). It is IM7's soft impulse, for a joint's row.
template <class S, class Q> Q soft_impulse(S mass_scale, Q rigid, S impulse_scale, Q accumulated) {
    return im7::soft_impulse(mass_scale, rigid, impulse_scale, accumulated);
}

/// \srs{IM6} A joint's reaction: its impulse over the substep, lambda / h, from the substep rate
/// 1/h (a force from a linear impulse, a torque from an angular one).
template <class J> auto reaction(J impulse, Rate inv_h) {
    return impulse * inv_h;
}

} // namespace tamias2d::model::im6
