// The World's queries (include/tamias2d/world.hpp, "queries"): rays, shape casts, overlaps,
// points and distances, each walking the broad phase's trees and answering from the exact
// routines of one shape: geometry/shape_queries (DD33's ray entry, T5's containment) and
// collision/time_of_impact (DD34's distance, DD29's conservative advancement).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "tamias2d/collision/collider.hpp"
#include "tamias2d/collision/time_of_impact.hpp"
#include "tamias2d/errors.hpp"
#include "tamias2d/geometry/shape_queries.hpp"
#include "tamias2d/model/dd27_collision_filter.hpp"
#include "tamias2d/validation.hpp"
#include "tamias2d/world.hpp"
#include "tamias2d/world_impl.hpp"

namespace tamias2d {
namespace {

/// A ray clipped at a hit still visits shapes hit at the same fraction (the lower index wins)
/// whatever the rounding of the clipped ray's box tests: the clip lies this far (of the ray's
/// length) past the hit, as ShapeStore::ray_cast's does.
constexpr double clip_margin = 1e-9;
/// Conservative advancement's evaluations before a shape cast takes the last safe fraction.
constexpr int cast_iterations = 50;

/// The filter's body, checked: a stale or unknown body is a programming mistake, not a body
/// to leave out.
void check_filter(const World::Impl& w, const QueryFilter& f) {
    if (f.exclude_body.index != null_index && !w.bodies.is_valid(f.exclude_body))
        throw InvalidHandle("filter.exclude_body: stale or unknown BodyId " +
                            std::to_string(f.exclude_body.index) + ":" +
                            std::to_string(f.exclude_body.generation));
}

/// \srs{DD27} Whether the query sees shape s: DD27's category rule between the query (no
/// group) and the shape, and the shape not on the excluded body.
bool admits(const World::Impl& w, const QueryFilter& f, std::uint32_t s) {
    const Shape& sh = w.shapes.shapes[s];
    if (f.exclude_body.index != null_index && sh.body == f.exclude_body.index)
        return false;
    const Filter& g = w.shapes.defs[s].filter;
    return model::dd27::should_collide({f.category_bits, f.mask_bits, 0},
                                       {g.category_bits, g.mask_bits, g.group_index});
}

void check_ray(Vec2d origin, Vec2d translation) {
    // Within the supported range, |translation|^2 and the hit fraction cannot overflow.
    require_within("origin", origin, supported::input_max, "m");
    require_within("translation", translation, supported::input_max, "m");
}

/// A shape given to a query: the create_shape rules (DCX_shape), a pose within range.
void check_shape(const Geometry& shape, Vec2d origin, double angle) {
    ShapeDef def;
    def.geometry = shape;
    validate(def);
    require_within("origin", origin, supported::input_max, "m");
    require_within("angle", angle, supported::input_max, "rad");
}

/// Walks the trees along the ray; on_hit(hit) answers as a RayCastCallback does.
template <class OnHit>
void walk_ray(const World::Impl& w, Vec2d origin, Vec2d translation, const QueryFilter& filter,
              OnHit&& on_hit) {
    const ShapeStore& st = w.shapes;
    st.broad_phase.ray_cast(origin, translation, [&](int proxy, double max_fraction) -> double {
        const std::uint32_t s = st.broad_phase.user_data(proxy);
        if (st.defs[s].is_sensor || !admits(w, filter, s)) // a sensor is not there for rays
            return max_fraction;
        const Shape& sh = st.shapes[s];
        const auto hit = tamias2d::ray_cast(st.defs[s].geometry, w.bodies.bodies[sh.body].xf,
                                            origin, translation);
        if (!hit || hit->fraction > max_fraction)
            return max_fraction;
        const double v = on_hit(
            RayCastHit{st.id(s), w.bodies.id(sh.body), hit->point, hit->normal, hit->fraction});
        if (v < 0.0)
            return max_fraction; // ignored
        return v < max_fraction ? v : max_fraction;
    });
}

/// Whether hit a comes before hit b: the nearer, then the lower shape index.
template <class Hit> bool before(const Hit& a, const Hit& b) {
    return a.fraction < b.fraction || (a.fraction == b.fraction && a.shape.index < b.shape.index);
}

/// The cast's scale (m): the shape's reach from its centre, both ways, plus the translation.
double cast_scale(const Collider& k, Vec2d translation) {
    return 2.0 * reach(k, k.center) + length(translation);
}

/// Walks the shapes near the sweep; on_hit(hit) answers as a ShapeCastCallback does.
template <class OnHit>
void walk_cast(const World::Impl& w, const Geometry& shape, Vec2d origin, double angle,
               Vec2d translation, const QueryFilter& filter, OnHit&& on_hit) {
    const ShapeStore& st = w.shapes;
    const Collider moving = make_collider(shape);
    Sweep sweep;
    sweep.c0 = origin;
    sweep.c1 = origin + translation;
    sweep.a0 = sweep.a1 = angle;
    const Transform start = sweep.at(0.0);
    const double tau = 1e-6 * cast_scale(moving, translation);
    // The trees are walked along the cast, clipped at each hit (the box at the start, grown by
    // the tolerance, so that a shape within it of the path is met whatever the rounding).
    const Aabb box = inflated(compute_aabb(moving, start), tau);
    const Vec2d centre = transform_point(start, moving.center);
    const Vec2d box_centre{0.5 * (box.min_x + box.max_x), 0.5 * (box.min_y + box.max_y)};
    const Vec2d half{0.5 * (box.max_x - box.min_x), 0.5 * (box.max_y - box.min_y)};
    st.broad_phase.box_cast(box, translation, [&](int proxy, double max_fraction) -> double {
        const std::uint32_t s = st.broad_phase.user_data(proxy);
        if (st.defs[s].is_sensor || !admits(w, filter, s))
            return max_fraction;
        const Shape& sh = st.shapes[s];
        const Transform& xf = w.bodies.bodies[sh.body].xf;
        const Collider& other = sh.collider;
        if (other.type == ShapeType::chain_segment &&
            dot(rotate(xf.q, other.normal(0)), centre - transform_point(xf, other.vertex(0))) < 0.0)
            return max_fraction; // one-sided (DD31): a shape starting behind a chain edge
        // The shape's own box (its fat box was the tree's) met by the moving box, before the
        // conservative advancement: a shape beside the path costs a box test, not a walk of
        // the advancement up to it.
        const Aabb own = compute_aabb(other, xf);
        const Aabb grown{own.min_x - half.x, own.min_y - half.y, own.max_x + half.x,
                         own.max_y + half.y};
        if (!detail::segment_crosses(grown, box_centre, translation, max_fraction))
            return max_fraction;
        // \srs{DD29} One time of impact, the continuous pass's: the gap at the fraction found
        // is at least the target (tau / 2) and at most target + tolerance (tau).
        const ToiResult r = time_of_impact(moving, sweep, other, xf, 0.5 * tau, 0.5 * tau,
                                           max_fraction, cast_iterations);
        if (r.state == ToiState::separated)
            return max_fraction;
        const Transform at = sweep.at(r.t);
        const ShapeDistance sd = shape_distance(moving, at, other, xf);
        ShapeCastHit hit{st.id(s), w.bodies.id(sh.body), at.p, {}, r.t};
        if (sd.distance > 0.0) { // apart (else overlapping at the start: no direction)
            hit.point = sd.point_b;
            hit.normal = Vec2d{} - sd.normal; // (0 - x: no negative zero)
        }
        const double v = on_hit(hit);
        if (v < 0.0)
            return max_fraction; // ignored
        return v < max_fraction ? v : max_fraction;
    });
}

/// A point as a collider: a circle of radius 0 (DD34's core of a point).
Collider point_collider(Vec2d p) {
    Collider k;
    k.type = ShapeType::circle;
    k.center = p;
    return k;
}

ClosestPoints closest(const ShapeDistance& sd) {
    ClosestPoints out;
    out.distance = sd.distance;
    out.overlapping = !(sd.distance > 0.0);
    if (!out.overlapping) {
        out.point_a = sd.point_a;
        out.point_b = sd.point_b;
        out.normal = sd.normal;
    }
    return out;
}

} // namespace

std::optional<RayCastHit> World::ray_cast(Vec2d origin, Vec2d translation,
                                          const QueryFilter& filter) const {
    check_ray(origin, translation);
    check_filter(*impl_, filter);
    std::optional<RayCastHit> best;
    walk_ray(*impl_, origin, translation, filter, [&](const RayCastHit& hit) {
        if (!best || before(hit, *best))
            best = hit;
        return best->fraction + clip_margin;
    });
    return best;
}

std::vector<RayCastHit> World::ray_cast_all(Vec2d origin, Vec2d translation,
                                            const QueryFilter& filter) const {
    check_ray(origin, translation);
    check_filter(*impl_, filter);
    std::vector<RayCastHit> hits;
    walk_ray(*impl_, origin, translation, filter, [&](const RayCastHit& hit) {
        hits.push_back(hit);
        return 1.0;
    });
    std::sort(hits.begin(), hits.end(), before<RayCastHit>);
    return hits;
}

std::size_t World::ray_cast_all(Vec2d origin, Vec2d translation, const QueryFilter& filter,
                                std::span<RayCastHit> out) const {
    check_ray(origin, translation);
    check_filter(*impl_, filter);
    std::size_t total = 0;
    std::size_t kept = 0;
    walk_ray(*impl_, origin, translation, filter, [&](const RayCastHit& hit) {
        ++total;
        // Insertion into the sorted prefix, the farthest dropped when it is full.
        std::size_t i = kept;
        if (kept < out.size())
            ++kept;
        else if (kept == 0 || !before(hit, out[kept - 1]))
            return 1.0;
        else
            i = kept - 1;
        while (i > 0 && before(hit, out[i - 1])) {
            out[i] = out[i - 1];
            --i;
        }
        out[i] = hit;
        return 1.0;
    });
    return total;
}

std::optional<RayCastHit> World::ray_cast_any(Vec2d origin, Vec2d translation,
                                              const QueryFilter& filter) const {
    check_ray(origin, translation);
    check_filter(*impl_, filter);
    std::optional<RayCastHit> found;
    walk_ray(*impl_, origin, translation, filter, [&](const RayCastHit& hit) {
        found = hit;
        return 0.0;
    });
    return found;
}

void World::ray_cast(Vec2d origin, Vec2d translation, const QueryFilter& filter,
                     RayCastCallback callback) const {
    check_ray(origin, translation);
    check_filter(*impl_, filter);
    walk_ray(*impl_, origin, translation, filter,
             [&](const RayCastHit& hit) { return callback(hit); });
}

std::optional<RayCastHit> World::ray_cast(ShapeId shape, Vec2d origin, Vec2d translation) const {
    const Shape& sh = impl_->shapes.get(shape);
    check_ray(origin, translation);
    const auto hit = tamias2d::ray_cast(impl_->shapes.defs[shape.index].geometry,
                                        impl_->bodies.bodies[sh.body].xf, origin, translation);
    if (!hit)
        return std::nullopt;
    return RayCastHit{shape, impl_->bodies.id(sh.body), hit->point, hit->normal, hit->fraction};
}

std::optional<ShapeCastHit> World::shape_cast(const Geometry& shape, Vec2d origin, double angle,
                                              Vec2d translation, const QueryFilter& filter) const {
    check_shape(shape, origin, angle);
    require_within("translation", translation, supported::input_max, "m");
    check_filter(*impl_, filter);
    std::optional<ShapeCastHit> best;
    walk_cast(*impl_, shape, origin, angle, translation, filter, [&](const ShapeCastHit& hit) {
        if (!best || before(hit, *best))
            best = hit;
        return std::min(1.0, best->fraction + clip_margin);
    });
    return best;
}

void World::shape_cast(const Geometry& shape, Vec2d origin, double angle, Vec2d translation,
                       const QueryFilter& filter, ShapeCastCallback callback) const {
    check_shape(shape, origin, angle);
    require_within("translation", translation, supported::input_max, "m");
    check_filter(*impl_, filter);
    walk_cast(*impl_, shape, origin, angle, translation, filter,
              [&](const ShapeCastHit& hit) { return callback(hit); });
}

double World::cast_tolerance(const Geometry& shape, Vec2d translation) {
    return 1e-6 * cast_scale(make_collider(shape), translation);
}

std::vector<ShapeId> World::query_aabb(const Aabb& box, const QueryFilter& filter) const {
    std::vector<ShapeId> out;
    query_aabb(box, filter, [&](ShapeId s) {
        out.push_back(s);
        return true;
    });
    std::sort(out.begin(), out.end(), [](ShapeId a, ShapeId b) { return a.index < b.index; });
    return out;
}

void World::query_aabb(const Aabb& box, const QueryFilter& filter, OverlapCallback callback) const {
    validate_query_box(box, "box");
    check_filter(*impl_, filter);
    const Impl& w = *impl_;
    w.shapes.broad_phase.query(box, [&](int proxy) {
        const std::uint32_t s = w.shapes.broad_phase.user_data(proxy);
        if (!admits(w, filter, s))
            return true;
        const Shape& sh = w.shapes.shapes[s];
        if (!overlaps(w.shapes.box(sh, w.bodies.bodies[sh.body]), box))
            return true;
        return callback(w.shapes.id(s));
    });
}

std::vector<ShapeId> World::query_point(Vec2d point, const QueryFilter& filter) const {
    std::vector<ShapeId> out;
    query_point(point, filter, [&](ShapeId s) {
        out.push_back(s);
        return true;
    });
    std::sort(out.begin(), out.end(), [](ShapeId a, ShapeId b) { return a.index < b.index; });
    return out;
}

void World::query_point(Vec2d point, const QueryFilter& filter, OverlapCallback callback) const {
    require_finite("point", point); // a NaN point is in no shape: refused, not answered empty
    check_filter(*impl_, filter);
    const Impl& w = *impl_;
    w.shapes.broad_phase.query(Aabb{point.x, point.y, point.x, point.y}, [&](int proxy) {
        const std::uint32_t s = w.shapes.broad_phase.user_data(proxy);
        if (!admits(w, filter, s))
            return true;
        const Shape& sh = w.shapes.shapes[s];
        if (!test_point(w.shapes.defs[s].geometry, w.bodies.bodies[sh.body].xf, point))
            return true;
        return callback(w.shapes.id(s));
    });
}

std::vector<ShapeId> World::overlap_shape(const Geometry& shape, Vec2d origin, double angle,
                                          const QueryFilter& filter) const {
    std::vector<ShapeId> out;
    overlap_shape(shape, origin, angle, filter, [&](ShapeId s) {
        out.push_back(s);
        return true;
    });
    std::sort(out.begin(), out.end(), [](ShapeId a, ShapeId b) { return a.index < b.index; });
    return out;
}

void World::overlap_shape(const Geometry& shape, Vec2d origin, double angle,
                          const QueryFilter& filter, OverlapCallback callback) const {
    check_shape(shape, origin, angle);
    check_filter(*impl_, filter);
    const Impl& w = *impl_;
    const Collider k = make_collider(shape);
    const Transform xf{origin, Rot::from_angle(angle)};
    w.shapes.broad_phase.query(compute_aabb(k, xf), [&](int proxy) {
        const std::uint32_t s = w.shapes.broad_phase.user_data(proxy);
        if (!admits(w, filter, s))
            return true;
        const Shape& sh = w.shapes.shapes[s];
        // \srs{DD34} They share a point when their gap is not positive.
        if (shape_distance(k, xf, sh.collider, w.bodies.bodies[sh.body].xf).distance > 0.0)
            return true;
        return callback(w.shapes.id(s));
    });
}

ClosestPoints World::distance(ShapeId a, ShapeId b) const {
    const Shape& sa = impl_->shapes.get(a);
    const Shape& sb = impl_->shapes.get(b);
    const auto& bodies = impl_->bodies.bodies;
    return closest(
        shape_distance(sa.collider, bodies[sa.body].xf, sb.collider, bodies[sb.body].xf));
}

ClosestPoints World::closest_point(ShapeId shape, Vec2d point) const {
    const Shape& sh = impl_->shapes.get(shape);
    require_within("point", point, supported::input_max, "m");
    ClosestPoints out = closest(shape_distance(sh.collider, impl_->bodies.bodies[sh.body].xf,
                                               point_collider(point), Transform{}));
    out.point_b = point;
    return out;
}

} // namespace tamias2d
