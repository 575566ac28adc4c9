/// \file
/// An explosion (World::explode): a radial impulse on every dynamic shape within reach of a
/// point, by SRS DD38.
#pragma once

#include <cstdint>

#include "tamias2d/vec2.hpp"

namespace tamias2d {

/// \srs{DD38} A blast at `position`: every shape of a dynamic body whose nearest point lies
/// within radius + falloff of it is pushed away from it, at that point, with an impulse of
/// impulse_per_length times the width the shape shows the blast (its extent across the line
/// to the blast), full within `radius` and fading linearly to zero over `falloff` beyond it;
/// each such body also takes impulse_per_body once, at its nearest shape's nearest point.
struct ExplosionDef {
    Vec2d position{};                ///< m, the blast's centre
    double radius = 1.0;             ///< m, >= 0: full strength up to this distance
    double falloff = 0.0;            ///< m, >= 0: the impulse fades to zero over this beyond radius
    double impulse_per_length = 0.0; ///< N s m^-1 (negative: drawn towards the centre)
    double impulse_per_body = 0.0;   ///< N s (negative: drawn towards the centre)
    /// The shapes it moves: those whose Filter::category_bits share a bit with it (DD27's
    /// categories). Sensors are never moved (DD28).
    std::uint32_t mask_bits = 0xFFFFFFFF;
};

} // namespace tamias2d
