// Erratum (DD16; srs/errata.yaml E06): the seed gives g in PE = m g h the unit m s^-1. Then
// m g h is in kg m^2 s^-1, not J; g is the gravitational acceleration, m s^-2 (GD2).
#include "tamias2d/model/dd16_potential_energy.hpp"

using namespace tamias2d::units;

Energy dd16_with_g_in_metres_per_second() {
    const Mass m = 2.0 * kilogram;
    const Length h = 10.0 * metre;
#ifdef TAMIAS_WRONG_FORM
    const Velocity g = 9.81 * metre / second; // the seed's unit
    const Energy PE = m * g * h;
#else
    const Acceleration g = 9.81 * metre / (second * second);
    const Energy PE = tamias2d::model::dd16::potential_energy(m, g, h);
#endif
    return PE;
}
