#pragma once
#include "tamias2d/units/vec2.hpp"

namespace tamias2d::model::dd29 {
using namespace tamias2d::units;

/// \srs{DD29} A quantity at the fraction t of the step, moved linearly from its value at the
/// step's start to its value at the end: x(t) = x_0 + t (x_1 - x_0). The centre of mass and the
/// angle sweep so, and a body put back to its time of impact takes its velocities so too.
template <class Q> Q at_fraction(Q start, Q end, double t) {
    return start + t * (end - start);
}

/// \srs{DD29} The farthest any point of a shape can move over a step that translates its body's
/// centre by |dp| and turns it by |dq|: a point at most `reach` from the centre moves at most
/// |dp| + |dq| reach (the arc is no longer than the angle times the radius).
inline Length motion_bound(Length translation, Angle rotation, Length reach) {
    const Dimensionless turns = rotation / (1.0 * radian);
    return translation + turns * reach;
}

/// \srs{DD29} Conservative advancement: with the shapes `distance` apart and no point moving
/// farther than `bound` over the whole step, the gap cannot close to `target` before this
/// fraction of the step more has passed (the distance falls at most as fast as the bound).
inline Dimensionless advance(Length distance, Length target, Length bound) {
    return (distance - target) / bound;
}

} // namespace tamias2d::model::dd29
