// Independent brute-force oracles for the collision tests: exact-arithmetic-free but
// algorithmically naive (all vertex-edge pairs), sharing no code with the library.
#pragma once

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "tamias2d/geometry/shape_factory.hpp"
#include "tamias2d/math/vec2d.hpp"
#include "tamias2d/model/t5_collision_detection.hpp"

namespace oracle {

using tamias2d::Circle;
using tamias2d::Geometry;
using tamias2d::Polygon;
using tamias2d::ShapeType;
using tamias2d::Transform;
using tamias2d::Vec2d;
using tamias2d::units::Length;
using tamias2d::units::Vec2;

inline double cross(Vec2d a, Vec2d b) {
    return a.x * b.y - a.y * b.x;
}
inline double dotp(Vec2d a, Vec2d b) {
    return a.x * b.x + a.y * b.y;
}
inline double len(Vec2d a) {
    return std::sqrt(dotp(a, a));
}

inline std::vector<Vec2d> world_vertices(const Polygon& p, const Transform& xf) {
    std::vector<Vec2d> out;
    for (int i = 0; i < p.count; ++i) {
        const Vec2d v = p.vertices[i];
        out.push_back({xf.q.c * v.x - xf.q.s * v.y + xf.p.x, xf.q.s * v.x + xf.q.c * v.y + xf.p.y});
    }
    return out;
}

inline Vec2d world_point(const Transform& xf, Vec2d v) {
    return {xf.q.c * v.x - xf.q.s * v.y + xf.p.x, xf.q.s * v.x + xf.q.c * v.y + xf.p.y};
}

inline double point_segment_distance(Vec2d p, Vec2d a, Vec2d b) {
    const Vec2d ab{b.x - a.x, b.y - a.y};
    const Vec2d ap{p.x - a.x, p.y - a.y};
    const double t = std::clamp(dotp(ap, ab) / dotp(ab, ab), 0.0, 1.0);
    return len({ap.x - t * ab.x, ap.y - t * ab.y});
}

/// Closed CCW polygon contains p (brute force half-plane test).
inline bool inside(const std::vector<Vec2d>& poly, Vec2d p) {
    for (std::size_t i = 0; i < poly.size(); ++i) {
        const Vec2d a = poly[i];
        const Vec2d b = poly[(i + 1) % poly.size()];
        if (cross({b.x - a.x, b.y - a.y}, {p.x - a.x, p.y - a.y}) < 0.0)
            return false;
    }
    return true;
}

inline bool segments_cross(Vec2d a, Vec2d b, Vec2d c, Vec2d d) {
    const double d1 = cross({b.x - a.x, b.y - a.y}, {c.x - a.x, c.y - a.y});
    const double d2 = cross({b.x - a.x, b.y - a.y}, {d.x - a.x, d.y - a.y});
    const double d3 = cross({d.x - c.x, d.y - c.y}, {a.x - c.x, a.y - c.y});
    const double d4 = cross({d.x - c.x, d.y - c.y}, {b.x - c.x, b.y - c.y});
    return ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0));
}

/// Distance between two convex polygons (0 when they share a point): all vertex-edge pairs.
inline double distance(const std::vector<Vec2d>& A, const std::vector<Vec2d>& B) {
    for (const Vec2d& v : A)
        if (inside(B, v))
            return 0.0;
    for (const Vec2d& v : B)
        if (inside(A, v))
            return 0.0;
    double d = INFINITY;
    for (std::size_t i = 0; i < A.size(); ++i)
        for (std::size_t j = 0; j < B.size(); ++j) {
            const Vec2d a0 = A[i], a1 = A[(i + 1) % A.size()];
            const Vec2d b0 = B[j], b1 = B[(j + 1) % B.size()];
            if (segments_cross(a0, a1, b0, b1))
                return 0.0;
            d = std::min(
                {d, point_segment_distance(a0, b0, b1), point_segment_distance(b0, a0, a1)});
        }
    return d;
}

