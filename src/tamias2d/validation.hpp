// \srs{R4} Input validation: every check of the data constraints (section 5.2.6 and the ones
// the SRS forgot, labelled DCX_*). Each throws ValidationError naming field, value and label.
//
// The scene library checks a file's values with the same functions, so that a rule lives in one
// place. The ones it calls are marked TAMIAS2D_EXPORT: a shared libtamias2d exports them for
// libtamias2d_io, beside the API. They are not part of the API (no public header declares
// them); the two libraries come from one build, and share one SONAME version.
#pragma once

#include <string>
#include <string_view>

#include "tamias2d/aabb.hpp"
#include "tamias2d/body_def.hpp"
#include "tamias2d/export.hpp"
#include "tamias2d/joint_def.hpp"
#include "tamias2d/shape_def.hpp"
#include "tamias2d/world_def.hpp"

namespace tamias2d {

/// \srs{DCX_range} The supported magnitudes (docs/design.md, "Supported ranges", derives them). An
/// input is one factor of at most `input_max` in its SI unit, and a size, density, time step or
/// axis length at least `input_min`; a given mass or moment of inertia may span what rho w h and
/// rho w h (w^2 + h^2) / 12 span (3 and 5 factors). A step starts only from a state (position,
/// velocity, angle, angular velocity, accumulated one-step loads) within `state_max`, the
/// square of input_max: the headroom a simulation may grow into.
namespace supported {
inline constexpr double input_max = 1e12;
inline constexpr double input_min = 1e-12;
inline constexpr double mass_min = 1e-36, mass_max = 1e36;       ///< kg
inline constexpr double inertia_min = 1e-60, inertia_max = 1e60; ///< kg m^2
inline constexpr double state_max = 1e24;
/// \srs{DCX_joint} The largest lever ratio |r| / k of a joint's anchor on a dynamic body that
/// turns: r its offset from the centre of mass, k = sqrt(I / m) the radius of gyration. A
/// pin's effective-mass matrix K = (1/m) 1 + (1/I) r_perp r_perp^T (DD19) has the condition
/// number 1 + (r / k)^2 per body, and its impulse is solved to about eps x that, relative: at
/// 1e5 (condition <= 1 + 2e10 with two such bodies) at least five digits are kept; the fuzzed
/// joints that turned NaN within a step had ratios of 3e8 to 2.4e13 (no digit left).
inline constexpr double joint_lever_ratio_max = 1e5;
} // namespace supported

/// DCX_finite: a real input must be a finite number.
void require_finite(std::string_view field, double value);
void require_finite(std::string_view field, Vec2d value);
/// DCX_finite, then DCX_range: |value| <= max (`unit` names the SI unit in the message).
TAMIAS2D_EXPORT void require_within(std::string_view field, double value, double max,
                                    std::string_view unit);
TAMIAS2D_EXPORT void require_within(std::string_view field, Vec2d value, double max,
                                    std::string_view unit);
/// DCX_range for a positive scale already checked > 0 by its own constraint: lo <= value <= hi.
void require_scale(std::string_view field, double value, double lo, double hi,
                   std::string_view unit);
/// DCX_finite, DCX_shape (> 0) and DCX_range: a shape dimension (width, height, radius) in
/// [input_min, input_max] m.
TAMIAS2D_EXPORT void validate_size(std::string_view field, double value);
/// DCX_shape: the sliver rule, the one criterion for every polygon, boxes included: each vertex
/// lies at least hull_weld_tolerance x extent from the chord of its neighbours, and twice the
/// area exceeds 2 x that tolerance x extent (extent: the larger of the x and y spans). make_polygon
/// applies the same rule to the hull it builds, so a box is accepted exactly when its vertices,
/// written as a polygon (io::scene_to_json), are.
void validate_proportions(const Polygon& p);

TAMIAS2D_EXPORT void validate(const BodyDef& def);
TAMIAS2D_EXPORT void validate(const Material& material);
/// \srs{DD46} A rolling resistance: finite, >= 0 (DD46) and within DCX_range.
void validate_rolling_resistance(std::string_view field, double c);
/// \srs{DD47} A tangent speed: finite, any sign, within DCX_range (m s^-1).
void validate_tangent_speed(std::string_view field, double speed);
TAMIAS2D_EXPORT void validate(const ShapeDef& def);
void validate(const WorldDef& def);
/// "static", "kinematic" or "dynamic", as messages name a body's type.
const char* type_name(BodyType type);

/// A body a joint definition names: its handle, its name in messages ("body[3 'slider']") and
/// its type. The handle is checked by the caller.
struct JointBody {
    BodyId id;
    std::string label;
    BodyType type;
};

/// DCX_joint: distinct bodies, one of them dynamic, a finite anchor, a break force > 0. A
/// message about the bodies names them by their labels, not by a number.
void validate(const RevoluteJointDef& def, const JointBody& a, const JointBody& b);
/// DCX_joint for a distance joint: as above, and a rest length > 0 (given, or the anchors'
/// distance), hertz and damping ratio >= 0.
void validate(const DistanceJointDef& def, const JointBody& a, const JointBody& b);
/// DCX_joint for a target joint: a dynamic body, a finite target, hertz > 0, damping ratio
/// >= 0, max force > 0.
void validate(const TargetJointDef& def, const JointBody& body);
/// DCX_joint for a prismatic joint: as for a revolute one, a non-zero finite axis, limits
/// lower <= upper, a motor force >= 0, an enabled spring's hertz > 0.
void validate(const PrismaticJointDef& def, const JointBody& a, const JointBody& b);
/// DCX_joint for a weld joint: as for a revolute one, frequencies and damping ratios >= 0.
void validate(const WeldJointDef& def, const JointBody& a, const JointBody& b);
/// DCX_joint for a wheel joint: as for a prismatic one, with a motor torque >= 0.
void validate(const WheelJointDef& def, const JointBody& a, const JointBody& b);
/// DCX_joint for a motor joint: finite offsets, max force and torque >= 0, correction factor
/// in [0, 1].
void validate(const MotorJointDef& def, const JointBody& a, const JointBody& b);
/// DCX_joint for a filter joint: two bodies, one of them dynamic.
void validate(const FilterJointDef& def, const JointBody& a, const JointBody& b);
/// DCX_joint: an anchor at offset `r` (m) from the centre of mass of a body of inverse mass and
/// inverse inertia `inv_mass`, `inv_inertia` lies within supported::joint_lever_ratio_max
/// radii of gyration of it (a body that does not move or turn has no such limit).
void validate_joint_lever(std::string_view field, Vec2d r, double inv_mass, double inv_inertia);
/// Whether validate_joint_lever accepts (for a check that names the field only on failure).
bool joint_lever_fits(Vec2d r, double inv_mass, double inv_inertia);
// --- joint_control: the definitions' rules, a field at a time, for the joints' setters ---
/// \srs{DCX_joint} A break torque > 0 (N m; infinite: never), named joint.break_torque.
void validate_break_torque(double torque);
/// DCX_joint: a break force > 0 (N; infinite: never), named joint.break_force.
void validate_break_force(double force);
/// DCX_joint: limits lower <= upper, both finite and within the supported range, named as the
/// definition names them (`unit`: rad or m).
void validate_joint_limits(const char* lower_field, double lower, const char* upper_field,
                           double upper, std::string_view unit);
/// DCX_joint: a distance joint's 0 <= min_length <= max_length (m; max infinite: no bound).
void validate_length_range(double min_length, double max_length);
/// DCX_joint: a motor's largest force or torque >= 0 (infinite: unbounded).
void validate_joint_max_motor(const char* field, double max);
/// DCX_joint: a revolute, prismatic or wheel joint's spring: hertz > 0 when enabled, damping
/// ratio >= 0.
void validate_joint_spring(bool enabled, double hertz, double damping_ratio);
/// DCX_joint: a distance joint's spring: hertz >= 0 (0: rigid), damping ratio >= 0.
void validate_distance_spring(double hertz, double damping_ratio);
/// DCX_joint: a target joint's spring: hertz > 0, damping ratio >= 0.
void validate_target_spring(double hertz, double damping_ratio);
/// DCX_joint: a distance joint's rest length > 0 (m), within the supported range.
void validate_rest_length(double length);
/// DCX_joint: a joint's own soft bias, hertz and damping ratio > 0, as WorldDef::joint_hertz
/// and joint_damping_ratio (named joint.tuning_hertz, joint.tuning_damping_ratio).
void validate_constraint_tuning(double hertz, double damping_ratio);
/// The same, naming the two fields as given (a definition's joint.constraint_tuning.hertz).
void validate_constraint_tuning(double hertz, double damping_ratio, const char* hertz_field,
                                const char* ratio_field);

/// DCX_dt: the time step is finite and > 0; DCX_range: in [input_min, input_max] s.
TAMIAS2D_EXPORT void validate_time_step(double dt);
/// DCI_m: a mass given for a dynamic body is > 0 (the SRS's m >= 0 would divide by zero in IM1).
TAMIAS2D_EXPORT void validate_mass(std::string_view field, double mass);
/// DCI_I: a moment of inertia given is > 0 (the SRS's I >= 0 would divide by zero in IM2).
TAMIAS2D_EXPORT void validate_inertia(std::string_view field, double inertia);
/// A body's sleep threshold (m s^-1; BodyDef::sleep_threshold, World::set_sleep_threshold):
/// finite, >= 0 and within the supported range.
TAMIAS2D_EXPORT void validate_sleep_threshold(std::string_view field, double speed);
/// DCX_damping: a damping rate is finite and >= 0 (a negative one would feed energy in).
TAMIAS2D_EXPORT void validate_damping(std::string_view field, double rate);
/// An event threshold (events.hpp): a number >= 0; a joint's (N or N m, `may_be_infinite`)
/// may be infinite for never, the world's hit speed (m s^-1) must be finite and in range.
/// Not an SRS constraint: "events" names the rule.
void validate_event_threshold(std::string_view field, double value, bool may_be_infinite);

/// A query's box (`name`: "box", "draw.bounds"): finite sides, min <= max on each axis.
void validate_query_box(const Aabb& box, const std::string& name);

} // namespace tamias2d
