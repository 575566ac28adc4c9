#include "tamias2d/dynamics/shape_store.hpp"

#include <algorithm>
#include <string>

#include "tamias2d/dynamics/body_store.hpp"
#include "tamias2d/dynamics/snapshot_io.hpp"
#include "tamias2d/dynamics/state_hasher.hpp"
#include "tamias2d/errors.hpp"
#include "tamias2d/geometry/shape_factory.hpp"
#include "tamias2d/geometry/shape_queries.hpp"
#include "tamias2d/math/prefetch.hpp"
#include "tamias2d/memory/allocator.hpp"
#include "tamias2d/validation.hpp"

namespace tamias2d {

std::uint32_t ShapeStore::create(std::uint32_t body_index, Body& b, const ShapeDef& def) {
    const std::uint32_t i = slots.acquire();
    if (i == shapes.size()) {
        shapes.emplace_back();
        defs.emplace_back();
    }
    Shape& s = shapes[i];
    s.body = body_index;
    s.next = null_index;
    defs[i] = def;
    defs[i].geometry = canonical(def.geometry); // unused members carry nothing
    note_surface_motion(def.material);
    s.collider = make_collider(defs[i].geometry);
    if (last_of_body.size() <= body_index)
        last_of_body.resize(std::size_t(body_index) + 1, null_index);
    std::uint32_t& link =
        b.first_shape != null_index ? shapes[last_of_body[body_index]].next : b.first_shape;
    link = i;
    last_of_body[body_index] = i;
    s.proxy = broad_phase.create_proxy(box(s, b), i, b.type == BodyType::static_body);
    s.fat_box = broad_phase.fat_aabb(s.proxy);
    return i;
}

void ShapeStore::destroy(std::uint32_t i, Body& b) {
    Shape& s = shapes[i];
    std::uint32_t* link = &b.first_shape;
    std::uint32_t before = null_index;
    while (*link != i) {
        before = *link;
        link = &shapes[*link].next;
    }
    *link = s.next;
    if (s.next == null_index) // the last shape: the one before it is now
        last_of_body[s.body] = before;
    release(i);
}

void ShapeStore::forget_pending(std::uint32_t s) {
    std::erase(undecided_, s);
    const int proxy = shapes[s].proxy;
    std::erase_if(proxy_moves_,
                  [proxy](const BroadPhase::ProxyMove& m) { return m.proxy == proxy; });
}

void ShapeStore::release(std::uint32_t i) {
    forget_pending(i);
    broad_phase.destroy_proxy(shapes[i].proxy);
    shapes[i].proxy = -1;
    slots.release(i);
}

void ShapeStore::sync_poses(const Body& b) {
    for (std::uint32_t s = b.first_shape; s != null_index; s = shapes[s].next) {
        shapes[s].body_xf = b.xf;
        shapes[s].body_center = b.center;
    }
}

void ShapeStore::refit_undecided() {
    // The shapes the header could not decide (moving ones) read their vertex lines, which the
    // step's sweep does not ask for: read after the sweep, a few shapes ahead, rather than
    // waited for one by one inside it. The same shapes in the same order: the same moves.
    constexpr std::size_t refit_ahead = 4;
    for (std::size_t j = 0; j < undecided_.size(); ++j) {
        if (j + refit_ahead < undecided_.size()) {
            const Shape& next = shapes[undecided_[j + refit_ahead]];
            const char* p = reinterpret_cast<const char*>(&next.collider);
            prefetch(p); // vertex pairs 0 and 1: a box's four vertices
            prefetch(p + 64);
            prefetch(&next.fat_box);
            prefetch(&next.body_xf);
        }
        refit_fat_box(shapes[undecided_[j]]);
    }
    undecided_.clear();
    apply_moves();
}

std::vector<ShapeId> ShapeStore::ids_of(const Body& b) const {
    std::vector<ShapeId> out;
    for (std::uint32_t s = b.first_shape; s != null_index; s = shapes[s].next)
        out.push_back(id(s));
    return out;
}

void ShapeStore::move_with(const Body& b) {
    for (std::uint32_t s = b.first_shape; s != null_index; s = shapes[s].next)
        follow_body(shapes[s], b);
    apply_moves();
}

std::vector<ShapeId> ShapeStore::overlapping(const Aabb& box, const BodyStore& bodies) const {
    std::vector<ShapeId> out;
    broad_phase.query(box, [&](int proxy) {
        const std::uint32_t s = broad_phase.user_data(proxy);
        const Shape& sh = shapes[s];
        if (!bodies.disabled(sh.body) && overlaps(this->box(sh, bodies.bodies[sh.body]), box))
            out.push_back(id(s));
        return true;
    });
    std::sort(out.begin(), out.end(), [](ShapeId a, ShapeId b) { return a.index < b.index; });
    return out;
}

std::vector<ShapeId> ShapeStore::containing(Vec2d p, const BodyStore& bodies) const {
    std::vector<ShapeId> out;
    const Aabb box{p.x, p.y, p.x, p.y};
    broad_phase.query(box, [&](int proxy) {
        const std::uint32_t s = broad_phase.user_data(proxy);
        const Shape& sh = shapes[s];
        if (!bodies.disabled(sh.body) && test_point(defs[s].geometry, bodies.bodies[sh.body].xf, p))
            out.push_back(id(s));
        return true;
    });
    std::sort(out.begin(), out.end(), [](ShapeId a, ShapeId b) { return a.index < b.index; });
    return out;
}

std::optional<RayCastHit> ShapeStore::ray_cast(Vec2d origin, Vec2d translation,
                                               const BodyStore& bodies) const {
    // The trees are walked along the ray, clipped at the nearest hit so far: a shape beyond it
    // is not visited (a long diagonal ray no longer visits every shape in its bounding box).
    // The clip lies a little past the hit, so that a shape hit at the same fraction (the lower
    // index wins) is still visited whatever the rounding of the clipped ray's box tests.
    constexpr double clip_margin = 1e-9; // of the ray's length
    std::optional<RayCastHit> best;
    broad_phase.ray_cast(origin, translation, [&](int proxy, double max_fraction) {
        const std::uint32_t s = broad_phase.user_data(proxy);
        // A sensor is not there for rays (DD28), nor a disabled body's shape.
        if (!defs[s].is_sensor && !bodies.disabled(shapes[s].body)) {
            const Shape& sh = shapes[s];
            const auto hit = tamias2d::ray_cast(defs[s].geometry, bodies.bodies[sh.body].xf, origin,
                                                translation);
            if (hit && (!best || hit->fraction < best->fraction ||
                        (hit->fraction == best->fraction && s < best->shape.index)))
                best =
                    RayCastHit{id(s), bodies.id(sh.body), hit->point, hit->normal, hit->fraction};
        }
        return best ? std::min(max_fraction, best->fraction + clip_margin) : max_fraction;
    });
    return best;
}

void ShapeStore::hash(StateHasher& hs) const {
    hs(std::uint64_t(shapes.size()));
    for (std::uint32_t i = 0; i < shapes.size(); ++i) {
        const Shape& s = shapes[i];
        hs(std::uint64_t(slots.generation(i)) << 1 | std::uint64_t(slots.live(i)));
        if (!slots.live(i))
            continue;
        const ShapeDef& d = defs[i];
        hs(std::uint64_t(s.body));
        hs(std::uint64_t(d.geometry.type));
        hs(d.geometry.circle.center);
        hs(d.geometry.circle.radius);
        hs(std::uint64_t(d.geometry.polygon.count));
        for (int k = 0; k < d.geometry.polygon.count; ++k)
            hs(d.geometry.polygon.vertices[std::size_t(k)]);
        if (d.geometry.type == ShapeType::capsule) {
            hs(d.geometry.capsule.center1);
            hs(d.geometry.capsule.center2);
            hs(d.geometry.capsule.radius);
        } else if (d.geometry.type == ShapeType::segment) {
            hs(d.geometry.segment.point1);
            hs(d.geometry.segment.point2);
        } else if (d.geometry.type == ShapeType::chain_segment) {
            hs(d.geometry.chain_segment.ghost1);
            hs(d.geometry.chain_segment.point1);
            hs(d.geometry.chain_segment.point2);
            hs(d.geometry.chain_segment.ghost2);
        }
        hs(d.material.density);
        hs(d.material.restitution);
        hs(d.material.friction);
        if (d.material.user_material_id != 0) // (DD42; default shapes hash as they always did)
            hs(d.material.user_material_id);
        if (!d.enable_pre_solve) // (switches the callback off for its pairs; the same)
            hs(std::uint64_t(0x9e5017e));
        if (d.material.rolling_resistance != 0.0 || d.material.tangent_speed != 0.0) {
            hs(d.material.rolling_resistance); // (DD46, DD47; the same)
            hs(d.material.tangent_speed);
        }
        if (!(d.filter == Filter{}) || d.is_sensor) { // (default shapes hash as they always did)
            hs(std::uint64_t(d.filter.category_bits) << 32 | d.filter.mask_bits);
            hs(std::uint64_t(std::uint32_t(d.filter.group_index)) << 1 |
               std::uint64_t(d.is_sensor));
        }
    }
}

// --- snapshot ---

namespace {

/// Every field of a shape definition, in the snapshot's order (the writer and the reader both
/// call it): the one place a field added to ShapeDef is added to snapshots.
template <class IO, class D> void shape_def_fields(IO& io, D& d) {
    auto& g = d.geometry;
    io.enumeration("geometry.type", g.type, ShapeType::chain_segment);
    io("circle.center", g.circle.center);
    io("circle.radius", g.circle.radius);
    for (auto& v : g.polygon.vertices)
        io("polygon.vertices", v);
    for (auto& v : g.polygon.normals)
        io("polygon.normals", v);
    io("polygon.centroid", g.polygon.centroid);
    io("polygon.count", g.polygon.count);
    io("capsule.center1", g.capsule.center1);
    io("capsule.center2", g.capsule.center2);
    io("capsule.radius", g.capsule.radius);
    io("segment.point1", g.segment.point1);
    io("segment.point2", g.segment.point2);
    io("chain_segment.ghost1", g.chain_segment.ghost1);
    io("chain_segment.point1", g.chain_segment.point1);
    io("chain_segment.point2", g.chain_segment.point2);
    io("chain_segment.ghost2", g.chain_segment.ghost2);
    io("material.density", d.material.density);
    io("material.restitution", d.material.restitution);
    io("material.friction", d.material.friction);
    io("material.user_material_id", d.material.user_material_id);
    io("material.rolling_resistance", d.material.rolling_resistance);
    io("material.tangent_speed", d.material.tangent_speed);
    io("filter.category_bits", d.filter.category_bits);
    io("filter.mask_bits", d.filter.mask_bits);
    io("filter.group_index", d.filter.group_index);
    io("is_sensor", d.is_sensor);
    io("enable_contact_events", d.enable_contact_events);
    io("enable_sensor_events", d.enable_sensor_events);
    io("enable_hit_events", d.enable_hit_events);
    io("enable_pre_solve", d.enable_pre_solve);
    io.user_data("user_data", d.user_data);
}

/// Every field of a Shape but its collider (made from the definition), in the snapshot's order.
template <class IO, class S> void shape_fields(IO& io, S& s) {
    io("fat_box", s.fat_box);
    io("body_xf", s.body_xf);
    io("body_center", s.body_center);
    io("body", s.body);
    io("proxy", s.proxy);
    io("next", s.next);
}

} // namespace

void ShapeStore::write(SnapshotWriter& out) const {
    out.section("SHAP");
    slots.write(out);
    for (std::uint32_t i = 0; i < shapes.size(); ++i) {
        shape_def_fields(out, defs[i]);
        shape_fields(out, shapes[i]);
    }
    broad_phase.write(out);
    out("surface_motion", surface_motion);
}

void ShapeStore::read(SnapshotReader& in) {
    in.section("SHAP");
    in.in("shapes");
    slots.read(in);
    const std::size_t n = slots.size();
    shapes.resize(n);
    defs.resize(n);
    memory::vector<std::size_t> at(n);
    for (std::uint32_t i = 0; i < n; ++i) {
        in.in("shapes", i);
        at[i] = in.offset();
        shape_def_fields(in, defs[i]);
        Shape& s = shapes[i];
        s = Shape{};
        shape_fields(in, s);
        in.require(s.alive() == slots.live(i), "proxy",
                   "must be a proxy for a live slot and -1 for a dead one", at[i]);
        if (!s.alive())
            continue;
        const int count = defs[i].geometry.polygon.count;
        if (!(count >= 0 && count <= max_polygon_vertices)) // (message built only to fail)
            in.fail_at(at[i], "polygon.count",
                       "must be in [0, " + decimal(std::uint64_t(max_polygon_vertices)) + "]");
        try {
            validate(defs[i]);
        } catch (const ValidationError& e) {
            in.fail_at(at[i], "", std::string("the definition is refused: ") + e.what());
        }
        s.collider = make_collider(defs[i].geometry);
        note_surface_motion(defs[i].material);
    }
    in.in(nullptr);
    broad_phase.read(in);
    int live = 0;
    for (std::uint32_t i = 0; i < n; ++i) {
        const Shape& s = shapes[i];
        if (!s.alive())
            continue;
        ++live;
        in.in("shapes", i);
        if (!broad_phase.is_proxy(s.proxy) || broad_phase.user_data(s.proxy) != i)
            in.fail_at(at[i], "proxy", "must be a leaf of the broad phase whose user is the shape");
    }
    in.in(nullptr);
    if (live != broad_phase.proxy_count()) // (message built only to fail)
        in.fail("broad_phase",
                "must hold one proxy per live shape (" + decimal(std::uint64_t(live)) + ")");
    // DD46, DD47: the steps solve surface motion as the world written did (a shape may have
    // had it and have it no more); a world with a live shape that has it had it since that
    // shape was made or set, so a snapshot saying otherwise is refused rather than mended (it
    // would not write back as the same bytes).
    const bool needed = surface_motion;
    const std::size_t flag_at = in.offset();
    bool had = false;
    in("surface_motion", had);
    in.require(had || !needed, "surface_motion", "must be 1 when a live shape has surface motion",
               flag_at);
    surface_motion = had;
}

// --- shape_control ---

void ShapeStore::reshape(std::uint32_t i, const Geometry& geometry) {
    defs[i].geometry = canonical(geometry); // unused members carry nothing
    shapes[i].collider = make_collider(defs[i].geometry);
}

void ShapeStore::refit_proxy(std::uint32_t i, const Body& b) {
    Shape& sh = shapes[i];
    sh.fat_box = broad_phase.fattened(box(sh, b));
    const BroadPhase::ProxyMove move{sh.proxy, sh.fat_box};
    broad_phase.move_proxies({&move, 1});
    broad_phase.touch_proxy(sh.proxy);
}

// --- run-time control ---

void ShapeStore::refile_proxies(const Body& b) {
    const bool is_static = b.type == BodyType::static_body;
    for (std::uint32_t s = b.first_shape; s != null_index; s = shapes[s].next) {
        Shape& sh = shapes[s];
        if (broad_phase.is_static(sh.proxy) == is_static) {
            broad_phase.touch_proxy(sh.proxy);
            continue;
        }
        forget_pending(s);
        broad_phase.destroy_proxy(sh.proxy);
        sh.proxy = broad_phase.create_proxy(box(sh, b), s, is_static); // (counts as moved)
        sh.fat_box = broad_phase.fat_aabb(sh.proxy);
    }
}

} // namespace tamias2d
