/// \file
/// The world: the space in which rigid bodies move and collide (SRS R1).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "tamias2d/aabb.hpp"
#include "tamias2d/body_def.hpp"
#include "tamias2d/body_state.hpp"
#include "tamias2d/contact_info.hpp"
#include "tamias2d/errors.hpp"
#include "tamias2d/export.hpp"
#include "tamias2d/handles.hpp"
#include "tamias2d/joint_def.hpp"
#include "tamias2d/joint_kind.hpp"
#include "tamias2d/shape_def.hpp"
#include "tamias2d/world_def.hpp"

namespace tamias2d {

/// The first shape a ray meets (World::ray_cast).
struct RayCastHit {
    ShapeId shape;         ///< the shape hit
    BodyId body;           ///< the body carrying it
    Vec2d point{};         ///< m
    Vec2d normal{};        ///< unit, outward from the shape
    double fraction = 0.0; ///< along the ray's translation, in [0, 1]
};

/// \srs{R1} The space in which all rigid bodies of a simulation interact.
/// Every mutating call validates its input first (SRS R4) and throws ValidationError,
/// InvalidHandle or WrongKind (errors.hpp) without changing anything: the world is left exactly
/// as it was.
/// Every real input must be finite (DCX_finite) and within the supported range (DCX_range:
/// magnitudes up to 1e12 in SI units, sizes from 1e-12; docs/design.md, "Supported ranges").
class TAMIAS2D_EXPORT World {
  public:
    /// An empty world with the given settings; throws ValidationError if a setting breaks its
    /// constraint (e.g. substeps < 1, a non-finite gravity).
    explicit World(const WorldDef& def = {});
    ~World();
    /// Worlds move (handles stay valid in the moved-to world) but are not copied: a copy of a
    /// whole simulation is rarely meant, and a scene file (io/scene.hpp) rebuilds one.
    World(World&&) noexcept;
    /// Takes over the other world's bodies, shapes and state.
    World& operator=(World&&) noexcept;
    World(const World&) = delete;
    World& operator=(const World&) = delete;

    // --- bodies and shapes (R1, R2, R3) ---
    /// Adds a body (R1, R2) and returns its handle; throws ValidationError naming the field
    /// of `def` that breaks its data constraint. The body has no mass until a shape gives it
    /// one (or BodyDef::mass is set).
    BodyId create_body(const BodyDef& def);
    /// Destroys the body, its shapes and its contacts.
    void destroy_body(BodyId body);
    /// Attaches a shape to a body (R3) and recomputes the body's mass, centre of mass and
    /// inertia (DD1, DD14) unless BodyDef overrides them; throws ValidationError for degenerate
    /// geometry or a material out of range.
    ShapeId create_shape(BodyId body, const ShapeDef& def);
    /// \srs{DD31} Attaches a chain's segments (chain_shapes) to a body, all or none: every
    /// definition is checked before the first is attached. Returns their handles in order.
    std::vector<ShapeId> create_chain(BodyId body, std::span<const ShapeDef> segments);
    /// Removes a shape and its contacts and recomputes the body's mass.
    void destroy_shape(ShapeId shape);
    /// \srs{DD27} Changes a shape's collision filter: its contacts the new filter refuses are
    /// removed now (with their end events), and the pairs it now admits are found by the next
    /// step.
    void set_filter(ShapeId shape, const Filter& filter);
    Filter filter(ShapeId shape) const; ///< the shape's collision filter (DD27)
    /// \srs{DD27} A filter of the game's own, asked for each pair of shapes that comes close
    /// and that the rules admit (DD27's bits and groups, joints, one body): false refuses the
    /// pair. It must answer the same for the same pair (the step stays deterministic only if it
    /// does), and not change the world. An empty function removes it. A pair in contact is not
    /// asked again; a refused one is, whenever the broad phase reports it anew (one of its
    /// shapes moved out of its fat box), and set_filter on a shape asks again for its pairs.
    void set_custom_filter(std::function<bool(ShapeId, ShapeId)> filter);
    /// Whether the handle names a body that exists (not destroyed, slot not reused).
    bool is_valid(BodyId body) const;
    /// Whether the handle names a shape that exists.
    bool is_valid(ShapeId shape) const;
    std::vector<BodyId> bodies() const;             ///< in creation order of their slots
    std::vector<ShapeId> shapes(BodyId body) const; ///< the body's shapes, in creation order
    std::size_t body_count() const;                 ///< bodies that exist

