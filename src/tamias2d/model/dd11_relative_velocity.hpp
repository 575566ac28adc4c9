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

/// \srs{DD11} The same for the components of v^AP and v^BP along one direction (the normal
/// relative velocity the contact solver works with).
template <class V>
Over<Velocity, V> relative_velocity(Over<Velocity, V> v_AP_n, Over<Velocity, V> v_BP_n) {
    return v_AP_n - v_BP_n;
}

} // namespace tamias2d::model::dd11
