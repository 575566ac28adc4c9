#pragma once
#include <numbers>

#include "tamias2d/units/angle.hpp"
#include "tamias2d/units/quantities.hpp"

namespace tamias2d::model::dd30 {
using namespace tamias2d::units;

/// \srs{DD30} Area of a capsule of core length L and radius r: a 2r x L rectangle and two half
/// discs, A = pi r^2 + 2 r L.
inline Area area(Length L, Length r) {
    return std::numbers::pi * r * r + 2.0 * r * L;
}

/// \srs{DD30} Moment of inertia of a uniform capsule of areal density rho about its centre
/// (DD14 in the continuum limit): the rectangle's rho 2rL (L^2 + 4r^2) / 12, plus the two half
/// discs as one disc moved out by L/2, rho pi r^2 (r^2/2 + L^2/4), plus the cross term of each
/// half disc's centroid lying 4r / (3 pi) beyond its flat side: rho pi r^2 L 4r / (3 pi), that is
/// rho (4/3) r^3 L.
inline MomentOfInertia inertia(AreaDensity rho, Length L, Length r) {
    const Mass rectangle = rho * (2.0 * r * L);
    const Mass discs = rho * (std::numbers::pi * r * r);
    return per_radian(per_radian(rectangle * (L * L + 4.0 * r * r) / 12.0 +
                                 discs * (r * r / 2.0 + L * L / 4.0) +
                                 rho * (4.0 / 3.0) * r * r * r * L));
}

} // namespace tamias2d::model::dd30
