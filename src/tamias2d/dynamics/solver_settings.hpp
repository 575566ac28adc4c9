// What every contact iteration of a substep reads: the substep rate, the contact's softness and
// the push-out limits. Kept apart so that the iterations (contact_iteration.hpp) depend on it
// and not on any of their callers.
#pragma once

#include "tamias2d/dynamics/softness.hpp"

namespace tamias2d {

struct ContactSolverSettings {
    double inv_h = 0.0;                 ///< s^-1, substep rate
    Softness softness{};                ///< contact softness for this substep length
    double linear_slop = 0.0;           ///< m
    double push_max_velocity = 0.0;     ///< m s^-1
    double restitution_threshold = 0.0; ///< m s^-1
};

} // namespace tamias2d
