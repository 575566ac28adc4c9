// World::draw: the world handed to a DebugDraw as primitives (include/tamias2d/debug_draw.hpp).
// It only reads: the shapes' geometry and their bodies' poses, the broad phase's boxes, the
// joints' anchors, the contact report, the bodies' centres of mass.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "tamias2d/debug_draw.hpp"
#include "tamias2d/errors.hpp"
#include "tamias2d/geometry/aabb.hpp"
#include "tamias2d/memory/allocator.hpp"
#include "tamias2d/validation.hpp"
#include "tamias2d/world.hpp"
#include "tamias2d/world_impl.hpp"

namespace tamias2d {

namespace {

/// The settings of `draw` a drawing can be made with: every length finite and > 0, and the
/// bounds (if any) a box right side up with finite sides, as World::query_aabb asks.
void validate_draw(const DebugDraw& draw) {
    // Drawing's own rules, not SRS data constraints: "draw" and "query" name them.
    require_finite("draw.contact_normal_length", draw.contact_normal_length);
    if (!(draw.contact_normal_length > 0.0))
        throw ValidationError("draw.contact_normal_length", draw.contact_normal_length,
                              "must be > 0 (m)", "draw");
    require_finite("draw.axis_length", draw.axis_length);
    if (!(draw.axis_length > 0.0))
        throw ValidationError("draw.axis_length", draw.axis_length, "must be > 0 (m)", "draw");
    if (!draw.bounds)
        return;
    validate_query_box(*draw.bounds, "draw.bounds");
}

bool inside(const std::optional<Aabb>& bounds, Vec2d p) {
    return !bounds || (bounds->min_x <= p.x && p.x <= bounds->max_x && bounds->min_y <= p.y &&
                       p.y <= bounds->max_y);
}

/// The shapes to draw, in index order: every live one, or those whose broad-phase boxes
/// overlap `bounds`.
memory::vector<std::uint32_t> shapes_to_draw(const ShapeStore& shapes,
                                             const std::optional<Aabb>& bounds) {
    memory::vector<std::uint32_t> out;
    if (!bounds) {
        for (std::uint32_t s = 0; s < shapes.shapes.size(); ++s) {
            if (shapes.shapes[s].alive())
                out.push_back(s);
        }
        return out;
    }
    shapes.broad_phase.query(*bounds, [&](int proxy) {
        out.push_back(shapes.broad_phase.user_data(proxy));
        return true;
    });
    std::sort(out.begin(), out.end());
    return out;
}

void draw_shape(const Geometry& g, const Transform& xf, double angle, Color color,
                DebugDraw& draw) {
    switch (g.type) {
    case ShapeType::circle:
        draw.solid_circle(transform_point(xf, g.circle.center), g.circle.radius, angle, color);
        break;
    case ShapeType::polygon: {
        std::array<Vec2d, max_polygon_vertices> v{};
        for (int k = 0; k < g.polygon.count; ++k)
            v[std::size_t(k)] = transform_point(xf, g.polygon.vertices[std::size_t(k)]);
        draw.solid_polygon(std::span<const Vec2d>(v.data(), std::size_t(g.polygon.count)), color);
        break;
    }
    case ShapeType::capsule:
        draw.solid_capsule(transform_point(xf, g.capsule.center1),
                           transform_point(xf, g.capsule.center2), g.capsule.radius, color);
        break;
    case ShapeType::segment:
        draw.segment(transform_point(xf, g.segment.point1), transform_point(xf, g.segment.point2),
                     color);
        break;
    case ShapeType::chain_segment:
        draw.segment(transform_point(xf, g.chain_segment.point1),
                     transform_point(xf, g.chain_segment.point2), color);
        break;
    }
}

} // namespace

void World::draw(DebugDraw& draw) const {
    validate_draw(draw);
    const Impl& w = *impl_;
    w.bodies.settle(); // the centres of mass attach_shape left pending
    const DrawColors& colors = draw.colors;
    const std::optional<Aabb>& bounds = draw.bounds;

    if (draw.draw_shapes || draw.draw_aabbs) {
        const memory::vector<std::uint32_t> drawn = shapes_to_draw(w.shapes, bounds);
        if (draw.draw_shapes) {
            for (const std::uint32_t s : drawn) {
                const Shape& sh = w.shapes.shapes[s];
                const Body& b = w.bodies.bodies[sh.body];
                Color color = colors.awake;
                if (w.shapes.defs[s].is_sensor)
                    color = colors.sensor;
                else if (w.bodies.settings[sh.body].bullet)
                    color = colors.bullet;
                else if (b.type == BodyType::static_body)
                    color = colors.static_body;
                else if (b.type == BodyType::kinematic)
                    color = colors.kinematic;
                else if (!w.bodies.sleep_states[sh.body].awake)
                    color = colors.sleeping;
                draw_shape(w.shapes.defs[s].geometry, b.xf, b.angle, color, draw);
            }
        }
        if (draw.draw_aabbs) {
            for (const std::uint32_t s : drawn) {
                const Aabb& a = w.shapes.shapes[s].fat_box;
                const std::array<Vec2d, 4> v{{{a.min_x, a.min_y},
                                              {a.max_x, a.min_y},
                                              {a.max_x, a.max_y},
                                              {a.min_x, a.max_y}}};
                draw.polygon(v, colors.aabb);
            }
        }
    }

    if (draw.draw_joints) {
        for (std::uint32_t i = 0; i < w.joints.joints.size(); ++i) {
            if (!w.joints.alive(i))
                continue;
            const Joint& j = w.joints.joints[i];
            const Body& a = w.bodies.bodies[j.body_a];
            const Body& b = w.bodies.bodies[j.body_b];
            const Color c = colors.joint;
            switch (j.type) {
            case JointType::target: { // the body's point, pulled towards the target
                const Vec2d anchor = transform_point(b.xf, j.local_anchor_b);
                if (!inside(bounds, anchor) && !inside(bounds, j.target))
                    break;
                draw.segment(b.center, anchor, c);
                draw.segment(anchor, j.target, c);
                break;
            }
            case JointType::filter: // no anchors: the two bodies it keeps apart
            case JointType::motor:  // a pose of B relative to A, not a point
                if (!inside(bounds, a.center) && !inside(bounds, b.center))
                    break;
                draw.segment(a.center, b.center, c);
                break;
            default: {
                const Vec2d pa = transform_point(a.xf, j.local_anchor_a);
                const Vec2d pb = transform_point(b.xf, j.local_anchor_b);
                if (!inside(bounds, pa) && !inside(bounds, pb))
                    break;
                draw.segment(a.center, pa, c);
                draw.segment(pa, pb, c);
                draw.segment(pb, b.center, c);
                break;
            }
            }
        }
    }

    if (draw.draw_contacts || draw.draw_contact_normals) {
        for (const ContactInfo& ci : contacts()) {
            for (int k = 0; k < ci.point_count; ++k) {
                const Vec2d p = ci.points[k].point;
                if (!inside(bounds, p))
                    continue;
                if (draw.draw_contacts)
                    draw.point(p, 5.0, colors.contact_point);
                if (draw.draw_contact_normals)
                    draw.segment(p, p + draw.contact_normal_length * ci.normal,
                                 colors.contact_normal);
            }
        }
    }

    if (draw.draw_mass_centers) {
        for (std::uint32_t i = 0; i < w.bodies.size(); ++i) {
            const Body& b = w.bodies.bodies[i];
            if (w.bodies.alive(i) && inside(bounds, b.center))
                draw.transform(b.center, b.angle, draw.axis_length);
        }
    }
}

} // namespace tamias2d
