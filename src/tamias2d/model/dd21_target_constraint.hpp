#pragma once
#include "tamias2d/units/vec2.hpp"

namespace tamias2d::model::dd21 {
using namespace tamias2d::units;

/// \srs{DD21} Position error C = (p_B + r_B) - x_T: the grabbed point minus the target.
inline Vec2<Length> position_error(Vec2<Length> center, Vec2<Length> r, Vec2<Length> target) {
    return (center + r) - target;
}

/// \srs{DD21} The bound F_max h on the impulse accumulated in a substep h: the impulse of the
/// largest force over h (DD10's J = F dt). DD23's motor and DD26 bound theirs so too.
inline Impulse impulse_bound(Force max_force, Time h) {
    return max_force * h;
}

/// \srs{DD21} The accumulated impulse clamped to the length F_max h: the joint never pulls
/// with more than its maximum force.
inline Vec2<Impulse> clamp(Vec2<Impulse> accumulated, Impulse max_impulse) {
    const Impulse length = norm(accumulated);
    if (!(length > max_impulse))
        return accumulated;
    return (max_impulse / length) * accumulated;
}

} // namespace tamias2d::model::dd21
