/// \file
/// The world: the space in which rigid bodies move and collide (SRS R1).
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "tamias2d/aabb.hpp"
#include "tamias2d/body_def.hpp"
#include "tamias2d/body_state.hpp"
#include "tamias2d/config.hpp"
#include "tamias2d/contact_hooks.hpp"
#include "tamias2d/contact_info.hpp"
#include "tamias2d/debug_draw.hpp"
#include "tamias2d/errors.hpp"
#include "tamias2d/events.hpp"
#include "tamias2d/explosion.hpp"
#include "tamias2d/export.hpp"
#include "tamias2d/handles.hpp"
#include "tamias2d/joint_def.hpp"
#include "tamias2d/joint_kind.hpp"
#include "tamias2d/mass_data.hpp"
#include "tamias2d/motion_locks.hpp"
#include "tamias2d/mover_plane.hpp"
#include "tamias2d/profile.hpp"
#include "tamias2d/query_filter.hpp"
#include "tamias2d/query_results.hpp"
#include "tamias2d/result.hpp"
#include "tamias2d/shape_def.hpp"
#include "tamias2d/shapes.hpp"
#include "tamias2d/snapshot_error.hpp"
#include "tamias2d/task_system.hpp"
#include "tamias2d/user_data.hpp"
#include "tamias2d/world_def.hpp"
#include "tamias2d/world_definitions.hpp"

namespace tamias2d {

/// \srs{R1} The space in which all rigid bodies of a simulation interact.
/// Every mutating call validates its input first (SRS R4) and throws ValidationError,
/// InvalidHandle (WrongWorld for a handle of another world) or WrongKind (errors.hpp) without
/// changing anything: the world is left exactly as it was.
/// Every real input must be finite (DCX_finite) and within the supported range (DCX_range:
/// magnitudes up to 1e12 in SI units, sizes from 1e-12; docs/design.md, "Supported ranges").
class TAMIAS2D_EXPORT World {
  public:
    ~World();
    /// Worlds move (handles stay valid in the moved-to world, which keeps the tag) but are not
    /// copied: a copy of a whole simulation is rarely meant, and a scene file (io/scene.hpp)
    /// rebuilds one.
    World(World&&) noexcept;
    /// Takes over the other world's bodies, shapes and state.
    World& operator=(World&&) noexcept;
    World(const World&) = delete;
    World& operator=(const World&) = delete;

    // Every call below this point may throw (ValidationError, InvalidHandle, WrongKind, ...,
    // std::bad_alloc: none is noexcept) and is declared only when TAMIAS2D_EXCEPTIONS is 1
    // (config.hpp); its error-returning form, declared at the end of the class, always is.
#if TAMIAS2D_EXCEPTIONS
    /// An empty world with the given settings; throws ValidationError if a setting breaks its
    /// constraint (e.g. substeps < 1, a non-finite gravity).
    explicit World(const WorldDef& def = {});

    /// The world's tag, which every handle it issues carries (BodyId::world): distinct for
    /// every World of the process and never 0, so that a handle of another world, or a default
    /// one, names nothing here. Not part of the state hash: equal worlds hash equal.
    std::uint32_t tag() const;

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
    /// \srs{DD46} Sets the shape's rolling resistance (finite, >= 0, named "rolling_resistance"
    /// with DD46 when not); its contacts resist rolling with the new value from the next step.
    void set_rolling_resistance(ShapeId shape, double rolling_resistance);
    double rolling_resistance(ShapeId shape) const; ///< Material::rolling_resistance (DD46)
    /// \srs{DD47} Sets the shape's tangent speed (m s^-1, finite, any sign, within DCX_range);
    /// its contacts' friction drives towards the new value from the next step.
    void set_tangent_speed(ShapeId shape, double tangent_speed);
    double tangent_speed(ShapeId shape) const; ///< Material::tangent_speed (DD47, m s^-1)
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
    /// Sets the angular velocity (rad s^-1); ignored for static bodies and for a dynamic body
    /// under the angular lock (DD39, BodyDef::fixed_rotation: nothing turns it).
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
    /// Puts the body to sleep (velocities, one-step loads and its time at rest zero, as for a
    /// body defined asleep; no effect with sleeping off or on a static body), or wakes it (its
    /// time at rest starts again from zero, as after every wake). A body put to sleep that
    /// touches an awake one wakes again at the next step.
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

    // --- snapshot ---
    // A snapshot is the world's whole state as bytes: the settings, the time, every body,
    // shape, contact (manifolds and warm-start impulses), joint (impulses), sensor overlap,
    // sleep timer and the broad phase's trees. A world built or restored from it continues
    // with the same bits as the world it was taken from, on any number of workers (with the
    // same library version and build: docs/user-guide.md, "Determinism, snapshots and
    // replays"). Functions are not data and are not in a snapshot: the custom filter
    // (set_custom_filter) and the load functions (set_load). User data (the world's, bodies',
    // shapes' and joints') is not simulation state but is in a snapshot, as 64 bits: a world
    // built or restored from it has the values it had when the snapshot was taken (a pointer
    // held there means something only in the process that took the snapshot).

#endif
    /// The version of the snapshot format this library writes and reads.
    static constexpr std::uint32_t snapshot_format_version = 3;
#if TAMIAS2D_EXCEPTIONS
    /// The world's state as bytes (a versioned header with an XXH64 checksum, then
    /// little-endian fields): for save games, rollback and bug reports. Call between steps.
    /// Changes nothing (pending mass updates are done, as a step would do them).
    std::vector<std::byte> snapshot() const;
    /// The same bytes written into `bytes`, reusing its memory (what it held is replaced): for
    /// a snapshot every frame (rollback), where a new vector would be allocated and zeroed each
    /// time. If it throws (std::bad_alloc), what `bytes` holds is unspecified.
    void snapshot(std::vector<std::byte>& bytes) const;
    /// A new world in the state `snapshot` holds, stepping with `workers` workers and
    /// `task_system` (these are the host's, not in the snapshot). The new world has a tag of
    /// its own (tag()): a handle the world the snapshot was taken from issued is not valid in
    /// it, but the same index and generation with the new world's tag name the same body,
    /// shape or joint. It has no custom filter, no load function and profiling off: set them
    /// again where the original had them.
    /// Throws SnapshotError for a snapshot that is not one (magic), of another format version,
    /// truncated, changed (checksum) or inconsistent, naming the byte offset, the field and the
    /// rule; ValidationError for workers < 1.
    static World from_snapshot(std::span<const std::byte> snapshot, int workers = 1,
                               const TaskSystem& task_system = {});
    /// Puts this world in the state `snapshot` holds (rollback, reload). Handles issued before
    /// the snapshot was taken stay valid and name the same objects; handles issued after it
    /// name nothing (or, for a slot the snapshot has in use, what the snapshot has there).
    /// Kept from this world: its workers and task system, its custom filter, whether it
    /// profiles its steps (set_profiling), and the load
    /// function of every body whose handle is valid in both this world and the snapshot and
    /// which had one when the snapshot was taken (other bodies have none). Throws SnapshotError
    /// as from_snapshot does, leaving the world exactly as it was.
    void restore(std::span<const std::byte> snapshot);
    /// The definitions that build this world as it is now (io::scene_from_world writes them as
    /// a scene): each live body's BodyDef with its pose, velocities, persistent loads, load
    /// function and settings now, its shapes' ShapeDefs, each live joint's definition with its
    /// anchors where they are now, and the settings. Not in them: what a step keeps between
    /// steps (contacts and their warm-start impulses, joint impulses, sleep timers, the broad
    /// phase), one-step loads not yet applied, and the custom filter: a world built from them
    /// starts from this state without that history (a snapshot keeps it). A world built from
    /// them before its first step steps bit for bit as this one: each anchor is the world point
    /// that gives the joint's local anchors back bit for bit when one lies within 4 ulps of
    /// where the anchor is. A joint's reference angle (the zero of its angle and limits) is
    /// taken again, as at creation, from its bodies' angles now. Throws nothing.
    WorldDefinitions definitions() const;
    // --- queries ---
    // Every query below walks the broad phase's trees, sees only the shapes its QueryFilter
    // admits, changes nothing, and throws ValidationError (the world unchanged) for an input
    // that is not finite or beyond the supported range (DCX_finite, DCX_range: |x| <= 1e12 m).
    // Rays and shape casts do not see sensors (DD28); the overlap queries do. A ray that
    // starts inside a solid shape (circle, polygon, capsule), or on its boundary heading
    // inward, does not hit that shape: it reports the shapes it enters after. Segments and
    // chain edges have no inside; a chain edge is hit from its solid side's outside (the right
    // of point1 -> point2) only. Callbacks are called in the trees' order (the same for the
    // same world) and must not change the world.
    /// \srs{DD33} The first shape the filter admits on the segment origin -> origin +
    /// translation (m); ties go to the lower shape index.
    std::optional<RayCastHit> ray_cast(Vec2d origin, Vec2d translation,
                                       const QueryFilter& filter) const;
    /// \srs{DD33} Every shape the filter admits on the segment, ordered by fraction (ties by
    /// shape index); allocates the vector.
    std::vector<RayCastHit> ray_cast_all(Vec2d origin, Vec2d translation,
                                         const QueryFilter& filter = {}) const;
    /// \srs{DD33} The same without allocating: the nearest out.size() hits, ordered as above,
    /// are written to `out`; returns how many hits there are in all (more than out.size() when
    /// some did not fit).
    std::size_t ray_cast_all(Vec2d origin, Vec2d translation, const QueryFilter& filter,
                             std::span<RayCastHit> out) const;
    /// \srs{DD33} Some hit on the segment, the first the walk finds (not the nearest): whether
    /// a line of sight is blocked. Stops at that hit.
    std::optional<RayCastHit> ray_cast_any(Vec2d origin, Vec2d translation,
                                           const QueryFilter& filter = {}) const;
    /// \srs{DD33} Calls `callback` for hits on the segment as the walk finds them; its return
    /// value ignores the hit, stops the cast, or clips it (RayCastCallback). Allocates nothing.
    void ray_cast(Vec2d origin, Vec2d translation, const QueryFilter& filter,
                  RayCastCallback callback) const;
    /// \srs{DD33} Where the segment first enters one shape, whatever its filter or sensor
    /// flag. Throws InvalidHandle for a shape that does not exist, ValidationError as above.
    std::optional<RayCastHit> ray_cast(ShapeId shape, Vec2d origin, Vec2d translation) const;

