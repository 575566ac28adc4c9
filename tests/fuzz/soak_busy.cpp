// The busy soak (tamias_soak --busy): a scene that keeps every part of the step working for a
// million steps. A rain of 300 boxes and circles (0.25 and 0.2 kg, restitution 0.5, friction
// 0.6) falls into an open container; beside it a 10-row pyramid is struck by a heavy box (20 kg
// at 41 m/s), which is launched again every 2000 steps; every 10 steps a body leaves (one
// thrown out of the container first) and a new one is dropped from 20-25 m.
//
// Oracle, checked at every step unless said otherwise:
//  * every state is finite (DCO_p, DCO_v, DCO_omega);
//  * no body moves faster than 100 m/s: the striker reaches 42.7 m/s (41.2 at launch, then its
//    fall), a drop lands at 22 m/s, and a 0.25 kg box struck head-on by it at C_R = 0.5 leaves
//    at most at (1 + 0.5) x 20 / 20.25 x 42.7 = 63 m/s;
//  * no step adds energy beyond what the soft contact may add: the rise of kinetic plus
//    potential energy over each step stays within the bound of tests/properties (docs/
//    verification.md, "The energy bound and its justification"): the sum over the overlapping
//    contact points of m_eff omega^2 x^2 / 2 + M g x, plus round-off. The churn and the
//    launches happen between steps and are not part of any step's rise;
//  * memory is flat (every 1000 steps): the resident set and the large blocks at the end may
//    exceed their values after the first tenth by at most 10 % + 4 MiB.
#include "fuzz/soak_busy.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "fuzz/fuzz_support.hpp"
#include "support/reliability_support.hpp"
#include "tamias2d/memory.hpp"
#include "tamias2d/world.hpp"

