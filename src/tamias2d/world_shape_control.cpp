// The shapes' settings after creation (World's shape_control calls): material, geometry and the
// sensor flag. Each call checks the handle and the value (the rule create_shape applies,
// validation.hpp) before it changes anything; a change that would leave a joint's anchor beyond
// its lever limit is undone and refused.
#include <cstdint>
#include <string>

#include "tamias2d/dynamics/joints/joint_store.hpp"
#include "tamias2d/errors.hpp"
#include "tamias2d/validation.hpp"
#include "tamias2d/world.hpp"
#include "tamias2d/world_impl.hpp"

namespace tamias2d {

namespace {

/// A changed shape acts from the next step: its body is woken, and with sleeping on the bodies
/// touching it (a static body does not wake, and its sleeping neighbours must feel the change).
void wake_shape(World::Impl& w, std::uint32_t body) {
    w.bodies.wake(body);
    if (w.def.enable_sleep)
        w.contacts.wake_touching(body, w.bodies);
}

/// Shape i's body's mass from its shapes (DD1, DD14), refused (DCX_joint) if a joint's anchor
/// would then lie beyond its lever limit; `undo` restores what the caller changed, and the mass
/// is then computed again from the shapes as they were: the same shapes, the same bits.
template <class Undo> void update_mass_checked(World::Impl& w, std::uint32_t body, Undo&& undo) {
    w.bodies.update_mass(body, w.shapes);
    try {
        for (const std::uint32_t k : w.joints.of_body(body))
            validate_levers(w.bodies, w.joints.joints[k], k);
    } catch (...) {
        undo();
        w.bodies.update_mass(body, w.shapes);
        throw;
    }
}

/// The shape of a handle, its body's mass brought up to date (a mass left pending by
/// create_shape is settled before anything is compared or changed).
Shape& shape_of(World::Impl& w, ShapeId id) {
    Shape& sh = w.shapes.get(id);
    w.bodies.get(w.bodies.id(sh.body));
    return sh;
}

/// \srs{DD46, DD47} Sets a shape's surface-motion field (Material::rolling_resistance or
/// tangent_speed) to a validated value. The contacts read it from the shapes at each step, so
/// nothing else is updated; the world solves surface motion from then on.
void set_surface_motion(World::Impl& w, ShapeId id, double Material::*field, double value) {
    const Shape& sh = shape_of(w, id);
    Material& m = w.shapes.defs[id.index].material;
    if (m.*field == value)
        return;
    m.*field = value;
    w.shapes.note_surface_motion(m);
    wake_shape(w, sh.body);
}

/// Replaces a shape's geometry by a validated one (set_circle, set_capsule, ...).
void reshape(World::Impl& w, ShapeId id, const Geometry& geometry, const char* call) {
    const Shape& sh = shape_of(w, id);
    if (w.shapes.defs[id.index].geometry.type == ShapeType::chain_segment)
        throw WrongKind(call, "shape[" + std::to_string(id.index) + "]", "chain segment",
                        "must not be a chain's segment (its neighbours' ghost vertices depend "
                        "on it: make the chain again)");
    ShapeDef def = w.shapes.defs[id.index];
    def.geometry = geometry;
    validate(def); // as create_shape: DCX_shape, DCX_range
    const Geometry old = w.shapes.defs[id.index].geometry;
    const std::uint32_t body = sh.body;
    w.shapes.reshape(id.index, geometry);
    update_mass_checked(w, body, [&] { w.shapes.reshape(id.index, old); });
    // The contacts of the old outline end; the new one's pairs are found by the next step.
    w.contacts.destroy_of_shape(id.index, w.bodies, w.shapes);
    w.shapes.refit_proxy(id.index, w.bodies.bodies[body]);
    wake_shape(w, body);
}

/// Whether two geometries are the same, member by member (as canonical stores them).
bool same_geometry(const Geometry& a, const Geometry& b) {
    if (a.type != b.type)
        return false;
    const auto same = [](Vec2d p, Vec2d q) { return p.x == q.x && p.y == q.y; };
    switch (a.type) {
    case ShapeType::circle:
        return same(a.circle.center, b.circle.center) && a.circle.radius == b.circle.radius;
    case ShapeType::capsule:
        return same(a.capsule.center1, b.capsule.center1) &&
               same(a.capsule.center2, b.capsule.center2) && a.capsule.radius == b.capsule.radius;
    case ShapeType::segment:
        return same(a.segment.point1, b.segment.point1) && same(a.segment.point2, b.segment.point2);
    case ShapeType::polygon:
        if (a.polygon.count != b.polygon.count)
            return false;
        for (int k = 0; k < a.polygon.count; ++k) {
            const auto i = std::size_t(k);
            if (!same(a.polygon.vertices[i], b.polygon.vertices[i]) ||
                !same(a.polygon.normals[i], b.polygon.normals[i]))
                return false;
        }
        return same(a.polygon.centroid, b.polygon.centroid);
    case ShapeType::chain_segment:
        return false; // (never set through these calls)
    }
    return false;
}

void set_geometry(World::Impl& w, ShapeId id, const Geometry& geometry, const char* call) {
    shape_of(w, id);
    // (a chain segment's geometry is never equal to a circle, capsule, polygon or segment)
    if (same_geometry(w.shapes.defs[id.index].geometry, geometry))
        return; // the stored geometry, valid: nothing to change
    reshape(w, id, geometry, call);
}

} // namespace

void World::set_friction(ShapeId id, double friction) {
    Impl& w = *impl_;
    const Shape& sh = shape_of(w, id);
    Material m = w.shapes.defs[id.index].material;
    m.friction = friction;
    validate(m);
    if (w.shapes.defs[id.index].material.friction == friction)
        return;
    w.contacts.rematerial(id.index, w.shapes, m);
    wake_shape(w, sh.body);
}

double World::friction(ShapeId id) const {
    impl_->shapes.get(id);
    return impl_->shapes.defs[id.index].material.friction;
}

void World::set_restitution(ShapeId id, double restitution) {
    Impl& w = *impl_;
    const Shape& sh = shape_of(w, id);
    Material m = w.shapes.defs[id.index].material;
    m.restitution = restitution;
    validate(m);
    if (w.shapes.defs[id.index].material.restitution == restitution)
        return;
    w.contacts.rematerial(id.index, w.shapes, m);
    wake_shape(w, sh.body);
}

double World::restitution(ShapeId id) const {
    impl_->shapes.get(id);
    return impl_->shapes.defs[id.index].material.restitution;
}

void World::set_rolling_resistance(ShapeId id, double rolling_resistance) {
    shape_of(*impl_, id); // the handle before the value, as every setter
    validate_rolling_resistance("rolling_resistance", rolling_resistance);
    set_surface_motion(*impl_, id, &Material::rolling_resistance, rolling_resistance);
}

double World::rolling_resistance(ShapeId id) const {
    impl_->shapes.get(id);
    return impl_->shapes.defs[id.index].material.rolling_resistance;
}

void World::set_tangent_speed(ShapeId id, double tangent_speed) {
    shape_of(*impl_, id); // the handle before the value, as every setter
    validate_tangent_speed("tangent_speed", tangent_speed);
    set_surface_motion(*impl_, id, &Material::tangent_speed, tangent_speed);
}

double World::tangent_speed(ShapeId id) const {
    impl_->shapes.get(id);
    return impl_->shapes.defs[id.index].material.tangent_speed;
}

void World::set_density(ShapeId id, double density, bool update_body_mass) {
    Impl& w = *impl_;
    const Shape& sh = shape_of(w, id);
    Material m = w.shapes.defs[id.index].material;
    m.density = density;
    validate(m);
    double& stored = w.shapes.defs[id.index].material.density;
    const double old = stored;
    if (old == density && !update_body_mass)
        return;
    const std::uint32_t body = sh.body;
    stored = density;
    if (update_body_mass) {
        const Body& b = w.bodies.bodies[body];
        const double mass = b.mass, inertia = b.inertia;
        const Vec2d center = b.local_center;
        update_mass_checked(w, body, [&] { stored = old; });
        if (b.mass == mass && b.inertia == inertia && b.local_center.x == center.x &&
            b.local_center.y == center.y && old == density)
            return; // nothing changed: no wake
    }
    wake_shape(w, body);
}

double World::density(ShapeId id) const {
    impl_->shapes.get(id);
    return impl_->shapes.defs[id.index].material.density;
}

void World::set_circle(ShapeId id, const Circle& circle) {
    Geometry g;
    g.type = ShapeType::circle;
    g.circle = circle;
    set_geometry(*impl_, id, g, "set_circle");
}

void World::set_capsule(ShapeId id, const Capsule& capsule) {
    Geometry g;
    g.type = ShapeType::capsule;
    g.capsule = capsule;
    set_geometry(*impl_, id, g, "set_capsule");
}

void World::set_polygon(ShapeId id, const Polygon& polygon) {
    Geometry g;
    g.type = ShapeType::polygon;
    g.polygon = polygon;
    set_geometry(*impl_, id, g, "set_polygon");
}

void World::set_segment(ShapeId id, const Segment& segment) {
    Geometry g;
    g.type = ShapeType::segment;
    g.segment = segment;
    set_geometry(*impl_, id, g, "set_segment");
}

Geometry World::shape_geometry(ShapeId id) const {
    impl_->shapes.get(id);
    return impl_->shapes.defs[id.index].geometry;
}

void World::set_sensor(ShapeId id, bool sensor) {
    Impl& w = *impl_;
    const Shape& sh = shape_of(w, id);
    if (w.shapes.defs[id.index].is_sensor == sensor)
        return;
    // Its overlaps end (as a sensor, or as a visitor of others: sensors do not see sensors).
    w.sensors.remove_shape(id.index, w.bodies, w.shapes);
    if (sensor) {
        w.contacts.destroy_of_shape(id.index, w.bodies, w.shapes); // (end events, wakes)
        w.shapes.defs[id.index].is_sensor = true;
        w.sensors.add(id.index);
    } else {
        w.shapes.defs[id.index].is_sensor = false;
        w.shapes.broad_phase.touch_proxy(sh.proxy); // its contacts, from the next step
    }
    wake_shape(w, sh.body);
}

bool World::is_sensor(ShapeId id) const {
    impl_->shapes.get(id);
    return impl_->shapes.defs[id.index].is_sensor;
}

} // namespace tamias2d
