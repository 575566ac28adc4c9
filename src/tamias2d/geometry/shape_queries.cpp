#include "tamias2d/geometry/shape_queries.hpp"

#include <algorithm>
#include <cmath>

#include "tamias2d/model/dd33_ray_intersection.hpp"
#include "tamias2d/model/t5_collision_detection.hpp"

namespace tamias2d {
namespace {

bool contains(const Circle& c, Vec2d local) {
    return model::t5::contains(c.center, c.radius, local);
}

bool contains(const Polygon& p, Vec2d local) {
    return model::t5::contains(p.vertices.data(), p.normals.data(), p.count, local);
}

namespace u = tamias2d::units;

/// \srs{DD33} The face crossing t = num / den on plain SI values.
double plane_crossing(double num, double den) {
    return model::dd33::plane_crossing(u::Length::from_value(num), u::Length::from_value(den))
        .value();
}

/// The point of segment a -> b nearest p.
Vec2d nearest_on_segment(Vec2d a, Vec2d b, Vec2d p) {
    const Vec2d e = b - a;
    const double t = std::clamp(dot(p - a, e) / dot(e, e), 0.0, 1.0);
    return a + t * e;
}

/// T5's disc containment about the core's nearest point.
bool contains(const Capsule& c, Vec2d local) {
    return model::t5::contains(nearest_on_segment(c.center1, c.center2, local), c.radius, local);
}

/// \srs{DD33} Ray in the shape's body frame.
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
    const double t =
        model::dd33::circle_entry(u::Length::from_value(t_mid), u::Area::from_value(h2)).value();
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
            lower = plane_crossing(num, den); // entering through face i later than before
            entry = i;
        } else if (den > 0.0 && num < upper * den) {
            upper = plane_crossing(num, den); // leaving through face i earlier than before
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

/// A segment a -> b, hit from the side `n` faces, or either side when two_sided.
std::optional<RayHit> cast_segment(Vec2d a, Vec2d b, Vec2d o, Vec2d d, bool two_sided) {
    Vec2d n = normalize(right_perp(b - a));
    const double den = dot(n, d);
    if (den == 0.0 || !(dot(d, d) > 0.0))
        return std::nullopt; // parallel: a zero-thickness segment is never entered
    if (den > 0.0) {
        if (!two_sided)
            return std::nullopt; // from behind a one-sided segment
        n = -n;
    }
    const double t = plane_crossing(dot(n, a - o), dot(n, d));
    if (!(t >= 0.0 && t <= 1.0))
        return std::nullopt;
    const Vec2d p = o + t * d;
    const Vec2d e = b - a;
    const double u = dot(p - a, e);
    if (!(u >= 0.0 && u <= dot(e, e)))
        return std::nullopt;
    return RayHit{p, n, t};
}

/// The side faces (offset by the radius) and the two end discs; the earliest entry wins.
std::optional<RayHit> cast(const Capsule& c, Vec2d o, Vec2d d) {
    if (contains(c, o))
        return std::nullopt;
    std::optional<RayHit> best;
    auto keep = [&](std::optional<RayHit> h) {
        if (h && (!best || h->fraction < best->fraction))
            best = h;
    };
    const Vec2d n = normalize(right_perp(c.center2 - c.center1));
    for (double side : {1.0, -1.0}) {
        const Vec2d off = (side * c.radius) * n;
        const Vec2d a = side > 0.0 ? c.center1 + off : c.center2 + off;
        const Vec2d b = side > 0.0 ? c.center2 + off : c.center1 + off;
        keep(cast_segment(a, b, o, d, false));
    }
    keep(cast(Circle{c.center1, c.radius}, o, d));
    keep(cast(Circle{c.center2, c.radius}, o, d));
    return best;
}

} // namespace

/// \srs{T5} p in A, for one placed shape. Segments and chains have no interior.
bool test_point(const Geometry& g, const Transform& xf, Vec2d p) {
    const Vec2d local = inv_transform_point(xf, p);
    switch (g.type) {
    case ShapeType::circle:
        return contains(g.circle, local);
    case ShapeType::polygon:
        return contains(g.polygon, local);
    case ShapeType::capsule:
        return contains(g.capsule, local);
    case ShapeType::segment:
    case ShapeType::chain_segment:
        break;
    }
    return false;
}

/// \srs{DD33} The first entry of the segment into one placed shape.
std::optional<RayHit> ray_cast(const Geometry& g, const Transform& xf, Vec2d origin,
                               Vec2d translation) {
    const Vec2d o = inv_transform_point(xf, origin);
    const Vec2d d = inv_rotate(xf.q, translation);
    std::optional<RayHit> hit;
    switch (g.type) {
    case ShapeType::circle:
        hit = cast(g.circle, o, d);
        break;
    case ShapeType::polygon:
        hit = cast(g.polygon, o, d);
        break;
    case ShapeType::capsule:
        hit = cast(g.capsule, o, d);
        break;
    case ShapeType::segment:
        hit = cast_segment(g.segment.point1, g.segment.point2, o, d, true);
        break;
    case ShapeType::chain_segment:
        hit = cast_segment(g.chain_segment.point1, g.chain_segment.point2, o, d, false);
        break;
    }
    if (hit) {
        hit->point = origin + hit->fraction * translation; // consistent with the fraction
        hit->normal = rotate(xf.q, hit->normal);
    }
    return hit;
}

} // namespace tamias2d
