#include "tamias2d/geometry/shape_queries.hpp"

#include <cmath>

namespace tamias2d {
namespace {

bool contains(const Circle& c, Vec2d local) {
    const Vec2d d = local - c.center;
    return dot(d, d) <= c.radius * c.radius;
}

bool contains(const Polygon& p, Vec2d local) {
    for (int i = 0; i < p.count; ++i)
        if (dot(p.normals[i], local - p.vertices[i]) > 0.0)
            return false;
    return true;
}

/// Ray in the shape's body frame.
std::optional<RayHit> cast(const Circle& c, Vec2d o, Vec2d d) {
    const double len = length(d);
    if (!(len > 0.0))
        return std::nullopt;
    const Vec2d u{d.x / len, d.y / len};
    const Vec2d s = o - c.center;
    // Closest approach of the line to the centre, then back off along the chord: this form
    // keeps its precision when the ray is long compared with the circle.
    const double t_mid = -dot(s, u);
    const Vec2d closest = s + t_mid * u;
    const double h2 = c.radius * c.radius - dot(closest, closest);
    if (h2 < 0.0)
        return std::nullopt;
    const double t = t_mid - std::sqrt(h2);
    if (t < 0.0 || t > len)
        return std::nullopt; // starts inside, points away, or too short
    RayHit hit;
    hit.fraction = t / len;
    hit.point = o + t * u;
    hit.normal = normalize(hit.point - c.center);
    return hit;
}

std::optional<RayHit> cast(const Polygon& p, Vec2d o, Vec2d d) {
    if (!(dot(d, d) > 0.0))
        return std::nullopt;
    // Clip the segment's parameter range against every face's half-plane (Cyrus-Beck).
    double lower = 0.0;
    double upper = 1.0;
    int entry = -1;
    for (int i = 0; i < p.count; ++i) {
        const double num = dot(p.normals[i], p.vertices[i] - o); // > 0: origin inside face i
        const double den = dot(p.normals[i], d);
        if (den == 0.0) {
            if (num < 0.0)
                return std::nullopt; // parallel and outside this face
        } else if (den < 0.0 && num < lower * den) {
            lower = num / den; // entering through face i later than before
            entry = i;
        } else if (den > 0.0 && num < upper * den) {
            upper = num / den; // leaving through face i earlier than before
        }
        if (upper < lower)
            return std::nullopt;
    }
    if (entry < 0)
        return std::nullopt; // origin inside
    RayHit hit;
    hit.fraction = lower;
    hit.point = o + lower * d;
    hit.normal = p.normals[entry];
    return hit;
}

} // namespace

/// \srs{T5} p in A, for one placed shape.
bool test_point(const Geometry& g, const Transform& xf, Vec2d p) {
    const Vec2d local = inv_transform_point(xf, p);
    return g.type == ShapeType::circle ? contains(g.circle, local) : contains(g.polygon, local);
}

std::optional<RayHit> ray_cast(const Geometry& g, const Transform& xf, Vec2d origin,
                               Vec2d translation) {
    const Vec2d o = inv_transform_point(xf, origin);
    const Vec2d d = inv_rotate(xf.q, translation);
    std::optional<RayHit> hit =
        g.type == ShapeType::circle ? cast(g.circle, o, d) : cast(g.polygon, o, d);
    if (hit) {
        hit->point = origin + hit->fraction * translation; // consistent with the fraction
        hit->normal = rotate(xf.q, hit->normal);
    }
    return hit;
}

} // namespace tamias2d