    // --- shape_control ---
    // Every setter below checks the handle and the value first and throws without changing
    // anything (InvalidHandle, ValidationError naming the field and the constraint, WrongKind).
    // A value equal to the current one changes nothing (no wake, no contact touched). A
    // changed value wakes the shape's body (a static body: the bodies touching it).
    /// \srs{LC2} Sets the shape's Coulomb friction coefficient (>= 0, DCX_friction); its
    /// contacts take the new combined value (geometric mean) at once.
    void set_friction(ShapeId shape, double friction);
    double friction(ShapeId shape) const; ///< the shape's friction coefficient (LC2)
    /// \srs{DD12} Sets the shape's coefficient of restitution (in [0, 1], DCI_CR); its contacts
    /// take the new combined value (the larger of the two) at once.
    void set_restitution(ShapeId shape, double restitution);
    double restitution(ShapeId shape) const; ///< the shape's coefficient of restitution (DD12)
    /// \srs{DD1} Sets the shape's density (kg m^-2, > 0, DCX_density). With update_body_mass
    /// the body's mass, centre of mass and inertia are recomputed now (DD1, DD14); without, they
    /// stay until the next mass update (a shape added or removed, or a call with true).
    /// Throws ValidationError (DCX_joint) if the new mass would put a joint's anchor beyond its
    /// lever limit.
    void set_density(ShapeId shape, double density, bool update_body_mass = true);
    double density(ShapeId shape) const; ///< kg m^-2
    /// \srs{R3} Replaces the shape's geometry by a circle (m, body frame), checked as
    /// create_shape checks it (DCX_shape, DCX_range). The body's mass is recomputed (DD1,
    /// DD14); the shape's contacts end now (with end events) and the pairs of its new outline
    /// are found by the next step; its broad-phase box is moved. WrongKind for a chain's
    /// segment (a chain's shape is changed by making the chain again); ValidationError
    /// (DCX_joint) if the new mass would put a joint's anchor beyond its lever limit.
    void set_circle(ShapeId shape, const Circle& circle);
    /// \srs{DD30} As set_circle, with a capsule (DD30's mass).
    void set_capsule(ShapeId shape, const Capsule& capsule);
    /// \srs{R3} As set_circle, with a convex polygon (polygon_shape(points).geometry.polygon
    /// makes one from points).
    void set_polygon(ShapeId shape, const Polygon& polygon);
    /// \srs{R3} As set_circle, with a two-sided segment (no area: no mass).
    void set_segment(ShapeId shape, const Segment& segment);
    /// The shape's geometry (body frame, m): only the member its `type` names is set.
    Geometry shape_geometry(ShapeId shape) const;
    /// \srs{DD28} Makes the shape a sensor (true) or a solid shape (false). A shape becoming a
    /// sensor loses its contacts now (end events) and, as a visitor of other sensors, its
    /// overlaps (sensor end events); from the next step it reports the shapes overlapping it.
    /// A sensor becoming solid ends its overlaps now (sensor end events), and its contacts
    /// begin from the next step.
    void set_sensor(ShapeId shape, bool is_sensor);
    bool is_sensor(ShapeId shape) const; ///< whether the shape is a sensor (DD28)

    // --- stepping (R5, R6, R7, R8) ---
    /// Advances by dt (s, in [1e-12, 1e12]). Throws ValidationError (DCX_range), changing
    /// nothing, if a moving body's position, velocity, angle or angular velocity has grown
    /// beyond 1e24 in SI units, or a load function returns a value beyond the supported range.
    void step(double dt);
    double time() const;              ///< s, simulated so far
    void set_gravity(Vec2d g);        ///< m s^-2 (GD2)
    Vec2d gravity() const;            ///< m s^-2
    const WorldDef& settings() const; ///< the settings, with the current gravity

