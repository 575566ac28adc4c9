// Erratum (DD13, with T4): the seed gives the torque tau = r x F the unit N m, and T4's
// moment of inertia the unit kg m^2. With the radian as a dimension (Boost.Units SI, and the
// only way T4's tau = I alpha balances with alpha in rad s^-2), a torque is N m per radian of
// rotation, N m rad^-1: r x F in N m is a moment, not yet a torque, and only becomes one
// through per_radian (docs/units.md). Assigning the naive N m product to a torque must fail.
#include "tamias2d/model/dd13_torque.hpp"

using namespace tamias2d::units;

Torque dd13_torque() {
    const Vec2<Length> r{0.5 * metre, 0.0 * metre};
    const Vec2<Force> F{0.0 * newton, 200.0 * newton};
#ifdef TAMIAS_WRONG_FORM
    const Torque tau = cross(r, F); // N m, as the seed states
#else
    const Torque tau = tamias2d::model::dd13::torque(r, F); // = per_radian(cross(r, F))
#endif
    return tau;
}
