// Erratum (srs/errata.yaml): the SRS gives the collision normal n the unit m. With a normal in
// metres DD8 yields kg s^-1, not an impulse (N s), so it must not type-check.
#include "tamias2d/model/dd08_collision_impulse.hpp"

using namespace tamias2d::units;

Impulse dd08_with_normal() {
    const Velocity v_rel_n = -1.0 * metre / second;
    const InverseMass inv_m = 1.0 / (1.0 * kilogram);
#ifdef TAMIAS_WRONG_FORM
    // n in metres: v . n has m^2 s^-1 and |n|^2 / m has m^2 kg^-1.
    const Vec2<Length> n{1.0 * metre, 0.0 * metre};
    const Vec2<Velocity> v{v_rel_n, 0.0 * metre / second};
    const Impulse j = -2.0 * dot(v, n) / (inv_m * norm_squared(n));
#else
    const Impulse j = -2.0 * v_rel_n / inv_m;
#endif
    return j;
}