    // --- body state (R2, Table 2) ---
    /// The body's outputs as the SRS states them (Table 2). Every getter throws InvalidHandle
    /// for a handle that names no body.
    BodyState state(BodyId body) const;
    Vec2d position(BodyId body) const;          ///< m, centre of mass
    Vec2d origin(BodyId body) const;            ///< m, body origin (where shapes are placed from)
    double orientation(BodyId body) const;      ///< rad in [0, 2 pi)
    Vec2d velocity(BodyId body) const;          ///< m s^-1, of the centre of mass
    double angular_velocity(BodyId body) const; ///< rad s^-1, CCW positive
    double mass(BodyId body) const;             ///< kg (0 for static and kinematic bodies)
    double inertia(BodyId body) const;          ///< kg m^2 about the centre of mass
    Vec2d local_center(BodyId body) const;      ///< m, centre of mass in the body frame
    BodyType type(BodyId body) const;           ///< as created
    const std::string& name(BodyId body) const; ///< BodyDef::name

    /// Moves the body origin to `origin` (m) at orientation `angle` (rad), without sweeping:
    /// it teleports, and its contacts are found again at the next step.
    void set_transform(BodyId body, Vec2d origin, double angle);
    /// Sets the velocity (m s^-1) of the centre of mass; ignored for static bodies.
    void set_velocity(BodyId body, Vec2d v);
    /// Sets the angular velocity (rad s^-1); ignored for static bodies.
    void set_angular_velocity(BodyId body, double omega);
    /// \srs{IM5} Sets the damping rates (s^-1, >= 0: DCX_damping) of BodyDef::linear_damping
    /// and BodyDef::angular_damping; they act on dynamic bodies only.
    void set_damping(BodyId body, double linear, double angular);
    double linear_damping(BodyId body) const;  ///< s^-1 (DD17)
    double angular_damping(BodyId body) const; ///< s^-1 (DD18)

    // --- loads (R2, IM1, IM2) ---
    // Loads move dynamic bodies only. The persistent ones (set_force, set_torque, set_load) are
    // settings of the body, as BodyDef::force, torque and load are: a static or kinematic body
    // keeps them, and they do not move it. The one-step ones (apply_force, apply_torque,
    // apply_impulse) act at once or at the next step: given to a static or kinematic body they
    // would be lost without a trace, so they throw WrongKind.
    /// Persistent force at the centre of mass (N) and torque (N m): act every step until changed
    /// (on a dynamic body; another keeps it unused).
    void set_force(BodyId body, Vec2d force);
    /// Persistent torque (N m, CCW positive) until changed (on a dynamic body).
    void set_torque(BodyId body, double torque);
    /// One-step force at a world point (N at m): the torque r x F (DD13) comes with it. The
    /// one-step forces and torques applied before a step must sum to at most 1e24 (DCX_range).
    /// Throws WrongKind for a static or kinematic body.
    void apply_force(BodyId body, Vec2d force, Vec2d world_point);
    /// One-step torque (N m), cleared after the next step. Throws WrongKind for a static or
    /// kinematic body.
    void apply_torque(BodyId body, double torque);
    /// Instantaneous impulse J (N s) at a world point: dv = J / m (DD10), domega = r x J / I;
    /// refused (DCX_range) if the velocities it gives exceed 1e24. Throws WrongKind for a
    /// static or kinematic body.
    void apply_impulse(BodyId body, Vec2d impulse, Vec2d world_point);
    /// Time-varying load F(t), tau(t); an empty function removes it. Evaluated for a dynamic
    /// body only.
    void set_load(BodyId body, LoadFunction load);

