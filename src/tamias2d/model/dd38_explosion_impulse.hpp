#pragma once
#include <algorithm>

#include "tamias2d/units/vec2.hpp"

namespace tamias2d::model::dd38 {
using namespace tamias2d::units;

/// Impulse per length of exposed width (N s m^-1).
using ImpulsePerLength = decltype(Impulse{} / Length{});

/// \srs{DD38} The blast's strength at distance d from its centre: 1 within the radius r,
/// falling linearly to 0 over the falloff f beyond it, 0 from r + f on:
/// s = clamp((r + f - d) / f, 0, 1) for d > r (f > 0), 1 for d <= r, 0 for d > r when f = 0.
inline Dimensionless falloff_scale(Length d, Length r, Length f) {
    if (d <= r)
        return Dimensionless::from_value(1.0);
    if (!(f > Length{}))
        return Dimensionless::from_value(0.0);
    const double s = ((r + f - d) / f).value();
    return Dimensionless::from_value(std::clamp(s, 0.0, 1.0));
}

/// \srs{DD38} The magnitude of a shape's blast impulse: J = s j_w w, the impulse per length
/// j_w times the width w the shape shows the blast (its extent across the line to the centre),
/// scaled by the strength s (falloff_scale).
inline Impulse shape_impulse(Dimensionless s, ImpulsePerLength j_w, Length w) {
    return s * j_w * w;
}

/// \srs{DD38} The magnitude of a body's own blast impulse: J = s j_b, the impulse per body j_b
/// scaled by the strength s at its nearest shape.
inline Impulse body_impulse(Dimensionless s, Impulse j_b) {
    return s * j_b;
}

} // namespace tamias2d::model::dd38
