// Narrow phase (T5): contact manifolds by the separating axis test and reference-face clipping.
// See docs/collision.md for the conventions (A4 normal from A into B, midway points, ids).
#include "tamias2d/collision/narrow_phase.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <utility>

#include "tamias2d/collision/collider.hpp"
#include "tamias2d/collision/segment_distance.hpp"
#include "tamias2d/math/lanes.hpp"
#include "tamias2d/model/dd31_chain_segment_normal.hpp"

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

/// Two lanes: SSE2's register, which every x86-64 has (a four-lane pack split in two by the
/// compiler went through the stack). Lane-wise IEEE arithmetic without fused multiply-add: each
/// lane computes bit for bit what the scalar expression computes. Without GCC/Clang vector
/// extensions (or with TAMIAS_PORTABLE_LANES), a plain pair doing the same lane by lane.
#if TAMIAS_GNU_LANES
using Duo = double __attribute__((vector_size(2 * sizeof(double))));
#else
using Duo = lanes::Doubles<2>;
#endif

/// x in both lanes, bit for bit (-0 stays -0).
Duo in_both_lanes(double x) {
    return Duo{x, x};
}

/// std::min(a, b) lane by lane: b if b < a, else a (one SSE2 minpd).
Duo min2(Duo a, Duo b) {
#if TAMIAS_GNU_LANES
    return b < a ? b : a;
#else
    return lanes::select(b < a, b, a);
#endif
}

/// A polygon's vertices and normals in A's centroid frame, a plain array per coordinate (one
/// load per scalar access), read and written two lanes at a time by the separating axis test.
/// Filled before use, only the pairs in use (a lane past the count repeats vertex 0): nothing is
/// zero-initialised.
struct Local {
    alignas(16) double vx[max_polygon_vertices], vy[max_polygon_vertices];
    alignas(16) double nx[max_polygon_vertices], ny[max_polygon_vertices];
    int count;
    int duos() const { return (count + 1) / 2; }
    Vec2d v(int i) const { return {vx[i], vy[i]}; }
    Vec2d n(int i) const { return {nx[i], ny[i]}; }
};

/// Two lanes from (to) two consecutive doubles.
Duo load2(const double* x) {
    Duo d;
    std::memcpy(&d, x, sizeof d);
    return d;
}
void store2(double* x, Duo d) {
    std::memcpy(x, &d, sizeof d);
}

/// The first of `other`'s vertices (in order) whose projection on n is at or below `beat`, as
/// that projection (there is one: the smallest projection is at or below beat).
[[gnu::noinline]] double first_at_or_below(Vec2d n, const Local& other, int count, double beat) {
    double s = beat;
    for (int j = 0; j < count; ++j) {
        s = dot(n, other.v(j));
        if (s <= beat)
            break;
    }
    return s;
}