    /// \srs{DD29} Sweeps `shape` (body frame about `origin`, turned by `angle` rad) along
    /// `translation` (m) without turning, and returns the first shape the filter admits that
    /// it touches: the fraction of the translation where the gap between them first falls
    /// within DD29's target, found by the conservative advancement the continuous pass uses
    /// (the pose there leaves a gap of at most cast_tolerance, never an overlap), with the
    /// point and normal there. A shape overlapping at the start is hit at fraction 0. A chain
    /// edge whose solid side the shape's centre starts on is passed through. Throws
    /// ValidationError for a shape the create_shape rules refuse (DCX_shape), or an input not
    /// finite or out of range.
    std::optional<ShapeCastHit> shape_cast(const Geometry& shape, Vec2d origin, double angle,
                                           Vec2d translation, const QueryFilter& filter = {}) const;
    /// \srs{DD29} The same, calling `callback` for each hit as the walk finds it (returns as
    /// a RayCastCallback does). Allocates nothing.
    void shape_cast(const Geometry& shape, Vec2d origin, double angle, Vec2d translation,
                    const QueryFilter& filter, ShapeCastCallback callback) const;
    /// The gap (m) a shape cast's pose may leave: the shapes touch within this distance
    /// (1e-6 of the cast's scale, the shape's size plus the translation's length).
    static double cast_tolerance(const Geometry& shape, Vec2d translation);

    /// Shapes the filter admits whose bounding boxes overlap `box`, by shape index; throws as
    /// query_aabb(box) does.
    std::vector<ShapeId> query_aabb(const Aabb& box, const QueryFilter& filter) const;
    /// The same without allocating: `callback` for each such shape in the trees' order, until
    /// it returns false.
    void query_aabb(const Aabb& box, const QueryFilter& filter, OverlapCallback callback) const;
    /// Shapes the filter admits that contain `point` (m), by shape index.
    std::vector<ShapeId> query_point(Vec2d point, const QueryFilter& filter) const;
    /// The same without allocating, in the trees' order, until `callback` returns false.
    void query_point(Vec2d point, const QueryFilter& filter, OverlapCallback callback) const;
    /// \srs{DD34} Shapes the filter admits that share a point with `shape` placed at `origin`
    /// turned by `angle` rad (exact: the shapes themselves, not their boxes), by shape index.
    /// Throws ValidationError for a shape the create_shape rules refuse (DCX_shape), or an
    /// input not finite or out of range.
    std::vector<ShapeId> overlap_shape(const Geometry& shape, Vec2d origin, double angle,
                                       const QueryFilter& filter = {}) const;
    /// The same without allocating, in the trees' order, until `callback` returns false.
    void overlap_shape(const Geometry& shape, Vec2d origin, double angle, const QueryFilter& filter,
                       OverlapCallback callback) const;
    /// \srs{DD34} The closest points of two shapes of the world (point_a on `a`). Throws
    /// InvalidHandle for a shape that does not exist.
    ClosestPoints distance(ShapeId a, ShapeId b) const;
    /// \srs{DD34} The point of `shape` nearest `point` (m), as point_a (point_b is `point`);
    /// a point inside a solid shape overlaps it. Throws InvalidHandle for a shape that does not
    /// exist, ValidationError for a point not finite or out of range.
    ClosestPoints closest_point(ShapeId shape, Vec2d point) const;
    // --- events ---
    // What a game reacts to after a step, beside the contact and sensor begin and end events
    // above (events.hpp). Every list is in a deterministic order that depends only on the
    // inputs, the same on any number of workers (WorldDef::workers); each is replaced by the
    // next step's. Switching an event kind on or off changes no body's motion.
    /// \srs{DD11} The pairs that hit in the last step: touching, pushed, and approaching
    /// faster than WorldDef::hit_event_threshold (m s^-1) at a manifold point at the step's
    /// start, one of their shapes with hit events on (ShapeDef::enable_hit_events). In contact
    /// creation order.
    std::span<const ContactHitEvent> contact_hit_events() const;
    /// The bodies with move events on (BodyDef::enable_move_events) that moved in the last
    /// step (awake and not static), with their pose after it, and those that fell asleep in
    /// it (BodyMoveEvent::fell_asleep). In body index order.
    std::span<const BodyMoveEvent> body_move_events() const;
    /// The joints that exceeded a threshold (force_threshold, torque_threshold) or broke
    /// (break_force) in the last step, in joint index order (the broken ones first), then those
    /// destroyed with a body since (JointEventKind::body_destroyed, in the order they went).
    /// broken_joints() lists the broken ones too.
    std::span<const JointEvent> joint_events() const;
    /// \srs{DD28} The shapes overlapping the sensor shape after the last step (less those
    /// destroyed since), in shape index order: the set that its begin and end events build, one
    /// by one. Throws InvalidHandle for a stale handle, WrongKind for a shape that is not a
    /// sensor.
    std::vector<ShapeId> sensor_overlaps(ShapeId sensor) const;
    /// Sets WorldDef::hit_event_threshold (m s^-1, finite, >= 0): from the next step. Throws
    /// ValidationError (rule "events") for a negative or non-finite value. Wakes nothing.
    void set_hit_event_threshold(double speed);
    /// Switches a shape's hits on or off (ShapeDef::enable_hit_events), from the next step.
    /// Throws InvalidHandle for a stale handle. Wakes nothing.
    void set_hit_events_enabled(ShapeId shape, bool on);
    bool hit_events_enabled(ShapeId shape) const; ///< ShapeDef::enable_hit_events
    /// Switches a shape's contact begin and end events on or off (ShapeDef::
    /// enable_contact_events): the flag is read when a pair begins or ends touching. Throws
    /// InvalidHandle for a stale handle. Wakes nothing.
    void set_contact_events_enabled(ShapeId shape, bool on);
    bool contact_events_enabled(ShapeId shape) const; ///< ShapeDef::enable_contact_events
    /// \srs{DD28} Switches a shape's part in sensor overlaps on or off (ShapeDef::
    /// enable_sensor_events). Off, its overlaps end at the next step, with end events, so that
    /// a set built from the events stays equal to sensor_overlaps(); on, they begin again at
    /// the next step that finds them. Throws InvalidHandle for a stale handle. Wakes nothing.
    void set_sensor_events_enabled(ShapeId shape, bool on);
    bool sensor_events_enabled(ShapeId shape) const; ///< ShapeDef::enable_sensor_events
    /// Switches a body's move events on or off (BodyDef::enable_move_events), from the next
    /// step. Throws InvalidHandle for a stale handle. Wakes nothing.
    void set_move_events_enabled(BodyId body, bool on);
    bool move_events_enabled(BodyId body) const; ///< BodyDef::enable_move_events
    /// Sets a joint's event thresholds (N and N m, >= 0, infinite: never; see
    /// RevoluteJointDef::force_threshold), from the next step. Throws InvalidHandle for a stale
    /// handle, WrongKind for a filter joint (it carries no force), ValidationError (rule
    /// "events") for a negative or NaN threshold. Wakes nothing.
    void set_joint_event_thresholds(JointId joint, double force, double torque);
    double joint_force_threshold(JointId joint) const;  ///< N (infinite: none)
    double joint_torque_threshold(JointId joint) const; ///< N m (infinite: none)

