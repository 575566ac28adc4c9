#include "tamias2d/validation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <tuple>
#include <utility>

#include "tamias2d/errors.hpp"
#include "tamias2d/geometry/shape_factory.hpp"
#include "tamias2d/math/hypot.hpp"
#include "tamias2d/math/vec2d.hpp"
#include "tamias2d/model/dcx_shape_non_degenerate_shapes.hpp"

namespace tamias2d {

void require_finite(std::string_view field, double value) {
    if (!std::isfinite(value)) {
        throw ValidationError(std::string(field), value, "must be a finite number", "DCX_finite");
    }
}

void require_finite(std::string_view field, Vec2d value) {
    // The field's name is built only for a message: validation runs on every creation and
    // every snapshot read, where a string per vector was most of its time.
    if (std::isfinite(value.x) && std::isfinite(value.y))
        return;
    require_finite(std::string(field) + ".x", value.x);
    require_finite(std::string(field) + ".y", value.y);
}

namespace {
std::string with_unit(std::string_view unit) {
    return unit.empty() ? std::string{} : " " + std::string(unit);
}
} // namespace

void require_within(std::string_view field, double value, double max, std::string_view unit) {
    require_finite(field, value);
    if (!(std::abs(value) <= max))
        throw ValidationError(std::string(field), value,
                              "must be in [-" + detail::format_value(max) + ", " +
                                  detail::format_value(max) + "]" + with_unit(unit) +
                                  ", the supported range",
                              "DCX_range");
}

void require_within(std::string_view field, Vec2d value, double max, std::string_view unit) {
    if (std::isfinite(value.x) && std::isfinite(value.y) && std::abs(value.x) <= max &&
        std::abs(value.y) <= max)
        return;
    require_within(std::string(field) + ".x", value.x, max, unit);
    require_within(std::string(field) + ".y", value.y, max, unit);
}

void require_scale(std::string_view field, double value, double lo, double hi,
                   std::string_view unit) {
    if (!(value >= lo && value <= hi))
        throw ValidationError(std::string(field), value,
                              "must be in [" + detail::format_value(lo) + ", " +
                                  detail::format_value(hi) + "]" + with_unit(unit) +
                                  ", the supported range",
                              "DCX_range");
}

void validate_size(std::string_view field, double value) {
    require_finite(field, value);
    if (!(value > 0.0))
        throw ValidationError(std::string(field), value, "must be > 0", "DCX_shape");
    require_scale(field, value, supported::input_min, supported::input_max, "m");
}

namespace {
/// Distance from p to the line through a and b, as make_polygon computes it.
double distance_to_line(Vec2d a, Vec2d b, Vec2d p) {
    return std::abs(cross(b - a, p - a)) / length(b - a);
}
} // namespace

void validate_proportions(const Polygon& p) {
    const int n = p.count;
    double lo_x = p.vertices[0].x, hi_x = lo_x, lo_y = p.vertices[0].y, hi_y = lo_y;
    for (int i = 1; i < n; ++i) {
        lo_x = std::min(lo_x, p.vertices[i].x);
        hi_x = std::max(hi_x, p.vertices[i].x);
        lo_y = std::min(lo_y, p.vertices[i].y);
        hi_y = std::max(hi_y, p.vertices[i].y);
    }
    const double extent = std::max(hi_x - lo_x, hi_y - lo_y);
    const double tol = hull_weld_tolerance * extent;
    // make_polygon's final check, term for term, on the same vertex triples and the same fan
    // (its hull order is the polygon's); the area's sign is dropped so that a clockwise
    // polygon reaches validate's orientation check instead.
    double min_height = extent;
    for (int i = 0; i < n; ++i)
        min_height = std::min(min_height, distance_to_line(p.vertices[(i + n - 1) % n],
                                                           p.vertices[(i + 1) % n], p.vertices[i]));
    const double area = model::dcx_shape::polygon_area(p.vertices.data(), std::size_t(n)).value();
    const auto of_extent = [&] { // (made only to fail)
        return detail::format_value(hull_weld_tolerance) + " x the extent (" +
               detail::format_value(extent) + " m)";
    };
    if (!(min_height >= tol))
        throw ValidationError("polygon.thickness", min_height,
                              "must be >= " + of_extent() +
                                  ": every vertex that far from its neighbours' chord (a sliver)",
                              "DCX_shape");
    if (!(std::abs(area) > tol * extent))
        throw ValidationError("polygon.area", area,
                              "must be > " + of_extent() + " x the extent (a sliver)", "DCX_shape");
}

void validate_mass(std::string_view field, double mass) {
    require_finite(field, mass);
    if (!(mass > 0.0))
        throw ValidationError(std::string(field), mass, "must be > 0", "DCI_m");
    require_scale(field, mass, supported::mass_min, supported::mass_max, "kg");
}

void validate_inertia(std::string_view field, double inertia) {
    require_finite(field, inertia);
    if (!(inertia > 0.0)) {
        throw ValidationError(std::string(field), inertia, "must be > 0", "DCI_I");
    }
    require_scale(field, inertia, supported::inertia_min, supported::inertia_max, "kg m^2");
}

void validate_damping(std::string_view field, double rate) {
    require_finite(field, rate);
    if (!(rate >= 0.0))
        throw ValidationError(std::string(field), rate, "must be >= 0", "DCX_damping");
    require_within(field, rate, supported::input_max, "s^-1");
}

void validate(const BodyDef& def) {
    using supported::input_max;
    require_within("body.position", def.position, input_max, "m");
    // DCI_phi: any real orientation (within the supported range: joints multiply angle
    // differences) is accepted on input and wrapped to [0, 2 pi) on output.
    require_within("body.angle", def.angle, input_max, "rad");
    require_within("body.linear_velocity", def.linear_velocity, input_max, "m s^-1");
    require_within("body.angular_velocity", def.angular_velocity, input_max, "rad s^-1");
    require_within("body.force", def.force, input_max, "N");
    require_within("body.torque", def.torque, input_max, "N m");
    require_within("body.gravity_scale", def.gravity_scale, input_max, "");
    validate_damping("body.linear_damping", def.linear_damping);
    validate_damping("body.angular_damping", def.angular_damping);
    if (def.mass)
        validate_mass("body.mass", *def.mass);
    if (def.inertia)
        validate_inertia("body.inertia", *def.inertia);
    if (def.sleep_threshold)
        validate_sleep_threshold("body.sleep_threshold", *def.sleep_threshold);
}

void validate_sleep_threshold(std::string_view field, double speed) {
    require_finite(field, speed);
    if (!(speed >= 0.0))
        throw ValidationError(std::string(field), speed, "must be >= 0", "DCX_finite");
    require_within(field, speed, supported::input_max, "m s^-1");
}

void validate(const Material& material) {
    require_finite("material.density", material.density);
    if (!(material.density > 0.0)) {
        throw ValidationError("material.density", material.density, "must be > 0", "DCX_density");
    }
    require_scale("material.density", material.density, supported::input_min, supported::input_max,
                  "kg m^-2");
    require_finite("material.restitution", material.restitution);
    if (!(material.restitution >= 0.0 && material.restitution <= 1.0)) {
        throw ValidationError("material.restitution", material.restitution, "must be in [0, 1]",
                              "DCI_CR");
    }
    require_finite("material.friction", material.friction);
    if (!(material.friction >= 0.0)) {
        throw ValidationError("material.friction", material.friction, "must be >= 0",
                              "DCX_friction");
    }
    require_within("material.friction", material.friction, supported::input_max, "");
    validate_rolling_resistance("material.rolling_resistance", material.rolling_resistance);
    validate_tangent_speed("material.tangent_speed", material.tangent_speed);
}

void validate_rolling_resistance(std::string_view field, double c) {
    require_finite(field, c);
    if (!(c >= 0.0)) // \srs{DD46}
        throw ValidationError(std::string(field), c, "must be >= 0", "DD46");
    require_within(field, c, supported::input_max, "");
}

void validate_tangent_speed(std::string_view field, double speed) {
    require_finite(field, speed); // \srs{DD47} any sign
    require_within(field, speed, supported::input_max, "m s^-1");
}

namespace {
/// DCX_range of a shape's numbers that are finite and positive where they must be (the rest is
/// left to validate(Geometry), which names them): before the structural checks, which a shape
/// too large or too small for doubles fails with a meaningless message (a normal of length 0).
void validate_geometry_range(const Geometry& g) {
    using supported::input_max;
    if (g.type == ShapeType::circle) {
        if (std::isfinite(g.circle.radius) && g.circle.radius > 0.0)
            validate_size("shape.radius", g.circle.radius);
        if (std::isfinite(g.circle.center.x) && std::isfinite(g.circle.center.y))
            require_within("shape.center", g.circle.center, input_max, "m");
        return;
    }
    if (g.type != ShapeType::polygon) {
        // A segment kind: its points within range, its length (and a capsule's radius) in
        // scale; non-finite values are left to validate(Geometry), which names them.
        Vec2d ends[4]{};
        const char* names[4]{};
        const char* kind = g.type == ShapeType::capsule   ? "capsule.length"
                           : g.type == ShapeType::segment ? "segment.length"
                                                          : "chain_segment.length";
        int count = 2;
        double radius = 0.0;
        if (g.type == ShapeType::capsule) {
            ends[0] = g.capsule.center1, ends[1] = g.capsule.center2;
            names[0] = "capsule.center1", names[1] = "capsule.center2";
            radius = g.capsule.radius;
        } else if (g.type == ShapeType::segment) {
            ends[0] = g.segment.point1, ends[1] = g.segment.point2;
            names[0] = "segment.point1", names[1] = "segment.point2";
        } else {
            const ChainSegment& c = g.chain_segment;
            ends[0] = c.point1, ends[1] = c.point2, ends[2] = c.ghost1, ends[3] = c.ghost2;
            names[0] = "chain_segment.point1", names[1] = "chain_segment.point2";
            names[2] = "chain_segment.ghost1", names[3] = "chain_segment.ghost2";
            count = 4;
        }
        for (int i = 0; i < count; ++i)
            if (!std::isfinite(ends[i].x) || !std::isfinite(ends[i].y))
                return;
        for (int i = 0; i < count; ++i)
            require_within(names[i], ends[i], input_max, "m");
        if (std::isfinite(radius) && radius > 0.0)
            validate_size("capsule.radius", radius);
        const double len = length(ends[1] - ends[0]);
        if (len > 0.0)
            require_scale(kind, len, supported::input_min, 2.0 * input_max, "m");
        return;
    }
    const Polygon& p = g.polygon;
    if (p.count < 3 || p.count > max_polygon_vertices)
        return;
    for (int i = 0; i < p.count; ++i) {
        if (!std::isfinite(p.vertices[i].x) || !std::isfinite(p.vertices[i].y))
            return;
    }
    for (int i = 0; i < p.count; ++i) {
        const Vec2d v = p.vertices[i];
        if (!(std::abs(v.x) <= input_max && std::abs(v.y) <= input_max)) // named only to fail
            require_within("polygon.vertices[" + std::to_string(i) + "]", v, input_max, "m");
    }
    double lo_x = p.vertices[0].x, hi_x = lo_x, lo_y = p.vertices[0].y, hi_y = lo_y;
    for (int i = 1; i < p.count; ++i) {
        lo_x = std::min(lo_x, p.vertices[i].x);
        hi_x = std::max(hi_x, p.vertices[i].x);
        lo_y = std::min(lo_y, p.vertices[i].y);
        hi_y = std::max(hi_y, p.vertices[i].y);
    }
    require_scale("polygon.extent", std::max(hi_x - lo_x, hi_y - lo_y), supported::input_min,
                  2.0 * input_max, "m");
    validate_proportions(p);
}
} // namespace

void validate(const ShapeDef& def) {
    validate_geometry_range(def.geometry);
    validate(def.geometry);
    validate(def.material);
}

const char* type_name(BodyType type) {
    const std::string_view name = to_string(type);
    return name.empty() ? "of no known type" : name.data();
}

namespace {
/// The bodies are named by their labels: a handle's index is a slot, not a value to fix.
void validate_joint_bodies(const JointBody& a, const JointBody& b, double break_force) {
    constexpr ValidationError::NotANumber bodies{};
    if (a.id == b.id)
        throw ValidationError(bodies, "joint.body_b",
                              "must be another body than body_a, " + a.label, "DCX_joint");
    if (a.type != BodyType::dynamic && b.type != BodyType::dynamic)
        throw ValidationError(bodies, "joint.body_b",
                              b.label + " is " + type_name(b.type) + " and body_a, " + a.label +
                                  ", " + type_name(a.type) +
                                  ": one of a joint's two bodies must be dynamic",
                              "DCX_joint");
    if (!(break_force > 0.0))
        throw ValidationError("joint.break_force", break_force, "must be > 0", "DCX_joint");
}

/// A frequency, damping ratio or length >= 0, within the supported range.
void non_negative(const char* field, double v, std::string_view unit = "") {
    require_finite(field, v);
    if (!(v >= 0.0))
        throw ValidationError(field, v, "must be >= 0", "DCX_joint");
    require_within(field, v, supported::input_max, unit);
}

/// A frequency (Hz) already checked >= 0: 0 (off, where allowed) or within [input_min,
/// input_max]. A smaller one underflows h omega to zero, and with a damping ratio of 0 the soft
/// step's omega / (2 zeta + h omega) divides by zero.
void frequency(const char* field, double hertz) {
    if (hertz != 0.0)
        require_scale(field, hertz, supported::input_min, supported::input_max, "Hz");
}

/// A point (m): finite and within the supported range.
void point(const char* field, Vec2d p) {
    require_within(field, p, supported::input_max, "m");
}

/// An enabled spring: hertz > 0 and damping ratio >= 0 (a disabled one's values are unused,
/// but must still be numbers).
void validate_spring(bool enabled, double hertz, double damping_ratio) {
    require_finite("joint.hertz", hertz);
    if (enabled && !(hertz > 0.0))
        throw ValidationError("joint.hertz", hertz, "must be > 0 with the spring enabled",
                              "DCX_joint");
    non_negative("joint.hertz", hertz, "Hz");
    frequency("joint.hertz", hertz);
    non_negative("joint.damping_ratio", damping_ratio);
}

/// Limits lower <= upper, both finite and within the supported range (named as the definition
/// names them; `unit`: rad or m).
void validate_limits(const char* lower_field, double lower, const char* upper_field, double upper,
                     std::string_view unit) {
    require_within(lower_field, lower, supported::input_max, unit);
    require_within(upper_field, upper, supported::input_max, unit);
    if (!(lower <= upper))
        throw ValidationError(upper_field, upper, std::string("must be >= ") + (lower_field + 6),
                              "DCX_joint");
}

/// A motor: a speed within the supported range, largest force or torque >= 0 (infinite:
/// unbounded; it only clamps, so any value is safe).
void validate_motor(double speed, std::string_view speed_unit, const char* max_field, double max) {
    require_within("joint.motor_speed", speed, supported::input_max, speed_unit);
    if (!(max >= 0.0))
        throw ValidationError(max_field, max, "must be >= 0", "DCX_joint");
}

/// An axis: finite and of non-zero length (it is normalised); DCX_range: components within
/// input_max and a length of at least input_min, so that its squared length neither overflows
/// nor underflows (either would normalise it to zero).
void validate_axis(Vec2d axis) {
    require_within("joint.axis", axis, supported::input_max, "");
    const double len = math::hypot(axis.x, axis.y); // the same bits everywhere
    if (!(len > 0.0))
        throw ValidationError("joint.axis", len, "must have a non-zero length", "DCX_joint");
    require_scale("joint.axis", len, supported::input_min, 2.0 * supported::input_max, "");
}
} // namespace

namespace {
/// The fields a joint's definition shares with its run-time setters (World::
/// set_joint_spring_target, set_constraint_tuning), checked as those check them.
template <class Def> void validate_definition_controls(const Def& def, const char* target_unit) {
    if constexpr (requires { def.spring_target; })
        require_within("joint.spring_target", def.spring_target, supported::input_max, target_unit);
    if (def.constraint_tuning)
        validate_constraint_tuning(
            def.constraint_tuning->hertz, def.constraint_tuning->damping_ratio,
            "joint.constraint_tuning.hertz", "joint.constraint_tuning.damping_ratio");
}
} // namespace

void validate(const DistanceJointDef& def, const JointBody& a, const JointBody& b) {
    validate_joint_bodies(a, b, def.break_force);
    point("joint.anchor_a", def.anchor_a);
    point("joint.anchor_b", def.anchor_b);
    const Vec2d d = def.anchor_b - def.anchor_a;
    const double length = def.length.value_or(std::sqrt(d.x * d.x + d.y * d.y));
    require_finite("joint.length", length);
    if (!(length > 0.0))
        throw ValidationError("joint.length", length,
                              "must be > 0 (given, or the anchors' distance)", "DCX_joint");
    if (def.length) // (the anchors' distance is within range with them)
        require_within("joint.length", *def.length, supported::input_max, "m");
    non_negative("joint.hertz", def.hertz, "Hz");
    frequency("joint.hertz", def.hertz);
    non_negative("joint.damping_ratio", def.damping_ratio);
    non_negative("joint.min_length", def.min_length, "m");
    if (!(def.max_length >= def.min_length)) // an infinite max_length: no upper bound
        throw ValidationError("joint.max_length", def.max_length, "must be >= min_length",
                              "DCX_joint");
    if (std::isfinite(def.max_length)) // the limit multiplies its error: a finite one is bounded
        require_within("joint.max_length", def.max_length, supported::input_max, "m");
    validate_motor(def.motor_speed, "m s^-1", "joint.max_motor_force", def.max_motor_force);
    validate_definition_controls(def, "m");
}

void validate(const TargetJointDef& def, const JointBody& body) {
    if (body.type != BodyType::dynamic)
        throw ValidationError(ValidationError::NotANumber{}, "joint.body",
                              body.label + " is " + type_name(body.type) +
                                  ": a target joint's body must be dynamic",
                              "DCX_joint");
    point("joint.target", def.target);
    require_finite("joint.hertz", def.hertz);
    if (!(def.hertz > 0.0))
        throw ValidationError("joint.hertz", def.hertz, "must be > 0", "DCX_joint");
    frequency("joint.hertz", def.hertz);
    non_negative("joint.damping_ratio", def.damping_ratio);
    if (!(def.max_force > 0.0))
        throw ValidationError("joint.max_force", def.max_force, "must be > 0", "DCX_joint");
}

bool joint_lever_fits(Vec2d r, double inv_mass, double inv_inertia) {
    // (|r| / k)^2 = |r|^2 m / I, from the inverses the solver holds (0: does not move or turn).
    constexpr double max = supported::joint_lever_ratio_max;
    return !(inv_mass > 0.0) || !(inv_inertia > 0.0) ||
           dot(r, r) * inv_inertia / inv_mass <= max * max;
}

void validate_joint_lever(std::string_view field, Vec2d r, double inv_mass, double inv_inertia) {
    if (joint_lever_fits(r, inv_mass, inv_inertia))
        return;
    const double ratio = std::sqrt(dot(r, r) * inv_inertia / inv_mass);
    constexpr double max = supported::joint_lever_ratio_max;
    throw ValidationError(std::string(field), ratio,
                          "the anchor's distance from its body's centre of mass, in radii of "
                          "gyration sqrt(I / m), must be <= " +
                              detail::format_value(max) + " (a joint cannot hold it)",
                          "DCX_joint");
}

void validate(const RevoluteJointDef& def, const JointBody& a, const JointBody& b) {
    validate_joint_bodies(a, b, def.break_force);
    validate_break_torque(def.break_torque);
    point("joint.anchor", def.anchor);
    validate_limits("joint.lower_angle", def.lower_angle, "joint.upper_angle", def.upper_angle,
                    "rad");
    validate_motor(def.motor_speed, "rad s^-1", "joint.max_motor_torque", def.max_motor_torque);
    validate_spring(def.enable_spring, def.hertz, def.damping_ratio);
    validate_definition_controls(def, "rad");
}

void validate(const PrismaticJointDef& def, const JointBody& a, const JointBody& b) {
    validate_joint_bodies(a, b, def.break_force);
    validate_break_torque(def.break_torque);
    point("joint.anchor", def.anchor);
    validate_axis(def.axis);
    validate_limits("joint.lower_translation", def.lower_translation, "joint.upper_translation",
                    def.upper_translation, "m");
    validate_motor(def.motor_speed, "m s^-1", "joint.max_motor_force", def.max_motor_force);
    validate_spring(def.enable_spring, def.hertz, def.damping_ratio);
    validate_definition_controls(def, "m");
}

void validate(const WeldJointDef& def, const JointBody& a, const JointBody& b) {
    validate_joint_bodies(a, b, def.break_force);
    validate_break_torque(def.break_torque);
    point("joint.anchor", def.anchor);
    non_negative("joint.linear_hertz", def.linear_hertz, "Hz");
    frequency("joint.linear_hertz", def.linear_hertz);
    non_negative("joint.linear_damping_ratio", def.linear_damping_ratio);
    non_negative("joint.angular_hertz", def.angular_hertz, "Hz");
    frequency("joint.angular_hertz", def.angular_hertz);
    non_negative("joint.angular_damping_ratio", def.angular_damping_ratio);
    validate_definition_controls(def, "");
}

void validate(const WheelJointDef& def, const JointBody& a, const JointBody& b) {
    validate_joint_bodies(a, b, def.break_force);
    validate_break_torque(def.break_torque);
    point("joint.anchor", def.anchor);
    validate_axis(def.axis);
    validate_spring(def.enable_spring, def.hertz, def.damping_ratio);
    validate_limits("joint.lower_translation", def.lower_translation, "joint.upper_translation",
                    def.upper_translation, "m");
    validate_motor(def.motor_speed, "rad s^-1", "joint.max_motor_torque", def.max_motor_torque);
    validate_definition_controls(def, "m");
}

void validate(const MotorJointDef& def, const JointBody& a, const JointBody& b) {
    validate_joint_bodies(a, b, def.break_force);
    validate_break_torque(def.break_torque);
    point("joint.linear_offset", def.linear_offset);
    require_within("joint.angular_offset", def.angular_offset, supported::input_max, "rad");
    if (!(def.max_force >= 0.0))
        throw ValidationError("joint.max_force", def.max_force, "must be >= 0", "DCX_joint");
    if (!(def.max_torque >= 0.0))
        throw ValidationError("joint.max_torque", def.max_torque, "must be >= 0", "DCX_joint");
    require_finite("joint.correction_factor", def.correction_factor);
    if (!(def.correction_factor >= 0.0 && def.correction_factor <= 1.0))
        throw ValidationError("joint.correction_factor", def.correction_factor, "must be in [0, 1]",
                              "DCX_joint");
}

void validate(const FilterJointDef&, const JointBody& a, const JointBody& b) {
    validate_joint_bodies(a, b, std::numeric_limits<double>::infinity());
}

void validate(const WorldDef& def) {
    require_within("world.gravity", def.gravity, supported::input_max, "m s^-2");
    if (def.substeps < 1 || def.substeps > 64) {
        throw ValidationError("world.substeps", def.substeps, "must be in [1, 64]", "DCX_dt");
    }
    const auto positive = [](const char* field, double v, std::string_view unit) {
        require_finite(field, v);
        if (!(v > 0.0))
            throw ValidationError(field, v, "must be > 0", "DCX_finite");
        require_within(field, v, supported::input_max, unit);
    };
    positive("world.contact_hertz", def.contact_hertz, "Hz");
    frequency("world.contact_hertz", def.contact_hertz);
    positive("world.contact_damping_ratio", def.contact_damping_ratio, "");
    positive("world.contact_push_max_velocity", def.contact_push_max_velocity, "m s^-1");
    positive("world.joint_hertz", def.joint_hertz, "Hz");
    frequency("world.joint_hertz", def.joint_hertz);
    positive("world.joint_damping_ratio", def.joint_damping_ratio, "");
    const auto non_negative = [](const char* field, double v, std::string_view unit) {
        require_finite(field, v);
        if (!(v >= 0.0))
            throw ValidationError(field, v, "must be >= 0", "DCX_finite");
        require_within(field, v, supported::input_max, unit);
    };
    non_negative("world.linear_slop", def.linear_slop, "m");
    non_negative("world.speculative_distance", def.speculative_distance, "m");
    non_negative("world.manifold_reuse_distance", def.manifold_reuse_distance, "m");
    non_negative("world.restitution_threshold", def.restitution_threshold, "m s^-1");
    validate_event_threshold("world.hit_event_threshold", def.hit_event_threshold, false);
    // \srs{DD40} A speed limit: any speed > 0, infinite for none.
    if (!(def.maximum_linear_speed > 0.0))
        throw ValidationError("world.maximum_linear_speed", def.maximum_linear_speed,
                              "must be > 0 (infinite: no limit)", "DD40");
    non_negative("world.time_to_sleep", def.time_to_sleep, "s");
    non_negative("world.linear_sleep_tolerance", def.linear_sleep_tolerance, "m s^-1");
    non_negative("world.angular_sleep_tolerance", def.angular_sleep_tolerance, "rad s^-1");
    // Threads are the library's own setting, not the SRS's: "threads" names the rule.
    if (def.workers < 1 || def.workers > 256)
        throw ValidationError("world.workers", def.workers, "must be in [1, 256]", "threads");
    if (def.contact_regions < 1 || def.contact_regions > 8)
        throw ValidationError("world.contact_regions", def.contact_regions, "must be in [1, 8]",
                              "threads");
    if ((def.task_system.enqueue == nullptr) != (def.task_system.finish == nullptr))
        throw ValidationError("world.task_system", std::nan(""),
                              "needs both enqueue and finish, or neither", "threads");
    // Sizing, not physics: "capacity" names the rule.
    const auto hint = [](const char* field, int n) {
        if (n < 0 || n > max_capacity_hint)
            throw ValidationError(
                field, n, "must be in [0, " + std::to_string(max_capacity_hint) + "]", "capacity");
    };
    hint("world.capacity.bodies", def.capacity.bodies);
    hint("world.capacity.shapes", def.capacity.shapes);
    hint("world.capacity.joints", def.capacity.joints);
    hint("world.capacity.contacts", def.capacity.contacts);
}

void validate_event_threshold(std::string_view field, double value, bool may_be_infinite) {
    // (the field's name is made only to fail: a world's calls allocate nothing else)
    if (std::isnan(value) || (!may_be_infinite && std::isinf(value)))
        throw ValidationError(std::string(field), value,
                              may_be_infinite ? "must be a number" : "must be finite", "events");
    if (!(value >= 0.0))
        throw ValidationError(std::string(field), value, "must be >= 0", "events");
    if (!may_be_infinite)
        require_within(field, value, supported::input_max, "m s^-1");
}

void validate_time_step(double dt) {
    require_finite("dt", dt);
    if (!(dt > 0.0))
        throw ValidationError("dt", dt, "must be > 0", "DCX_dt");
    require_scale("dt", dt, supported::input_min, supported::input_max, "s");
}

// --- joint_control: the definitions' rules, a field at a time, for the joints' setters ---

void validate_break_torque(double torque) {
    if (!(torque > 0.0))
        throw ValidationError("joint.break_torque", torque, "must be > 0", "DCX_joint");
}

void validate_break_force(double force) {
    if (!(force > 0.0))
        throw ValidationError("joint.break_force", force, "must be > 0", "DCX_joint");
}

void validate_joint_limits(const char* lower_field, double lower, const char* upper_field,
                           double upper, std::string_view unit) {
    validate_limits(lower_field, lower, upper_field, upper, unit);
}

void validate_length_range(double min_length, double max_length) {
    non_negative("joint.min_length", min_length, "m");
    if (!(max_length >= min_length))
        throw ValidationError("joint.max_length", max_length, "must be >= min_length", "DCX_joint");
    if (std::isfinite(max_length))
        require_within("joint.max_length", max_length, supported::input_max, "m");
}

void validate_joint_max_motor(const char* field, double max) {
    if (!(max >= 0.0))
        throw ValidationError(field, max, "must be >= 0", "DCX_joint");
}

void validate_joint_spring(bool enabled, double hertz, double damping_ratio) {
    validate_spring(enabled, hertz, damping_ratio);
}

void validate_distance_spring(double hertz, double damping_ratio) {
    non_negative("joint.hertz", hertz, "Hz");
    frequency("joint.hertz", hertz);
    non_negative("joint.damping_ratio", damping_ratio);
}

void validate_target_spring(double hertz, double damping_ratio) {
    require_finite("joint.hertz", hertz);
    if (!(hertz > 0.0))
        throw ValidationError("joint.hertz", hertz, "must be > 0", "DCX_joint");
    frequency("joint.hertz", hertz);
    non_negative("joint.damping_ratio", damping_ratio);
}

void validate_rest_length(double length) {
    require_finite("joint.length", length);
    if (!(length > 0.0))
        throw ValidationError("joint.length", length, "must be > 0", "DCX_joint");
    require_within("joint.length", length, supported::input_max, "m");
}

void validate_constraint_tuning(double hertz, double damping_ratio) {
    validate_constraint_tuning(hertz, damping_ratio, "joint.tuning_hertz",
                               "joint.tuning_damping_ratio");
}

void validate_constraint_tuning(double hertz, double damping_ratio, const char* hertz_field,
                                const char* ratio_field) {
    // As WorldDef::joint_hertz and joint_damping_ratio are checked (validate(WorldDef)).
    for (const auto& [field, v, unit] :
         {std::tuple{hertz_field, hertz, "Hz"}, std::tuple{ratio_field, damping_ratio, ""}}) {
        require_finite(field, v);
        if (!(v > 0.0))
            throw ValidationError(field, v, "must be > 0", "DCX_joint");
        require_within(field, v, supported::input_max, unit);
    }
    frequency(hertz_field, hertz);
}

void validate_query_box(const Aabb& box, const std::string& name) {
    // A box upside down on an axis (min > max) or with a NaN side contains nothing: answering
    // it with no shapes would hide the caller's mistake (corners swapped, a size for a corner).
    require_finite(name + ".min_x", box.min_x);
    require_finite(name + ".min_y", box.min_y);
    require_finite(name + ".max_x", box.max_x);
    require_finite(name + ".max_y", box.max_y);
    // The query's own rule, not an SRS data constraint: "query" names it.
    if (!(box.min_x <= box.max_x))
        throw ValidationError(
            name + ".max_x", box.max_x,
            "must be >= " + name + ".min_x (" + detail::format_value(box.min_x) + " m)", "query");
    if (!(box.min_y <= box.max_y))
        throw ValidationError(
            name + ".max_y", box.max_y,
            "must be >= " + name + ".min_y (" + detail::format_value(box.min_y) + " m)", "query");
}

} // namespace tamias2d
