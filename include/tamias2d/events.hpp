/// \file
/// What a game reacts to after a step beyond the begin and end events of contact_info.hpp:
/// hard hits, the bodies that moved (and those that fell asleep), and joints that carried
/// more than a threshold, broke or went with their body. World::contact_hit_events,
/// body_move_events and joint_events list them; each kind is switched on per shape, body or
/// joint (ShapeDef, BodyDef, the joint definitions).
#pragma once

#include <cstdint>
#include <string_view>

#include "tamias2d/handles.hpp"
#include "tamias2d/vec2.hpp"

namespace tamias2d {

/// \srs{DD11} A touching pair that pushed in the last step while its bodies approached faster
/// than WorldDef::hit_event_threshold at a manifold point: an impact to play a sound or leave a
/// dent for. Reported for a pair of which at least one shape has ShapeDef::enable_hit_events.
struct ContactHitEvent {
    ShapeId shape_a; ///< the first shape of the pair
    ShapeId shape_b; ///< the second shape of the pair
    BodyId body_a;   ///< the body carrying shape_a
    BodyId body_b;   ///< the body carrying shape_b
    /// m, world frame: the manifold point that approached fastest (of two that approached
    /// equally fast, the first in the manifold's order, ContactInfo::points).
    Vec2d point{};
    Vec2d normal{}; ///< unit, from shape_a into shape_b
    /// m s^-1, > 0: the speed at which the two bodies' points approached along the normal at
    /// the step's start, before the solver acted: -(v_B - v_A) . n at the point (DD11).
    double approach_speed = 0.0;
};

/// A body that moved in the last step (awake and not static) and has
/// BodyDef::enable_move_events: its pose after the step, to move its sprite without asking
/// every body. `fell_asleep` marks the step in which it went to sleep (it is then still, and
/// is reported no more until it wakes).
struct BodyMoveEvent {
    BodyId body;        ///< the body
    Vec2d origin{};     ///< m, its origin after the step (World::origin)
    double angle = 0.0; ///< rad in [0, 2 pi), its orientation after the step (World::orientation)
    bool fell_asleep = false; ///< it fell asleep in this step (WorldDef::enable_sleep)
};

/// Why a joint is in World::joint_events.
enum class JointEventKind : std::uint8_t {
    /// In the last step the joint's reaction force exceeded its force_threshold or its
    /// reaction torque its torque_threshold (it still exists).
    threshold_exceeded,
    /// In the last step its reaction force exceeded its break_force: it no longer exists (it
    /// is in World::broken_joints too).
    broke,
    /// Its body was destroyed (World::destroy_body) since the last step: it no longer exists.
    body_destroyed
};

/// A joint event's kind as messages and the command-line tool spell it: "threshold_exceeded",
/// "broke" or "body_destroyed"; "" for a value outside the enumeration.
constexpr std::string_view to_string(JointEventKind kind) noexcept {
    switch (kind) {
    case JointEventKind::threshold_exceeded:
        return "threshold_exceeded";
    case JointEventKind::broke:
        return "broke";
    case JointEventKind::body_destroyed:
        return "body_destroyed";
    }
    return "";
}

/// A joint a game may want to react to (a creaking hinge, a rope that snapped, a chain whose
/// anchor was removed). After `broke` or `body_destroyed` the handle names nothing any more.
struct JointEvent {
    JointId joint;       ///< the joint
    JointEventKind kind; ///< why it is reported
    BodyId body_a;       ///< its first body (destroyed with body_destroyed when it was this one)
    BodyId body_b;       ///< its second body (a target joint's one body: body_a == body_b)
    Vec2d force{};       ///< N: its reaction force in the last step (World::joint_reaction_force)
    double torque = 0.0; ///< N m: its reaction torque in the last step (joint_reaction_torque)
};

} // namespace tamias2d
