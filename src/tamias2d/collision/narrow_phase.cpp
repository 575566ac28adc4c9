// Narrow phase (T5): contact manifolds by the separating axis test and reference-face clipping.
// See docs/collision.md for the conventions (A4 normal from A into B, midway points, ids).
#include "tamias2d/collision/narrow_phase.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "tamias2d/collision/segment_distance.hpp"

namespace tamias2d {
namespace {

constexpr std::uint8_t vertex_feature = 0;
constexpr std::uint8_t face_feature = 1;

/// Reference-face hysteresis and the "separated" threshold, as a fraction of the smaller
/// polygon's radius: a resting box's SAT separations for its face and its support's face
/// differ by ~size x tilt, so a relative band keeps the choice steady (no jitter, warm
/// starting keeps its ids) while staying far below any visible offset.
constexpr double relative_tolerance = 1e-3;

/// conj(a) * b: the rotation of frame b seen from frame a.
Rot inv_mul(Rot a, Rot b) {
    return {a.c * b.c + a.s * b.s, a.c * b.s - a.s * b.c};
}

/// Fills a manifold point from a point in A's (shifted) local frame.
void set_point(ManifoldPoint& mp, Vec2d local, double separation, FeatureId id,
               const Transform& frame, const CollideInput& in) {
    // Anchors first, from the frame's offset to the centre of mass (exactly zero for a lone
    // shape centred on its body's centre), so contacts symmetric in the frame keep exactly
    // symmetric lever arms; the world point is derived from them.
    mp.anchor_a = rotate(frame.q, local) + (frame.p - in.center_a);
    mp.anchor_b = mp.anchor_a + (in.center_a - in.center_b);
    mp.point = in.center_a + mp.anchor_a;
    mp.separation = separation;
    mp.id = id;
}

/// A polygon's vertices and normals in a common frame. Plain arrays, filled before use: Vec2d
/// zero-initialises, and clearing two of these cost ~10 % of a box-box collision.
struct Local {
    double vx[max_polygon_vertices], vy[max_polygon_vertices];
    double nx[max_polygon_vertices], ny[max_polygon_vertices];
    int count = 0;
    Vec2d v(int i) const { return {vx[i], vy[i]}; }
    Vec2d n(int i) const { return {nx[i], ny[i]}; }
    void set(int i, Vec2d vertex, Vec2d normal) {
        vx[i] = vertex.x;
        vy[i] = vertex.y;
        nx[i] = normal.x;
        ny[i] = normal.y;
    }
};

/// Greatest separation of `other`'s vertices along one of `ref`'s face normals (SAT). Stops
/// as soon as a face separates by `stop` or more (no contact), and abandons a face once it
/// cannot beat the best so far: the common cases cost a fraction of the n x m products.
double max_separation(const Local& ref, const Local& other, double stop, int& edge) {
    double best = -std::numeric_limits<double>::infinity();
    edge = 0;
    for (int i = 0; i < ref.count; ++i) {
        const Vec2d n = ref.n(i);
        const double offset = dot(n, ref.v(i));
        const double beat = best + offset; // this face loses once its minimum drops to here
        double s = std::numeric_limits<double>::infinity();
        for (int j = 0; j < other.count && s > beat; ++j)
            s = std::min(s, dot(n, other.v(j)));
        s -= offset;
        if (s > best) {
            best = s;
            edge = i;
            if (!(best < stop))
                return best;
        }
    }
    return best;
}

/// Largest squared vertex distance from the centroid: the polygon's size (rotation-free).
double radius_squared(const Polygon& p) {
    double r2 = 0.0;
    for (int i = 0; i < p.count; ++i)
        r2 = std::max(r2, dot(p.vertices[i] - p.centroid, p.vertices[i] - p.centroid));
    return r2;
}

FeatureId make_id(bool flip, int ref_index, std::uint8_t ref_type, int inc_index,
                  std::uint8_t inc_type) {
    FeatureId id;
    if (!flip) {
        id.index_a = static_cast<std::uint8_t>(ref_index);
        id.type_a = ref_type;
        id.index_b = static_cast<std::uint8_t>(inc_index);
        id.type_b = inc_type;
    } else {
        id.index_a = static_cast<std::uint8_t>(inc_index);
        id.type_a = inc_type;
        id.index_b = static_cast<std::uint8_t>(ref_index);
        id.type_b = ref_type;
    }
    return id;
}

} // namespace

/// \srs{T5} circles collide when their centres are closer than the sum of the radii.
Manifold collide_circles(const Circle& a, const Circle& b, const CollideInput& in) {
    Manifold m;
    const Vec2d ca = transform_point(in.xf_a, a.center);
    const Vec2d cb = transform_point(in.xf_b, b.center);
    const Vec2d d = cb - ca;
    const double dist = length(d);
    const double separation = dist - a.radius - b.radius;
    if (!(separation < in.margin))
        return m;
    // Concentric circles have no preferred direction: +x is a deterministic choice.
    const Vec2d n = dist > 0.0 ? Vec2d{d.x / dist, d.y / dist} : Vec2d{1.0, 0.0};
    const Vec2d on_a = ca + a.radius * n;
    const Vec2d on_b = cb - b.radius * n;
    m.normal = n;
    m.count = 1;
    ManifoldPoint& mp = m.points[0];
    mp.point = 0.5 * (on_a + on_b);
    mp.anchor_a = mp.point - in.center_a;
    mp.anchor_b = mp.point - in.center_b;
    mp.separation = separation;
    mp.id = FeatureId{};
    return m;
}

/// \srs{T5} polygon and circle: the nearest face or vertex of the polygon.
Manifold collide_polygon_circle(const Polygon& a, const Circle& b, const CollideInput& in) {
    Manifold m;
    // Work in A's body frame: the circle centre is one transformed point.
    const Vec2d c = inv_transform_point(in.xf_a, transform_point(in.xf_b, b.center));
    const double r = b.radius;

    int edge = 0;
    double sep = -std::numeric_limits<double>::infinity();
    for (int i = 0; i < a.count; ++i) {
        const double s = dot(a.normals[i], c - a.vertices[i]);
        if (s > sep) {
            sep = s;
            edge = i;
        }
    }
    if (!(sep - r < in.margin))
        return m;

    const Vec2d v1 = a.vertices[edge];
    const Vec2d v2 = a.vertices[(edge + 1) % a.count];
    Vec2d n = a.normals[edge];
    Vec2d on_a;
    double separation;
    FeatureId id{static_cast<std::uint8_t>(edge), face_feature, 0, vertex_feature};
    const bool behind_v1 = sep > 0.0 && dot(c - v1, v2 - v1) < 0.0;
    const bool beyond_v2 = sep > 0.0 && dot(c - v2, v1 - v2) < 0.0;
    if (behind_v1 || beyond_v2) {
        // Vertex region: the closest point of A is the vertex itself.
        const int vi = behind_v1 ? edge : (edge + 1) % a.count;
        on_a = a.vertices[vi];
        const Vec2d d = c - on_a;
        const double dist = length(d);
        separation = dist - r;
        if (!(separation < in.margin))
            return m;
        n = Vec2d{d.x / dist, d.y / dist}; // dist >= sep > 0
        id = {static_cast<std::uint8_t>(vi), vertex_feature, 0, vertex_feature};
    } else {
        // Face region, or the centre inside A: the nearest face's plane.
        on_a = c - sep * n;
        separation = sep - r;
    }
    const Vec2d on_b = c - r * n;
    m.normal = rotate(in.xf_a.q, n);
    m.count = 1;
    set_point(m.points[0], 0.5 * (on_a + on_b), separation, id, in.xf_a, in);
    return m;
}

namespace {

/// No contact: count 0 and the zero normal, as a default manifold has.
void set_empty(Manifold& m) {
    m.normal = {};
    m.count = 0;
}

/// \srs{T5} polygons by the separating axis test; \srs{A5} vertex-edge gives one point,
/// \srs{LC1} edge-edge two. Writes the normal and the count on every path, and the points in
/// use; the slots past the count are the caller's (see collide's in-place form).
void collide_polygons_into(const Polygon& a, const Polygon& b, const CollideInput& in, Manifold& m,
                           SeparationHint* hint) {
    // Work in A's frame shifted to A's centroid: B's vertices are transformed once, and the
    // numbers stay small for shapes far from the world origin.
    const Transform frame{transform_point(in.xf_a, a.centroid), in.xf_a.q};
    const Rot q = inv_mul(in.xf_a.q, in.xf_b.q);
    const Vec2d p = inv_transform_point(frame, in.xf_b.p);
    if (hint != nullptr && hint->face >= 0) {
        // The hinted face's separation, computed exactly as max_separation computes it below
        // (same expressions, same order): if it still reaches the margin, so would the full
        // test, and the answer is the same empty manifold.
        const int i = hint->face;
        double s = std::numeric_limits<double>::infinity();
        double offset = 0.0;
        if (!hint->on_b && i < a.count) {
            const Vec2d n = a.normals[i];
            offset = dot(n, a.vertices[i] - a.centroid);
            for (int j = 0; j < b.count; ++j)
                s = std::min(s, dot(n, rotate(q, b.vertices[j]) + p));
        } else if (hint->on_b && i < b.count) {
            const Vec2d n = rotate(q, b.normals[i]);
            offset = dot(n, rotate(q, b.vertices[i]) + p);
            for (int j = 0; j < a.count; ++j)
                s = std::min(s, dot(n, a.vertices[j] - a.centroid));
        }
        s -= offset;
        if (!(s < in.margin))
            return set_empty(m);
        hint->face = -1;
    }
    Local la;
    Local lb;
    la.count = a.count;
    lb.count = b.count;
    for (int i = 0; i < a.count; ++i)
        la.set(i, a.vertices[i] - a.centroid, a.normals[i]);
    for (int i = 0; i < b.count; ++i)
        lb.set(i, rotate(q, b.vertices[i]) + p, rotate(q, b.normals[i]));

    int edge_a = 0;
    const double sep_a = max_separation(la, lb, in.margin, edge_a);
    if (!(sep_a < in.margin)) {
        if (hint != nullptr)
            *hint = {static_cast<std::int8_t>(edge_a), false};
        return set_empty(m);
    }
    int edge_b = 0;
    const double sep_b = max_separation(lb, la, in.margin, edge_b);
    if (!(sep_b < in.margin)) {
        if (hint != nullptr)
            *hint = {static_cast<std::int8_t>(edge_b), true};
        return set_empty(m);
    }

    // The tolerance needs both polygons' sizes; the common resting case (A's face best,
    // penetrating) never asks for it.
    const double tol =
        sep_b > sep_a || std::max(sep_a, sep_b) > 0.0
            ? relative_tolerance * std::sqrt(std::min(radius_squared(a), radius_squared(b)))
            : 0.0;

    // Reference face: A's unless B's separates clearly more (hysteresis against flipping).
    const bool flip = sep_b > sep_a + tol;
    const Local& ref = flip ? lb : la;
    const Local& inc = flip ? la : lb;
    const int i11 = flip ? edge_b : edge_a;
    const int i12 = (i11 + 1) % ref.count;
    const Vec2d n = ref.n(i11);

    // Incident edge: the face of the other polygon most anti-parallel to the reference normal.
    int i21 = 0;
    double min_dot = std::numeric_limits<double>::infinity();
    for (int i = 0; i < inc.count; ++i) {
        const double d = dot(n, inc.n(i));
        if (d < min_dot) {
            min_dot = d;
            i21 = i;
        }
    }
    const int i22 = (i21 + 1) % inc.count;
    const Vec2d v11 = ref.v(i11);
    const Vec2d v12 = ref.v(i12);
    const Vec2d v21 = inc.v(i21);
    const Vec2d v22 = inc.v(i22);

    if (std::max(sep_a, sep_b) > tol) {
        // Apart: if the closest features are two vertices, the face normal would understate
        // the gap; report one point along the true vertex-vertex direction instead. Two
        // parallel faces that overlap along the tangent also end at vertices (the closest pair
        // is not unique) but their gap is the face separation: they are a face contact, and
        // clipping below gives both points (finding O3, docs/verification.md).
        const SegmentDistance sd = segment_distance(v11, v12, v21, v22);
        const bool ref_vertex = sd.fraction1 == 0.0 || sd.fraction1 == 1.0;
        const bool inc_vertex = sd.fraction2 == 0.0 || sd.fraction2 == 1.0;
        const double dist = std::sqrt(sd.distance_squared);
        if (ref_vertex && inc_vertex && dist > std::max(sep_a, sep_b) + tol) {
            if (!(dist < in.margin))
                return set_empty(m);
            const Vec2d g = (sd.closest2 - sd.closest1) / dist; // reference -> incident
            const int ri = sd.fraction1 == 0.0 ? i11 : i12;
            const int ii = sd.fraction2 == 0.0 ? i21 : i22;
            m.normal = rotate(frame.q, flip ? -g : g);
            m.count = 1;
            set_point(m.points[0], 0.5 * (sd.closest1 + sd.closest2), dist,
                      make_id(flip, ri, vertex_feature, ii, vertex_feature), frame, in);
            return;
        }
    }

    // Clip the incident edge to the side planes of the reference face. The tangent runs
    // along the reference edge (CCW); the incident edge runs against it.
    const Vec2d t = left_perp(n);
    const double upper1 = dot(v12 - v11, t);
    const double upper2 = dot(v21 - v11, t);
    const double lower2 = dot(v22 - v11, t);
    const double span = upper2 - lower2;
    // Endpoints inside the slab are kept bit-exact (symmetric head-on contacts stay symmetric).
    Vec2d lower = v22;
    Vec2d upper = v21;
    if (span > 0.0) {
        if (lower2 < 0.0)
            lower = v22 + ((0.0 - lower2) / span) * (v21 - v22);
        if (upper2 > upper1)
            upper = v22 + ((upper1 - lower2) / span) * (v21 - v22);
    }
    const double sep_lower = dot(lower - v11, n);
    const double sep_upper = dot(upper - v11, n);

    /// \srs{A4} the normal points from A into B whichever polygon holds the reference face.
    m.normal = rotate(frame.q, flip ? -n : n);
    // Midway between the surfaces: half the separation back along the reference normal.
    int count = 0;
    if (sep_lower < in.margin) {
        set_point(m.points[count++], lower - (0.5 * sep_lower) * n, sep_lower,
                  make_id(flip, i11, face_feature, i22, vertex_feature), frame, in);
    }
    if (sep_upper < in.margin) {
        set_point(m.points[count++], upper - (0.5 * sep_upper) * n, sep_upper,
                  make_id(flip, i11, face_feature, i21, vertex_feature), frame, in);
    }
    m.count = count;
}

} // namespace

Manifold collide_polygons(const Polygon& a, const Polygon& b, const CollideInput& in,
                          SeparationHint* hint) {
    Manifold m;
    collide_polygons_into(a, b, in, m, hint);
    return m;
}

void collide(const Geometry& a, const Geometry& b, const CollideInput& in, Manifold& m,
             SeparationHint* hint) {
    const int used = m.count;
    if (a.type == ShapeType::polygon && b.type == ShapeType::polygon)
        collide_polygons_into(a.polygon, b.polygon, in, m, hint);
    else
        m = collide(a, b, in, hint);
    // The slots this manifold no longer uses read as in a new one.
    for (int k = m.count; k < used; ++k)
        m.points[k] = ManifoldPoint{};
}

Manifold collide(const Geometry& a, const Geometry& b, const CollideInput& in,
                 SeparationHint* hint) {
    if (a.type == ShapeType::polygon) {
        return b.type == ShapeType::polygon ? collide_polygons(a.polygon, b.polygon, in, hint)
                                            : collide_polygon_circle(a.polygon, b.circle, in);
    }
    if (b.type == ShapeType::circle)
        return collide_circles(a.circle, b.circle, in);
    // Circle A, polygon B: solve as polygon-circle with the roles swapped, then flip back.
    const CollideInput swapped{in.xf_b, in.center_b, in.xf_a, in.center_a, in.margin};
    Manifold m = collide_polygon_circle(b.polygon, a.circle, swapped);
    m.normal = -m.normal;
    for (int i = 0; i < m.count; ++i) {
        ManifoldPoint& mp = m.points[i];
        std::swap(mp.anchor_a, mp.anchor_b);
        mp.id = {mp.id.index_b, mp.id.type_b, mp.id.index_a, mp.id.type_a};
    }
    return m;
}

} // namespace tamias2d