    // --- joints (LC3, IM6) ---
    /// \srs{DD19} Pins body_b to body_a at the anchor (see RevoluteJointDef) and wakes both.
    /// Throws InvalidHandle for a body that does not exist, ValidationError (DCX_joint) for one
    /// body twice, two bodies of which neither is dynamic, a non-finite anchor or a break force
    /// that is not > 0. Unless collide_connected, the two bodies' contacts are removed.
    JointId create_joint(const RevoluteJointDef& def);
    /// \srs{DD20} Holds the two anchors at a distance (see DistanceJointDef) and wakes both
    /// bodies. Throws as the revolute overload does, and ValidationError (DCX_joint) for a
    /// length, hertz or damping ratio out of range.
    JointId create_joint(const DistanceJointDef& def);
    /// \srs{DD21} Pulls a body's point towards a target (see TargetJointDef) and wakes it.
    /// Throws InvalidHandle for a body that does not exist, ValidationError (DCX_joint) for a
    /// body that is not dynamic, a non-finite target, hertz not > 0, a negative damping ratio
    /// or a max force not > 0.
    JointId create_joint(const TargetJointDef& def);
    /// \srs{DD23} Lets body_b slide along an axis fixed in body_a (see PrismaticJointDef) and
    /// wakes both bodies. Throws as the revolute overload does, and ValidationError (DCX_joint)
    /// for a zero or non-finite axis, limits lower > upper, a negative motor force or an
    /// enabled spring without a frequency > 0.
    JointId create_joint(const PrismaticJointDef& def);
    /// \srs{DD24} Welds body_b to body_a (see WeldJointDef) and wakes both bodies. Throws as
    /// the revolute overload does, and ValidationError (DCX_joint) for a negative frequency or
    /// damping ratio.
    JointId create_joint(const WeldJointDef& def);
    /// \srs{DD25} Mounts the wheel body_b on the chassis body_a (see WheelJointDef) and wakes
    /// both. Throws as the prismatic overload does.
    JointId create_joint(const WheelJointDef& def);
    /// \srs{DD26} Drives body_b's pose relative to body_a (see MotorJointDef) and wakes both.
    /// Throws as the revolute overload does, and ValidationError (DCX_joint) for non-finite
    /// offsets, a negative force or torque, or a correction factor outside [0, 1].
    JointId create_joint(const MotorJointDef& def);
    /// \srs{DD27} Stops body_a's and body_b's shapes from colliding (see FilterJointDef): no
    /// constraint, no solver work; their contacts are removed and both bodies woken. Throws as
    /// the revolute overload does for the bodies.
    JointId create_joint(const FilterJointDef& def);
    /// Moves a motor joint's target pose (m in body_a's frame, rad; finite) and wakes its
    /// bodies; WrongKind for a joint of another kind.
    void set_motor_joint_offsets(JointId joint, Vec2d linear_offset, double angular_offset);
    /// Moves a target joint's target (m, world frame) and wakes its body; throws
    /// ValidationError for a non-finite target, WrongKind for a joint of another kind.
    void set_joint_target(JointId joint, Vec2d target);
    /// Removes the joint and wakes its bodies. Destroying a body destroys its joints.
    void destroy_joint(JointId joint);
    bool is_valid(JointId joint) const; ///< whether the handle names a joint that exists
    /// \srs{IM6} N: the force the joint applied to body_b during the last substep of the last
    /// step (its impulse over the substep); the opposite force acted on body_a.
    Vec2d joint_reaction_force(JointId joint) const;
    /// \srs{DD22} N m: the torque the joint's angular parts applied to body_b during the last
    /// substep (the opposite acted on body_a): a revolute joint's motor, limits and spring, a
    /// wheel's motor, the angle a prismatic, weld or motor joint holds; 0 for distance and
    /// target joints. (The linear force's moment is not included: it acts at the anchors.)
    double joint_reaction_torque(JointId joint) const;
    /// \srs{DD22} rad: body_b's turn against body_a since the joint was made (CCW positive, not
    /// wrapped) of a revolute, prismatic, weld or wheel joint; WrongKind for another kind.
    double joint_angle(JointId joint) const;
    /// \srs{DD23} m: a prismatic or wheel joint's translation, the anchors' separation along
    /// the axis (0 at creation); WrongKind for another kind of joint.
    double joint_translation(JointId joint) const;
    /// Sets the motor speed of a revolute or wheel joint (rad s^-1) or a prismatic or distance
    /// joint (m s^-1), finite (the motor must be enabled to act), and wakes its bodies: a car's
    /// throttle, an elevator's lever, a winch. WrongKind for another kind of joint.
    void set_joint_motor_speed(JointId joint, double speed);
    /// The joints that broke in the last step (reaction force above break_force, or reaction
    /// torque above break_torque: DD36): they no longer exist; their handles are listed so that
    /// a game can react.
    std::span<const JointId> broken_joints() const;
    std::size_t joint_count() const; ///< joints that exist