/// Distance between two placed shapes (0 when they share a point).
inline double distance(const Geometry& a, const Transform& xa, const Geometry& b,
                       const Transform& xb) {
    if (a.type == ShapeType::circle && b.type == ShapeType::circle) {
        const Vec2d ca = world_point(xa, a.circle.center), cb = world_point(xb, b.circle.center);
        return std::max(0.0, len({cb.x - ca.x, cb.y - ca.y}) - a.circle.radius - b.circle.radius);
    }
    if (a.type == ShapeType::circle)
        return distance(b, xb, a, xa);
    const std::vector<Vec2d> A = world_vertices(a.polygon, xa);
    if (b.type == ShapeType::polygon)
        return distance(A, world_vertices(b.polygon, xb));
    const Vec2d c = world_point(xb, b.circle.center);
    if (inside(A, c))
        return 0.0;
    double d = INFINITY;
    for (std::size_t i = 0; i < A.size(); ++i)
        d = std::min(d, point_segment_distance(c, A[i], A[(i + 1) % A.size()]));
    return std::max(0.0, d - b.circle.radius);
}

/// The polygon's edges pushed out by delta (exact parallel offset, mitred corners), in
/// Boost.Units lengths for the T5 model.
inline std::vector<Vec2<Length>> grown(const std::vector<Vec2d>& poly, double delta) {
    const std::size_t n = poly.size();
    std::vector<Vec2d> normals(n);
    for (std::size_t i = 0; i < n; ++i) {
        const Vec2d e{poly[(i + 1) % n].x - poly[i].x, poly[(i + 1) % n].y - poly[i].y};
        normals[i] = {e.y / len(e), -e.x / len(e)};
    }
    std::vector<Vec2<Length>> out;
    for (std::size_t i = 0; i < n; ++i) {
        const Vec2d n0 = normals[(i + n - 1) % n], n1 = normals[i];
        const double k = delta / (1.0 + dotp(n0, n1));
        out.push_back(tamias2d::units::vec_from_values<Length>(poly[i].x + k * (n0.x + n1.x),
                                                               poly[i].y + k * (n0.y + n1.y)));
    }
    return out;
}

inline Vec2<Length> metres(Vec2d v) {
    return tamias2d::units::vec_from_values<Length>(v.x, v.y);
}

/// T5 (model::t5::collided_at) for p and the two shapes each grown by delta.
inline bool collided_at_within(const Geometry& a, const Transform& xa, const Geometry& b,
                               const Transform& xb, Vec2d p, double delta) {
    namespace t5 = tamias2d::model::t5;
    auto as_disc = [&](const Geometry& g, const Transform& x) {
        return t5::Disc{metres(world_point(x, g.circle.center)),
                        Length::from_value(g.circle.radius + delta)};
    };
    if (a.type == ShapeType::circle && b.type == ShapeType::circle)
        return t5::collided_at(as_disc(a, xa), as_disc(b, xb), metres(p));
    if (a.type == ShapeType::circle)
        return collided_at_within(b, xb, a, xa, p, delta);
    const auto A = grown(world_vertices(a.polygon, xa), delta);
    const t5::ConvexPolygon pa(A);
    if (b.type == ShapeType::circle)
        return t5::collided_at(pa, as_disc(b, xb), metres(p));
    const auto B = grown(world_vertices(b.polygon, xb), delta);
    return t5::collided_at(pa, t5::ConvexPolygon(B), metres(p));
}

/// A random shape of size ~0.2..1.5 m: box, hull of a point cloud, or circle.
inline Geometry random_shape(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> size(0.2, 1.5);
    std::uniform_int_distribution<int> kind(0, 2);
    switch (kind(rng)) {
    case 0:
        return tamias2d::to_geometry(tamias2d::make_box(size(rng) / 2, size(rng) / 2));
    case 1: {
        std::uniform_real_distribution<double> u(-0.7, 0.7);
        for (;;) {
            std::vector<Vec2d> pts(6);
            for (Vec2d& v : pts)
                v = {u(rng), u(rng)};
            try {
                return tamias2d::to_geometry(tamias2d::make_polygon(pts));
            } catch (const std::exception&) {
            }
        }
    }
    default:
        return tamias2d::to_geometry(tamias2d::make_circle(size(rng) / 2));
    }
}

