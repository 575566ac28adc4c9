// Shared pieces of the seeded fuzz drivers: a portable random source, the extreme values
// they feed in, the iteration count and seed from the environment, and the check that a
// world's observable state is finite.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iterator>
#include <limits>
#include <random>
#include <span>
#include <sstream>
#include <string>
#include <vector>

#include "tamias2d/world.hpp"

namespace tamias2d::fuzz {

/// std::mt19937_64's sequence is fixed by the standard; the distributions are not, so the
/// drivers map its output themselves: a seed replays the same input on every platform.
struct Rng {
    std::mt19937_64 engine;
    explicit Rng(std::uint64_t seed) : engine(seed) {}
    std::uint64_t bits() { return engine(); }
    /// In [0, n), n > 0.
    std::size_t below(std::size_t n) { return static_cast<std::size_t>(bits() % n); }
    bool chance(unsigned percent) { return below(100) < percent; }
    /// Uniform in [0, 1).
    double unit() { return static_cast<double>(bits() >> 11) * 0x1.0p-53; }
    double between(double lo, double hi) { return lo + (hi - lo) * unit(); }
};

inline constexpr double nan = std::numeric_limits<double>::quiet_NaN();
inline constexpr double inf = std::numeric_limits<double>::infinity();

/// The values that break arithmetic: non-finite, denormal, signed zero, the supported range's
/// bounds (1e-12, 1e12) and just beyond, and the limits of double.
inline constexpr double extremes[] = {0.0,
                                      -0.0,
                                      nan,
                                      inf,
                                      -inf,
                                      std::numeric_limits<double>::denorm_min(),
                                      std::numeric_limits<double>::min(),
                                      std::numeric_limits<double>::max(),
                                      -std::numeric_limits<double>::max(),
                                      std::numeric_limits<double>::epsilon(),
                                      1e-300,
                                      1e-13,
                                      1e-12,
                                      1e12,
                                      1.0000001e12,
                                      -1e12,
                                      1e24,
                                      1e300,
                                      -1e300,
                                      1e308};

/// Mostly ordinary values (a world that runs), often an extreme one.
inline double any_double(Rng& r) {
    switch (r.below(4)) {
    case 0:
        return extremes[r.below(std::size(extremes))];
    case 1:
        return r.between(-1e3, 1e3) * std::pow(10.0, static_cast<double>(r.below(30)) - 15.0);
    default:
        return r.between(-10.0, 10.0);
    }
}

inline double positive_size(Rng& r) {
    return r.chance(75) ? r.between(0.05, 3.0) : any_double(r);
}

/// The iteration count: `variable` when set (longer runs on request), else `fallback`.
inline long iterations(const char* variable, long fallback) {
    if (const char* s = std::getenv(variable); s && *s) {
        const long n = std::strtol(s, nullptr, 10);
        if (n > 0)
            return n;
    }
    return fallback;
}

/// The first iteration's seed: TAMIAS_FUZZ_SEED when set (replay a printed seed with
/// TAMIAS_FUZZ_ITERATIONS=1), else a fixed one so that CI runs the same inputs every time.
inline std::uint64_t base_seed(std::uint64_t fallback) {
    if (const char* s = std::getenv("TAMIAS_FUZZ_SEED"); s && *s)
        return std::strtoull(s, nullptr, 10);
    return fallback;
}

inline bool finite(Vec2d v) {
    return std::isfinite(v.x) && std::isfinite(v.y);
}

/// The bodies' states, the clock and the reactions of `joints` (those that exist), bit for bit:
/// what a SolverDivergence promises to leave as it was (the contacts, also in state_hash(), are
/// brought up to date with those poses). A joint's reaction is read from the impulses and axis
/// of its last solve, the part of it a refused step must give back.
inline std::vector<double> body_states(const World& w, std::span<const JointId> joints = {}) {
    std::vector<double> out{w.time()};
    for (const BodyId id : w.bodies()) {
        const BodyState s = w.state(id);
        out.insert(out.end(), {s.position.x, s.position.y, s.velocity.x, s.velocity.y,
                               s.orientation, s.angular_velocity});
    }
    for (const JointId j : joints) {
        if (!w.is_valid(j))
            continue;
        const Vec2d f = w.joint_reaction_force(j);
        out.insert(out.end(), {f.x, f.y, w.joint_reaction_torque(j)});
    }
    return out;
}

/// "" when every body's position, origin, orientation, velocities, and the world's energies
/// and momentum are finite (DCO_p, DCO_v, DCO_omega); else what is not.
inline std::string non_finite_state(const World& w) {
    std::ostringstream out;
    for (const BodyId b : w.bodies()) {
        if (!finite(w.position(b)) || !finite(w.origin(b)) || !std::isfinite(w.orientation(b)) ||
            !finite(w.velocity(b)) || !std::isfinite(w.angular_velocity(b))) {
            out << "body " << b.index << " (" << w.name(b) << "): position (" << w.position(b).x
                << ", " << w.position(b).y << "), velocity (" << w.velocity(b).x << ", "
                << w.velocity(b).y << "), omega " << w.angular_velocity(b);
            return out.str();
        }
    }
    if (!std::isfinite(w.kinetic_energy()) || !std::isfinite(w.potential_energy()) ||
        !finite(w.linear_momentum())) {
        out << "energy/momentum: kinetic " << w.kinetic_energy() << ", potential "
            << w.potential_energy();
        return out.str();
    }
    return {};
}

/// "" when a ray cast's result is well formed (fraction in [0, 1], point and normal finite).
inline std::string bad_ray_cast(const World& w, Vec2d origin, Vec2d translation) {
    const auto hit = w.ray_cast(origin, translation);
    if (!hit)
        return {};
    if (!(hit->fraction >= 0.0 && hit->fraction <= 1.0) || !finite(hit->point) ||
        !finite(hit->normal)) {
        std::ostringstream out;
        out << "ray_cast from (" << origin.x << ", " << origin.y << ") by (" << translation.x
            << ", " << translation.y << "): fraction " << hit->fraction << ", point ("
            << hit->point.x << ", " << hit->point.y << ")";
        return out.str();
    }
    return {};
}

} // namespace tamias2d::fuzz
