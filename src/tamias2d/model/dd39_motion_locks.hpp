#pragma once
#include "tamias2d/units/vec2.hpp"

namespace tamias2d::model::dd39 {
using namespace tamias2d::units;

/// \srs{DD39} Motion-lock projection of the velocity of the centre of mass:
/// v' = ((1 - l_x) v_x, (1 - l_y) v_y), a locked world axis's component held at zero. (The
/// angular lock, omega' = (1 - l_phi) omega, is realised by a zero inverse moment of inertia
/// with omega set to zero when the lock is set: no torque then changes omega.)
inline Vec2<Velocity> projected_velocity(Vec2<Velocity> v, bool lock_x, bool lock_y) {
    const Velocity zero = Velocity::from_value(0.0);
    return {lock_x ? zero : v.x, lock_y ? zero : v.y};
}

} // namespace tamias2d::model::dd39
