#pragma once
#include "tamias2d/units/vec2.hpp"

namespace tamias2d::model::t2 {
using namespace tamias2d::units;

/// \srs{T2} Newton's third law: the force on body 1 from body 2 is F1 = -F2, where F2 is the
/// force on body 2 from body 1. Also holds for impulses (integrated over the same interval).
/// (Q: a vector, or a scalar such as the moment of an impulse about z.)
template <class Q> constexpr Q reaction(Q action) {
    return -action;
}

} // namespace tamias2d::model::t2