    // --- debug_draw ---
    /// Hands the world to `draw` as primitives, in world coordinates (m): each shape filled in
    /// its state's colour, each broad-phase box, each joint's segments, each touching contact's
    /// points and normals, each body's centre of mass, as draw's flags select, limited to
    /// draw.bounds when set (found through the broad phase). Calls only `draw`'s functions,
    /// from the calling thread, in a fixed order; changes nothing and wakes nothing. Throws
    /// ValidationError, before any call, for a length of `draw` not finite and > 0 or bounds
    /// not finite or upside down (min > max).
    void draw(DebugDraw& draw) const;

    // --- profile ---
    /// Turns the timing of each step's stages on or off (off when the world is made). Off,
    /// a step reads no clock; on or off, no simulated value changes by a bit. Turning it off
    /// forgets the last step's times. Wakes nothing.
    void set_profiling(bool on);
    bool profiling() const; ///< whether set_profiling turned the timing on
    /// The last step's time per stage (s), measured with profiling on; all zero with it off or
    /// before the first profiled step. A refused step (an exception from step) leaves the
    /// previous step's times.
    StepProfile profile() const;
    /// What the world holds now: bodies, awake bodies, shapes, joints, pairs, touching pairs
    /// and their points, islands, the last step's solver packs; counted when asked (O(bodies
    /// + contacts + joints)), so a world that never asks pays nothing.
    WorldCounters counters() const;

    // --- explosion ---
    /// \srs{DD38} Pushes every shape of a dynamic body within def.radius + def.falloff (m) of
    /// def.position away from it (see ExplosionDef): applies DD38's impulse at the shape's
    /// nearest point (DD10: dv = J / m, domega = r x J / I) and wakes each body it moves.
    /// Returns how many bodies it moved. Throws ValidationError naming the field for a
    /// non-finite or out-of-range position, radius, falloff or impulse (DCX_finite, DCX_range),
    /// a negative radius or falloff (DD38), and (DCX_range) when a body's resulting velocity
    /// would exceed the supported range; the world is then unchanged.
    std::size_t explode(const ExplosionDef& def);

    // --- character ---
    // A kinematic character moved by queries (Box2D v3's mover): collide_mover gives the
    // planes of what the capsule touches, solve_planes (plane_solver.hpp) the translation they
    // allow, cast_mover how far of it is free, clip_vector the velocity left; then
    // set_target_transform sends the character's kinematic body there over the next step.
    // The mover calls are queries: they change nothing and wake nothing.
    /// \srs{DD29} The fraction in [0, 1] of `translation` (m) the capsule `mover` (world
    /// frame, m) can move before it touches a shape the filter sees: the queries' shape cast
    /// (shape_cast), its gap at the fraction within cast_tolerance. Shapes it already touches
    /// or overlaps (within the cast's tolerance at the start) are passed over: collide_mover's
    /// planes hold the mover off them. Throws ValidationError for a capsule that create_shape
    /// would refuse (DCX_shape, DCX_range) or a translation out of range, InvalidHandle for a
    /// stale filter.exclude_body.
    double cast_mover(const Capsule& mover, Vec2d translation,
                      const QueryFilter& filter = {}) const;
    /// \srs{DD34} The planes of the shapes the capsule `mover` (world frame, m) overlaps or
    /// comes within WorldDef::speculative_distance of, as MoverPlane (normal from the shape
    /// towards the mover's core segment, offset = radius - distance from the core), in shape
    /// order. Sensors and the back of a chain's edges (DD31) give none; nor does a shape the
    /// core itself lies in (deep overlap: no direction). Throws as cast_mover does.
    std::vector<MoverPlane> collide_mover(const Capsule& mover,
                                          const QueryFilter& filter = {}) const;
    /// collide_mover's planes one by one, in the broad phase's order, without allocating;
    /// the callback returns false to stop.
    void collide_mover(const Capsule& mover, const QueryFilter& filter,
                       MoverPlaneCallback callback) const;
    /// \srs{DD44} Sets a kinematic body's velocities so that one step of dt (s) brings its
    /// origin to `origin` (m) and its angle to `angle` (rad) by the shortest turn: v = (c_t -
    /// c) / dt for the centre of mass, omega = Delta / dt with Delta the turn in [-pi, pi].
    /// Wakes the body, unless the velocities are already those (then nothing changes). Throws
    /// InvalidHandle for a stale handle, WrongKind for a static or dynamic body,
    /// ValidationError for an origin or angle out of range (DCX_range), dt out of [1e-12,
    /// 1e12] (DCX_dt), or velocities beyond the supported state (DCX_range).
    void set_target_transform(BodyId body, Vec2d origin, double angle, double dt);
    /// \srs{DD45} The wind's force on a shape for the next step: with u = wind - (the velocity
    /// of the shape's centroid), F = 1/2 rho h w |u| (drag u + lift u_perp), rho = 1.225 kg
    /// m^-3, h = 1 m, w the shape's width across u (m), u_perp u turned a quarter turn
    /// counter-clockwise; applied at the centroid as apply_force does (one step, DD13's
    /// torque). `wind` in m s^-1; drag (>= 0) and lift dimensionless. A sleeping body is woken
    /// if `wake`, else left alone (no force). Throws InvalidHandle for a stale handle,
    /// WrongKind for a shape of a static or kinematic body, ValidationError for a value not
    /// finite or out of range (DCX_range) or a negative drag (DD45).
    void apply_wind(ShapeId shape, Vec2d wind, double drag, double lift, bool wake = true);

    // --- identity ---
    // What a game needs to tie its objects to the world's and to walk from one to another. None
    // of these calls changes the simulation: user data is not state (state_hash does not see
    // it), and it survives every other call (a type change, a step, a refused call). Each
    // throws InvalidHandle for a handle that names nothing, and changes nothing then.
    void set_user_data(UserData data);              ///< the world's own value (WorldDef::user_data)
    UserData user_data() const;                     ///< the world's value, 0 unless set
    void set_user_data(BodyId body, UserData data); ///< BodyDef::user_data, after creation
    UserData user_data(BodyId body) const;          ///< the body's value, 0 unless set
    void set_user_data(ShapeId shape, UserData data); ///< ShapeDef::user_data, after creation
    UserData user_data(ShapeId shape) const;          ///< the shape's value, 0 unless set
    void set_user_data(JointId joint, UserData data); ///< the joint definition's user_data
    UserData user_data(JointId joint) const;          ///< the joint's value, 0 unless set
    BodyId body(ShapeId shape) const;                 ///< the body carrying the shape
    ShapeType shape_type(ShapeId shape) const;        ///< circle, polygon, capsule, ...
    /// The shape's geometry in its body's frame (m), as stored: only the member its type
    /// names is set (a box is a polygon of four vertices).
    Geometry geometry(ShapeId shape) const;
    /// m, world frame: the shape's tight bounding box at its body's pose now.
    Aabb shape_aabb(ShapeId shape) const;
    /// m, world frame: the union of the body's shapes' tight boxes; a body without shapes
    /// gives the box of its origin alone (zero width and height).
    Aabb body_aabb(BodyId body) const;
    /// The joints holding the body (as body_a or body_b), oldest first.
    std::vector<JointId> joints(BodyId body) const;
    /// The body's touching pairs after the last step (as contacts() lists them, in its order):
    /// those with one of its shapes as shape_a or shape_b.
    std::vector<ContactInfo> contacts(BodyId body) const;
    // (a joint's kind and bodies: joint_kind, joint_body_a, joint_body_b, with the joints'
    // controls)

