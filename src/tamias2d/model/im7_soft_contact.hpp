#pragma once
#include <algorithm>
#include <numbers>

#include "tamias2d/units/quantities.hpp"

namespace tamias2d::model::im7 {
using namespace tamias2d::units;

/// The soft constraint's three coefficients for one substep (IM7; IM6's joint springs use the
/// same ones).
struct Softness {
    Rate bias_rate;              ///< velocity bias per metre of overlap (s^-1)
    Dimensionless mass_scale;    ///< fraction of the rigid impulse applied
    Dimensionless impulse_scale; ///< fraction of the accumulated impulse relaxed away
};

/// \srs{IM7} The contact spring's frequency: the requested one, capped at a quarter of the
/// substep rate n / dt, above which the implicit step no longer resolves the spring.
inline Rate frequency(Rate requested, int substeps, Time dt) {
    return std::min(requested, 0.25 * substeps / dt);
}

/// \srs{IM7} Backward Euler over a substep h of the damped spring x'' = -omega^2 x -
/// 2 zeta omega x' (omega = 2 pi f) acting on the constraint's effective mass, written as a
/// correction of the rigid impulse: with a = h omega (2 zeta + h omega), the bias rate is
/// omega / (2 zeta + h omega), the mass scale a / (1 + a) and the impulse scale 1 / (1 + a).
/// f = 0 is the rigid constraint (mass scale 1, nothing relaxed).
inline Softness softness(Rate f, Dimensionless zeta, Time h) {
    if (f == Rate{})
        return {Rate{}, Dimensionless{1.0}, Dimensionless{}};
    const Rate omega = 2.0 * std::numbers::pi * f;
    const Dimensionless a1 = 2.0 * zeta + h * omega;
    const Dimensionless a2 = h * omega * a1;
    const Dimensionless a3 = 1.0 / (1.0 + a2);
    return {omega / a1, a2 * a3, a3};
}

/// \srs{IM7} The soft impulse of one iteration: the rigid impulse (DD8's impulse_to_reach
/// towards the point's target) scaled by the mass scale, minus the relaxed share of the
/// impulse accumulated so far. Q: an impulse (N s), a vector of them or an angular impulse (a
/// joint's, IM6), of doubles or of packs of lanes; S: the scales, dimensionless (plain values
/// of the packs' type, or quantities).
template <class S, class Q> Q soft_impulse(S mass_scale, Q rigid, S impulse_scale, Q accumulated) {
    return rigid * mass_scale - accumulated * impulse_scale;
}

} // namespace tamias2d::model::im7
