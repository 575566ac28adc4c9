// Soft constraint coefficients (Catto, "Solver2D" / "Soft Step", 2024): a contact behaves like
// a damped spring of stiffness `hertz` and `damping_ratio`, solved implicitly over a substep h,
// which removes overlap smoothly instead of Baumgarte's energy-adding kicks.
#pragma once

#include <numbers>

namespace tamias2d {

struct Softness {
    double bias_rate = 0.0;     ///< s^-1: velocity bias per metre of overlap
    double mass_scale = 1.0;    ///< fraction of the rigid impulse applied
    double impulse_scale = 0.0; ///< fraction of the accumulated impulse relaxed away
};

inline Softness make_softness(double hertz, double damping_ratio, double h) {
    if (hertz == 0.0)
        return {};
    const double omega = 2.0 * std::numbers::pi * hertz;
    const double a1 = 2.0 * damping_ratio + h * omega;
    const double a2 = h * omega * a1;
    const double a3 = 1.0 / (1.0 + a2);
    return {omega / a1, a2 * a3, a3};
}

} // namespace tamias2d
