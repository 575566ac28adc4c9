#pragma once
#include "tamias2d/units/vec2.hpp"
#include "tamias2d/world_def.hpp"

namespace tamias2d::model::gd2 {
using namespace tamias2d::units;

/// The SRS's standard gravitational acceleration magnitude g (section 2.2): 9.81 m s^-2, the
/// value the public WorldDef's default gravity also uses (one literal, in world_def.hpp).
inline const Acceleration g_srs = srs_gravity * metre / (second * second);

/// SRS GD2 writes g = [-g_x, -g_y] with g_x, g_y the magnitudes pulling along -x and -y.
inline Vec2<Acceleration> gravity_vector(Acceleration g_x, Acceleration g_y) {
    return {-g_x, -g_y};
}

/// \srs{GD2} Force due to gravity F_g = m g (N; the SRS lists m s^-2 as its unit, an erratum).
inline Vec2<Force> gravitational_force(Mass m, Vec2<Acceleration> g) {
    return m * g;
}

} // namespace tamias2d::model::gd2
