#include "tamias2d/geometry/shape_factory.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "tamias2d/errors.hpp"
#include "tamias2d/geometry/mass_properties.hpp"
#include "tamias2d/math/vec2d.hpp"
#include "tamias2d/memory/allocator.hpp"
#include "tamias2d/model/dcx_shape_non_degenerate_shapes.hpp"

namespace tamias2d {
namespace {

// Field names are made into strings only for a message: these checks run on every shape made
// and every snapshot read, where a string per vertex was most of the time they took.

void require_finite(double v, std::string_view field) {
    if (!std::isfinite(v))
        throw ValidationError(std::string(field), v, "must be finite", "DCX_finite");
}

void require_finite(Vec2d v, std::string_view field) {
    if (std::isfinite(v.x) && std::isfinite(v.y))
        return;
    require_finite(v.x, std::string(field) + ".x");
    require_finite(v.y, std::string(field) + ".y");
}

/// "array[i]".
std::string element(const char* array, std::size_t i) {
    return std::string(array) + "[" + std::to_string(i) + "]";
}

/// require_finite on array[i], named only if it fails.
void require_finite_element(Vec2d v, const char* array, std::size_t i) {
    if (!(std::isfinite(v.x) && std::isfinite(v.y)))
        require_finite(v, element(array, i));
}

void require_positive(double v, std::string_view field) {
    require_finite(v, field);
    if (!(v > 0.0))
        throw ValidationError(std::string(field), v, "must be > 0", "DCX_shape");
}

/// Distance from p to the line through a and b (a != b).
double distance_to_line(Vec2d a, Vec2d b, Vec2d p) {
    return std::abs(cross(b - a, p - a)) / length(b - a);
}

/// Whether direction a's angle, taken in [0, 2 pi), is below b's (exact: no trigonometry).
bool direction_before(Vec2d a, Vec2d b) {
    const auto half = [](Vec2d v) { return v.y < 0.0 || (v.y == 0.0 && v.x < 0.0) ? 1 : 0; };
    const int ha = half(a), hb = half(b);
    return ha != hb ? ha < hb : cross(a, b) > 0.0;
}

/// Fills normals and centroid from CCW vertices.
Polygon finish(Polygon p) {
    for (int i = 0; i < p.count; ++i) {
        const Vec2d e = p.vertices[(i + 1) % p.count] - p.vertices[i];
        p.normals[i] = normalize(right_perp(e)); // outward for CCW order
    }
    p.centroid = compute_mass(p, 1.0).center;
    return p;
}

} // namespace

/// \srs{DCX_shape} \srs{DCX_finite} rectangles need w > 0, h > 0, all finite.
Polygon make_box(double half_w, double half_h, Vec2d center, double angle) {
    require_positive(half_w, "shape.half_width");
    require_positive(half_h, "shape.half_height");
    require_finite(center, "shape.center");
    require_finite(angle, "shape.angle");
    // Axis-aligned boxes skip the rotation so their vertices are exact.
    const Rot q = angle == 0.0 ? Rot{} : Rot::from_angle(angle);
    const Vec2d corners[4] = {
        {-half_w, -half_h}, {half_w, -half_h}, {half_w, half_h}, {-half_w, half_h}};
    const Vec2d normals[4] = {{0.0, -1.0}, {1.0, 0.0}, {0.0, 1.0}, {-1.0, 0.0}};
    Polygon p;
    p.count = 4;
    for (int i = 0; i < 4; ++i) {
        p.vertices[i] = rotate(q, corners[i]) + center;
        p.normals[i] = rotate(q, normals[i]);
    }
    p.centroid = center;
    return p;
}

/// \srs{DCX_shape} \srs{DCX_finite} as make_box, the sizes named as box_shape's caller gave them.
Polygon make_box_of_size(double width, double height, Vec2d center, double angle) {
    require_positive(width, "shape.width");
    require_positive(height, "shape.height");
    return make_box(0.5 * width, 0.5 * height, center, angle);
}

/// \srs{DCX_shape} convex, counter-clockwise, 3 to 8 vertices, positive area.
Polygon make_polygon(std::span<const Vec2d> points) {
    if (points.size() < 3)
        throw ValidationError("polygon.points.size", double(points.size()), "must be >= 3",
                              "DCX_shape");
    for (std::size_t i = 0; i < points.size(); ++i)
        require_finite_element(points[i], "polygon.points", i);

    // Andrew's monotone chain: O(n log n), no recursion, deterministic for a given input set.
    memory::vector<Vec2d> pts(points.begin(), points.end());
    std::sort(pts.begin(), pts.end(),
              [](Vec2d a, Vec2d b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    const auto [lo_y, hi_y] =
        std::minmax_element(pts.begin(), pts.end(), [](Vec2d a, Vec2d b) { return a.y < b.y; });
    const double extent = std::max(pts.back().x - pts.front().x, hi_y->y - lo_y->y);
    if (!(extent > 0.0))
        throw ValidationError("polygon.extent", extent, "points must not all coincide",
                              "DCX_shape");
    const double tol = hull_weld_tolerance * extent;

    memory::vector<Vec2d> hull(2 * pts.size());
    std::size_t k = 0;
    // Strict left turns only: exactly collinear points are dropped here.
    for (const Vec2d& p : pts) { // lower chain
        while (k >= 2 && cross(hull[k - 1] - hull[k - 2], p - hull[k - 2]) <= 0.0)
            --k;
        hull[k++] = p;
    }
    for (std::size_t i = pts.size() - 1, t = k + 1; i-- > 0;) { // upper chain
        while (k >= t && cross(hull[k - 1] - hull[k - 2], pts[i] - hull[k - 2]) <= 0.0)
            --k;
        hull[k++] = pts[i];
    }
    hull.resize(k - 1); // the last point repeats the first

    // Weld and drop nearly collinear vertices: a vertex within `tol` of the chord of its
    // neighbours adds nothing but round-off (a coincident neighbour is a special case).
    // The nearest one goes first, so the result does not depend on where the loop starts.
    while (hull.size() > 3) {
        std::size_t worst = 0;
        double worst_d = tol;
        const std::size_t n = hull.size();
        for (std::size_t i = 0; i < n; ++i) {
            const double d = distance_to_line(hull[(i + n - 1) % n], hull[(i + 1) % n], hull[i]);
            if (d < worst_d) {
                worst_d = d;
                worst = i;
            }
        }
        if (worst_d >= tol)
            break;
        hull.erase(hull.begin() + static_cast<std::ptrdiff_t>(worst));
    }

    if (hull.size() < 3)
        throw ValidationError("polygon.hull_count", double(hull.size()),
                              "must be >= 3 (points are collinear)", "DCX_shape");
    double min_height = extent;
    for (std::size_t i = 0, n = hull.size(); i < n; ++i)
        min_height = std::min(min_height,
                              distance_to_line(hull[(i + n - 1) % n], hull[(i + 1) % n], hull[i]));
    const double area = model::dcx_shape::polygon_area(hull.data(), hull.size()).value();
    if (!(min_height >= tol) || !(area > tol * extent))
        throw ValidationError("polygon.area", area, "must not be near zero", "DCX_shape");
    if (hull.size() > std::size_t(max_polygon_vertices))
        throw ValidationError("polygon.hull_count", double(hull.size()),
                              "must be <= " + std::to_string(max_polygon_vertices), "DCX_shape");

    Polygon p;
    p.count = static_cast<int>(hull.size());
    std::copy(hull.begin(), hull.end(), p.vertices.begin());
    return finish(p);
}

Circle make_circle(double radius, Vec2d center) {
    require_positive(radius, "shape.radius");
    require_finite(center, "shape.center");
    return {center, radius};
}

namespace {

void require_distinct(Vec2d a, Vec2d b, std::string_view field) {
    if (!(length(b - a) > 0.0))
        throw ValidationError(std::string(field) + ".length", length(b - a),
                              "must be > 0 (the two ends coincide)", "DCX_shape");
}

} // namespace

Capsule make_capsule(Vec2d center1, Vec2d center2, double radius) {
    const Capsule c{center1, center2, radius};
    validate(c);
    return c;
}

Segment make_segment(Vec2d point1, Vec2d point2) {
    const Segment s{point1, point2};
    validate(s);
    return s;
}

memory::vector<ChainSegment> make_chain(std::span<const Vec2d> points, bool loop) {
    const std::size_t n = points.size();
    const std::size_t least = loop ? 3 : 2;
    if (n < least)
        throw ValidationError("chain.points.size", double(n),
                              "must be >= " + std::to_string(least) + (loop ? " (a loop)" : ""),
                              "DCX_shape");
    for (std::size_t i = 0; i < n; ++i)
        require_finite_element(points[i], "chain.points", i);
    const std::size_t edges = loop ? n : n - 1;
    for (std::size_t i = 0; i < edges; ++i) {
        if (!(length(points[(i + 1) % n] - points[i]) > 0.0))
            require_distinct(points[i], points[(i + 1) % n], element("chain.points", (i + 1) % n));
    }
    memory::vector<ChainSegment> out(edges);
    for (std::size_t i = 0; i < edges; ++i) {
        ChainSegment& s = out[i];
        s.point1 = points[i];
        s.point2 = points[(i + 1) % n];
        const Vec2d n_right = normalize(right_perp(s.point2 - s.point1));
        const double len = length(s.point2 - s.point1);
        // An open end's ghost makes the edge before (after) it run along the normal (against
        // it): a right-angle convex corner, whose arc admits every normal a free end can have.
        s.ghost1 = loop || i > 0 ? points[(i + n - 1) % n] : s.point1 - len * n_right;
        s.ghost2 = loop || i + 1 < edges ? points[(i + 2) % n] : s.point2 - len * n_right;
    }
    return out;
}

Geometry to_geometry(const Circle& c) {
    Geometry g;
    g.type = ShapeType::circle;
    g.circle = c;
    return g;
}

Geometry to_geometry(const Polygon& p) {
    Geometry g;
    g.type = ShapeType::polygon;
    g.polygon = p;
    return g;
}

Geometry to_geometry(const Capsule& c) {
    Geometry g;
    g.type = ShapeType::capsule;
    g.capsule = c;
    return g;
}

Geometry to_geometry(const Segment& s) {
    Geometry g;
    g.type = ShapeType::segment;
    g.segment = s;
    return g;
}

Geometry to_geometry(const ChainSegment& s) {
    Geometry g;
    g.type = ShapeType::chain_segment;
    g.chain_segment = s;
    return g;
}

void validate(const Capsule& c) {
    require_positive(c.radius, "capsule.radius");
    require_finite(c.center1, "capsule.center1");
    require_finite(c.center2, "capsule.center2");
    require_distinct(c.center1, c.center2, "capsule");
}

void validate(const Segment& s) {
    require_finite(s.point1, "segment.point1");
    require_finite(s.point2, "segment.point2");
    require_distinct(s.point1, s.point2, "segment");
}

void validate(const ChainSegment& s) {
    require_finite(s.ghost1, "chain_segment.ghost1");
    require_finite(s.point1, "chain_segment.point1");
    require_finite(s.point2, "chain_segment.point2");
    require_finite(s.ghost2, "chain_segment.ghost2");
    require_distinct(s.point1, s.point2, "chain_segment");
    require_distinct(s.ghost1, s.point1, "chain_segment.ghost1");
    require_distinct(s.point2, s.ghost2, "chain_segment.ghost2");
}

void validate(const Circle& c) {
    require_positive(c.radius, "shape.radius");
    require_finite(c.center, "shape.center");
}

void validate(const Polygon& p) {
    if (p.count < 3 || p.count > max_polygon_vertices)
        throw ValidationError("polygon.count", double(p.count),
                              "must be in [3, " + std::to_string(max_polygon_vertices) + "]",
                              "DCX_shape");
    for (int i = 0; i < p.count; ++i) {
        require_finite_element(p.vertices[i], "polygon.vertices", std::size_t(i));
        require_finite_element(p.normals[i], "polygon.normals", std::size_t(i));
    }
    require_finite(p.centroid, "polygon.centroid");
    int wraps = 0; // the times the edge direction passes angle 0 going round (see below)
    for (int i = 0; i < p.count; ++i) {
        const Vec2d a = p.vertices[i];
        const Vec2d b = p.vertices[(i + 1) % p.count];
        const Vec2d c = p.vertices[(i + 2) % p.count];
        const double turn = cross(b - a, c - b);
        if (!(turn > 0.0))
            throw ValidationError(element("polygon.vertices", std::size_t((i + 1) % p.count)) +
                                      ".turn",
                                  turn, "must be > 0 (convex, CCW)", "DCX_shape");
        if (direction_before(c - b, b - a))
            ++wraps;
        const Vec2d n = normalize(right_perp(b - a));
        const Vec2d dn = p.normals[i] - n;
        if (!(length(dn) < 1e-9))
            throw ValidationError("polygon.normals[" + std::to_string(i) + "].error", length(dn),
                                  "must be the unit outward edge normal", "DCX_shape");
    }
    // Turning left at every vertex is not convexity: a pentagram does so and turns round twice
    // (4 pi). Each turn is in (0, pi), so the edge direction passes angle 0 once per full turn,
    // exactly where its angle in [0, 2 pi) drops: a simple polygon turns round once.
    if (wraps != 1)
        throw ValidationError("polygon.winding_number", double(wraps),
                              "must be 1: the boundary turns round once (a simple polygon; a "
                              "self-intersecting one such as a pentagram turns more)",
                              "DCX_shape");
    // The centroid is derived data: it must be the vertices' centroid, up to the rounding of the
    // sums that compute it (a box's is its exact centre, within a few ulps of the vertices').
    double extent = 0.0, magnitude = 0.0;
    for (int i = 0; i < p.count; ++i) {
        magnitude = std::max({magnitude, std::abs(p.vertices[i].x), std::abs(p.vertices[i].y)});
        for (int j = 0; j < i; ++j)
            extent = std::max({extent, std::abs(p.vertices[i].x - p.vertices[j].x),
                               std::abs(p.vertices[i].y - p.vertices[j].y)});
    }
    const Vec2d derived = compute_mass(p, 1.0).center;
    const double centroid_error = length(p.centroid - derived);
    const double centroid_tolerance =
        hull_weld_tolerance * extent + 16.0 * std::numeric_limits<double>::epsilon() * magnitude;
    if (!(centroid_error <= centroid_tolerance))
        throw ValidationError("polygon.centroid.error", centroid_error,
                              "must be <= " + detail::format_value(centroid_tolerance) +
                                  " m: the centroid of the vertices (" +
                                  detail::format_value(derived.x) + ", " +
                                  detail::format_value(derived.y) + ")",
                              "DCX_shape");
}

Geometry canonical(const Geometry& g) {
    switch (g.type) {
    case ShapeType::polygon: {
        Polygon p;
        p.count = g.polygon.count;
        p.centroid = g.polygon.centroid;
        for (int i = 0; i < p.count && i < max_polygon_vertices; ++i) {
            p.vertices[std::size_t(i)] = g.polygon.vertices[std::size_t(i)];
            p.normals[std::size_t(i)] = g.polygon.normals[std::size_t(i)];
        }
        return to_geometry(p);
    }
    case ShapeType::capsule:
        return to_geometry(g.capsule);
    case ShapeType::segment:
        return to_geometry(g.segment);
    case ShapeType::chain_segment:
        return to_geometry(g.chain_segment);
    case ShapeType::circle:
        break;
    }
    return to_geometry(g.circle);
}

void validate(const Geometry& g) {
    switch (g.type) {
    case ShapeType::circle:
        return validate(g.circle);
    case ShapeType::polygon:
        return validate(g.polygon);
    case ShapeType::capsule:
        return validate(g.capsule);
    case ShapeType::segment:
        return validate(g.segment);
    case ShapeType::chain_segment:
        return validate(g.chain_segment);
    }
    throw ValidationError("shape.type", double(g.type), "must be a ShapeType", "DCX_shape");
}

} // namespace tamias2d