    // --- body_control ---
    // A body's definition changed after creation. Each call checks its handle and its values
    // first and throws InvalidHandle or ValidationError (naming the field and the constraint)
    // without changing anything; setting a value a body already has changes no bit of the
    // simulation (nothing is woken).
    /// Changes the body's type, keeping its handle, shapes, joints, settings and user data.
    /// Its contacts are removed (with their end events, the bodies they touched woken) and
    /// found again by the next step; its mass follows the new type (R2: none for static and
    /// kinematic bodies; its shapes' or its overrides' for a dynamic one). A body made static
    /// stops (velocities and one-step loads zero); one made kinematic or dynamic keeps its
    /// motion (DD41: every point its velocity, though the centre of mass moves with the mass).
    /// The body and the bodies its joints hold are woken; its joints start their next solve
    /// without a warm start. A joint none of whose
    /// bodies is dynamic stays but is not solved. Throws ValidationError (R2) for a type outside
    /// the enumeration and (DCX_joint) when the new mass would put a joint's anchor beyond its
    /// lever limit.
    void set_body_type(BodyId body, BodyType type);
    /// Disables (false) or enables a body. A disabled body keeps its pose, velocities, loads and
    /// settings but takes no part in the world: the step does not move it, its contacts and
    /// sensor overlaps are removed (with their end events, the bodies it touched woken), no
    /// pair, sensor, query or ray cast finds its shapes, and its joints are not solved (the
    /// bodies they hold move freely). Enabling wakes it and the bodies its joints hold; its
    /// pairs are found by the next step.
    void set_enabled(BodyId body, bool enabled);
    bool is_enabled(BodyId body) const; ///< true unless set_enabled(body, false)
    /// Multiplies the world's gravity for this body (BodyDef::gravity_scale; finite, |s| <=
    /// 1e12: DCX_range) and wakes it. Acts on a dynamic body.
    void set_gravity_scale(BodyId body, double scale);
    double gravity_scale(BodyId body) const; ///< BodyDef::gravity_scale or the last set
    /// \srs{DD29} Whether the body is swept against dynamic bodies too (BodyDef::bullet).
    void set_bullet(BodyId body, bool bullet);
    bool is_bullet(BodyId body) const; ///< BodyDef::bullet or the last set
    /// \srs{DD39} Locks motions of a dynamic body: a locked linear axis's velocity is held at
    /// zero at every substep; the angular lock (BodyDef::fixed_rotation) gives the body an
    /// infinite moment of inertia (DD14's I no longer resists: nothing turns it). A motion
    /// locked now is stopped now (its velocity component zero); the body is woken.
    void set_motion_locks(BodyId body, MotionLocks locks);
    MotionLocks motion_locks(BodyId body) const; ///< as set; angular is fixed_rotation
    /// set_motion_locks with only the angular lock changed (BodyDef::fixed_rotation).
    void set_fixed_rotation(BodyId body, bool fixed);
    bool fixed_rotation(BodyId body) const; ///< the angular lock
    /// \srs{DD41} Overrides a dynamic body's mass (kg, > 0), centre of mass (m, body frame)
    /// and moment of inertia about it (kg m^2, > 0), all finite and within DCX_range. The
    /// body's origin stays; its centre moves to the new one, which keeps the velocity it had as
    /// a point of the body (DD9): the body's motion is unchanged, so its momentum changes by
    /// the change of mass (GD1 does not hold across the call: it is the game's act, not a
    /// force). Wakes the body. Throws WrongKind for a static or kinematic body (they have no
    /// mass, R2), ValidationError (DCI_m, DCI_I, DCX_range) for a value out of range, and
    /// (DCX_joint) when a joint's anchor would be beyond its lever limit.
    void set_mass_data(BodyId body, const BodyMassData& data);
    BodyMassData mass_data(BodyId body) const; ///< mass, local_center and inertia now
    /// \srs{DD41} Forgets every override of the mass, centre and inertia (BodyDef::mass,
    /// BodyDef::inertia, set_mass_data) and computes them from the shapes (DD1, DD14), with
    /// set_mass_data's rule for the velocities. Wakes the body. Any body type (a static or
    /// kinematic body keeps no mass, R2; the overrides are forgotten all the same).
    void reset_mass_data(BodyId body);
    /// m s^-1, >= 0 and finite: the body rests (and may sleep, WorldDef::enable_sleep) below
    /// this speed instead of WorldDef::linear_sleep_tolerance. Wakes the body.
    void set_sleep_threshold(BodyId body, double speed);
    double sleep_threshold(BodyId body) const; ///< m s^-1: its own, or the world's tolerance
    /// Wakes every body touching this one, and with it their islands at the next step: what
    /// holds them up may be about to go (a platform the game will remove).
    void wake_touching(BodyId body);

    // --- contact_hooks ---
    // The game's say in how contacts are solved. The functions are not data: a snapshot holds
    // none of them, and state_hash does not see them. Each runs on the thread that calls step,
    // never on a worker, so none needs to be thread-safe; each must answer the same for the
    // same input (the step stays deterministic only if it does) and must not call the World.
    /// Sets the pre-solve callback (empty: none), asked once per step for every touching pair
    /// whose bodies are awake, after the narrow phase and before the solver, serially in the
    /// contacts' storage order (the same on any number of workers). It returns whether the
    /// contact is solved this step; false empties its manifold for this step (the pair counts
    /// as not touching: no force, no begin event, an end event if it touched). A one-way
    /// platform refuses contacts whose normal does not push the body up. Cost: one call per
    /// touching pair per step, on one thread, only while a callback is set. An exception it
    /// throws counts as `true` (the step finishes whole) and step() then rethrows the first.
    void set_pre_solve(PreSolveFunction callback);
    /// \srs{DD42} Replaces the friction rule mu = sqrt(mu_a mu_b) (empty: back to it) by
    /// f(mu_a, user_material_a, mu_b, user_material_b). Every contact's friction is mixed
    /// again now, each value checked before any is written: a value that is not finite and
    /// >= 0 throws ValidationError naming "friction_mixing" (DCX_friction), as does anything
    /// the function throws, and the world and the old function stay. The bodies of a touching
    /// contact whose friction changed are woken. A new contact whose mixed value is refused
    /// during a step is not made (the pair is not solved) and step() throws that
    /// ValidationError after finishing the step.
    void set_friction_mixing(MaterialMixFunction mix);
    /// \srs{DD42} As set_friction_mixing for the restitution rule C_R = max(C_R,a, C_R,b):
    /// values outside [0, 1] (or NaN) throw ValidationError naming "restitution_mixing"
    /// (DCI_CR).
    void set_restitution_mixing(MaterialMixFunction mix);
    /// \srs{DD42} Sets the shape's Material::user_material_id, which the mixing functions
    /// receive; its contacts are mixed again now (set_friction's rules: a refused value throws
    /// ValidationError naming the function, the world unchanged). A changed id wakes the
    /// shape's body. InvalidHandle for a handle that names no shape.
    void set_user_material(ShapeId shape, std::uint64_t id);
    std::uint64_t user_material(ShapeId shape) const; ///< Material::user_material_id

    // --- world_settings ---
    // The settings of WorldDef that a game may change between steps. Each validates as
    // WorldDef does (ValidationError naming "world.<field>" and its constraint) and changes
    // nothing when it throws; setting a value the world already has changes no bit.
    /// \srs{DD29} WorldDef::enable_continuous.
    void set_continuous(bool enabled);
    /// WorldDef::enable_sleep. Off: every sleeping body wakes (its time at rest zero); on: bodies
    /// start counting their time at rest at the next step.
    void set_sleeping(bool enabled);
    /// \srs{IM7} WorldDef::contact_hertz (Hz, > 0), contact_damping_ratio (> 0) and
    /// contact_push_max_velocity (m s^-1, > 0), from the next step on.
    void set_contact_tuning(double hertz, double damping_ratio, double push_max_velocity);
    /// \srs{IM6} WorldDef::joint_hertz (Hz, > 0) and joint_damping_ratio (> 0).
    void set_joint_tuning(double hertz, double damping_ratio);
    /// \srs{DD12} WorldDef::restitution_threshold (m s^-1, >= 0).
    void set_restitution_threshold(double speed);
    /// \srs{DD40} WorldDef::maximum_linear_speed (m s^-1, > 0; infinite: no limit). A body
    /// faster than a new, lower limit is slowed to it by the next step.
    void set_maximum_linear_speed(double speed);
    /// WorldDef::workers ([1, 256]): the World's own pool is replaced (with a task system,
    /// its number of worker numbers). The results stay bitwise those of one worker.
    void set_workers(int workers);
    /// Bodies awake now (with sleeping off, every enabled body that is not static).
    std::size_t awake_body_count() const;

