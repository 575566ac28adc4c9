/// \file
/// What a body is made from (SRS R2). Every field is in SI units, stated beside it.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include "tamias2d/motion_locks.hpp"
#include "tamias2d/user_data.hpp"
#include "tamias2d/vec2.hpp"

namespace tamias2d {

/// Static bodies never move; kinematic bodies move with their velocity and are not pushed;
/// dynamic bodies obey IM1/IM2 and collisions.
enum class BodyType : std::uint8_t { static_body, kinematic, dynamic };

/// A body type's name as scene files, the command-line tool, the viewer and messages spell it:
/// "static", "kinematic" or "dynamic"; "" for a value outside the enumeration.
constexpr std::string_view to_string(BodyType type) noexcept {
    switch (type) {
    case BodyType::static_body:
        return "static";
    case BodyType::kinematic:
        return "kinematic";
    case BodyType::dynamic:
        return "dynamic";
    }
    return "";
}

/// Time-varying loads (SRS IM1's F_i(t), IM2's tau_i(t)) at the centre of mass.
struct Load {
    Vec2d force{};       ///< N
    double torque = 0.0; ///< N m, CCW positive (A4)
};

/// Called once per step with the simulation time t (s) at the start of the step; the returned
/// load acts through the step (held constant over its substeps).
using LoadFunction = std::function<Load(double t)>;

/// \srs{R2} The inputs of a body: mass, initial position, velocity, orientation, angular
/// velocity and the forces applied to it.
struct BodyDef {
    BodyType type = BodyType::dynamic; ///< how the body moves
    Vec2d position{};                  ///< m, world position of the body origin
    double angle = 0.0;                ///< rad, orientation (|phi| <= 1e12; read back in [0, 2 pi))
    Vec2d linear_velocity{};           ///< m s^-1, of the centre of mass
    double angular_velocity = 0.0;     ///< rad s^-1, CCW positive
    Vec2d force{};                     ///< N, persistent force at the centre of mass
    double torque = 0.0;               ///< N m, persistent torque
    /// kg, > 0. Overrides the mass computed from the shapes and their densities (DD1).
    std::optional<double> mass{};
    /// kg m^2 about the centre of mass, > 0. Overrides the computed moment of inertia (DD14).
    std::optional<double> inertia{};
    double gravity_scale = 1.0; ///< multiplies the world's gravity for this body
    /// \srs{DD17} s^-1, >= 0: viscous damping of the velocity (a = -c v, IM5). A body left
    /// alone keeps e^(-c t) of its speed; 0 (the default) is the SRS's regime (A6).
    double linear_damping = 0.0;
    /// \srs{DD18} s^-1, >= 0: viscous damping of the angular velocity, as linear_damping.
    double angular_damping = 0.0;
    /// No rotation: infinite moment of inertia, and a dynamic body's angular velocity zero from
    /// the start (DD39's angular lock, as World::set_fixed_rotation sets it).
    bool fixed_rotation = false;
    /// \srs{DD39} Motions held at zero velocity from the start (World::set_motion_locks):
    /// linear_x, linear_y, and angular, which is fixed_rotation's lock (either one set locks
    /// the rotation; World::definitions gives both). Act on a dynamic body.
    MotionLocks motion_locks{};
    /// \srs{DD29} A fast dynamic body (a projectile) swept over each step against the other
    /// dynamic bodies too (at their end poses), not only against static shapes, so it cannot
    /// pass through a thin moving body. Costs a sweep per fast step; meant for a few bodies.
    bool bullet = false;
    /// With the world's sleeping on (WorldDef::enable_sleep): whether this body may sleep (a
    /// body that may not keeps every body touching it awake), and whether it starts awake.
    bool enable_sleep = true;
    bool awake = true; ///< starts awake (false: asleep, e.g. a stack built at rest)
    /// m s^-1, finite and >= 0: the body rests (and may sleep) below this speed instead of
    /// WorldDef::linear_sleep_tolerance (World::set_sleep_threshold). Unset: the world's.
    std::optional<double> sleep_threshold{};
    /// False: the body is made disabled (World::set_enabled): it keeps its definition but
    /// takes no part in the world (no motion, contacts, sensor overlaps, queries or joint
    /// solves) until enabled.
    bool enabled = true;
    /// Whether the body's pose is reported after each step in which it moves
    /// (World::body_move_events), and the step in which it falls asleep. Off by default (the
    /// report costs a pass over the bodies per step while any body asks).
    bool enable_move_events = false;
    LoadFunction load{};    ///< optional F(t), tau(t), added to the persistent loads
    std::string name{};     ///< free text, for scene files and reports
    UserData user_data = 0; ///< the game's own value (user_data.hpp), not simulation state
};

} // namespace tamias2d
