// Independent geometry for the query tests: shapes as convex cores (a point, a segment or a
// convex polygon) grown by a radius, placed with the C library's cos and sin, with signed
// distances and gaps written from their definitions (point-to-segment distances, vertex-edge
// pairs, containment by cross products), sharing no code with the engine's collision routines.
#pragma once

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "tamias2d/shape_def.hpp"

namespace query_oracle {

using tamias2d::Vec2d;

inline double dot(Vec2d a, Vec2d b) {
    return a.x * b.x + a.y * b.y;
}
inline double cross(Vec2d a, Vec2d b) {
    return a.x * b.y - a.y * b.x;
}
inline double norm(Vec2d a) {
    return std::hypot(a.x, a.y);
}
inline Vec2d scaled(double s, Vec2d a) {
    return {s * a.x, s * a.y};
}

/// A placed shape: its core's vertices (world frame; a polygon counter-clockwise) and radius.
struct Core {
    std::vector<Vec2d> v;
    double r = 0.0;
    bool solid() const { return v.size() >= 3 || r > 0.0; }
};

inline Vec2d place(Vec2d p, Vec2d origin, double angle) {
    const double c = std::cos(angle), s = std::sin(angle);
    return {origin.x + c * p.x - s * p.y, origin.y + s * p.x + c * p.y};
}

inline Core core_of(const tamias2d::Geometry& g, Vec2d origin, double angle) {
    using tamias2d::ShapeType;
    Core c;
    switch (g.type) {
    case ShapeType::circle:
        c.v = {place(g.circle.center, origin, angle)};
        c.r = g.circle.radius;
        break;
    case ShapeType::polygon:
        for (int i = 0; i < g.polygon.count; ++i)
            c.v.push_back(place(g.polygon.vertices[std::size_t(i)], origin, angle));
        break;
    case ShapeType::capsule:
        c.v = {place(g.capsule.center1, origin, angle), place(g.capsule.center2, origin, angle)};
        c.r = g.capsule.radius;
        break;
    case ShapeType::segment:
        c.v = {place(g.segment.point1, origin, angle), place(g.segment.point2, origin, angle)};
        break;
    case ShapeType::chain_segment:
        c.v = {place(g.chain_segment.point1, origin, angle),
               place(g.chain_segment.point2, origin, angle)};
        break;
    }
    return c;
}

/// Distance from p to the segment a-b (the nearest point's parameter clamped to [0, 1]).
inline double point_segment(Vec2d p, Vec2d a, Vec2d b) {
    const Vec2d e = b - a;
    const double ee = dot(e, e);
    const double t = ee > 0.0 ? std::clamp(dot(p - a, e) / ee, 0.0, 1.0) : 0.0;
    return norm(p - (a + scaled(t, e)));
}

/// Whether p lies in the closed convex polygon (left of, or on, every edge).
inline bool in_polygon(const std::vector<Vec2d>& v, Vec2d p) {
    if (v.size() < 3)
        return false;
    for (std::size_t i = 0; i < v.size(); ++i)
        if (cross(v[(i + 1) % v.size()] - v[i], p - v[i]) < 0.0)
            return false;
    return true;
}

/// The core's edges: a point is one degenerate edge, a segment one, a polygon n.
inline std::size_t edges(const Core& c) {
    return c.v.size() <= 2 ? 1 : c.v.size();
}
inline Vec2d edge_end(const Core& c, std::size_t i) {
    return c.v.size() == 1 ? c.v[0] : c.v[(i + 1) % c.v.size()];
}

/// Distance from p to the core (0 inside a polygon core).
inline double core_distance(const Core& c, Vec2d p) {
    if (in_polygon(c.v, p))
        return 0.0;
    double d = INFINITY;
    for (std::size_t i = 0; i < edges(c); ++i)
        d = std::min(d, point_segment(p, c.v[i], edge_end(c, i)));
    return d;
}

/// Signed distance from p to the shape: negative inside (a polygon core's depth is its least
/// distance to a face line), the distance outside. A segment's is never negative.
inline double signed_distance(const Core& c, Vec2d p) {
    if (in_polygon(c.v, p)) {
        double depth = INFINITY;
        for (std::size_t i = 0; i < c.v.size(); ++i) {
            const Vec2d e = c.v[(i + 1) % c.v.size()] - c.v[i];
            depth = std::min(depth, cross(e, p - c.v[i]) / norm(e));
        }
        return -depth - c.r;
    }
    return core_distance(c, p) - c.r;
}

/// Whether segments a-b and c-d share a point (orientation signs; collinear overlaps too).
inline bool segments_meet(Vec2d a, Vec2d b, Vec2d c, Vec2d d) {
    const double o1 = cross(b - a, c - a), o2 = cross(b - a, d - a);
    const double o3 = cross(d - c, a - c), o4 = cross(d - c, b - c);
    if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0)))
        return true;
    return point_segment(c, a, b) == 0.0 || point_segment(d, a, b) == 0.0 ||
           point_segment(a, c, d) == 0.0 || point_segment(b, c, d) == 0.0;
}

/// The least distance between two cores: 0 when they share a point, else attained at a vertex
/// of one against an edge of the other (convex cores).
inline double cores_distance(const Core& a, const Core& b) {
    for (const Vec2d& p : b.v)
        if (in_polygon(a.v, p))
            return 0.0;
    for (const Vec2d& p : a.v)
        if (in_polygon(b.v, p))
            return 0.0;
    for (std::size_t i = 0; i < edges(a); ++i)
        for (std::size_t j = 0; j < edges(b); ++j)
            if (segments_meet(a.v[i], edge_end(a, i), b.v[j], edge_end(b, j)))
                return 0.0;
    double d = INFINITY;
    for (const Vec2d& p : a.v)
        d = std::min(d, core_distance(b, p));
    for (const Vec2d& p : b.v)
        d = std::min(d, core_distance(a, p));
    return d;
}

