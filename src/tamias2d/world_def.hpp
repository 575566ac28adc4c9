// World settings. Defaults suit games in metres, kilograms and seconds.
#pragma once

#include "tamias2d/math/vec2d.hpp"

namespace tamias2d {

struct WorldDef {
    Vec2d gravity{0.0, -9.81}; ///< m s^-2 (GD2; the SRS's g = 9.81 m s^-2)
    /// Substeps per step (soft step). IM1/IM2 are integrated with h = dt / substeps.
    int substeps = 4;
    /// Contact softness: stiffness (Hz) and damping ratio of the soft contact constraint that
    /// removes overlap, and the fastest speed (m s^-1) it may push bodies apart with.
    double contact_hertz = 30.0;
    double contact_damping_ratio = 10.0;
    double contact_push_max_velocity = 3.0;
    /// Overlap (m) tolerated without correction: keeps resting contacts from jittering.
    double linear_slop = 0.005;
    /// Contacts are created this far (m) before the shapes touch (speculative contacts).
    double speculative_distance = 0.02;
    /// Restitution (DD12) applies when the bodies approach faster than this (m s^-1).
    double restitution_threshold = 0.0;
};

} // namespace tamias2d
