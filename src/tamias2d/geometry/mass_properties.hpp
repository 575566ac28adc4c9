// Mass properties of shapes (DD1, DD14): what a body's mass, centre of mass and moment of
// inertia are, computed once when a shape is attached (not a hot path).
#pragma once

#include <span>

#include "tamias2d/shapes.hpp"

namespace tamias2d {

struct MassData {
    double mass = 0.0;    ///< kg
    Vec2d center{};       ///< m, body frame: the centre of mass
    double inertia = 0.0; ///< kg m^2, about `center`
};

/// Mass properties of a uniform shape of areal `density` (kg m^-2, finite and >= 0; a zero
/// density gives zero mass and inertia with the geometric centroid as centre).
/// Throws ValidationError (DCX_density) otherwise.
MassData compute_mass(const Circle& c, double density);
MassData compute_mass(const Polygon& p, double density);
MassData compute_mass(const Capsule& c, double density);
/// Segments and chain segments have no area: zero mass and inertia, centred on their midpoint.
MassData compute_mass(const Geometry& g, double density);

/// The mass properties of several parts of one body: centre by DD1, inertia about it by the
/// parallel-axis theorem (DD14). An empty span, or parts of zero total mass, give zero mass
/// and inertia (the centre is then the plain mean of the parts' centres, or the origin).
MassData combine(std::span<const MassData> parts);

/// Area of a shape (m^2).
double area(const Circle& c);
double area(const Polygon& p);
double area(const Capsule& c);

} // namespace tamias2d
