// Erratum (IM2, T4): IM2's ODE alpha = tau / I with the seed's units tau in N m and I in kg m^2
// gives s^-2, not the rad s^-2 it states for alpha: the radian is lost. With the per-radian
// convention (torque N m rad^-1, inertia kg m^2 rad^-2, docs/units.md) tau / I is rad s^-2.
#include "tamias2d/model/im2_rotational_motion.hpp"

using namespace tamias2d::units;

AngularAcceleration im2_alpha() {
#ifdef TAMIAS_WRONG_FORM
    const auto tau = 200.0 * newton * metre;        // seed: N m
    const auto I = 74.5 * kilogram * metre * metre; // seed: kg m^2
    const AngularAcceleration alpha = tau / I;
#else
    const Torque tau = 200.0 * newton * metre / radian;
    const MomentOfInertia I = 74.5 * kilogram * metre * metre / (radian * radian);
    const AngularAcceleration alpha = tamias2d::model::im2::angular_acceleration(tau, I);
#endif
    return alpha;
}