namespace tamias2d::soak {

namespace {

constexpr double dt = 1.0 / 60.0;
constexpr double max_speed = 100.0;           // m/s, see above
constexpr int launch_every = 2000;            // steps
constexpr Vec2d launch_from{0.0, 10.0};       // m
constexpr Vec2d launch_velocity{40.0, -10.0}; // m/s: through the pyramid's upper half
constexpr double wall_x = 30.0, wall_height = 20.0;

double energy(const World& w) {
    return w.kinetic_energy() + w.potential_energy();
}

/// The bodies' centres of mass by body index (static ones too), before a step.
void centres_of(const World& w, std::vector<Vec2d>& out) {
    for (const BodyId b : w.bodies()) {
        if (b.index >= out.size())
            out.resize(b.index + 1);
        out[b.index] = w.position(b);
    }
}

/// The energy the soft contact may add in one step (J): tests/properties/test_properties.cpp's
/// soft_contact_bound, from the contacts reported after the step (their separations measured
/// at its start) and the centres before it. DD8's K = sum 1/m + (r x n)^2 / I over the dynamic
/// bodies gives each point's effective mass 1/K.
double soft_contact_bound(const World& w, const std::vector<Vec2d>& centres, double total_mass) {
    const WorldDef& d = w.settings();
    const double f = std::min(d.contact_hertz, 0.25 * d.substeps / dt);
    const double omega = 2.0 * std::numbers::pi * f;
    const double g = std::hypot(d.gravity.x, d.gravity.y);
    double bound = 0.0;
    for (const ContactInfo& c : w.contacts())
        for (int j = 0; j < c.point_count; ++j) {
            const double x = -c.points[j].separation;
            if (x <= 0.0)
                continue;
            double k = 0.0;
            for (const BodyId b : {c.body_a, c.body_b}) {
                if (w.type(b) != BodyType::dynamic)
                    continue;
                const double rn = cross(c.points[j].point - centres[b.index], c.normal);
                k += 1.0 / w.mass(b) + rn * rn / w.inertia(b);
            }
            bound += 0.5 / k * omega * omega * x * x + total_mass * g * x;
        }
    return bound;
}

bool grew(std::size_t start, std::size_t end) {
    return end > start + start / 10 + (std::size_t{4} << 20);
}

struct Scene {
    World world;
    std::vector<BodyId> rain; ///< the bodies the churn replaces (the pyramid's join them)
    BodyId striker;
};

ShapeDef rain_shape(std::size_t i) {
    const Material m{1.0, 0.5, 0.6};
    return i % 2 == 0 ? box_shape(0.5, 0.5, m) : circle_shape(0.25, m);
}

Scene build(fuzz::Rng& r) {
    Scene s{World(WorldDef{}), {}, {}};
    World& w = s.world;
    BodyDef fixed;
    fixed.type = BodyType::static_body;
    const Material wall{1.0, 0.0, 0.6};
    fixed.position = {0.0, -0.5};
    w.create_shape(w.create_body(fixed), box_shape(2 * wall_x + 2.0, 1.0, wall));
    for (const double x : {-wall_x - 0.5, wall_x + 0.5}) {
        fixed.position = {x, wall_height / 2};
        w.create_shape(w.create_body(fixed), box_shape(1.0, wall_height, wall));
    }
    for (std::size_t i = 0; i < 300; ++i) {
        BodyDef d;
        d.position = {-28.0 + 26.0 * double(i % 40) / 39.0 + r.between(-0.1, 0.1),
                      5.0 + 0.7 * double(i / 40)};
        const BodyId b = w.create_body(d);
        w.create_shape(b, rain_shape(i));
        s.rain.push_back(b);
    }
    const Material brick{1.0, 0.0, 0.6};
    for (int row = 0; row < 10; ++row)
        for (int i = 0; i < 10 - row; ++i) {
            BodyDef d;
            d.position = {15.0 + (i - (10 - row - 1) * 0.5) * 1.05, 0.5 + row};
            const BodyId b = w.create_body(d);
            w.create_shape(b, box_shape(1.0, 1.0, brick));
            s.rain.push_back(b);
        }
    BodyDef d;
    d.position = launch_from;
    d.linear_velocity = launch_velocity;
    s.striker = w.create_body(d);
    w.create_shape(s.striker, box_shape(1.0, 1.0, Material{20.0, 0.0, 0.6}));
    return s;
}

} // namespace

int run_busy(long steps) {
    fuzz::Rng r(20263100);
    Scene scene = build(r);
    World& w = scene.world;
    double mass = 0.0;
    for (const BodyId b : w.bodies())
        mass += w.mass(b);
    const std::size_t count = w.body_count();
    std::printf("busy soak: %zu bodies (%.1f kg moving), %ld steps\n", count, mass, steps);

    std::vector<Vec2d> centres;
    double worst_rise = 0.0, bound_then = 0.0, fastest = 0.0;
    long replaced = 0, thrown_out = 0, launches = 1;
    std::size_t rss_warm = 0, blocks_warm = 0;
    const long warm = steps / 10;
    for (long s = 1; s <= steps; ++s) {
        centres_of(w, centres);
        const double before = energy(w);
        w.step(dt);
        const double after = energy(w);
        if (!std::isfinite(after)) {
            std::printf("FAIL step %ld: non-finite state: %s\n", s,
                        fuzz::non_finite_state(w).c_str());
            return 1;
        }
        const double scale =
            std::abs(w.kinetic_energy()) + std::abs(w.potential_energy()) + mass * 9.81 * 25.0;
        const double bound = soft_contact_bound(w, centres, mass) + 1e-12 * scale;
        if (after - before > worst_rise) {
            worst_rise = after - before;
            bound_then = bound;
        }
        if (after - before > bound) {
            std::printf("FAIL step %ld: the step added %.6g J, above the soft contact's bound "
                        "%.6g J\n",
                        s, after - before, bound);
            return 1;
        }
        for (const BodyId b : w.bodies()) {
            const Vec2d v = w.velocity(b);
            fastest = std::max(fastest, std::hypot(v.x, v.y));
        }
        if (fastest > max_speed) {
            std::printf("FAIL step %ld: a body at %g m/s (bound %g)\n", s, fastest, max_speed);
            return 1;
        }
        if (s % 10 == 0) {
            // A body leaves (one thrown out of the container first), a new one falls in.
            std::size_t i = r.below(scene.rain.size());
            for (std::size_t k = 0; k < scene.rain.size(); ++k) {
                const Vec2d p = w.position(scene.rain[k]);
                if (p.y < -1.0 || std::abs(p.x) > wall_x) {
                    i = k;
                    ++thrown_out;
                    break;
                }
            }
            w.destroy_body(scene.rain[i]);
            BodyDef d;
            d.position = {r.between(-28.0, 28.0), r.between(20.0, 25.0)};
            scene.rain[i] = w.create_body(d);
            w.create_shape(scene.rain[i], rain_shape(std::size_t(replaced)));
            ++replaced;
        }
        if (s % launch_every == 0) {
            w.set_transform(scene.striker, launch_from, 0.0);
            w.set_velocity(scene.striker, launch_velocity);
            w.set_angular_velocity(scene.striker, 0.0);
            ++launches;
        }
        if (w.body_count() != count) {
            std::printf("FAIL step %ld: %zu bodies, expected %zu\n", s, w.body_count(), count);
            return 1;
        }
        if (s == warm) {
            rss_warm = reliability::resident_bytes();
            blocks_warm = large_array_stats().mapped_bytes;
        }
        if (s % (steps >= 100000 ? 100000 : 1000) == 0 || s == steps)
            std::printf("step %ld: energy %.6g J, largest rise in a step %.3g J (its bound %.3g "
                        "J), fastest so far %.3g m/s, %ld replaced (%ld thrown out), %ld "
                        "launches, resident %.1f MiB, large blocks %.1f MiB\n",
                        s, after, worst_rise, bound_then, fastest, replaced, thrown_out, launches,
                        static_cast<double>(reliability::resident_bytes()) / (1 << 20),
                        static_cast<double>(large_array_stats().mapped_bytes) / (1 << 20));
    }
    const std::size_t rss_end = reliability::resident_bytes();
    const std::size_t blocks_end = large_array_stats().mapped_bytes;
    if (grew(rss_warm, rss_end) || grew(blocks_warm, blocks_end)) {
        std::printf("FAIL memory grew: resident %zu -> %zu bytes, large blocks %zu -> %zu bytes "
                    "(from step %ld to the end)\n",
                    rss_warm, rss_end, blocks_warm, blocks_end, warm);
        return 1;
    }
    std::printf("busy soak passed: %ld steps, finite, fastest %.3g m/s (bound %g), largest "
                "energy rise in a step %.3g J (its bound %.3g J), resident %zu -> %zu bytes, "
                "large blocks %zu -> %zu bytes from step %ld\n",
                steps, fastest, max_speed, worst_rise, bound_then, rss_warm, rss_end, blocks_warm,
                blocks_end, warm);
    return 0;
}

} // namespace tamias2d::soak
