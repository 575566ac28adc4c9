#pragma once
#include "tamias2d/units/vec2.hpp"

namespace tamias2d::model::dd11 {
using namespace tamias2d::units;

/// \srs{DD11} Relative velocity in collisions: v^AB = v^AP - v^BP (velocity of A relative to B
/// at the common point P).
inline Vec2<Velocity> relative_velocity(Vec2<Velocity> v_AP, Vec2<Velocity> v_BP) {
    return v_AP - v_BP;
}

} // namespace tamias2d::model::dd11