    // --- joint_control ---
    // The joints' settings after creation. Every call checks the handle, the joint's kind and
    // the values first and throws without changing anything: InvalidHandle for a stale handle,
    // WrongKind (naming the joint) for a joint of a kind the call does not apply to,
    // ValidationError (DCX_joint) naming the field for a value out of its range, as the
    // definition's field is checked at creation. A value equal to the current one changes
    // nothing; a changed one wakes the joint's bodies.
    JointKind joint_kind(JointId joint) const; ///< the definition the joint was made from
    /// The joint's first body (a target joint's body).
    BodyId joint_body_a(JointId joint) const;
    /// The joint's second body (a target joint's body, as joint_body_a).
    BodyId joint_body_b(JointId joint) const;
    /// \srs{DD22} Turns the limits of a revolute joint's angle, a prismatic or wheel joint's
    /// translation (DD23) or a distance joint's length (DD20) on or off. A distance joint's
    /// limits act when its length is free (a spring, hertz > 0, or its motor enabled).
    void enable_joint_limit(JointId joint, bool enable);
    bool is_joint_limit_enabled(JointId joint) const; ///< revolute, prismatic, wheel, distance
    /// \srs{DD22} Sets the limits lower <= upper: rad for a revolute joint (lower_angle,
    /// upper_angle), m for a prismatic or wheel joint (lower_translation, upper_translation)
    /// and a distance joint (min_length >= 0, max_length; infinite: no upper bound).
    void set_joint_limits(JointId joint, double lower, double upper);
    JointLimits joint_limits(JointId joint) const; ///< as set_joint_limits takes them
    /// \srs{DD22} Turns the motor of a revolute, prismatic, wheel or distance joint (DD35) on
    /// or off; its speed is set_joint_motor_speed's.
    void enable_joint_motor(JointId joint, bool enable);
    bool is_joint_motor_enabled(JointId joint) const; ///< revolute, prismatic, wheel, distance
    /// rad s^-1 (revolute, wheel) or m s^-1 (prismatic, distance): the motor's target speed.
    double joint_motor_speed(JointId joint) const;
    /// \srs{DD22} N m, >= 0: the largest torque of a revolute or wheel joint's motor.
    void set_joint_max_motor_torque(JointId joint, double torque);
    double joint_max_motor_torque(JointId joint) const; ///< N m (revolute, wheel)
    /// \srs{DD23} N, >= 0: the largest force of a prismatic or distance joint's motor (DD35).
    void set_joint_max_motor_force(JointId joint, double force);
    double joint_max_motor_force(JointId joint) const; ///< N (prismatic, distance)
    /// \srs{DD22} Turns the spring of a revolute, prismatic or wheel joint on or off; turning
    /// it on needs hertz > 0 (set_joint_spring). A distance joint's spring is on while its
    /// hertz is > 0 (WrongKind here).
    void enable_joint_spring(JointId joint, bool enable);
    bool is_joint_spring_enabled(JointId joint) const; ///< a distance joint's: hertz > 0
    /// \srs{IM6} Sets a joint's spring: natural frequency (Hz) and damping ratio (>= 0) of a
    /// revolute, prismatic or wheel joint's spring (hertz > 0 while it is enabled), a distance
    /// joint's (hertz 0: a rigid rod) or a target joint's (hertz > 0).
    void set_joint_spring(JointId joint, double hertz, double damping_ratio);
    double joint_spring_hertz(JointId joint) const;         ///< Hz
    double joint_spring_damping_ratio(JointId joint) const; ///< 1: critically damped
    /// \srs{DD22} The value a revolute joint's spring pulls its angle to (rad), or a prismatic
    /// or wheel joint's its translation (m, DD23); 0 (the pose at creation) until set.
    void set_joint_spring_target(JointId joint, double target);
    double joint_spring_target(JointId joint) const; ///< rad or m
    /// \srs{DD20} m, > 0: a distance joint's rest length (the rod's, or the spring's).
    void set_distance_joint_length(JointId joint, double length);
    double distance_joint_length(JointId joint) const; ///< m
    /// \srs{IM6} This joint's soft bias (hertz > 0, damping ratio > 0, as WorldDef::joint_hertz
    /// and joint_damping_ratio are checked) in place of the world's, capped as the world's is.
    /// The same values as the world's give the same motion, bit for bit. WrongKind for a
    /// target or motor joint (held by their own spring and correction factor) and a filter
    /// joint (nothing to solve).
    void set_constraint_tuning(JointId joint, double hertz, double damping_ratio);
    /// The joint's own tuning, or the world's if it has none.
    ConstraintTuning constraint_tuning(JointId joint) const;
    /// \srs{DD27} Whether the joint's two bodies collide with each other. Turned off, their
    /// contacts end now (end events); turned on, their pairs are found by the next step (unless
    /// another joint keeps them apart). WrongKind for a filter joint, whose only effect it
    /// would undo, and for a target joint (one body).
    void set_joint_collide_connected(JointId joint, bool collide);
    bool joint_collide_connected(JointId joint) const; ///< whether its two bodies collide
    /// \srs{DD36} N, > 0 (infinite: never): the joint breaks after a step whose reaction force
    /// exceeds it (broken_joints). WrongKind for a target or filter joint.
    void set_joint_break_force(JointId joint, double force);
    double joint_break_force(JointId joint) const; ///< N
    /// \srs{DD36} N m, > 0 (infinite: never): the joint breaks after a step whose reaction
    /// torque (joint_reaction_torque) exceeds it in magnitude. WrongKind for a target, filter
    /// or distance joint (none carries a torque).
    void set_joint_break_torque(JointId joint, double torque);
    double joint_break_torque(JointId joint) const; ///< N m

