// The narrow phase's inputs as the collision tests write them: a pose from a position and an
// angle, and a pair's CollideInput from two poses (each body's centre at its origin).
#pragma once

#include "tamias2d/collision/narrow_phase.hpp"

namespace tamias2d::test {

inline Transform at(double x, double y, double angle = 0.0) {
    return {{x, y}, angle == 0.0 ? Rot{} : Rot::from_angle(angle)};
}

inline CollideInput input(const Transform& a, const Transform& b, double margin = 0.0) {
    return {a, a.p, b, b.p, margin};
}

} // namespace tamias2d::test