/// The gap between two shapes: the cores' distance less both radii (<= 0: they share a point).
inline double gap(const Core& a, const Core& b) {
    return cores_distance(a, b) - a.r - b.r;
}

/// The core's centre: a polygon's area centroid (its triangles' centroids weighted by their
/// areas), a segment's midpoint, a point itself.
inline Vec2d centroid(const Core& c) {
    if (c.v.size() < 3) {
        Vec2d m{};
        for (const Vec2d& p : c.v)
            m = m + scaled(1.0 / double(c.v.size()), p);
        return m;
    }
    double area = 0.0;
    Vec2d m{};
    for (std::size_t i = 1; i + 1 < c.v.size(); ++i) {
        const double a = 0.5 * cross(c.v[i] - c.v[0], c.v[i + 1] - c.v[0]);
        area += a;
        m = m + scaled(a / 3.0, c.v[0] + c.v[i] + c.v[i + 1]);
    }
    return scaled(1.0 / area, m);
}

inline Core moved(Core c, Vec2d by) {
    for (Vec2d& p : c.v)
        p = p + by;
    return c;
}

/// The minimum of a convex function on [lo, hi] (golden-section search), as (t, f(t)).
template <class F> std::pair<double, double> convex_min(F&& f, double lo, double hi) {
    const double g = 0.5 * (std::sqrt(5.0) - 1.0);
    double a = lo, b = hi;
    double x1 = b - g * (b - a), x2 = a + g * (b - a);
    double f1 = f(x1), f2 = f(x2);
    for (int i = 0; i < 80 && b - a > 1e-15 * (1.0 + std::abs(a)); ++i) {
        if (f1 <= f2) {
            b = x2;
            x2 = x1;
            f2 = f1;
            x1 = b - g * (b - a);
            f1 = f(x1);
        } else {
            a = x1;
            x1 = x2;
            f1 = f2;
            x2 = a + g * (b - a);
            f2 = f(x2);
        }
    }
    double t = 0.5 * (a + b), ft = f(t);
    for (double e : {lo, hi}) {
        const double fe = f(e);
        if (fe < ft) {
            t = e;
            ft = fe;
        }
    }
    return {t, ft};
}

/// The root of f on [lo, hi] where f(lo) > 0 >= f(hi) (bisection to the last bit).
template <class F> double first_root(F&& f, double lo, double hi) {
    for (int i = 0; i < 200 && hi - lo > 0.0; ++i) {
        const double m = 0.5 * (lo + hi);
        if (m <= lo || m >= hi)
            break;
        (f(m) > 0.0 ? lo : hi) = m;
    }
    return hi;
}

/// Kinds the generators make.
enum class Kind { circle, polygon, capsule, segment, chain };
inline const char* name(Kind k) {
    switch (k) {
    case Kind::circle:
        return "circle";
    case Kind::polygon:
        return "polygon";
    case Kind::capsule:
        return "capsule";
    case Kind::segment:
        return "segment";
    case Kind::chain:
        return "chain";
    }
    return "?";
}
inline constexpr Kind all_kinds[] = {Kind::circle, Kind::polygon, Kind::capsule, Kind::segment,
                                     Kind::chain};

/// A shape of the kind in its body frame, about 0.2 to 2 m across.
inline tamias2d::Geometry random_geometry(Kind k, std::mt19937_64& rng) {
    std::uniform_real_distribution<double> size(0.1, 1.0), off(-0.5, 0.5),
        ang(0.0, 6.283185307179586);
    switch (k) {
    case Kind::circle:
        return tamias2d::circle_shape(size(rng), {}, {off(rng), off(rng)}).geometry;
    case Kind::polygon:
        for (;;) {
            const int n = 3 + int(rng() % 6);
            std::vector<Vec2d> pts;
            const double rx = size(rng), ry = size(rng);
            for (int i = 0; i < n; ++i) {
                const double a = ang(rng);
                pts.push_back({rx * std::cos(a), ry * std::sin(a)});
            }
            try {
                return tamias2d::polygon_shape(pts).geometry;
            } catch (const std::exception&) {
                // a sliver hull the DCX_shape rule refuses: draw again
            }
        }
    case Kind::capsule: {
        const double a = ang(rng), h = size(rng);
        return tamias2d::capsule_shape({-h * std::cos(a), -h * std::sin(a)},
                                       {h * std::cos(a), h * std::sin(a)}, 0.5 * size(rng))
            .geometry;
    }
    case Kind::segment: {
        const double a = ang(rng), h = size(rng);
        return tamias2d::segment_shape({-h * std::cos(a), -h * std::sin(a)},
                                       {h * std::cos(a), h * std::sin(a)})
            .geometry;
    }
    case Kind::chain: {
        const double a = ang(rng), h = size(rng);
        const std::vector<Vec2d> pts{{-3 * h * std::cos(a), -3 * h * std::sin(a)},
                                     {-h * std::cos(a), -h * std::sin(a)},
                                     {h * std::cos(a), h * std::sin(a)},
                                     {3 * h * std::cos(a + 0.3), 3 * h * std::sin(a + 0.3)}};
        return tamias2d::chain_shapes(pts, false)[1].geometry;
    }
    }
    return {};
}

} // namespace query_oracle
