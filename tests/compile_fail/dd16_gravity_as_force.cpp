// Erratum (DD16; srs/errata.yaml E06): the seed also calls g in PE = m g h "the gravitational
// force acting [on] the body". With g a force, m g h is in kg N m = kg^2 m^2 s^-2, not J; g is
// the gravitational acceleration (m s^-2, GD2) and m g the force.
#include "tamias2d/model/dd16_potential_energy.hpp"

using namespace tamias2d::units;

Energy dd16_with_g_a_force() {
    const Mass m = 2.0 * kilogram;
    const Length h = 10.0 * metre;
#ifdef TAMIAS_WRONG_FORM
    const Force g = 19.62 * newton; // "the gravitational force acting the body"
    const Energy PE = m * g * h;
#else
    const Force weight = m * (9.81 * metre / (second * second));
    const Energy PE = weight * h; // m g h with g the acceleration
#endif
    return PE;
}
