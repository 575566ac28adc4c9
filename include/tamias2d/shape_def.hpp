/// \file
/// What a shape is made from: its geometry and its material (SRS R3).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "tamias2d/config.hpp"
#include "tamias2d/export.hpp"
#include "tamias2d/result.hpp"
#include "tamias2d/shapes.hpp"
#include "tamias2d/user_data.hpp"

namespace tamias2d {

/// \srs{R3} Surface properties of a body: the coefficient of restitution (and LC2 friction, the
/// surface motion of DD46 and DD47).
struct Material {
    double density = 1.0;     ///< kg m^-2 (2D: mass per area), > 0
    double restitution = 0.0; ///< C_R (DD12), in [0, 1]
    /// Coulomb friction coefficient, >= 0. Default 0: the SRS assumes no friction (A6); LC2.
    double friction = 0.0;
    /// The game's own material id, handed to the friction and restitution mixing functions
    /// (World::set_friction_mixing, DD42): ice against rubber. Not used by the default rules.
    std::uint64_t user_material_id = 0;
    /// \srs{DD46} Rolling resistance, dimensionless, finite and >= 0: a contact resists rolling
    /// with a torque of at most c l N, c the larger coefficient of its two shapes, l the larger
    /// radius of a circle or a capsule among them, N its normal force. 0 (default): none.
    double rolling_resistance = 0.0;
    /// \srs{DD47} Tangent speed, m s^-1, finite, any sign: the surface's own speed along its
    /// tangent, clockwise around the shape (a conveyor belt; a flat belt's top carries things
    /// towards +x when positive). A contact's friction drives the relative tangential velocity
    /// to the sum of its two shapes' speeds. 0 (default): a surface at rest.
    double tangent_speed = 0.0;
};

/// \srs{DD27} Which shapes a shape collides with: it belongs to the categories set in
/// category_bits and collides with those set in mask_bits (both ways: each must accept the
/// other); shapes of one non-zero group_index always collide (positive) or never (negative),
/// whatever their bits. The default collides with everything.
struct Filter {
    std::uint32_t category_bits = 0x00000001; ///< the categories the shape belongs to
    std::uint32_t mask_bits = 0xFFFFFFFF;     ///< the categories it collides with
    std::int32_t group_index = 0;             ///< 0: no group
    /// Field by field.
    friend bool operator==(const Filter&, const Filter&) = default;
};

/// \srs{R3} The inputs of a shape: its geometry (body frame) and its material.
struct ShapeDef {
    Geometry geometry{}; ///< circle or convex polygon, m in the body frame
    Material material{}; ///< density, restitution, friction
    Filter filter{};     ///< DD27: which shapes it collides with
    /// \srs{DD28} A sensor exerts no force and is not hit by ray casts: it reports the shapes
    /// that begin and end overlapping it (World::sensor_begin_events), a pickup or a trigger.
    /// Sensors do not detect each other. Its density still counts in its body's mass.
    bool is_sensor = false;
    /// Whether this shape's contacts begin and end events are reported
    /// (World::contact_begin_events): a pair's events are reported when both its shapes
    /// allow them, so that debris switched off has none. On by default.
    bool enable_contact_events = true;
    /// \srs{DD28} Whether this shape takes part in sensor overlaps: a sensor that does not
    /// detects nothing, a shape that does not is seen by no sensor (World::sensor_overlaps, and
    /// so no begin or end event). On by default.
    bool enable_sensor_events = true;
    /// Whether this shape's hard hits are reported (World::contact_hit_events): a pair's hits
    /// are reported when either shape asks. Off by default (the check costs a pass over the
    /// contacts per step while any shape asks).
    bool enable_hit_events = false;
    /// Whether the pre-solve callback (World::set_pre_solve) is asked about this shape's
    /// contacts: a touching pair is handed to it when either of its shapes allows it, and a pair
    /// neither allows is solved without asking. On by default.
    bool enable_pre_solve = true;
    UserData user_data = 0; ///< the game's own value (user_data.hpp), not simulation state
};

#if TAMIAS2D_EXCEPTIONS
/// A rectangle w x h (m) centred on the body origin (or on `center`, rotated by `angle`).
TAMIAS2D_EXPORT ShapeDef box_shape(double width, double height, Material material = {},
                                   Vec2d center = {}, double angle = 0.0);
/// A circle of radius r (m).
TAMIAS2D_EXPORT ShapeDef circle_shape(double radius, Material material = {}, Vec2d center = {});
/// The convex hull of 3 to 8 points (m, body frame).
TAMIAS2D_EXPORT ShapeDef polygon_shape(std::span<const Vec2d> points, Material material = {});
/// \srs{DD30} A capsule: the points within `radius` (m, > 0) of the segment center1 -> center2.
TAMIAS2D_EXPORT ShapeDef capsule_shape(Vec2d center1, Vec2d center2, double radius,
                                       Material material = {});
/// A two-sided segment point1 -> point2 (no area: no mass).
TAMIAS2D_EXPORT ShapeDef segment_shape(Vec2d point1, Vec2d point2, Material material = {});
/// \srs{DD31} The one-sided segments of a chain through `points` (at least 2; 3 for a loop),
/// each colliding on the right of its direction (a counter-clockwise loop is solid inside; a
/// ground drawn right to left is walked on from above), ready for World::create_shape. A
/// shape sliding along the chain meets no ghost corner at its vertices. World::create_chain
/// creates them all at once.
TAMIAS2D_EXPORT std::vector<ShapeDef> chain_shapes(std::span<const Vec2d> points, bool loop,
                                                   Material material = {});
#endif // TAMIAS2D_EXCEPTIONS

// The error-returning forms (result.hpp): each `try_` call is the call of the same name,
// returning its result or the Error its throwing form would throw, instead of throwing.
// Declared whatever TAMIAS2D_EXCEPTIONS is.
/// box_shape, returning its Error instead of throwing it.
TAMIAS2D_EXPORT Result<ShapeDef> try_box_shape(double width, double height, Material material = {},
                                               Vec2d center = {}, double angle = 0.0) noexcept;
/// circle_shape, returning its Error instead of throwing it.
TAMIAS2D_EXPORT Result<ShapeDef> try_circle_shape(double radius, Material material = {},
                                                  Vec2d center = {}) noexcept;
/// polygon_shape, returning its Error instead of throwing it.
TAMIAS2D_EXPORT Result<ShapeDef> try_polygon_shape(std::span<const Vec2d> points,
                                                   Material material = {}) noexcept;
/// capsule_shape, returning its Error instead of throwing it.
TAMIAS2D_EXPORT Result<ShapeDef> try_capsule_shape(Vec2d center1, Vec2d center2, double radius,
                                                   Material material = {}) noexcept;
/// segment_shape, returning its Error instead of throwing it.
TAMIAS2D_EXPORT Result<ShapeDef> try_segment_shape(Vec2d point1, Vec2d point2,
                                                   Material material = {}) noexcept;
/// chain_shapes, returning its Error instead of throwing it.
TAMIAS2D_EXPORT Result<std::vector<ShapeDef>>
try_chain_shapes(std::span<const Vec2d> points, bool loop, Material material = {}) noexcept;

} // namespace tamias2d
