#pragma once
#include "tamias2d/units/vec2.hpp"

namespace tamias2d::model::dd10 {
using namespace tamias2d::units;

/// \srs{DD10} Impulse J = m dv (= change of momentum).
inline Vec2<Impulse> impulse(Mass m, Vec2<Velocity> dv) {
    return m * dv;
}

/// \srs{DD10} The same law solved for the velocity change: dv = J / m (with 1/m = 0 for a
/// static body).
/// (V: double, or a pack of lanes.)
template <class V>
Vec2<Over<Velocity, V>> velocity_change(Vec2<Over<Impulse, V>> J, Over<InverseMass, V> inv_m) {
    return inv_m * J;
}

/// \srs{DD10} J = integral of F dt, for F constant over dt.
inline Vec2<Impulse> impulse_of_constant_force(Vec2<Force> F, Time dt) {
    return F * dt;
}

} // namespace tamias2d::model::dd10
