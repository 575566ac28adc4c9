#pragma once
#include <boost/units/systems/si/codata/universal_constants.hpp>

#include "tamias2d/units/vec2.hpp"

namespace tamias2d::model::t3 {
using namespace tamias2d::units;

using GravitationalConstant = decltype(Force{} * Area{} / (Mass{} * Mass{}));

/// The SRS's value of G (section 2.2): 6.673e-11 m^3 kg^-1 s^-2. CODATA 2018 gives
/// 6.67430e-11; the difference is recorded as an erratum and either can be passed in.
inline const GravitationalConstant G_srs =
    6.673e-11 * newton * metre * metre / (kilogram * kilogram);

/// \srs{T3} Newton's law of universal gravitation: the force on body 1 exerted by body 2,
/// F = G m1 m2 / |r|^2 r_hat with r = p2 - p1 (the SRS leaves the sign of r open; the force on
/// a body points toward the other one). Requires p1 != p2.
inline Vec2<Force> gravitational_force(GravitationalConstant G, Mass m1, Mass m2,
                                       Vec2<Length> r_1_to_2) {
    const Length d = norm(r_1_to_2);
    return (G * m1 * m2 / (d * d * d)) * r_1_to_2;
}

} // namespace tamias2d::model::t3