/// Greatest separation of `other`'s vertices along one of `ref`'s face normals (SAT): the same
/// double, and the same face, as this early-exit loop returns:
///
///     best = -inf; edge = 0;
///     for each face i: beat = best + offset_i;  s = +inf;
///         for each vertex j while s > beat: s = min(s, d_ij);   // d_ij = dot(n_i, v_j)
///         s -= offset_i;  if (s > best) { best = s; edge = i; if (!(best < stop)) return best; }
///
/// (a face abandoned once it cannot beat the best so far; the test stops at the first face that
/// separates by `stop` or more). Here every face's offset and full minimum come first, two faces
/// per register, branch-free and unrolled for D (E) two-vertex elements in ref (other); the
/// minimum runs over the vertices in order, like std::min, and a padding lane repeats vertex 0
/// after it, which changes no bit. The inner loop above ends with s = the full minimum when that
/// stays above beat, and otherwise with s = the first d_ij <= beat; such a face wins only if
/// (that d_ij) - offset_i > best, impossible unless beat - offset_i > best (beat rounded up):
/// only then is that first vertex looked for. NR and NO are the vertex counts when known at
/// compile time (0: read from ref and other).
template <int D, int E, int NR, int NO>
[[gnu::always_inline]] inline double max_separation(const Local& ref, const Local& other,
                                                    double stop, int& edge) {
    const int ref_count = NR != 0 ? NR : ref.count;
    const int other_count = NO != 0 ? NO : other.count;
    Duo off[D], low[D];
    for (int k = 0; k < D; ++k) {
        const Duo nx = load2(&ref.nx[2 * k]), ny = load2(&ref.ny[2 * k]);
        off[k] = nx * load2(&ref.vx[2 * k]) + ny * load2(&ref.vy[2 * k]);
        low[k] = in_both_lanes(std::numeric_limits<double>::infinity());
    }
    for (int j = 0; j < 2 * E; ++j) {
        const Duo x = in_both_lanes(other.vx[j]), y = in_both_lanes(other.vy[j]);
        for (int k = 0; k < D; ++k)
            low[k] = min2(low[k], load2(&ref.nx[2 * k]) * x + load2(&ref.ny[2 * k]) * y);
    }

    double best = -std::numeric_limits<double>::infinity();
    edge = 0;
    for (int i = 0; i < ref_count; ++i) {
        const double offset = off[i >> 1][i & 1];
        const double beat = best + offset; // this face loses once its minimum drops to here
        double s = low[i >> 1][i & 1];
        if (!(s > beat)) {
            if (!(beat - offset > best))
                continue;
            s = first_at_or_below(ref.n(i), other, other_count, beat);
        }
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

template <int D>
double max_separation_duos(const Local& ref, const Local& other, double stop, int& edge) {
    switch (other.duos()) {
    case 2:
        return max_separation<D, 2, 0, 0>(ref, other, stop, edge);
    case 3:
        return max_separation<D, 3, 0, 0>(ref, other, stop, edge);
    default:
        return max_separation<D, 4, 0, 0>(ref, other, stop, edge);
    }
}

/// Any counts, known at run time.
[[gnu::noinline]] double max_separation_any(const Local& ref, const Local& other, double stop,
                                            int& edge) {
    switch (ref.duos()) {
    case 2:
        return max_separation_duos<2>(ref, other, stop, edge);
    case 3:
        return max_separation_duos<3>(ref, other, stop, edge);
    default:
        return max_separation_duos<4>(ref, other, stop, edge);
    }
}

/// NR and NO vertices (0: known at run time only).
template <int NR, int NO>
[[gnu::always_inline]] inline double max_separation_n(const Local& ref, const Local& other,
                                                      double stop, int& edge) {
    if constexpr (NR != 0 && NO != 0)
        return max_separation<(NR + 1) / 2, (NO + 1) / 2, NR, NO>(ref, other, stop, edge);
    else
        return max_separation_any(ref, other, stop, edge);
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

/// No contact: count 0 and the zero normal, as a default manifold has.
void set_empty(Manifold& m) {
    m.normal = {};
    m.count = 0;
}

// The *_into functions write the normal and the count on every path, and the points in use;
// the slots past the count are left to collide (see its in-place form).

/// \srs{T5} circles collide when their centres are closer than the sum of the radii.
void circles_into(const Collider& a, const Collider& b, const CollideInput& in, Manifold& m) {
    const Vec2d ca = transform_point(in.xf_a, a.center);
    const Vec2d cb = transform_point(in.xf_b, b.center);
    const Vec2d d = cb - ca;
    const double dist = length(d);
    const double separation = dist - a.radius - b.radius;
    if (!(separation < in.margin))
        return set_empty(m);
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
}

/// \srs{T5} polygon and circle: the nearest face or vertex of the polygon.
void polygon_circle_into(const Collider& a, const Collider& b, const CollideInput& in,
                         Manifold& m) {
    // Work in A's body frame: the circle centre is one transformed point.
    const Vec2d c = inv_transform_point(in.xf_a, transform_point(in.xf_b, b.center));
    const double r = b.radius;

    int edge = 0;
    double sep = -std::numeric_limits<double>::infinity();
    for (int i = 0; i < a.count; ++i) {
        const double s = dot(a.normal(i), c - a.vertex(i));
        if (s > sep) {
            sep = s;
            edge = i;
        }
    }
    if (!(sep - r < in.margin))
        return set_empty(m);

    const int next = edge + 1 == a.count ? 0 : edge + 1;
    const Vec2d v1 = a.vertex(edge);
    const Vec2d v2 = a.vertex(next);
    Vec2d n = a.normal(edge);
    Vec2d on_a;
    double separation;
    FeatureId id{static_cast<std::uint8_t>(edge), face_feature, 0, vertex_feature};
    const bool behind_v1 = sep > 0.0 && dot(c - v1, v2 - v1) < 0.0;
    const bool beyond_v2 = sep > 0.0 && dot(c - v2, v1 - v2) < 0.0;
    const int vi = behind_v1 ? edge : next;
    const Vec2d d = c - a.vertex(vi);
    // In the vertex region dist >= sep > 0 exactly, but the squares of a distance below about
    // 1e-154 m underflow to 0: the centre is then on the vertex, where the face's plane serves
    // (d / 0 would be NaN).
    const double dist = behind_v1 || beyond_v2 ? length(d) : 0.0;
    if (dist > 0.0) {
        // Vertex region: the closest point of A is the vertex itself.
        on_a = a.vertex(vi);
        separation = dist - r;
        if (!(separation < in.margin))
            return set_empty(m);
        n = Vec2d{d.x / dist, d.y / dist};
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
}

/// The input with the two shapes' roles exchanged.
CollideInput swapped(const CollideInput& in) {
    return {in.xf_b, in.center_b, in.xf_a, in.center_a, in.margin};
}

/// A manifold of (b, a) made into one of (a, b): the normal reversed, anchors and ids swapped.
void swap_roles(Manifold& m) {
    m.normal = -m.normal;
    for (int i = 0; i < m.count; ++i) {
        ManifoldPoint& mp = m.points[i];
        std::swap(mp.anchor_a, mp.anchor_b);
        mp.id = {mp.id.index_b, mp.id.type_b, mp.id.index_a, mp.id.type_a};
    }
}

/// Circle A, polygon B: solved as polygon-circle with the roles swapped, then flipped back.
void circle_polygon_into(const Collider& a, const Collider& b, const CollideInput& in,
                         Manifold& m) {
    polygon_circle_into(b, a, swapped(in), m);
    swap_roles(m);
}

/// An incident edge v21 -> v22 clipped to the side planes of the reference face v11 -> v12
/// (outward normal n), and its ends' and the face's coordinates along the face's tangent.
struct Clipped {
    Vec2d lower, upper; ///< the clipped ends (from v22 and v21)
    double lower_t, upper_t, face_t;
};

[[gnu::always_inline]] inline Clipped clip_to_face(Vec2d v11, Vec2d v12, Vec2d n, Vec2d v21,
                                                   Vec2d v22) {
    // The tangent runs along the reference edge (CCW); the incident edge runs against it.
    const Vec2d t = left_perp(n);
    Clipped c;
    c.face_t = dot(v12 - v11, t);
    c.upper_t = dot(v21 - v11, t);
    c.lower_t = dot(v22 - v11, t);
    const double span = c.upper_t - c.lower_t;
    // Endpoints inside the slab are kept bit-exact (symmetric head-on contacts stay symmetric).
    c.lower = v22;
    c.upper = v21;
    if (span > 0.0) {
        if (c.lower_t < 0.0)
            c.lower = v22 + ((0.0 - c.lower_t) / span) * (v21 - v22);
        if (c.upper_t > c.face_t)
            c.upper = v22 + ((c.face_t - c.lower_t) / span) * (v21 - v22);
    }
    return c;
}

/// polygons_into's hinted face (the last call's separating face, of A or of B): its separation
/// as max_separation computes it (same expressions, same order), B's vertices in lb.
[[gnu::always_inline]] inline double hinted_separation(const Collider& a, const Collider& b,
                                                       const Local& lb, Rot q,
                                                       const SeparationHint& hint, int na, int nb) {
    const int i = hint.face;
    double s = std::numeric_limits<double>::infinity();
    double offset = 0.0;
    if (!hint.on_b && i < na) {
        const Vec2d n = a.normal(i);
        offset = dot(n, a.vertex(i) - a.center);
        for (int j = 0; j < nb; ++j)
            s = std::min(s, dot(n, lb.v(j)));
    } else if (hint.on_b && i < nb) {
        const Vec2d n = rotate(q, b.normal(i));
        offset = dot(n, lb.v(i));
        for (int j = 0; j < na; ++j)
            s = std::min(s, dot(n, a.vertex(j) - a.center));
    }
    return s - offset;
}

/// polygons_into's frame, after B's vertices: A's vertices from its centroid and its normals,
/// B's normals turned by q (cosine c, sine sn in both lanes), two at a time.
[[gnu::always_inline]] inline void place_rest(const Collider& a, const Collider& b, Duo c, Duo sn,
                                              int na, int nb, Local& la, Local& lb) {
    const Duo cx = in_both_lanes(a.center.x), cy = in_both_lanes(a.center.y);
    for (int k = 0; k < (na + 1) / 2; ++k) {
        const VertexPair& s = a.pairs[k];
        store2(&la.vx[2 * k], load2(s.vx) - cx);
        store2(&la.vy[2 * k], load2(s.vy) - cy);
        store2(&la.nx[2 * k], load2(s.nx));
        store2(&la.ny[2 * k], load2(s.ny));
    }
    for (int k = 0; k < (nb + 1) / 2; ++k) {
        const Duo nx = load2(b.pairs[k].nx), ny = load2(b.pairs[k].ny);
        store2(&lb.nx[2 * k], c * nx - sn * ny);
        store2(&lb.ny[2 * k], sn * nx + c * ny);
    }
}

/// The incident face: of `inc`'s faces, the first most anti-parallel to the reference normal n.
[[gnu::always_inline]] inline int incident_edge(Vec2d n, const Local& inc, int inc_count) {
    int i21 = 0;
    double min_dot = std::numeric_limits<double>::infinity();
    for (int i = 0; i < inc_count; ++i) {
        const double d = dot(n, inc.n(i));
        if (d < min_dot) {
            min_dot = d;
            i21 = i;
        }
    }
    return i21;
}

/// \srs{T5} polygons by the separating axis test; \srs{A5} vertex-edge gives one point,
/// \srs{LC1} edge-edge two. NA and NB are the vertex counts when known at compile time (0: read
/// from the colliders): boxes against boxes get straight-line code.
template <int NA, int NB>
void polygons_into(const Collider& a, const Collider& b, const CollideInput& in, Manifold& m,
                   SeparationHint* hint) {
    const int na = NA != 0 ? NA : a.count;
    const int nb = NB != 0 ? NB : b.count;
    // Work in A's frame shifted to A's centroid: B's vertices are transformed once, and the
    // numbers stay small for shapes far from the world origin.
    const Transform frame{transform_point(in.xf_a, a.center), in.xf_a.q};
    const Rot q = inv_mul(in.xf_a.q, in.xf_b.q);
    const Vec2d p = inv_transform_point(frame, in.xf_b.p);
    // Both polygons in that frame, two vertices at a time (lane by lane the scalar expressions
    // v - centroid and rotate(q, v) + p, rotate(q, n)); B's vertices first: the hint needs them.
    Local la;
    Local lb;
    la.count = na;
    lb.count = nb;
    const Duo c = in_both_lanes(q.c), sn = in_both_lanes(q.s);
    {
        const Duo px = in_both_lanes(p.x), py = in_both_lanes(p.y);
        for (int k = 0; k < (nb + 1) / 2; ++k) {
            const Duo vx = load2(b.pairs[k].vx), vy = load2(b.pairs[k].vy);
            store2(&lb.vx[2 * k], (c * vx - sn * vy) + px);
            store2(&lb.vy[2 * k], (sn * vx + c * vy) + py);
        }
    }
    if (hint != nullptr && hint->face >= 0) {
        // The hinted face's separation, computed exactly as max_separation computes it below
        // (same expressions, same order): if it still reaches the margin, so would the full
        // test, and the answer is the same empty manifold.
        if (!(hinted_separation(a, b, lb, q, *hint, na, nb) < in.margin))
            return set_empty(m);
        hint->face = -1;
    }
    place_rest(a, b, c, sn, na, nb, la, lb);

    int edge_a = 0;
    const double sep_a = max_separation_n<NA, NB>(la, lb, in.margin, edge_a);
    if (!(sep_a < in.margin)) {
        if (hint != nullptr)
            *hint = {static_cast<std::int8_t>(edge_a), false};
        return set_empty(m);
    }
    int edge_b = 0;
    const double sep_b = max_separation_n<NB, NA>(lb, la, in.margin, edge_b);
    if (!(sep_b < in.margin)) {
        if (hint != nullptr)
            *hint = {static_cast<std::int8_t>(edge_b), true};
        return set_empty(m);
    }

    // The tolerance is relative to the smaller polygon's size (the radii are the square roots
    // of each polygon's largest squared vertex distance, so their minimum is the root of the
    // smaller one); the common resting case (A's face best, penetrating) does not need it.
    const double tol = sep_b > sep_a || std::max(sep_a, sep_b) > 0.0
                           ? relative_tolerance * std::min(a.radius, b.radius)
                           : 0.0;

    // Reference face: A's unless B's separates clearly more (hysteresis against flipping).
    const bool flip = sep_b > sep_a + tol;
    const Local& ref = flip ? lb : la;
    const Local& inc = flip ? la : lb;
    const int ref_count = flip ? nb : na;
    const int inc_count = flip ? na : nb;
    const int i11 = flip ? edge_b : edge_a;
    const int i12 = i11 + 1 == ref_count ? 0 : i11 + 1;
    const Vec2d n = ref.n(i11);

    // Incident edge: the face of the other polygon most anti-parallel to the reference normal.
    const int i21 = incident_edge(n, inc, inc_count);
    const int i22 = i21 + 1 == inc_count ? 0 : i21 + 1;
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

    const Clipped clip = clip_to_face(v11, v12, n, v21, v22);
    const Vec2d lower = clip.lower, upper = clip.upper;
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

/// A shape's core in A's centroid frame: a point (a circle's centre), a segment or a polygon,
/// and the rounding every point of its surface has around the core.
struct Core {
    Vec2d v[max_polygon_vertices];
    Vec2d n[max_polygon_vertices];
    int count;     ///< 1: a point (no faces)
    double radius; ///< m
    double size;   ///< m: the rounding plus the core's largest vertex distance from its centre
};

/// k's core placed by `q`, `p` (its body frame seen from A's centroid frame).
Core core_of(const Collider& k, Rot q, Vec2d p) {
    Core c;
    if (k.type == ShapeType::circle) {
        c.count = 1;
        c.v[0] = rotate(q, k.center) + p;
        c.radius = k.radius;
        c.size = k.radius;
        return c;
    }
    c.count = k.count;
    c.radius = k.type == ShapeType::polygon ? 0.0 : k.radius;
    double reach = 0.0;
    for (int i = 0; i < c.count; ++i) {
        c.v[i] = rotate(q, k.vertex(i)) + p;
        c.n[i] = rotate(q, k.normal(i));
        reach = std::max(reach, length(k.vertex(i) - k.center));
    }
    c.size = c.radius + reach;
    return c;
}

/// The greatest separation of `other`'s core vertices along one of `ref`'s faces (SAT on the
/// cores, both of two or more vertices), and that face.
double core_separation(const Core& ref, const Core& other, int& edge) {
    double best = -std::numeric_limits<double>::infinity();
    edge = 0;
    for (int i = 0; i < ref.count; ++i) {
        double s = std::numeric_limits<double>::infinity();
        for (int j = 0; j < other.count; ++j)
            s = std::min(s, dot(ref.n[i], other.v[j] - ref.v[i]));
        if (s > best) {
            best = s;
            edge = i;
        }
    }
    return best;
}

/// The closest points of two cores, from A's to B's, and the features they lie on.
struct CoreGap {
    double distance = 0.0; ///< m: 0 when the cores overlap
    Vec2d from{}, to{};
    int feature_a = 0, feature_b = 0;
    std::uint8_t type_a = vertex_feature, type_b = vertex_feature;
};

/// The cores' least distance over their edges (a point is its own edge, a segment has one),
/// or 0 when a polygon core holds a vertex of the other (edges that cross give 0 themselves).
CoreGap core_gap(const Core& a, const Core& b) {
    CoreGap out;
    auto holds = [](const Core& p, const Core& q) {
        if (p.count < 3)
            return false;
        for (int j = 0; j < q.count; ++j) {
            bool in = true;
            for (int i = 0; i < p.count && in; ++i)
                in = dot(p.n[i], q.v[j] - p.v[i]) <= 0.0;
            if (in)
                return true;
        }
        return false;
    };
    if (holds(a, b) || holds(b, a))
        return out;
    const int ea = a.count <= 2 ? 1 : a.count, eb = b.count <= 2 ? 1 : b.count;
    double best = std::numeric_limits<double>::infinity();
    for (int i = 0; i < ea; ++i) {
        const int i2 = a.count == 1 ? i : (i + 1) % a.count;
        for (int j = 0; j < eb; ++j) {
            const int j2 = b.count == 1 ? j : (j + 1) % b.count;
            const SegmentDistance sd = segment_distance(a.v[i], a.v[i2], b.v[j], b.v[j2]);
            if (sd.distance_squared < best) {
                best = sd.distance_squared;
                out.from = sd.closest1;
                out.to = sd.closest2;
                const bool va = a.count == 1 || sd.fraction1 == 0.0 || sd.fraction1 == 1.0;
                const bool vb = b.count == 1 || sd.fraction2 == 0.0 || sd.fraction2 == 1.0;
                out.feature_a = va && sd.fraction1 == 1.0 ? i2 : i;
                out.feature_b = vb && sd.fraction2 == 1.0 ? j2 : j;
                out.type_a = va ? vertex_feature : face_feature;
                out.type_b = vb ? vertex_feature : face_feature;
            }
        }
    }
    out.distance = std::sqrt(best);
    return out;
}

/// One contact point along the cores' gap (A5), from A's core to B's, midway between the
/// surfaces, when that is nearer than the margin.
void one_point_along(const CoreGap& gap, double radius_a, double rsum, const Transform& frame,
                     const CollideInput& in, Manifold& m) {
    const double separation = gap.distance - rsum;
    if (!(separation < in.margin))
        return set_empty(m);
    const Vec2d g = (gap.to - gap.from) / gap.distance; // A -> B
    m.normal = rotate(frame.q, g);
    m.count = 1;
    set_point(m.points[0], gap.from + (radius_a + 0.5 * separation) * g, separation,
              make_id(false, gap.feature_a, gap.type_a, gap.feature_b, gap.type_b), frame, in);
}

/// The least separation of a manifold's points plus the radii: its cores' gap as it reports it.
double deepest_core(const Manifold& m, double rsum) {
    double d = std::numeric_limits<double>::infinity();
    for (int i = 0; i < m.count; ++i)
        d = std::min(d, m.points[i].separation);
    return d + rsum;
}

/// \srs{T5} Shapes with a rounding (capsules, segments) against any shape, as their cores (a
/// point, a segment or a polygon) grown by their radii: the separating axis test on the cores
/// picks the reference face, the incident edge is clipped to it (LC1: two points for parallel
/// faces) and each point's separation is its core distance less both radii. Cores apart by
/// more than the faces show give one point along the true gap (A5). With `forced_face` >= 0, A's
/// face of that index is the reference, whatever the test would pick (DD31's answer for a chain
/// edge).
void rounded_into(const Collider& a, const Collider& b, const CollideInput& in, Manifold& m,
                  int forced_face = -1) {
    const Transform frame{transform_point(in.xf_a, a.center), in.xf_a.q};
    const Core ca = core_of(a, Rot{}, -a.center);
    const Core cb =
        core_of(b, inv_mul(in.xf_a.q, in.xf_b.q), inv_transform_point(frame, in.xf_b.p));
    const double rsum = ca.radius + cb.radius;
    const double inf = std::numeric_limits<double>::infinity();

    int edge_a = 0, edge_b = 0;
    double sep_a = ca.count >= 2 ? core_separation(ca, cb, edge_a) : -inf;
    double sep_b = cb.count >= 2 ? core_separation(cb, ca, edge_b) : -inf;
    bool flip = false;
    CoreGap gap;
    double tol = 0.0;
    if (forced_face >= 0) {
        edge_a = forced_face;
        sep_b = -inf;
    } else {
        // The separating axis bounds the cores' distance from below: at or past the margin
        // plus both radii, the surfaces are apart by the margin.
        if (!(std::max(sep_a, sep_b) - rsum < in.margin))
            return set_empty(m);
        tol = relative_tolerance * std::min(ca.size, cb.size);
        // A point or a segment has no face along its own direction, so the faces' axes can
        // understate the cores' gap (two capsules end to end on one line read as overlapping):
        // the cores' true gap decides. Apart by more than the faces say, or nearest at two
        // vertices, the contact is one point along the gap (A5). (Cores whose edges cross give
        // a gap of rounding size, not exactly 0: below the tolerance, the faces decide.)
        gap = core_gap(ca, cb);
        const double sep_max = std::max(sep_a, sep_b);
        const bool vertices = gap.type_a == vertex_feature && gap.type_b == vertex_feature;
        if (gap.distance > tol &&
            (gap.distance > sep_max + tol || (vertices && gap.distance > sep_max + 1e-9 * ca.size)))
            return one_point_along(gap, ca.radius, rsum, frame, in, m);
        flip = sep_b > sep_a + tol;
    }
    const Core& ref = flip ? cb : ca;
    const Core& inc = flip ? ca : cb;
    const int i11 = flip ? edge_b : edge_a;
    const int i12 = i11 + 1 == ref.count ? 0 : i11 + 1;
    const Vec2d n = ref.n[i11];
    int i21 = 0;
    if (inc.count >= 2) {
        double min_dot = inf;
        for (int i = 0; i < inc.count; ++i) {
            const double d = dot(n, inc.n[i]);
            if (d < min_dot) {
                min_dot = d;
                i21 = i;
            }
        }
    }
    const int i22 = inc.count >= 2 ? (i21 + 1 == inc.count ? 0 : i21 + 1) : i21;
    const Vec2d v11 = ref.v[i11], v12 = ref.v[i12], v21 = inc.v[i21], v22 = inc.v[i22];
    const double r_inc = inc.radius;

    // Clip the incident edge (or point) to the reference face's side planes.
    const Clipped clip = clip_to_face(v11, v12, n, v21, v22);
    if (forced_face >= 0 && (std::max(clip.upper_t, clip.lower_t) < 0.0 ||
                             std::min(clip.upper_t, clip.lower_t) > clip.face_t))
        return set_empty(m); // wholly beside the forced face: another feature's contact
    const Vec2d lower = clip.lower, upper = clip.upper;
    const double sep_lower = dot(lower - v11, n) - rsum;
    const double sep_upper = dot(upper - v11, n) - rsum;
    m.normal = rotate(frame.q, flip ? -n : n);
    int count = 0;
    if (sep_lower < in.margin) {
        set_point(m.points[count++], lower - (r_inc + 0.5 * sep_lower) * n, sep_lower,
                  make_id(flip, i11, face_feature, i22, vertex_feature), frame, in);
    }
    if (inc.count >= 2 && sep_upper < in.margin) {
        set_point(m.points[count++], upper - (r_inc + 0.5 * sep_upper) * n, sep_upper,
                  make_id(flip, i11, face_feature, i21, vertex_feature), frame, in);
    }
    m.count = count;
    // Clipping keeps the incident points inside the reference face's side planes; when the
    // nearest point lies outside them, the clipped points would overstate the gap (or miss a
    // contact): the true gap is the answer then.
    if (forced_face < 0 && gap.distance > tol &&
        (count == 0 || deepest_core(m, rsum) > gap.distance + 1e-9 * ca.size)) {
        if (gap.distance - rsum < in.margin)
            return one_point_along(gap, ca.radius, rsum, frame, in, m);
    }
    if (m.count == 0)
        m.normal = {};
}

/// The admissible-normal tolerance of DD31 (the sine of about 0.6 degrees): a shape resting
/// almost flat on an edge keeps the normal the separating axis test gives it.
constexpr double chain_normal_tolerance = 1e-2;

/// \srs{DD31} A chain edge (A) against any shape but another chain edge: one-sided (a shape
/// whose centre is behind the edge's line does not collide with it), and a normal the edge's
/// vertices cannot have (a ghost of the joint between two edges) is replaced by the edge's own
/// face as the reference.
void chain_into(const Collider& a, const Collider& b, const CollideInput& in, Manifold& m) {
    if (b.type == ShapeType::chain_segment)
        return set_empty(m);
    const Vec2d v1 = a.vertex(0), v2 = a.vertex(1);
    const Vec2d n = a.normal(0);
    const Vec2d centre_b = inv_transform_point(in.xf_a, transform_point(in.xf_b, b.center));
    if (dot(n, centre_b - v1) < 0.0)
        return set_empty(m);
    rounded_into(a, b, in, m);
    if (m.count == 0)
        return;
    const Vec2d n_prev = normalize(right_perp(v1 - a.ghost(0)));
    const Vec2d n_next = normalize(right_perp(a.ghost(1) - v2));
    const Vec2d normal = inv_rotate(in.xf_a.q, m.normal);
    if (!model::dd31::admissible(n_prev, n, n_next, normal, chain_normal_tolerance))
        rounded_into(a, b, in, m, 0);
}

} // namespace

void collide(const Collider& a, const Collider& b, const CollideInput& in, Manifold& m,
             SeparationHint* hint) {
    const int used = m.count;
    if (a.is_segment_kind() || b.is_segment_kind()) {
        if (a.type == ShapeType::chain_segment) {
            chain_into(a, b, in, m);
        } else if (b.type == ShapeType::chain_segment) {
            chain_into(b, a, swapped(in), m);
            swap_roles(m);
        } else {
            rounded_into(a, b, in, m);
        }
    } else if (a.type == ShapeType::polygon) {
        if (b.type != ShapeType::polygon)
            polygon_circle_into(a, b, in, m);
        else if (a.count == 4 && b.count == 4)
            polygons_into<4, 4>(a, b, in, m, hint);
        else
            polygons_into<0, 0>(a, b, in, m, hint);
    } else if (b.type == ShapeType::circle) {
        circles_into(a, b, in, m);
    } else {
        circle_polygon_into(a, b, in, m);
    }
    // The slots this manifold no longer uses read as in a new one.
    for (int k = m.count; k < used; ++k)
        m.points[k] = ManifoldPoint{};
}

Manifold collide(const Geometry& a, const Geometry& b, const CollideInput& in,
                 SeparationHint* hint) {
    Manifold m;
    collide(make_collider(a), make_collider(b), in, m, hint);
    return m;
}

Manifold collide_circles(const Circle& a, const Circle& b, const CollideInput& in) {
    Manifold m;
    circles_into(make_collider(a), make_collider(b), in, m);
    return m;
}

Manifold collide_polygon_circle(const Polygon& a, const Circle& b, const CollideInput& in) {
    Manifold m;
    polygon_circle_into(make_collider(a), make_collider(b), in, m);
    return m;
}

} // namespace tamias2d
