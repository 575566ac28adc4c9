#pragma once
#include "tamias2d/units/quantities.hpp"

namespace tamias2d::model::dd36 {
using namespace tamias2d::units;

/// \srs{DD36} A joint breaks after a step whose reaction force's magnitude |F| exceeds its break
/// force F_break, or whose reaction torque's magnitude |tau| exceeds its break torque
/// tau_break (either infinite: never on that count): |F| > F_break or |tau| > tau_break.
inline bool breaks(Force force_magnitude, Force break_force, Torque torque, Torque break_torque) {
    const Torque magnitude = torque < Torque{} ? -torque : torque;
    return force_magnitude > break_force || magnitude > break_torque;
}

} // namespace tamias2d::model::dd36
