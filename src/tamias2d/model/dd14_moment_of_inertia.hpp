#pragma once
#include <span>

#include "tamias2d/units/angle.hpp"
#include "tamias2d/units/vec2.hpp"

namespace tamias2d::model::dd14 {
using namespace tamias2d::units;

/// A point mass at a distance from the axis (DD14's particle).
struct Particle {
    Mass m;
    Length r;
};

/// \srs{DD14} Moment of inertia I = sum_i m_i r_i^2 about the axis (per rad^2, see units).
inline MomentOfInertia moment_of_inertia(std::span<const Particle> particles) {
    decltype(Mass{} * Area{}) sum{};
    for (const Particle& q : particles)
        sum += q.m * q.r * q.r;
    return per_radian(per_radian(sum));
}

/// \srs{DD14} DD14 in the continuum limit for a uniform solid rectangle w x h about its
/// centroid: I = m (w^2 + h^2) / 12.
inline MomentOfInertia rectangle(Mass m, Length w, Length h) {
    return per_radian(per_radian(m * (w * w + h * h) / 12.0));
}

/// \srs{DD14} Uniform solid disc of radius R about its centre: I = m R^2 / 2.
inline MomentOfInertia disc(Mass m, Length R) {
    return per_radian(per_radian(m * R * R / 2.0));
}

/// \srs{DD14} Uniform triangle (0, a, b), one vertex at the reference point, about that point:
/// I = m (|a|^2 + a.b + |b|^2) / 6. A convex polygon is a fan of these.
inline MomentOfInertia triangle_about_vertex(Mass m, Vec2<Length> a, Vec2<Length> b) {
    return per_radian(per_radian(m * (dot(a, a) + dot(a, b) + dot(b, b)) / 6.0));
}

/// \srs{DD14} Parallel-axis theorem: I_axis = I_cm + m d^2, d the distance between the axes.
inline MomentOfInertia parallel_axis(MomentOfInertia I_cm, Mass m, Length d) {
    return I_cm + per_radian(per_radian(m * d * d));
}

} // namespace tamias2d::model::dd14
