#pragma once
#include <span>

#include "tamias2d/units/vec2.hpp"

namespace tamias2d::model::t5 {
using namespace tamias2d::units;

/// A closed convex polygon, vertices counter-clockwise (A4).
using ConvexPolygon = std::span<const Vec2<Length>>;

struct Disc {
    Vec2<Length> centre;
    Length radius;
};

/// p lies in the closed convex polygon: on the inner side of every edge.
inline bool contains(ConvexPolygon poly, Vec2<Length> p) {
    const std::size_t n = poly.size();
    for (std::size_t i = 0; i < n; ++i) {
        const Vec2<Length> a = poly[i];
        const Vec2<Length> b = poly[(i + 1) % n];
        if (cross(b - a, p - a) < 0.0 * metre * metre)
            return false;
    }
    return n >= 3;
}

inline bool contains(const Disc& d, Vec2<Length> p) {
    return norm_squared(p - d.centre) <= d.radius * d.radius;
}

/// p in the closed convex polygon of `count` vertices v_i with outward unit edge normals n_i
/// (edge i from v_i to v_i+1), as the engine stores polygons: n_i . (p - v_i) <= 0 for every i
/// (the normals' form of the cross-product test above). Plain SI doubles in (the engine's
/// storage), quantities inside.
inline bool contains(const Vec2d* v, const Vec2d* n, int count, Vec2d p) {
    const Vec2<Length> pt = vec_from_values<Length>(p.x, p.y);
    for (int i = 0; i < count; ++i)
        if (dot(n[i], pt - vec_from_values<Length>(v[i].x, v[i].y)) > Length{})
            return false;
    return true;
}

/// p in the closed disc of centre c and radius r, on plain SI doubles (m).
inline bool contains(Vec2d c, double r, Vec2d p) {
    return contains(Disc{vec_from_values<Length>(c.x, c.y), Length::from_value(r)},
                    vec_from_values<Length>(p.x, p.y));
}

/// \srs{T5} Collision detection: bodies A and B have collided when some point p lies in both.
/// The narrow phase finds such a witness (its contact point) much faster; this is the
/// definition it is checked against.
template <class ShapeA, class ShapeB>
bool collided_at(const ShapeA& a, const ShapeB& b, Vec2<Length> p) {
    return contains(a, p) && contains(b, p);
}

} // namespace tamias2d::model::t5
