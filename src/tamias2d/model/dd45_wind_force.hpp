#pragma once
#include "tamias2d/units/vec2.hpp"

namespace tamias2d::model::dd45 {
using namespace tamias2d::units;

/// Mass per volume (kg m^-3): the air's density.
using VolumeDensity = decltype(Mass{} / (Length{} * Length{} * Length{}));

/// \srs{DD45} The density of air at sea level and 15 degrees C, rho = 1.225 kg m^-3.
inline VolumeDensity air_density() {
    return VolumeDensity::from_value(1.225);
}
/// \srs{DD45} The depth a 2D shape is taken to have across the plane, h = 1 m.
inline Length depth() {
    return Length::from_value(1.0);
}

/// \srs{DD45} The air's velocity relative to the shape: u = W - v_s, the wind W less the
/// velocity v_s of the shape's centroid (DD9).
inline Vec2<Velocity> relative_wind(Vec2<Velocity> wind, Vec2<Velocity> v_shape) {
    return wind - v_shape;
}

/// \srs{DD45} The wind's force on a shape that shows it the width w (its extent across u):
/// drag along u and lift across it, both quadratic in the relative speed,
///   F = 1/2 rho h w |u| (C_d u + C_l u_perp),   u_perp = (-u_y, u_x) (u turned a quarter
/// turn counter-clockwise), applied at the shape's centroid.
inline Vec2<Force> wind_force(Vec2<Velocity> u, Length w, Dimensionless drag, Dimensionless lift) {
    const auto k = 0.5 * air_density() * depth() * w * norm(u); // kg m^-1
    const Vec2<Velocity> u_perp{-u.y, u.x};
    return k * (drag * u + lift * u_perp);
}

} // namespace tamias2d::model::dd45
