/// \file
/// Which of a body's three motions are locked (World::set_motion_locks).
#pragma once

namespace tamias2d {

/// \srs{DD39} A locked motion is held at zero velocity: a platformer's hero that never tips
/// (angular), a piston that moves only up and down (linear_x), a door that only slides
/// sideways (linear_y). Locks act on dynamic bodies; others keep them unused.
struct MotionLocks {
    bool linear_x = false; ///< no motion along the world's x axis
    bool linear_y = false; ///< no motion along the world's y axis
    bool angular = false;  ///< no rotation (BodyDef::fixed_rotation)
    /// Field by field.
    friend bool operator==(const MotionLocks&, const MotionLocks&) = default;
};

} // namespace tamias2d
