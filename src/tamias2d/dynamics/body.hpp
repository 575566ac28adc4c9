// A body as the world stores it (internal). Public access goes through World and BodyId.
// Split in two, indexed alike: what a step reads and writes (Body), and what it never reads
// (BodySettings). A step streams every body a few times; at 16k bodies the bodies no longer fit
// in the cache, so every byte a step does not need costs time (docs/performance.md).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include "tamias2d/body_def.hpp"
#include "tamias2d/handles.hpp"
#include "tamias2d/math/vec2d.hpp"

namespace tamias2d {

/// 192 bytes on a 64-byte boundary: three cache lines (at 200 bytes, unaligned, a body spanned
/// four or five). A step reads the first two; the third, the applied loads and the masses, only
/// for a body that `loaded` says may carry a load (rain_16k: a third less to stream per pass).
struct alignas(64) Body {
    BodyType type = BodyType::dynamic;
    /// False only if force, torque, force_once and torque_once are all zero: then the step
    /// reads none of them, nor the masses (with no load, a = g and alpha = 0 whatever m and I).
    /// True is always safe; the step clears it when the loads are zero again.
    bool loaded = false;
    /// A dynamic body with a non-zero damping rate (BodySettings): only then does the step read
    /// the rates (IM5). It fills the byte before first_shape, so the layout does not change.
    bool damped = false;
    /// The body's first shape (null_index: none); the rest follow Shape::next, in creation order.
    std::uint32_t first_shape = null_index;

    Transform xf{};     ///< body origin and rotation
    double angle = 0.0; ///< rad, unwrapped phi (wrapped only on output)
    Vec2d center{};     ///< m, centre of mass, world frame (the SRS's p)

    Vec2d local_center{};
    Vec2d v{};      ///< m s^-1
    double w = 0.0; ///< rad s^-1
    double inv_mass = 0.0, inv_inertia = 0.0;
    double gravity_scale = 1.0;

    Vec2d force{};       ///< N, persistent
    double torque = 0.0; ///< N m, persistent
    Vec2d force_once{};  ///< N, next step only
    double torque_once = 0.0;
    double mass = 0.0, inertia = 0.0;

    /// \srs{R2, IM1, IM2} Whether no force or torque is applied (R2's applied loads, the F
    /// and tau of IM1 and IM2): a step skips the loads of a body whose `loaded` is false.
    bool unloaded() const {
        return force.x == 0.0 && force.y == 0.0 && torque == 0.0 && force_once.x == 0.0 &&
               force_once.y == 0.0 && torque_once == 0.0;
    }
};

static_assert(sizeof(Body) == 192);
static_assert(offsetof(Body, local_center) == 64 && offsetof(Body, force) == 128,
              "what every step reads fills the first two lines, the loads and masses the third");

/// The body's settings that only its creation, its mass update and the queries read, and the
/// step for a damped body.
struct BodySettings {
    std::string name;
    LoadFunction load;
    std::optional<double> mass_override, inertia_override;
    bool fixed_rotation = false;
    bool bullet = false;                                ///< swept against dynamic bodies too (DD29)
    double linear_damping = 0.0, angular_damping = 0.0; ///< s^-1 (DD17, DD18)
    UserData user_data = 0; ///< the game's own value: never hashed, never read
    // Run-time control (World::set_motion_locks, set_mass_data, set_sleep_threshold).
    bool lock_linear_x = false, lock_linear_y = false; ///< DD39's linear locks
    std::optional<Vec2d> center_override{};            ///< m, body frame (set_mass_data)
    std::optional<double> sleep_threshold{};           ///< m s^-1; none: the world's
};

} // namespace tamias2d
