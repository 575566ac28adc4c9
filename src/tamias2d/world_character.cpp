// The World's character calls (include/tamias2d/world.hpp, "character"): a capsule mover cast
// and collided against the world (the queries' shape cast and DD34's distance), a kinematic
// body sent to a pose (DD44), and the wind's force on a shape (DD45).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "tamias2d/collision/collider.hpp"
#include "tamias2d/collision/time_of_impact.hpp"
#include "tamias2d/dynamics/bridge/typing.hpp"
#include "tamias2d/errors.hpp"
#include "tamias2d/geometry/projected_width.hpp"
#include "tamias2d/math/hypot.hpp"
#include "tamias2d/math/same_bits.hpp"
#include "tamias2d/model/dd09_chasles_theorem.hpp"
#include "tamias2d/model/dd44_kinematic_target.hpp"
#include "tamias2d/model/dd45_wind_force.hpp"
#include "tamias2d/validation.hpp"
#include "tamias2d/world.hpp"
#include "tamias2d/world_impl.hpp"

namespace tamias2d {

namespace {

namespace u = tamias2d::units;

/// The mover as a shape: create_shape's rules for a capsule (DCX_shape, DCX_range).
Geometry mover_geometry(const Capsule& mover) {
    ShapeDef def;
    def.geometry.type = ShapeType::capsule;
    def.geometry.capsule = mover;
    validate(def);
    return def.geometry;
}

} // namespace

double World::cast_mover(const Capsule& mover, Vec2d translation, const QueryFilter& filter) const {
    const Geometry g = mover_geometry(mover);
    double fraction = 1.0;
    // \srs{DD29} The queries' shape cast (one time of impact): a shape the mover already
    // touches or overlaps (a hit at fraction 0) is passed over, as collide_mover's planes
    // hold the mover off it.
    shape_cast(g, Vec2d{}, 0.0, translation, filter, [&](const ShapeCastHit& hit) -> double {
        if (!(hit.fraction > 0.0))
            return -1.0;
        if (hit.fraction < fraction)
            fraction = hit.fraction;
        return fraction;
    });
    return fraction;
}

std::vector<MoverPlane> World::collide_mover(const Capsule& mover,
                                             const QueryFilter& filter) const {
    std::vector<MoverPlane> out;
    collide_mover(mover, filter, [&](const MoverPlane& p) {
        out.push_back(p);
        return true;
    });
    std::sort(out.begin(), out.end(), [](const MoverPlane& a, const MoverPlane& b) {
        return a.shape.index < b.shape.index;
    });
    return out;
}

void World::collide_mover(const Capsule& mover, const QueryFilter& filter,
                          MoverPlaneCallback callback) const {
    mover_geometry(mover);
    const Impl& w = *impl_;
    const double r = mover.radius;
    const double reach = r + w.def.speculative_distance;
    const Collider core = make_collider(Segment{mover.center1, mover.center2});
    const Vec2d mid = 0.5 * (mover.center1 + mover.center2);
    const Aabb box{std::min(mover.center1.x, mover.center2.x) - reach,
                   std::min(mover.center1.y, mover.center2.y) - reach,
                   std::max(mover.center1.x, mover.center2.x) + reach,
                   std::max(mover.center1.y, mover.center2.y) + reach};
    query_aabb(box, filter, [&](ShapeId id) {
        const std::uint32_t s = id.index;
        if (w.shapes.defs[s].is_sensor) // a sensor holds nothing off
            return true;
        const Shape& sh = w.shapes.shapes[s];
        const Transform& xf = w.bodies.bodies[sh.body].xf;
        const Collider& k = sh.collider;
        if (k.type == ShapeType::chain_segment &&
            dot(rotate(xf.q, k.normal(0)), mid - transform_point(xf, k.vertex(0))) < 0.0)
            return true; // one-sided (DD31): the mover is behind the chain's edge
        // \srs{DD34} The distance from the shape to the mover's core and its direction.
        const ShapeDistance sd = shape_distance(k, xf, core, Transform{});
        if (!(sd.distance > 0.0) || sd.distance > reach)
            return true; // the core inside the shape (no direction), or beyond reach
        MoverPlane p{id, w.bodies.id(sh.body), {}, sd.point_a};
        p.plane.normal = sd.normal;
        p.plane.offset = r - sd.distance;
        return callback(p);
    });
}

/// \srs{DD44} The velocities that carry a kinematic body to a pose in one step.
void World::set_target_transform(BodyId body, Vec2d origin, double angle, double dt) {
    Impl& w = *impl_;
    Body& b = w.bodies.get(body);
    if (b.type != BodyType::kinematic)
        throw WrongKind("set_target_transform", w.bodies.label(body.index),
                        std::string(type_name(b.type)) + " body",
                        "must be a kinematic body (a dynamic body is moved by forces, a static "
                        "one does not move)");
    require_within("origin", origin, supported::input_max, "m");
    require_within("angle", angle, supported::input_max, "rad");
    validate_time_step(dt);
    const Transform target{origin, Rot::from_angle(angle)};
    const Vec2d c_target = transform_point(target, b.local_center);
    const u::Time h = u::from_value<u::Time>(dt);
    const Vec2d v = bridge::plain(model::dd44::target_velocity(
        bridge::typed<u::Length>(b.center), bridge::typed<u::Length>(c_target), h));
    const double omega = model::dd44::target_angular_velocity(
                             model::dd44::shortest_turn(u::from_value<u::Angle>(b.angle),
                                                        u::from_value<u::Angle>(angle)),
                             h)
                             .value();
    require_within("set_target_transform: the velocity", v, supported::state_max, "m s^-1");
    require_within("set_target_transform: the angular velocity", omega, supported::state_max,
                   "rad s^-1");
    if (math::same_bits(v.x, b.v.x) && math::same_bits(v.y, b.v.y) && math::same_bits(omega, b.w))
        return; // already on its way: nothing changes, nothing wakes
    b.v = v;
    b.w = omega;
    w.bodies.wake(body.index);
}

/// \srs{DD45} The wind's drag and lift on a shape, a one-step force at its centroid.
void World::apply_wind(ShapeId shape, Vec2d wind, double drag, double lift, bool wake) {
    Impl& w = *impl_;
    const Shape& sh = w.shapes.get(shape);
    const BodyId body = w.bodies.id(sh.body);
    const Body& b = w.bodies.get(body);
    if (b.type != BodyType::dynamic)
        throw WrongKind("apply_wind", w.bodies.label(sh.body),
                        std::string(type_name(b.type)) + " body",
                        "must be a dynamic body (a static or kinematic body does not move under "
                        "forces)");
    require_within("wind", wind, supported::input_max, "m s^-1");
    require_within("drag", drag, supported::input_max, "1");
    if (!(drag >= 0.0))
        throw ValidationError("drag", drag, "must be >= 0", "DD45");
    require_within("lift", lift, supported::input_max, "1");
    if (!wake && !w.bodies.active(sh.body))
        return; // asleep, and not to be woken: the wind waits
    const Vec2d centroid = transform_point(b.xf, sh.collider.center);
    const Vec2d v_shape = bridge::plain(model::dd09::point_velocity<double>(
        bridge::typed<u::Velocity>(b.v), u::from_value<u::AngularVelocity>(b.w),
        bridge::typed<u::Length>(centroid - b.center)));
    const u::Vec2<u::Velocity> rel = model::dd45::relative_wind(
        bridge::typed<u::Velocity>(wind), bridge::typed<u::Velocity>(v_shape));
    const double speed = math::hypot(rel.x.value(), rel.y.value());
    if (!(speed > 0.0))
        return; // still air: no force
    const Vec2d along{rel.x.value() / speed, rel.y.value() / speed};
    const double width = projected_width(w.shapes.defs[shape.index].geometry, b.xf.q, along);
    const Vec2d force = bridge::plain(model::dd45::wind_force(
        rel, u::from_value<u::Length>(width), u::from_value<u::Dimensionless>(drag),
        u::from_value<u::Dimensionless>(lift)));
    if (force.x == 0.0 && force.y == 0.0)
        return;
    apply_force(body, force, centroid); // DD13's torque r x F with it; wakes the body
}

} // namespace tamias2d