    // --- definitions ---
    // What a definition sets that a game may change later: the body's controls (BodyDef::
    // enabled, motion_locks, sleep_threshold), the joints' (spring_target, constraint_tuning)
    // and this setting of WorldDef.
    /// \srs{IM7} WorldDef::enable_warm_starting, from the next step: off, each step's solve
    /// starts from zero impulses (Box2D v3's b2World_EnableWarmStarting). On, the default, the
    /// step is bit for bit what it was before the setting existed. Setting the value the world
    /// has changes nothing. Throws nothing; wakes nothing.
    void set_warm_starting(bool enabled);
    bool warm_starting() const; ///< WorldDef::enable_warm_starting, as set

    /// A hash of the complete simulation state (bit patterns of every double): equal hashes
    /// mean bitwise-equal worlds. Used by the determinism and strong-guarantee tests.
    std::uint64_t state_hash() const;

#endif // TAMIAS2D_EXCEPTIONS

    // --- error-returning forms ---
    // Each `try_` call is the call of the same name (try_create: the constructor) with the same
    // arguments, effects and guarantee, returning its result, or the Error its throwing form
    // would throw (result.hpp), instead of throwing. A refused call changes nothing, as the
    // throwing form's does. None throws; each is declared whatever TAMIAS2D_EXCEPTIONS is.
    /// the constructor, returning its Error instead of throwing it.
    static Result<World> try_create(const WorldDef& def = {}) noexcept;
    /// tag, returning its Error instead of throwing it.
    Result<std::uint32_t> try_tag() const noexcept;
    /// create_body, returning its Error instead of throwing it.
    Result<BodyId> try_create_body(const BodyDef& def) noexcept;
    /// destroy_body, returning its Error instead of throwing it.
    Result<void> try_destroy_body(BodyId body) noexcept;
    /// create_shape, returning its Error instead of throwing it.
    Result<ShapeId> try_create_shape(BodyId body, const ShapeDef& def) noexcept;
    /// create_chain, returning its Error instead of throwing it.
    Result<std::vector<ShapeId>> try_create_chain(BodyId body,
                                                  std::span<const ShapeDef> segments) noexcept;
    /// destroy_shape, returning its Error instead of throwing it.
    Result<void> try_destroy_shape(ShapeId shape) noexcept;
    /// set_filter, returning its Error instead of throwing it.
    Result<void> try_set_filter(ShapeId shape, const Filter& filter) noexcept;
    /// filter, returning its Error instead of throwing it.
    Result<Filter> try_filter(ShapeId shape) const noexcept;
    /// set_custom_filter, returning its Error instead of throwing it.
    Result<void> try_set_custom_filter(std::function<bool(ShapeId, ShapeId)> filter) noexcept;
    /// is_valid, returning its Error instead of throwing it.
    Result<bool> try_is_valid(BodyId body) const noexcept;
    /// is_valid, returning its Error instead of throwing it.
    Result<bool> try_is_valid(ShapeId shape) const noexcept;
    /// bodies, returning its Error instead of throwing it.
    Result<std::vector<BodyId>> try_bodies() const noexcept;
    /// shapes, returning its Error instead of throwing it.
    Result<std::vector<ShapeId>> try_shapes(BodyId body) const noexcept;
    /// body_count, returning its Error instead of throwing it.
    Result<std::size_t> try_body_count() const noexcept;
    /// set_friction, returning its Error instead of throwing it.
    Result<void> try_set_friction(ShapeId shape, double friction) noexcept;
    /// friction, returning its Error instead of throwing it.
    Result<double> try_friction(ShapeId shape) const noexcept;
    /// set_restitution, returning its Error instead of throwing it.
    Result<void> try_set_restitution(ShapeId shape, double restitution) noexcept;
    /// restitution, returning its Error instead of throwing it.
    Result<double> try_restitution(ShapeId shape) const noexcept;
    /// set_rolling_resistance, returning its Error instead of throwing it.
    Result<void> try_set_rolling_resistance(ShapeId shape, double rolling_resistance) noexcept;
    /// rolling_resistance, returning its Error instead of throwing it.
    Result<double> try_rolling_resistance(ShapeId shape) const noexcept;
    /// set_tangent_speed, returning its Error instead of throwing it.
    Result<void> try_set_tangent_speed(ShapeId shape, double tangent_speed) noexcept;
    /// tangent_speed, returning its Error instead of throwing it.
    Result<double> try_tangent_speed(ShapeId shape) const noexcept;
    /// set_density, returning its Error instead of throwing it.
    Result<void> try_set_density(ShapeId shape, double density,
                                 bool update_body_mass = true) noexcept;
    /// density, returning its Error instead of throwing it.
    Result<double> try_density(ShapeId shape) const noexcept;
    /// set_circle, returning its Error instead of throwing it.
    Result<void> try_set_circle(ShapeId shape, const Circle& circle) noexcept;
    /// set_capsule, returning its Error instead of throwing it.
    Result<void> try_set_capsule(ShapeId shape, const Capsule& capsule) noexcept;
    /// set_polygon, returning its Error instead of throwing it.
    Result<void> try_set_polygon(ShapeId shape, const Polygon& polygon) noexcept;
    /// set_segment, returning its Error instead of throwing it.
    Result<void> try_set_segment(ShapeId shape, const Segment& segment) noexcept;
    /// shape_geometry, returning its Error instead of throwing it.
    Result<Geometry> try_shape_geometry(ShapeId shape) const noexcept;
    /// set_sensor, returning its Error instead of throwing it.
    Result<void> try_set_sensor(ShapeId shape, bool is_sensor) noexcept;
    /// is_sensor, returning its Error instead of throwing it.
    Result<bool> try_is_sensor(ShapeId shape) const noexcept;
    /// step, returning its Error instead of throwing it.
    Result<void> try_step(double dt) noexcept;
    /// time, returning its Error instead of throwing it.
    Result<double> try_time() const noexcept;
    /// set_gravity, returning its Error instead of throwing it.
    Result<void> try_set_gravity(Vec2d g) noexcept;
    /// gravity, returning its Error instead of throwing it.
    Result<Vec2d> try_gravity() const noexcept;
    /// settings, returning its Error instead of throwing it.
    Result<WorldDef> try_settings() const noexcept;
    /// state, returning its Error instead of throwing it.
    Result<BodyState> try_state(BodyId body) const noexcept;
    /// position, returning its Error instead of throwing it.
    Result<Vec2d> try_position(BodyId body) const noexcept;
    /// origin, returning its Error instead of throwing it.
    Result<Vec2d> try_origin(BodyId body) const noexcept;
    /// orientation, returning its Error instead of throwing it.
    Result<double> try_orientation(BodyId body) const noexcept;
    /// velocity, returning its Error instead of throwing it.
    Result<Vec2d> try_velocity(BodyId body) const noexcept;
    /// angular_velocity, returning its Error instead of throwing it.
    Result<double> try_angular_velocity(BodyId body) const noexcept;
    /// mass, returning its Error instead of throwing it.
    Result<double> try_mass(BodyId body) const noexcept;
    /// inertia, returning its Error instead of throwing it.
    Result<double> try_inertia(BodyId body) const noexcept;
    /// local_center, returning its Error instead of throwing it.
    Result<Vec2d> try_local_center(BodyId body) const noexcept;
    /// type, returning its Error instead of throwing it.
    Result<BodyType> try_type(BodyId body) const noexcept;
    /// name, returning its Error instead of throwing it.
    Result<std::string> try_name(BodyId body) const noexcept;
    /// set_transform, returning its Error instead of throwing it.
    Result<void> try_set_transform(BodyId body, Vec2d origin, double angle) noexcept;
    /// set_velocity, returning its Error instead of throwing it.
    Result<void> try_set_velocity(BodyId body, Vec2d v) noexcept;
    /// set_angular_velocity, returning its Error instead of throwing it.
    Result<void> try_set_angular_velocity(BodyId body, double omega) noexcept;
    /// set_damping, returning its Error instead of throwing it.
    Result<void> try_set_damping(BodyId body, double linear, double angular) noexcept;
    /// linear_damping, returning its Error instead of throwing it.
    Result<double> try_linear_damping(BodyId body) const noexcept;
    /// angular_damping, returning its Error instead of throwing it.
    Result<double> try_angular_damping(BodyId body) const noexcept;
    /// set_force, returning its Error instead of throwing it.
    Result<void> try_set_force(BodyId body, Vec2d force) noexcept;
    /// set_torque, returning its Error instead of throwing it.
    Result<void> try_set_torque(BodyId body, double torque) noexcept;
    /// apply_force, returning its Error instead of throwing it.
    Result<void> try_apply_force(BodyId body, Vec2d force, Vec2d world_point) noexcept;
    /// apply_torque, returning its Error instead of throwing it.
    Result<void> try_apply_torque(BodyId body, double torque) noexcept;
    /// apply_impulse, returning its Error instead of throwing it.
    Result<void> try_apply_impulse(BodyId body, Vec2d impulse, Vec2d world_point) noexcept;
    /// set_load, returning its Error instead of throwing it.
    Result<void> try_set_load(BodyId body, LoadFunction load) noexcept;
    /// create_joint, returning its Error instead of throwing it.
    Result<JointId> try_create_joint(const RevoluteJointDef& def) noexcept;
    /// create_joint, returning its Error instead of throwing it.
    Result<JointId> try_create_joint(const DistanceJointDef& def) noexcept;
    /// create_joint, returning its Error instead of throwing it.
    Result<JointId> try_create_joint(const TargetJointDef& def) noexcept;
    /// create_joint, returning its Error instead of throwing it.
    Result<JointId> try_create_joint(const PrismaticJointDef& def) noexcept;
    /// create_joint, returning its Error instead of throwing it.
    Result<JointId> try_create_joint(const WeldJointDef& def) noexcept;
    /// create_joint, returning its Error instead of throwing it.
    Result<JointId> try_create_joint(const WheelJointDef& def) noexcept;
    /// create_joint, returning its Error instead of throwing it.
    Result<JointId> try_create_joint(const MotorJointDef& def) noexcept;
    /// create_joint, returning its Error instead of throwing it.
    Result<JointId> try_create_joint(const FilterJointDef& def) noexcept;
    /// set_motor_joint_offsets, returning its Error instead of throwing it.
    Result<void> try_set_motor_joint_offsets(JointId joint, Vec2d linear_offset,
                                             double angular_offset) noexcept;
    /// set_joint_target, returning its Error instead of throwing it.
    Result<void> try_set_joint_target(JointId joint, Vec2d target) noexcept;
    /// destroy_joint, returning its Error instead of throwing it.
    Result<void> try_destroy_joint(JointId joint) noexcept;
    /// is_valid, returning its Error instead of throwing it.
    Result<bool> try_is_valid(JointId joint) const noexcept;
    /// joint_reaction_force, returning its Error instead of throwing it.
    Result<Vec2d> try_joint_reaction_force(JointId joint) const noexcept;
    /// joint_reaction_torque, returning its Error instead of throwing it.
    Result<double> try_joint_reaction_torque(JointId joint) const noexcept;
    /// joint_angle, returning its Error instead of throwing it.
    Result<double> try_joint_angle(JointId joint) const noexcept;
    /// joint_translation, returning its Error instead of throwing it.
    Result<double> try_joint_translation(JointId joint) const noexcept;
    /// set_joint_motor_speed, returning its Error instead of throwing it.
    Result<void> try_set_joint_motor_speed(JointId joint, double speed) noexcept;
    /// broken_joints, returning its Error instead of throwing it.
    Result<std::span<const JointId>> try_broken_joints() const noexcept;
    /// joint_count, returning its Error instead of throwing it.
    Result<std::size_t> try_joint_count() const noexcept;
    /// joint_kind, returning its Error instead of throwing it.
    Result<JointKind> try_joint_kind(JointId joint) const noexcept;
    /// joint_body_a, returning its Error instead of throwing it.
    Result<BodyId> try_joint_body_a(JointId joint) const noexcept;
    /// joint_body_b, returning its Error instead of throwing it.
    Result<BodyId> try_joint_body_b(JointId joint) const noexcept;
    /// enable_joint_limit, returning its Error instead of throwing it.
    Result<void> try_enable_joint_limit(JointId joint, bool enable) noexcept;
    /// is_joint_limit_enabled, returning its Error instead of throwing it.
    Result<bool> try_is_joint_limit_enabled(JointId joint) const noexcept;
    /// set_joint_limits, returning its Error instead of throwing it.
    Result<void> try_set_joint_limits(JointId joint, double lower, double upper) noexcept;
    /// joint_limits, returning its Error instead of throwing it.
    Result<JointLimits> try_joint_limits(JointId joint) const noexcept;
    /// enable_joint_motor, returning its Error instead of throwing it.
    Result<void> try_enable_joint_motor(JointId joint, bool enable) noexcept;
    /// is_joint_motor_enabled, returning its Error instead of throwing it.
    Result<bool> try_is_joint_motor_enabled(JointId joint) const noexcept;
    /// joint_motor_speed, returning its Error instead of throwing it.
    Result<double> try_joint_motor_speed(JointId joint) const noexcept;
    /// set_joint_max_motor_torque, returning its Error instead of throwing it.
    Result<void> try_set_joint_max_motor_torque(JointId joint, double torque) noexcept;
    /// joint_max_motor_torque, returning its Error instead of throwing it.
    Result<double> try_joint_max_motor_torque(JointId joint) const noexcept;
    /// set_joint_max_motor_force, returning its Error instead of throwing it.
    Result<void> try_set_joint_max_motor_force(JointId joint, double force) noexcept;
    /// joint_max_motor_force, returning its Error instead of throwing it.
    Result<double> try_joint_max_motor_force(JointId joint) const noexcept;
    /// enable_joint_spring, returning its Error instead of throwing it.
    Result<void> try_enable_joint_spring(JointId joint, bool enable) noexcept;
    /// is_joint_spring_enabled, returning its Error instead of throwing it.
    Result<bool> try_is_joint_spring_enabled(JointId joint) const noexcept;
    /// set_joint_spring, returning its Error instead of throwing it.
    Result<void> try_set_joint_spring(JointId joint, double hertz, double damping_ratio) noexcept;
    /// joint_spring_hertz, returning its Error instead of throwing it.
    Result<double> try_joint_spring_hertz(JointId joint) const noexcept;
    /// joint_spring_damping_ratio, returning its Error instead of throwing it.
    Result<double> try_joint_spring_damping_ratio(JointId joint) const noexcept;
    /// set_joint_spring_target, returning its Error instead of throwing it.
    Result<void> try_set_joint_spring_target(JointId joint, double target) noexcept;
    /// joint_spring_target, returning its Error instead of throwing it.
    Result<double> try_joint_spring_target(JointId joint) const noexcept;
    /// set_distance_joint_length, returning its Error instead of throwing it.
    Result<void> try_set_distance_joint_length(JointId joint, double length) noexcept;
    /// distance_joint_length, returning its Error instead of throwing it.
    Result<double> try_distance_joint_length(JointId joint) const noexcept;
    /// set_constraint_tuning, returning its Error instead of throwing it.
    Result<void> try_set_constraint_tuning(JointId joint, double hertz,
                                           double damping_ratio) noexcept;
    /// constraint_tuning, returning its Error instead of throwing it.
    Result<ConstraintTuning> try_constraint_tuning(JointId joint) const noexcept;
    /// set_joint_collide_connected, returning its Error instead of throwing it.
    Result<void> try_set_joint_collide_connected(JointId joint, bool collide) noexcept;
    /// joint_collide_connected, returning its Error instead of throwing it.
    Result<bool> try_joint_collide_connected(JointId joint) const noexcept;
    /// set_joint_break_force, returning its Error instead of throwing it.
    Result<void> try_set_joint_break_force(JointId joint, double force) noexcept;
    /// joint_break_force, returning its Error instead of throwing it.
    Result<double> try_joint_break_force(JointId joint) const noexcept;
    /// set_joint_break_torque, returning its Error instead of throwing it.
    Result<void> try_set_joint_break_torque(JointId joint, double torque) noexcept;
    /// joint_break_torque, returning its Error instead of throwing it.
    Result<double> try_joint_break_torque(JointId joint) const noexcept;
    /// is_awake, returning its Error instead of throwing it.
    Result<bool> try_is_awake(BodyId body) const noexcept;
    /// set_awake, returning its Error instead of throwing it.
    Result<void> try_set_awake(BodyId body, bool awake) noexcept;
    /// kinetic_energy, returning its Error instead of throwing it.
    Result<double> try_kinetic_energy() const noexcept;
    /// potential_energy, returning its Error instead of throwing it.
    Result<double> try_potential_energy() const noexcept;
    /// linear_momentum, returning its Error instead of throwing it.
    Result<Vec2d> try_linear_momentum() const noexcept;
    /// contacts, returning its Error instead of throwing it.
    Result<std::span<const ContactInfo>> try_contacts() const noexcept;
    /// contact_begin_events, returning its Error instead of throwing it.
    Result<std::span<const ContactEvent>> try_contact_begin_events() const noexcept;
    /// contact_end_events, returning its Error instead of throwing it.
    Result<std::span<const ContactEvent>> try_contact_end_events() const noexcept;
    /// sensor_begin_events, returning its Error instead of throwing it.
    Result<std::span<const SensorEvent>> try_sensor_begin_events() const noexcept;
    /// sensor_end_events, returning its Error instead of throwing it.
    Result<std::span<const SensorEvent>> try_sensor_end_events() const noexcept;
    /// query_aabb, returning its Error instead of throwing it.
    Result<std::vector<ShapeId>> try_query_aabb(const Aabb& box) const noexcept;
    /// query_point, returning its Error instead of throwing it.
    Result<std::vector<ShapeId>> try_query_point(Vec2d point) const noexcept;
    /// ray_cast, returning its Error instead of throwing it.
    Result<std::optional<RayCastHit>> try_ray_cast(Vec2d origin, Vec2d translation) const noexcept;
    /// snapshot, returning its Error instead of throwing it.
    Result<std::vector<std::byte>> try_snapshot() const noexcept;
    /// snapshot, returning its Error instead of throwing it.
    Result<void> try_snapshot(std::vector<std::byte>& bytes) const noexcept;
    /// from_snapshot, returning its Error instead of throwing it.
    static Result<World> try_from_snapshot(std::span<const std::byte> snapshot, int workers = 1,
                                           const TaskSystem& task_system = {}) noexcept;
    /// restore, returning its Error instead of throwing it.
    Result<void> try_restore(std::span<const std::byte> snapshot) noexcept;
    /// definitions, returning its Error instead of throwing it.
    Result<WorldDefinitions> try_definitions() const noexcept;
    /// ray_cast, returning its Error instead of throwing it.
    Result<std::optional<RayCastHit>> try_ray_cast(Vec2d origin, Vec2d translation,
                                                   const QueryFilter& filter) const noexcept;
    /// ray_cast_all, returning its Error instead of throwing it.
    Result<std::vector<RayCastHit>> try_ray_cast_all(Vec2d origin, Vec2d translation,
                                                     const QueryFilter& filter = {}) const noexcept;
    /// ray_cast_all, returning its Error instead of throwing it.
    Result<std::size_t> try_ray_cast_all(Vec2d origin, Vec2d translation, const QueryFilter& filter,
                                         std::span<RayCastHit> out) const noexcept;
    /// ray_cast_any, returning its Error instead of throwing it.
    Result<std::optional<RayCastHit>>
    try_ray_cast_any(Vec2d origin, Vec2d translation,
                     const QueryFilter& filter = {}) const noexcept;
    /// ray_cast, returning its Error instead of throwing it.
    Result<void> try_ray_cast(Vec2d origin, Vec2d translation, const QueryFilter& filter,
                              RayCastCallback callback) const noexcept;
    /// ray_cast, returning its Error instead of throwing it.
    Result<std::optional<RayCastHit>> try_ray_cast(ShapeId shape, Vec2d origin,
                                                   Vec2d translation) const noexcept;
    /// shape_cast, returning its Error instead of throwing it.
    Result<std::optional<ShapeCastHit>>
    try_shape_cast(const Geometry& shape, Vec2d origin, double angle, Vec2d translation,
                   const QueryFilter& filter = {}) const noexcept;
    /// shape_cast, returning its Error instead of throwing it.
    Result<void> try_shape_cast(const Geometry& shape, Vec2d origin, double angle,
                                Vec2d translation, const QueryFilter& filter,
                                ShapeCastCallback callback) const noexcept;
    /// cast_tolerance, returning its Error instead of throwing it.
    static Result<double> try_cast_tolerance(const Geometry& shape, Vec2d translation) noexcept;
    /// query_aabb, returning its Error instead of throwing it.
    Result<std::vector<ShapeId>> try_query_aabb(const Aabb& box,
                                                const QueryFilter& filter) const noexcept;
    /// query_aabb, returning its Error instead of throwing it.
    Result<void> try_query_aabb(const Aabb& box, const QueryFilter& filter,
                                OverlapCallback callback) const noexcept;
    /// query_point, returning its Error instead of throwing it.
    Result<std::vector<ShapeId>> try_query_point(Vec2d point,
                                                 const QueryFilter& filter) const noexcept;
    /// query_point, returning its Error instead of throwing it.
    Result<void> try_query_point(Vec2d point, const QueryFilter& filter,
                                 OverlapCallback callback) const noexcept;
    /// overlap_shape, returning its Error instead of throwing it.
    Result<std::vector<ShapeId>> try_overlap_shape(const Geometry& shape, Vec2d origin,
                                                   double angle,
                                                   const QueryFilter& filter = {}) const noexcept;
    /// overlap_shape, returning its Error instead of throwing it.
    Result<void> try_overlap_shape(const Geometry& shape, Vec2d origin, double angle,
                                   const QueryFilter& filter,
                                   OverlapCallback callback) const noexcept;
    /// distance, returning its Error instead of throwing it.
    Result<ClosestPoints> try_distance(ShapeId a, ShapeId b) const noexcept;
    /// closest_point, returning its Error instead of throwing it.
    Result<ClosestPoints> try_closest_point(ShapeId shape, Vec2d point) const noexcept;
    /// contact_hit_events, returning its Error instead of throwing it.
    Result<std::span<const ContactHitEvent>> try_contact_hit_events() const noexcept;
    /// body_move_events, returning its Error instead of throwing it.
    Result<std::span<const BodyMoveEvent>> try_body_move_events() const noexcept;
    /// joint_events, returning its Error instead of throwing it.
    Result<std::span<const JointEvent>> try_joint_events() const noexcept;
    /// sensor_overlaps, returning its Error instead of throwing it.
    Result<std::vector<ShapeId>> try_sensor_overlaps(ShapeId sensor) const noexcept;
    /// set_hit_event_threshold, returning its Error instead of throwing it.
    Result<void> try_set_hit_event_threshold(double speed) noexcept;
    /// set_hit_events_enabled, returning its Error instead of throwing it.
    Result<void> try_set_hit_events_enabled(ShapeId shape, bool on) noexcept;
    /// hit_events_enabled, returning its Error instead of throwing it.
    Result<bool> try_hit_events_enabled(ShapeId shape) const noexcept;
    /// set_contact_events_enabled, returning its Error instead of throwing it.
    Result<void> try_set_contact_events_enabled(ShapeId shape, bool on) noexcept;
    /// contact_events_enabled, returning its Error instead of throwing it.
    Result<bool> try_contact_events_enabled(ShapeId shape) const noexcept;
    /// set_sensor_events_enabled, returning its Error instead of throwing it.
    Result<void> try_set_sensor_events_enabled(ShapeId shape, bool on) noexcept;
    /// sensor_events_enabled, returning its Error instead of throwing it.
    Result<bool> try_sensor_events_enabled(ShapeId shape) const noexcept;
    /// set_move_events_enabled, returning its Error instead of throwing it.
    Result<void> try_set_move_events_enabled(BodyId body, bool on) noexcept;
    /// move_events_enabled, returning its Error instead of throwing it.
    Result<bool> try_move_events_enabled(BodyId body) const noexcept;
    /// set_joint_event_thresholds, returning its Error instead of throwing it.
    Result<void> try_set_joint_event_thresholds(JointId joint, double force,
                                                double torque) noexcept;
    /// joint_force_threshold, returning its Error instead of throwing it.
    Result<double> try_joint_force_threshold(JointId joint) const noexcept;
    /// joint_torque_threshold, returning its Error instead of throwing it.
    Result<double> try_joint_torque_threshold(JointId joint) const noexcept;
    /// draw, returning its Error instead of throwing it.
    Result<void> try_draw(DebugDraw& draw) const noexcept;
    /// set_profiling, returning its Error instead of throwing it.
    Result<void> try_set_profiling(bool on) noexcept;
    /// profiling, returning its Error instead of throwing it.
    Result<bool> try_profiling() const noexcept;
    /// profile, returning its Error instead of throwing it.
    Result<StepProfile> try_profile() const noexcept;
    /// counters, returning its Error instead of throwing it.
    Result<WorldCounters> try_counters() const noexcept;
    /// explode, returning its Error instead of throwing it.
    Result<std::size_t> try_explode(const ExplosionDef& def) noexcept;
    /// cast_mover, returning its Error instead of throwing it.
    Result<double> try_cast_mover(const Capsule& mover, Vec2d translation,
                                  const QueryFilter& filter = {}) const noexcept;
    /// collide_mover, returning its Error instead of throwing it.
    Result<std::vector<MoverPlane>>
    try_collide_mover(const Capsule& mover, const QueryFilter& filter = {}) const noexcept;
    /// collide_mover, returning its Error instead of throwing it.
    Result<void> try_collide_mover(const Capsule& mover, const QueryFilter& filter,
                                   MoverPlaneCallback callback) const noexcept;
    /// set_target_transform, returning its Error instead of throwing it.
    Result<void> try_set_target_transform(BodyId body, Vec2d origin, double angle,
                                          double dt) noexcept;
    /// apply_wind, returning its Error instead of throwing it.
    Result<void> try_apply_wind(ShapeId shape, Vec2d wind, double drag, double lift,
                                bool wake = true) noexcept;
    /// set_user_data, returning its Error instead of throwing it.
    Result<void> try_set_user_data(UserData data) noexcept;
    /// user_data, returning its Error instead of throwing it.
    Result<UserData> try_user_data() const noexcept;
    /// set_user_data, returning its Error instead of throwing it.
    Result<void> try_set_user_data(BodyId body, UserData data) noexcept;
    /// user_data, returning its Error instead of throwing it.
    Result<UserData> try_user_data(BodyId body) const noexcept;
    /// set_user_data, returning its Error instead of throwing it.
    Result<void> try_set_user_data(ShapeId shape, UserData data) noexcept;
    /// user_data, returning its Error instead of throwing it.
    Result<UserData> try_user_data(ShapeId shape) const noexcept;
    /// set_user_data, returning its Error instead of throwing it.
    Result<void> try_set_user_data(JointId joint, UserData data) noexcept;
    /// user_data, returning its Error instead of throwing it.
    Result<UserData> try_user_data(JointId joint) const noexcept;
    /// body, returning its Error instead of throwing it.
    Result<BodyId> try_body(ShapeId shape) const noexcept;
    /// shape_type, returning its Error instead of throwing it.
    Result<ShapeType> try_shape_type(ShapeId shape) const noexcept;
    /// geometry, returning its Error instead of throwing it.
    Result<Geometry> try_geometry(ShapeId shape) const noexcept;
    /// shape_aabb, returning its Error instead of throwing it.
    Result<Aabb> try_shape_aabb(ShapeId shape) const noexcept;
    /// body_aabb, returning its Error instead of throwing it.
    Result<Aabb> try_body_aabb(BodyId body) const noexcept;
    /// joints, returning its Error instead of throwing it.
    Result<std::vector<JointId>> try_joints(BodyId body) const noexcept;
    /// contacts, returning its Error instead of throwing it.
    Result<std::vector<ContactInfo>> try_contacts(BodyId body) const noexcept;
    /// set_body_type, returning its Error instead of throwing it.
    Result<void> try_set_body_type(BodyId body, BodyType type) noexcept;
    /// set_enabled, returning its Error instead of throwing it.
    Result<void> try_set_enabled(BodyId body, bool enabled) noexcept;
    /// is_enabled, returning its Error instead of throwing it.
    Result<bool> try_is_enabled(BodyId body) const noexcept;
    /// set_gravity_scale, returning its Error instead of throwing it.
    Result<void> try_set_gravity_scale(BodyId body, double scale) noexcept;
    /// gravity_scale, returning its Error instead of throwing it.
    Result<double> try_gravity_scale(BodyId body) const noexcept;
    /// set_bullet, returning its Error instead of throwing it.
    Result<void> try_set_bullet(BodyId body, bool bullet) noexcept;
    /// is_bullet, returning its Error instead of throwing it.
    Result<bool> try_is_bullet(BodyId body) const noexcept;
    /// set_motion_locks, returning its Error instead of throwing it.
    Result<void> try_set_motion_locks(BodyId body, MotionLocks locks) noexcept;
    /// motion_locks, returning its Error instead of throwing it.
    Result<MotionLocks> try_motion_locks(BodyId body) const noexcept;
    /// set_fixed_rotation, returning its Error instead of throwing it.
    Result<void> try_set_fixed_rotation(BodyId body, bool fixed) noexcept;
    /// fixed_rotation, returning its Error instead of throwing it.
    Result<bool> try_fixed_rotation(BodyId body) const noexcept;
    /// set_mass_data, returning its Error instead of throwing it.
    Result<void> try_set_mass_data(BodyId body, const BodyMassData& data) noexcept;
    /// mass_data, returning its Error instead of throwing it.
    Result<BodyMassData> try_mass_data(BodyId body) const noexcept;
    /// reset_mass_data, returning its Error instead of throwing it.
    Result<void> try_reset_mass_data(BodyId body) noexcept;
    /// set_sleep_threshold, returning its Error instead of throwing it.
    Result<void> try_set_sleep_threshold(BodyId body, double speed) noexcept;
    /// sleep_threshold, returning its Error instead of throwing it.
    Result<double> try_sleep_threshold(BodyId body) const noexcept;
    /// wake_touching, returning its Error instead of throwing it.
    Result<void> try_wake_touching(BodyId body) noexcept;
    /// set_pre_solve, returning its Error instead of throwing it.
    Result<void> try_set_pre_solve(PreSolveFunction callback) noexcept;
    /// set_friction_mixing, returning its Error instead of throwing it.
    Result<void> try_set_friction_mixing(MaterialMixFunction mix) noexcept;
    /// set_restitution_mixing, returning its Error instead of throwing it.
    Result<void> try_set_restitution_mixing(MaterialMixFunction mix) noexcept;
    /// set_user_material, returning its Error instead of throwing it.
    Result<void> try_set_user_material(ShapeId shape, std::uint64_t id) noexcept;
    /// user_material, returning its Error instead of throwing it.
    Result<std::uint64_t> try_user_material(ShapeId shape) const noexcept;
    /// set_continuous, returning its Error instead of throwing it.
    Result<void> try_set_continuous(bool enabled) noexcept;
    /// set_sleeping, returning its Error instead of throwing it.
    Result<void> try_set_sleeping(bool enabled) noexcept;
    /// set_contact_tuning, returning its Error instead of throwing it.
    Result<void> try_set_contact_tuning(double hertz, double damping_ratio,
                                        double push_max_velocity) noexcept;
    /// set_joint_tuning, returning its Error instead of throwing it.
    Result<void> try_set_joint_tuning(double hertz, double damping_ratio) noexcept;
    /// set_restitution_threshold, returning its Error instead of throwing it.
    Result<void> try_set_restitution_threshold(double speed) noexcept;
    /// set_maximum_linear_speed, returning its Error instead of throwing it.
    Result<void> try_set_maximum_linear_speed(double speed) noexcept;
    /// set_workers, returning its Error instead of throwing it.
    Result<void> try_set_workers(int workers) noexcept;
    /// awake_body_count, returning its Error instead of throwing it.
    Result<std::size_t> try_awake_body_count() const noexcept;
    /// set_warm_starting, returning its Error instead of throwing it.
    Result<void> try_set_warm_starting(bool enabled) noexcept;
    /// warm_starting, returning its Error instead of throwing it.
    Result<bool> try_warm_starting() const noexcept;
    /// state_hash, returning its Error instead of throwing it.
    Result<std::uint64_t> try_state_hash() const noexcept;

    // --- recording ---
    // A Recorder (recorder.hpp) records a world's calls and a Replayer (replay.hpp) plays them
    // back: World has no call of its own for it, so that a world not recorded pays nothing. They
    // read the engine's state (the bodies' exact angles, whether a function is installed)
    // through this internal access.
    /// \cond INTERNAL
    friend struct RecordingAccess;
    /// \endcond

    /// \cond INTERNAL
    struct Impl; // the engine's state (src/tamias2d/world.cpp): not part of the API
                 /// \endcond

  private:
    std::unique_ptr<Impl> impl_;
};

} // namespace tamias2d
