#include "tamias2d/validation.hpp"

#include <cmath>
#include <string>
#include <utility>

#include "tamias2d/errors.hpp"
#include "tamias2d/geometry/shape_factory.hpp"

namespace tamias2d {

void require_finite(std::string_view field, double value) {
    if (!std::isfinite(value)) {
        throw ValidationError(std::string(field), value, "must be a finite number", "DCX_finite");
    }
}

void require_finite(std::string_view field, Vec2d value) {
    require_finite(std::string(field) + ".x", value.x);
    require_finite(std::string(field) + ".y", value.y);
}

void validate_mass(std::string_view field, double mass) {
    require_finite(field, mass);
    if (!(mass > 0.0))
        throw ValidationError(std::string(field), mass, "must be > 0", "DCI_m");
}

void validate_inertia(std::string_view field, double inertia) {
    require_finite(field, inertia);
    if (!(inertia > 0.0)) {
        throw ValidationError(std::string(field), inertia, "must be > 0", "DCI_I");
    }
}

void validate_damping(std::string_view field, double rate) {
    require_finite(field, rate);
    if (!(rate >= 0.0))
        throw ValidationError(std::string(field), rate, "must be >= 0", "DCX_damping");
}

void validate(const BodyDef& def) {
    require_finite("body.position", def.position);
    // DCI_phi: any real orientation is accepted on input and wrapped to [0, 2 pi) on output.
    require_finite("body.angle", def.angle);
    require_finite("body.linear_velocity", def.linear_velocity);
    require_finite("body.angular_velocity", def.angular_velocity);
    require_finite("body.force", def.force);
    require_finite("body.torque", def.torque);
    require_finite("body.gravity_scale", def.gravity_scale);
    validate_damping("body.linear_damping", def.linear_damping);
    validate_damping("body.angular_damping", def.angular_damping);
    if (def.mass)
        validate_mass("body.mass", *def.mass);
    if (def.inertia)
        validate_inertia("body.inertia", *def.inertia);
}

void validate(const Material& material) {
    require_finite("material.density", material.density);
    if (!(material.density > 0.0)) {
        throw ValidationError("material.density", material.density, "must be > 0", "DCX_density");
    }
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
}

void validate(const ShapeDef& def) {
    validate(def.geometry);
    validate(def.material);
}

namespace {
void validate_joint_bodies(BodyId a, BodyId b, bool movable, double break_force) {
    if (a == b)
        throw ValidationError("joint.body_b", double(b.index), "must be another body than body_a",
                              "DCX_joint");
    if (!movable)
        throw ValidationError("joint.body_b", double(b.index),
                              "one of the two bodies must be dynamic", "DCX_joint");
    if (!(break_force > 0.0))
        throw ValidationError("joint.break_force", break_force, "must be > 0", "DCX_joint");
}

void non_negative(const char* field, double v) {
    require_finite(field, v);
    if (!(v >= 0.0))
        throw ValidationError(field, v, "must be >= 0", "DCX_joint");
}

/// An enabled spring: hertz > 0 and damping ratio >= 0 (a disabled one's values are unused,
/// but must still be numbers).
void validate_spring(bool enabled, double hertz, double damping_ratio) {
    require_finite("joint.hertz", hertz);
    if (enabled && !(hertz > 0.0))
        throw ValidationError("joint.hertz", hertz, "must be > 0 with the spring enabled",
                              "DCX_joint");
    non_negative("joint.hertz", hertz);
    non_negative("joint.damping_ratio", damping_ratio);
}

/// Limits lower <= upper, both finite (named as the definition names them).
void validate_limits(const char* lower_field, double lower, const char* upper_field, double upper) {
    require_finite(lower_field, lower);
    require_finite(upper_field, upper);
    if (!(lower <= upper))
        throw ValidationError(upper_field, upper, std::string("must be >= ") + (lower_field + 6),
                              "DCX_joint");
}

/// A motor: finite speed, largest force or torque >= 0 (infinite: unbounded).
void validate_motor(double speed, const char* max_field, double max) {
    require_finite("joint.motor_speed", speed);
    if (!(max >= 0.0))
        throw ValidationError(max_field, max, "must be >= 0", "DCX_joint");
}

/// An axis: finite and of non-zero length (it is normalised).
void validate_axis(Vec2d axis) {
    require_finite("joint.axis", axis);
    if (!(axis.x * axis.x + axis.y * axis.y > 0.0))
        throw ValidationError("joint.axis", std::sqrt(axis.x * axis.x + axis.y * axis.y),
                              "must have a non-zero length", "DCX_joint");
}
} // namespace

void validate(const DistanceJointDef& def, bool movable) {
    validate_joint_bodies(def.body_a, def.body_b, movable, def.break_force);
    require_finite("joint.anchor_a", def.anchor_a);
    require_finite("joint.anchor_b", def.anchor_b);
    const Vec2d d = def.anchor_b - def.anchor_a;
    const double length = def.length.value_or(std::sqrt(d.x * d.x + d.y * d.y));
    require_finite("joint.length", length);
    if (!(length > 0.0))
        throw ValidationError("joint.length", length,
                              "must be > 0 (given, or the anchors' distance)", "DCX_joint");
    non_negative("joint.hertz", def.hertz);
    non_negative("joint.damping_ratio", def.damping_ratio);
    non_negative("joint.min_length", def.min_length);
    if (!(def.max_length >= def.min_length)) // an infinite max_length: no upper bound
        throw ValidationError("joint.max_length", def.max_length, "must be >= min_length",
                              "DCX_joint");
}

void validate(const TargetJointDef& def, bool dynamic) {
    if (!dynamic)
        throw ValidationError("joint.body", double(def.body.index), "must be a dynamic body",
                              "DCX_joint");
    require_finite("joint.target", def.target);
    require_finite("joint.hertz", def.hertz);
    if (!(def.hertz > 0.0))
        throw ValidationError("joint.hertz", def.hertz, "must be > 0", "DCX_joint");
    require_finite("joint.damping_ratio", def.damping_ratio);
    if (!(def.damping_ratio >= 0.0))
        throw ValidationError("joint.damping_ratio", def.damping_ratio, "must be >= 0",
                              "DCX_joint");
    if (!(def.max_force > 0.0))
        throw ValidationError("joint.max_force", def.max_force, "must be > 0", "DCX_joint");
}

void validate(const RevoluteJointDef& def, bool movable) {
    validate_joint_bodies(def.body_a, def.body_b, movable, def.break_force);
    require_finite("joint.anchor", def.anchor);
    validate_limits("joint.lower_angle", def.lower_angle, "joint.upper_angle", def.upper_angle);
    validate_motor(def.motor_speed, "joint.max_motor_torque", def.max_motor_torque);
    validate_spring(def.enable_spring, def.hertz, def.damping_ratio);
}

void validate(const PrismaticJointDef& def, bool movable) {
    validate_joint_bodies(def.body_a, def.body_b, movable, def.break_force);
    require_finite("joint.anchor", def.anchor);
    validate_axis(def.axis);
    validate_limits("joint.lower_translation", def.lower_translation, "joint.upper_translation",
                    def.upper_translation);
    validate_motor(def.motor_speed, "joint.max_motor_force", def.max_motor_force);
    validate_spring(def.enable_spring, def.hertz, def.damping_ratio);
}

void validate(const WeldJointDef& def, bool movable) {
    validate_joint_bodies(def.body_a, def.body_b, movable, def.break_force);
    require_finite("joint.anchor", def.anchor);
    non_negative("joint.linear_hertz", def.linear_hertz);
    non_negative("joint.linear_damping_ratio", def.linear_damping_ratio);
    non_negative("joint.angular_hertz", def.angular_hertz);
    non_negative("joint.angular_damping_ratio", def.angular_damping_ratio);
}

void validate(const WheelJointDef& def, bool movable) {
    validate_joint_bodies(def.body_a, def.body_b, movable, def.break_force);
    require_finite("joint.anchor", def.anchor);
    validate_axis(def.axis);
    validate_spring(def.enable_spring, def.hertz, def.damping_ratio);
    validate_limits("joint.lower_translation", def.lower_translation, "joint.upper_translation",
                    def.upper_translation);
    validate_motor(def.motor_speed, "joint.max_motor_torque", def.max_motor_torque);
}

void validate(const MotorJointDef& def, bool movable) {
    validate_joint_bodies(def.body_a, def.body_b, movable, def.break_force);
    require_finite("joint.linear_offset", def.linear_offset);
    require_finite("joint.angular_offset", def.angular_offset);
    if (!(def.max_force >= 0.0))
        throw ValidationError("joint.max_force", def.max_force, "must be >= 0", "DCX_joint");
    if (!(def.max_torque >= 0.0))
        throw ValidationError("joint.max_torque", def.max_torque, "must be >= 0", "DCX_joint");
    require_finite("joint.correction_factor", def.correction_factor);
    if (!(def.correction_factor >= 0.0 && def.correction_factor <= 1.0))
        throw ValidationError("joint.correction_factor", def.correction_factor, "must be in [0, 1]",
                              "DCX_joint");
}

void validate(const WorldDef& def) {
    require_finite("world.gravity", def.gravity);
    if (def.substeps < 1 || def.substeps > 64) {
        throw ValidationError("world.substeps", def.substeps, "must be in [1, 64]", "DCX_dt");
    }
    const auto positive = [](const char* field, double v) {
        require_finite(field, v);
        if (!(v > 0.0))
            throw ValidationError(field, v, "must be > 0", "DCX_finite");
    };
    positive("world.contact_hertz", def.contact_hertz);
    positive("world.contact_damping_ratio", def.contact_damping_ratio);
    positive("world.contact_push_max_velocity", def.contact_push_max_velocity);
    positive("world.joint_hertz", def.joint_hertz);
    positive("world.joint_damping_ratio", def.joint_damping_ratio);
    const auto non_negative = [](const char* field, double v) {
        require_finite(field, v);
        if (!(v >= 0.0))
            throw ValidationError(field, v, "must be >= 0", "DCX_finite");
    };
    non_negative("world.linear_slop", def.linear_slop);
    non_negative("world.speculative_distance", def.speculative_distance);
    non_negative("world.restitution_threshold", def.restitution_threshold);
    non_negative("world.time_to_sleep", def.time_to_sleep);
    non_negative("world.linear_sleep_tolerance", def.linear_sleep_tolerance);
    non_negative("world.angular_sleep_tolerance", def.angular_sleep_tolerance);
}

void validate_time_step(double dt) {
    require_finite("dt", dt);
    if (!(dt > 0.0))
        throw ValidationError("dt", dt, "must be > 0", "DCX_dt");
}

} // namespace tamias2d
