// The mechanical energy of a scene's dynamic bodies, from the states the engine reports and the
// masses the scene gives: the same measure for every engine (the work-precision diagrams' energy
// drift, docs/performance.md). A scene of pins and no contacts (the joint scenes) conserves it
// exactly; what an engine's step gains or loses is its error.
#pragma once

#include <cmath>
#include <stdexcept>
#include <vector>

#include "bench_engines.hpp"
#include "bench_scenes.hpp"

namespace tamias_bench {

/// Mass (kg) and moment of inertia about the centre of mass (kg m^2) of a dynamic body whose
/// centre of mass is its origin: a body without shapes (its own mass and inertia) or one box
/// centred on the origin (its density times its area). Throws std::invalid_argument for others.
struct MassAtOrigin {
    double mass = 0.0, inertia = 0.0;
};

inline MassAtOrigin mass_at_origin(const BodyDesc& b) {
    if (b.boxes.empty())
        return {b.mass, b.inertia};
    const BoxPart& p = b.boxes.front();
    if (b.boxes.size() != 1 || p.center.x != 0.0 || p.center.y != 0.0)
        throw std::invalid_argument("scene energy: a dynamic body must be one centred box or "
                                    "have no shape");
    const double w = 2.0 * p.hx, h = 2.0 * p.hy, m = b.density * w * h;
    return {m, m * (w * w + h * h) / 12.0};
}

/// J: kinetic (translation and rotation) plus potential energy in the scene's gravity, zero at
/// the origin, of every dynamic body at `states` (index: SceneDesc::bodies); NaN when a state is
/// not finite.
inline double mechanical_energy(const SceneDesc& s, const std::vector<Probe>& states) {
    double e = 0.0;
    for (std::size_t i = 0; i < s.bodies.size(); ++i) {
        if (!s.bodies[i].dynamic)
            continue;
        const MassAtOrigin m = mass_at_origin(s.bodies[i]);
        const Probe& q = states[i];
        if (!finite(q))
            return NAN;
        e += 0.5 * m.mass * (q.v.x * q.v.x + q.v.y * q.v.y) + 0.5 * m.inertia * q.w * q.w -
             m.mass * (s.gravity.x * q.p.x + s.gravity.y * q.p.y);
    }
    return e;
}

/// The scene's energy as built (every engine starts from it).
inline double initial_energy(const SceneDesc& s) {
    std::vector<Probe> states(s.bodies.size());
    for (std::size_t i = 0; i < s.bodies.size(); ++i) {
        const BodyDesc& b = s.bodies[i];
        states[i] = {b.position, b.velocity, 0.0, b.angle};
    }
    return mechanical_energy(s, states);
}

/// N: the weight of the scene's dynamic bodies, which turns an energy error into the drop of the
/// whole mass that would make it (m).
inline double total_weight(const SceneDesc& s) {
    double m = 0.0;
    for (const BodyDesc& b : s.bodies) {
        if (b.dynamic)
            m += mass_at_origin(b).mass;
    }
    return m * std::hypot(s.gravity.x, s.gravity.y);
}

} // namespace tamias_bench
