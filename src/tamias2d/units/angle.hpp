// Angle conventions (SRS A4): radians, counter-clockwise positive, z out of the screen.
#pragma once

#include <cmath>
#include <numbers>

#include "tamias2d/units/quantities.hpp"

namespace tamias2d::units {

inline constexpr double two_pi = 2.0 * std::numbers::pi;

/// \srs{DCO_phi} Output orientation wrapped to [0, 2 pi) (SRS Table 2).
/// fmod keeps the sign of its argument, so negative angles need one more turn (signbit, so that
/// the -0 of fmod(-2 pi, 2 pi) ends as +0, not "-0"); the final comparison catches -tiny + 2 pi
/// rounding up to exactly 2 pi.
inline double wrap_orientation(double phi) {
    double w = std::fmod(phi, two_pi);
    if (std::signbit(w))
        w += two_pi;
    return w >= two_pi ? 0.0 : w;
}
inline Angle wrap_orientation(Angle phi) {
    return Angle::from_value(wrap_orientation(phi.value()));
}

/// Divides by one radian. In Boost.Units the radian is a base dimension, so a moment about z
/// is "per radian of rotation": r x F (N m) becomes a torque (N m rad^-1), r x J an angular
/// momentum, and omega x r (rad m s^-1) a linear velocity (m s^-1). Every crossing between
/// linear and rotational quantities goes through here, so the convention lives in one place.
template <class Q> constexpr auto per_radian(Q q) {
    return q / (1.0 * radian);
}

} // namespace tamias2d::units
