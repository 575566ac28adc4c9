#pragma once
#include <span>

#include "tamias2d/units/vec2.hpp"

namespace tamias2d::model::gd3 {
using namespace tamias2d::units;

/// One contact point at a step's start: its overlap x (minus its separation; > 0 overlapping)
/// and its effective mass 1/K along the normal (DD8's denominator).
struct ContactPoint {
    Length overlap;
    Mass effective_mass;
};

/// \srs{GD3} The most the total energy E = sum_k (KE_k + PE_k) (DD15, DD16) of the dynamic
/// bodies may rise in a step with soft contacts (IM7): for each point overlapping by x > 0, the
/// energy its contact spring of stiffness m_eff omega^2 stores, m_eff omega^2 x^2 / 2, and the
/// potential energy of lifting all the mass M by x against |g|, M |g| x; plus the round-off
/// allowance 1e-12 (|KE| + |PE| + M |g| 25 m). omega is the contact spring's angular frequency
/// (IM7: 2 pi min(f_C, n / (4 dt))), KE and PE the bodies' energies at the step's end.
inline Energy step_energy_bound(std::span<const ContactPoint> points, Rate omega, Mass M,
                                Acceleration g, Energy KE, Energy PE) {
    Energy stored{}, lifted{};
    for (const ContactPoint& p : points) {
        if (!(p.overlap > Length{}))
            continue;
        stored += 0.5 * p.effective_mass * omega * omega * p.overlap * p.overlap;
        lifted += M * g * p.overlap;
    }
    const Length scale = 25.0 * metre;
    const Energy allowance = 1e-12 * (abs(KE) + abs(PE) + M * g * scale);
    return stored + lifted + allowance;
}

} // namespace tamias2d::model::gd3
