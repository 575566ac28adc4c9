// Erratum (T4, DD14): the seed states tau = I alpha with tau in N m, I in kg m^2 and alpha in
// rad s^-2. Then I alpha is in kg m^2 rad s^-2 = N m rad, not N m: the law only balances when
// the radians are accounted for (torque N m rad^-1, inertia kg m^2 rad^-2, see docs/units.md).
// With the seed's units as written, T4 does not type-check.
#include "tamias2d/model/t4_rotational_second_law.hpp"

using namespace tamias2d::units;

double t4_balance() {
    const AngularAcceleration alpha = 0.4 * radian / (second * second);
#ifdef TAMIAS_WRONG_FORM
    using SeedTorque = decltype(Force{} * Length{}); // N m
    using SeedInertia = decltype(Mass{} * Area{});   // kg m^2
    const SeedInertia I = 74.5 * kilogram * metre * metre;
    const SeedTorque tau = I * alpha;
#else
    const MomentOfInertia I = 74.5 * kilogram * metre * metre / (radian * radian);
    const Torque tau = tamias2d::model::t4::torque(I, alpha);
#endif
    return tau.value();
}
