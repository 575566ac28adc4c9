#include "tamias2d/collision/time_of_impact.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "tamias2d/collision/segment_distance.hpp"
#include "tamias2d/model/dd29_time_of_impact.hpp"
#include "tamias2d/model/dd34_shape_distance.hpp"

namespace tamias2d {

namespace {

/// \srs{DD34} The gap of two rounded cores whose closest points are `core_distance` apart.
double rounded_gap(double core_distance, double radius_a, double radius_b) {
    namespace u = tamias2d::units;
    return model::dd34::rounded_gap(u::Length::from_value(core_distance),
                                    u::Length::from_value(radius_a),
                                    u::Length::from_value(radius_b))
        .value();
}

/// A collider's polygon in the world frame (vertices and outward normals).
struct WorldPolygon {
    Vec2d v[max_polygon_vertices];
    Vec2d n[max_polygon_vertices];
    int count = 0;
};

WorldPolygon place(const Collider& k, const Transform& xf) {
    WorldPolygon p;
    p.count = k.count;
    for (int i = 0; i < k.count; ++i) {
        p.v[i] = transform_point(xf, k.vertex(i));
        p.n[i] = rotate(xf.q, k.normal(i));
    }
    return p;
}

/// The greatest separation of b's vertices from a face of a (negative: all behind every face).
double max_face_separation(const WorldPolygon& a, const WorldPolygon& b) {
    double best = -INFINITY;
    for (int i = 0; i < a.count; ++i) {
        double least = INFINITY;
        for (int j = 0; j < b.count; ++j)
            least = std::min(least, dot(a.n[i], b.v[j] - a.v[i]));
        best = std::max(best, least);
    }
    return best;
}

/// A circle (centre c, radius r) and a polygon: the normal from the circle to the polygon.
ShapeDistance circle_polygon(Vec2d c, double r, const WorldPolygon& p) {
    ShapeDistance out;
    double face = -INFINITY;
    for (int i = 0; i < p.count; ++i)
        face = std::max(face, dot(p.n[i], c - p.v[i]));
    if (face <= 0.0)
        return out; // the centre is inside
    double best = INFINITY;
    Vec2d closest{};
    for (int i = 0; i < p.count; ++i) {
        const SegmentDistance sd = segment_distance(p.v[i], p.v[(i + 1) % p.count], c, c);
        if (sd.distance_squared < best) {
            best = sd.distance_squared;
            closest = sd.closest1;
        }
    }
    const double d = rounded_gap(std::sqrt(best), r, 0.0);
    if (d > 0.0) {
        out.distance = d;
        out.normal = normalize(closest - c);
        out.point_a = c + r * out.normal;
        out.point_b = closest;
    }
    return out;
}

ShapeDistance polygon_polygon(const WorldPolygon& a, const WorldPolygon& b) {
    ShapeDistance out;
    // Convex polygons overlap unless a face of one separates them (separating axis theorem).
    if (max_face_separation(a, b) <= 0.0 && max_face_separation(b, a) <= 0.0)
        return out;
    double best = INFINITY;
    Vec2d from{}, to{};
    for (int i = 0; i < a.count; ++i) {
        for (int j = 0; j < b.count; ++j) {
            const SegmentDistance sd =
                segment_distance(a.v[i], a.v[(i + 1) % a.count], b.v[j], b.v[(j + 1) % b.count]);
            if (sd.distance_squared < best) {
                best = sd.distance_squared;
                from = sd.closest1;
                to = sd.closest2;
            }
        }
    }
    if (best > 0.0) {
        out.distance = std::sqrt(best);
        out.normal = normalize(to - from);
        out.point_a = from;
        out.point_b = to;
    }
    return out;
}

/// A segment kind or any shape with it, as cores grown by their radii: a point (a circle's
/// centre), a segment or a polygon, placed in the world.
struct WorldCore {
    WorldPolygon shape;
    double radius = 0.0;
};

WorldCore place_core(const Collider& k, const Transform& xf) {
    WorldCore c;
    if (k.type == ShapeType::circle) {
        c.shape.count = 1;
        c.shape.v[0] = transform_point(xf, k.center);
        c.radius = k.radius;
        return c;
    }
    c.shape = place(k, xf);
    c.radius = k.type == ShapeType::polygon ? 0.0 : k.radius;
    return c;
}

/// One of a core's edges: a point is its own edge, a segment has one, a polygon `count`.
int edge_count(const WorldPolygon& p) {
    return p.count <= 2 ? 1 : p.count;
}
Vec2d edge_end(const WorldPolygon& p, int i) {
    return p.count == 1 ? p.v[0] : p.v[(i + 1) % p.count];
}

/// Whether a vertex of `b` lies in polygon `a` (three or more vertices).
bool holds_vertex_of(const WorldPolygon& a, const WorldPolygon& b) {
    for (int j = 0; j < b.count; ++j) {
        double face = -INFINITY;
        for (int i = 0; i < a.count; ++i)
            face = std::max(face, dot(a.n[i], b.v[j] - a.v[i]));
        if (face <= 0.0)
            return true;
    }
    return false;
}

ShapeDistance rounded_distance(const WorldCore& a, const WorldCore& b) {
    ShapeDistance out;
    const WorldPolygon& pa = a.shape;
    const WorldPolygon& pb = b.shape;
    // Cores overlap when polygons do (separating axes), or one holds a vertex of the other;
    // otherwise (segments crossing included) their least edge distance decides.
    if (pa.count >= 3 && pb.count >= 3) {
        if (max_face_separation(pa, pb) <= 0.0 && max_face_separation(pb, pa) <= 0.0)
            return out;
    } else if ((pa.count >= 3 && holds_vertex_of(pa, pb)) ||
               (pb.count >= 3 && holds_vertex_of(pb, pa))) {
        return out;
    }
    double best = INFINITY;
    Vec2d from{}, to{};
    for (int i = 0; i < edge_count(pa); ++i) {
        for (int j = 0; j < edge_count(pb); ++j) {
            const SegmentDistance sd =
                segment_distance(pa.v[i], edge_end(pa, i), pb.v[j], edge_end(pb, j));
            if (sd.distance_squared < best) {
                best = sd.distance_squared;
                from = sd.closest1;
                to = sd.closest2;
            }
        }
    }
    const double d = rounded_gap(std::sqrt(best), a.radius, b.radius);
    if (d > 0.0) {
        out.distance = d;
        out.normal = normalize(to - from);
        out.point_a = from + a.radius * out.normal;
        out.point_b = to - b.radius * out.normal;
    }
    return out;
}

} // namespace

ShapeDistance shape_distance(const Collider& a, const Transform& xa, const Collider& b,
                             const Transform& xb) {
    if (a.is_segment_kind() || b.is_segment_kind())
        return rounded_distance(place_core(a, xa), place_core(b, xb));
    const bool ca = a.type == ShapeType::circle, cb = b.type == ShapeType::circle;
    if (ca && cb) {
        const Vec2d pa = transform_point(xa, a.center), pb = transform_point(xb, b.center);
        ShapeDistance out;
        const double d = rounded_gap(length(pb - pa), a.radius, b.radius);
        if (d > 0.0) {
            out.distance = d;
            out.normal = normalize(pb - pa);
            out.point_a = pa + a.radius * out.normal;
            out.point_b = pb - b.radius * out.normal;
        }
        return out;
    }
    if (ca)
        return circle_polygon(transform_point(xa, a.center), a.radius, place(b, xb));
    if (cb) {
        ShapeDistance out = circle_polygon(transform_point(xb, b.center), b.radius, place(a, xa));
        out.normal = -1.0 * out.normal;
        std::swap(out.point_a, out.point_b);
        return out;
    }
    return polygon_polygon(place(a, xa), place(b, xb));
}

double reach(const Collider& k, Vec2d pivot) {
    if (k.type == ShapeType::circle)
        return length(k.center - pivot) + k.radius;
    double r = 0.0;
    for (int i = 0; i < k.count; ++i)
        r = std::max(r, length(k.vertex(i) - pivot));
    return k.is_segment_kind() ? r + k.radius : r;
}

ToiResult time_of_impact(const Collider& moving, const Sweep& sweep, const Collider& fixed,
                         const Transform& fixed_xf, double target, double tolerance, double t_max,
                         int max_iterations) {
    namespace u = tamias2d::units;
    ToiResult out;
    const Vec2d dp = sweep.c1 - sweep.c0;
    const double turn = std::abs(sweep.a1 - sweep.a0);
    // The reach only counts when the body turns (DD29's bound adds turn x reach): a shape
    // cast, which never turns, skips its square roots.
    const double r = turn > 0.0 ? reach(moving, sweep.local_center) : 0.0;
    double t = 0.0;
    ShapeDistance sd = shape_distance(moving, sweep.at(0.0), fixed, fixed_xf);
    if (sd.distance <= target + tolerance) {
        out.state = ToiState::overlapped;
        out.t = 0.0;
        return out;
    }
    for (;;) {
        // Every point of the moving shape moves towards the fixed one, across the plane
        // normal to sd.normal, at most this far per unit t.
        const double bound =
            model::dd29::motion_bound(u::Length::from_value(dot(dp, sd.normal)),
                                      u::Angle::from_value(turn), u::Length::from_value(r))
                .value();
        if (bound <= 0.0) { // it never reaches the plane
            out.t = t_max;
            return out;
        }
        const double step =
            model::dd29::advance(u::Length::from_value(sd.distance), u::Length::from_value(target),
                                 u::Length::from_value(bound))
                .value();
        if (step >= t_max - t) {
            out.t = t_max;
            return out;
        }
        t += step;
        ++out.iterations;
        sd = shape_distance(moving, sweep.at(t), fixed, fixed_xf);
        if (sd.distance <= target + tolerance || out.iterations >= max_iterations) {
            out.state = ToiState::hit;
            out.t = t;
            return out;
        }
    }
}

} // namespace tamias2d
