#pragma once
#include <span>

#include "tamias2d/units/vec2.hpp"

namespace tamias2d::model::gd1 {
using namespace tamias2d::units;

struct MassVelocity {
    Mass m;
    Vec2<Velocity> v;
};

/// \srs{GD1} Conservation of momentum: sum_k m_k v_k is the same before and after any
/// interaction in an isolated system. This evaluates the sum; the law is what tests assert.
inline Vec2<Momentum> total_momentum(std::span<const MassVelocity> bodies) {
    Vec2<Momentum> p{};
    for (const MassVelocity& b : bodies)
        p += b.m * b.v;
    return p;
}

} // namespace tamias2d::model::gd1
