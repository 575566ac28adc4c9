#pragma once
#include "tamias2d/units/vec2.hpp"

namespace tamias2d::model::dd11 {
using namespace tamias2d::units;

/// \srs{DD11} Relative velocity in collisions: v^AB = v^AP - v^BP (velocity of A relative to B
/// at the common point P).
template <class V>
Vec2<Over<Velocity, V>> relative_velocity(Vec2<Over<Velocity, V>> v_AP,
                                          Vec2<Over<Velocity, V>> v_BP) {
    return v_AP - v_BP;
}

} // namespace tamias2d::model::dd11