/// A shape as a core (one point, the two ends of a segment, or a polygon's vertices) and the
/// radius every surface point lies at from it: circles, capsules, segments, polygons alike.
struct Rounded {
    std::vector<Vec2d> core;
    double radius = 0.0;
};

inline Rounded rounded(const Geometry& g, const Transform& xf) {
    switch (g.type) {
    case ShapeType::circle:
        return {{world_point(xf, g.circle.center)}, g.circle.radius};
    case ShapeType::polygon:
        return {world_vertices(g.polygon, xf), 0.0};
    case ShapeType::capsule:
        return {{world_point(xf, g.capsule.center1), world_point(xf, g.capsule.center2)},
                g.capsule.radius};
    case ShapeType::segment:
        return {{world_point(xf, g.segment.point1), world_point(xf, g.segment.point2)}, 0.0};
    case ShapeType::chain_segment:
        return {{world_point(xf, g.chain_segment.point1), world_point(xf, g.chain_segment.point2)},
                0.0};
    }
    return {};
}

/// Distance between two cores (0 when they share a point): a polygon holding a vertex of the
/// other, crossing edges, else the least vertex-to-edge distance (a point is its own edge).
inline double core_distance(const std::vector<Vec2d>& A, const std::vector<Vec2d>& B) {
    if (A.size() >= 3)
        for (const Vec2d& v : B)
            if (inside(A, v))
                return 0.0;
    if (B.size() >= 3)
        for (const Vec2d& v : A)
            if (inside(B, v))
                return 0.0;
    auto edges = [](const std::vector<Vec2d>& P) {
        return P.size() <= 2 ? std::size_t(1) : P.size();
    };
    double d = INFINITY;
    for (std::size_t i = 0; i < edges(A); ++i)
        for (std::size_t j = 0; j < edges(B); ++j) {
            const Vec2d a0 = A[i], a1 = A[(i + 1) % A.size()];
            const Vec2d b0 = B[j], b1 = B[(j + 1) % B.size()];
            if (segments_cross(a0, a1, b0, b1))
                return 0.0;
            // A point's edge has no direction: the distance to it is to its one point.
            auto to_edge = [](Vec2d p, Vec2d e0, Vec2d e1) {
                return e0.x == e1.x && e0.y == e1.y ? len({p.x - e0.x, p.y - e0.y})
                                                    : point_segment_distance(p, e0, e1);
            };
            d = std::min({d, to_edge(a0, b0, b1), to_edge(a1, b0, b1), to_edge(b0, a0, a1),
                          to_edge(b1, a0, a1)});
        }
    return d;
}

/// Distance between two placed shapes of any kind (0 when they overlap).
inline double rounded_distance(const Geometry& a, const Transform& xa, const Geometry& b,
                               const Transform& xb) {
    const Rounded ra = rounded(a, xa), rb = rounded(b, xb);
    return std::max(0.0, core_distance(ra.core, rb.core) - ra.radius - rb.radius);
}

/// p lies in the shape grown by delta.
inline bool within(const Geometry& g, const Transform& xf, Vec2d p, double delta) {
    const Rounded r = rounded(g, xf);
    return core_distance(r.core, {p}) <= r.radius + delta;
}

/// A random capsule (radius 0.05-0.5 m) or segment, its core up to ~1.7 m long.
inline Geometry random_rounded_shape(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(-0.6, 0.6);
    std::uniform_real_distribution<double> radius(0.05, 0.5);
    Vec2d a{u(rng), u(rng)}, b{u(rng), u(rng)};
    if (len({b.x - a.x, b.y - a.y}) < 0.1)
        b = {a.x + 0.3, a.y};
    if (std::uniform_int_distribution<int>(0, 2)(rng) == 0)
        return tamias2d::to_geometry(tamias2d::make_segment(a, b));
    return tamias2d::to_geometry(tamias2d::make_capsule(a, b, radius(rng)));
}

inline Transform random_transform(std::mt19937_64& rng, double extent) {
    std::uniform_real_distribution<double> u(-extent, extent);
    std::uniform_real_distribution<double> angle(-3.14159, 3.14159);
    return {{u(rng), u(rng)}, tamias2d::Rot::from_angle(angle(rng))};
}

} // namespace oracle
