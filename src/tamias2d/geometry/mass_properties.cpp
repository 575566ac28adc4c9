#include "tamias2d/geometry/mass_properties.hpp"

#include <cmath>
#include <numbers>
#include <vector>

#include "tamias2d/errors.hpp"
#include "tamias2d/math/vec2d.hpp"
#include "tamias2d/memory/allocator.hpp"
#include "tamias2d/model/dcx_shape_non_degenerate_shapes.hpp"
#include "tamias2d/model/dd01_center_of_mass.hpp"
#include "tamias2d/model/dd14_moment_of_inertia.hpp"
#include "tamias2d/model/dd30_capsule_mass.hpp"

namespace tamias2d {
namespace {

namespace dd01 = model::dd01;
namespace dd14 = model::dd14;
namespace dd30 = model::dd30;
namespace dcx_shape = model::dcx_shape;
using units::from_value;
using units::Length;
using units::Mass;

// The model layer is unit-typed; the engine stores doubles. These wrap at the call site.
Mass kg(double m) {
    return from_value<Mass>(m);
}
Length metres(double l) {
    return from_value<Length>(l);
}
units::Vec2<Length> metres(Vec2d v) {
    return units::vec_from_values<Length>(v.x, v.y);
}
Vec2d plain(units::Vec2<Length> v) {
    return {v.x.value(), v.y.value()};
}

/// \srs{DCX_density} (zero is allowed here: massless parts still need a centroid).
void require_density(double density) {
    if (!std::isfinite(density) || density < 0.0)
        throw ValidationError("shape.density", density, "must be finite and >= 0", "DCX_density");
}

} // namespace

double area(const Circle& c) {
    return std::numbers::pi * c.radius * c.radius;
}

/// \srs{DCX_shape} a polygon's area
double area(const Polygon& p) {
    return dcx_shape::polygon_area(p.vertices.data(), std::size_t(p.count)).value();
}

/// \srs{DD30} a capsule's area
double area(const Capsule& c) {
    return dd30::area(metres(length(c.center2 - c.center1)), metres(c.radius)).value();
}

MassData compute_mass(const Capsule& c, double density) {
    require_density(density);
    const Vec2d center = 0.5 * (c.center1 + c.center2);
    const Length L = metres(length(c.center2 - c.center1));
    /// \srs{DD30} its inertia about its centre
    const double inertia =
        dd30::inertia(from_value<units::AreaDensity>(density), L, metres(c.radius)).value();
    return {density * area(c), center, inertia};
}

MassData compute_mass(const Circle& c, double density) {
    require_density(density);
    const double m = density * area(c);
    /// \srs{DD14} uniform disc about its centre
    return {m, c.center, dd14::disc(kg(m), metres(c.radius)).value()};
}

MassData compute_mass(const Polygon& p, double density) {
    require_density(density);
    // Triangle fan. The centre is DD1 over the triangles, each a point mass at its centroid;
    // the fan is rooted at vertex 0 (not the origin) so shapes far from the body origin keep
    // their precision. A zero density still needs the geometric centroid: use unit weights.
    const double weight = density > 0.0 ? density : 1.0;
    const Vec2d origin = p.vertices[0];
    dd01::PointMass parts[max_polygon_vertices];
    int n = 0;
    for (int i = 1; i + 1 < p.count; ++i) {
        const Vec2d e1 = p.vertices[i] - origin;
        const Vec2d e2 = p.vertices[i + 1] - origin;
        const double m = weight * dcx_shape::triangle_area(metres(e1), metres(e2)).value();
        parts[n++] = {kg(m), metres(Vec2d{(e1.x + e2.x) / 3.0, (e1.y + e2.y) / 3.0})};
    }
    /// \srs{DD1} centre of mass of the fan
    const Vec2d c_rel = plain(dd01::center_of_mass(std::span<const dd01::PointMass>(parts, n)));
    const Vec2d center = c_rel + origin;
    if (density == 0.0)
        return {0.0, center, 0.0};

    // Inertia about the centre: the polygon is convex and contains its centre, so the fan
    // rooted there has positive triangles, each given by DD14's triangle-about-vertex form.
    double mass = 0.0;
    double inertia = 0.0;
    for (int i = 0; i < p.count; ++i) {
        const Vec2d a = p.vertices[i] - center;
        const Vec2d b = p.vertices[(i + 1) % p.count] - center;
        const double m = density * dcx_shape::triangle_area(metres(a), metres(b)).value();
        mass += m;
        /// \srs{DD14} triangle (centre, a, b) about the centre
        inertia += dd14::triangle_about_vertex(kg(m), metres(a), metres(b)).value();
    }
    return {mass, center, inertia};
}

MassData compute_mass(const Geometry& g, double density) {
    switch (g.type) {
    case ShapeType::polygon:
        return compute_mass(g.polygon, density);
    case ShapeType::capsule:
        return compute_mass(g.capsule, density);
    case ShapeType::segment:
        require_density(density);
        return {0.0, 0.5 * (g.segment.point1 + g.segment.point2), 0.0};
    case ShapeType::chain_segment:
        require_density(density);
        return {0.0, 0.5 * (g.chain_segment.point1 + g.chain_segment.point2), 0.0};
    case ShapeType::circle:
        break;
    }
    return compute_mass(g.circle, density);
}

MassData combine(std::span<const MassData> parts) {
    MassData out;
    if (parts.empty())
        return out;
    memory::Scratch<dd01::PointMass, 8> points(parts.size());
    Vec2d mean{};
    for (std::size_t k = 0; k < parts.size(); ++k) {
        const MassData& d = parts[k];
        out.mass += d.mass;
        points[k] = {kg(d.mass), metres(d.center)};
        mean += d.center;
    }
    if (!(out.mass > 0.0)) {
        const double inv = 1.0 / double(parts.size());
        out.center = {mean.x * inv, mean.y * inv};
        out.mass = 0.0;
        return out;
    }
    /// \srs{DD1} combined centre of mass
    out.center = plain(dd01::center_of_mass({points.data(), points.size()}));
    for (const MassData& d : parts) {
        const double dist = length(d.center - out.center);
        /// \srs{DD14} parallel-axis theorem
        out.inertia += dd14::parallel_axis(from_value<units::MomentOfInertia>(d.inertia),
                                           kg(d.mass), metres(dist))
                           .value();
    }
    return out;
}

} // namespace tamias2d