    // --- sleeping (WorldDef::enable_sleep) ---
    /// Every call above that changes a body's transform, velocities or loads wakes it, and with
    /// it, at the next step, every body touching it. Adding a shape to a sleeping body leaves
    /// it asleep (so that a scene can be built asleep, BodyDef::awake); destroying a shape or a
    /// body wakes every body it touched.
    /// False for static bodies; true for all others while sleeping is off.
    bool is_awake(BodyId body) const;
    /// Puts the body to sleep (velocities and one-step loads zero; no effect with sleeping off
    /// or on a static body), or wakes it. A body put to sleep that touches an awake one wakes
    /// again at the next step.
    void set_awake(BodyId body, bool awake);

    // --- energy and momentum (SRS 5.2.7) ---
    double kinetic_energy() const;   ///< J, DD15 incl. rotation, all bodies
    double potential_energy() const; ///< J, DD16 with the world's gravity, origin as reference
    Vec2d linear_momentum() const;   ///< N s, GD1

    // --- contacts (R7) and queries ---
    /// Touching pairs after the last step (less those of shapes destroyed since), in a
    /// deterministic order. Built on the first call after a step; not safe to call from two
    /// threads at once (nothing in World is).
    std::span<const ContactInfo> contacts() const;
    /// Pairs that began touching during the last step, in a deterministic order.
    std::span<const ContactEvent> contact_begin_events() const;
    /// Pairs that stopped touching during the last step (or lost a shape or body to destruction).
    std::span<const ContactEvent> contact_end_events() const;
    /// \srs{DD28} Shapes that began overlapping a sensor during the last step, in a
    /// deterministic order (the pairs' storage order, which depends only on the inputs).
    std::span<const SensorEvent> sensor_begin_events() const;
    /// \srs{DD28} Shapes that stopped overlapping a sensor during the last step (or whose
    /// shape or body, or the sensor's, was destroyed).
    std::span<const SensorEvent> sensor_end_events() const;
    /// Shapes whose bounding boxes overlap `box` (m), by shape index. Throws ValidationError
    /// for a side that is not finite (DCX_finite) and for a box upside down, min_x > max_x or
    /// min_y > max_y (rule "query"): such a box holds nothing, and an empty answer would hide
    /// the mistake. A box of zero width or height (a segment, a point) is a box.
    std::vector<ShapeId> query_aabb(const Aabb& box) const;
    /// Shapes that contain `point` (m, world frame), by shape index. Throws ValidationError for
    /// a point that is not finite (DCX_finite).
    std::vector<ShapeId> query_point(Vec2d point) const;
    /// The first shape met by the segment origin -> origin + translation (m), if any; ties go
    /// to the lower shape index so that the answer is deterministic. Both within the supported
    /// range (DCX_range, |x| <= 1e12 m), so that the answer is never NaN.
    std::optional<RayCastHit> ray_cast(Vec2d origin, Vec2d translation) const;

    /// A hash of the complete simulation state (bit patterns of every double): equal hashes
    /// mean bitwise-equal worlds. Used by the determinism and strong-guarantee tests.
    std::uint64_t state_hash() const;

    /// \cond INTERNAL
    struct Impl; // the engine's state (src/tamias2d/world.cpp): not part of the API
                 /// \endcond

  private:
    std::unique_ptr<Impl> impl_;
};

} // namespace tamias2d
