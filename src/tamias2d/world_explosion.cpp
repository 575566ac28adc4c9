// World::explode: DD38's blast impulse on the dynamic shapes within reach of a point, found
// through the broad phase, computed in full before any body changes (strong guarantee).
#include <algorithm>
#include <cstdint>
#include <vector>

#include "tamias2d/dynamics/bridge/point_impulse.hpp"
#include "tamias2d/dynamics/solver_body.hpp"
#include "tamias2d/errors.hpp"
#include "tamias2d/explosion.hpp"
#include "tamias2d/geometry/blast_exposure.hpp"
#include "tamias2d/memory/allocator.hpp"
#include "tamias2d/model/dd38_explosion_impulse.hpp"
#include "tamias2d/validation.hpp"
#include "tamias2d/world.hpp"
#include "tamias2d/world_impl.hpp"

namespace tamias2d {

namespace {

namespace u = tamias2d::units;
namespace dd38 = tamias2d::model::dd38;

/// \srs{DD38} The definition's fields within their ranges: finite, within the supported range
/// (DCX_range), the radius and the falloff >= 0.
void validate(const ExplosionDef& def) {
    require_within("explosion.position", def.position, supported::input_max, "m");
    require_within("explosion.radius", def.radius, supported::input_max, "m");
    if (!(def.radius >= 0.0))
        throw ValidationError("explosion.radius", def.radius, "must be >= 0 (m)", "DD38");
    require_within("explosion.falloff", def.falloff, supported::input_max, "m");
    if (!(def.falloff >= 0.0))
        throw ValidationError("explosion.falloff", def.falloff, "must be >= 0 (m)", "DD38");
    require_within("explosion.impulse_per_length", def.impulse_per_length, supported::input_max,
                   "N s m^-1");
    require_within("explosion.impulse_per_body", def.impulse_per_body, supported::input_max, "N s");
}

/// One impulse of the blast: its magnitude (N s) along `direction`, at `point`, on `body`.
struct Push {
    std::uint32_t body;
    Vec2d direction;
    Vec2d point;
    double magnitude;
};

/// A body's nearest shape within reach so far (impulse_per_body).
struct Nearest {
    std::uint32_t body;
    double distance;
    Vec2d direction;
    Vec2d point;
};

} // namespace

std::size_t World::explode(const ExplosionDef& def) {
    validate(def);
    Impl& w = *impl_;
    w.bodies.settle();
    const double reach = def.radius + def.falloff;
    const Vec2d x = def.position;
    const Aabb box{x.x - reach, x.y - reach, x.x + reach, x.y + reach};
    memory::vector<std::uint32_t> candidates;
    w.shapes.broad_phase.query(box, [&](int proxy) {
        candidates.push_back(w.shapes.broad_phase.user_data(proxy));
        return true;
    });
    std::sort(candidates.begin(), candidates.end()); // shape order: the same result every time

    const auto r = u::from_value<u::Length>(def.radius);
    const auto f = u::from_value<u::Length>(def.falloff);
    memory::vector<Push> pushes;
    memory::vector<Nearest> nearest; // in the order the bodies are first met
    for (const std::uint32_t s : candidates) {
        const Shape& sh = w.shapes.shapes[s];
        const ShapeDef& sd = w.shapes.defs[s];
        const Body& b = w.bodies.bodies[sh.body];
        if (b.type != BodyType::dynamic || sd.is_sensor ||
            (sd.filter.category_bits & def.mask_bits) == 0)
            continue;
        const BlastExposure e = blast_exposure(sd.geometry, b.xf, x);
        if (!(e.distance <= reach))
            continue;
        const u::Dimensionless scale =
            dd38::falloff_scale(u::from_value<u::Length>(e.distance), r, f);
        const double j = dd38::shape_impulse(
                             scale, u::from_value<dd38::ImpulsePerLength>(def.impulse_per_length),
                             u::from_value<u::Length>(e.width))
                             .value();
        if (j != 0.0)
            pushes.push_back({sh.body, e.direction, e.point, j});
        if (def.impulse_per_body == 0.0)
            continue;
        const auto at = std::find_if(nearest.begin(), nearest.end(),
                                     [&](const Nearest& n) { return n.body == sh.body; });
        if (at == nearest.end())
            nearest.push_back({sh.body, e.distance, e.direction, e.point});
        else if (e.distance < at->distance) // ties: the lower shape index, met first
            *at = {sh.body, e.distance, e.direction, e.point};
    }
    for (const Nearest& n : nearest) {
        const double j =
            dd38::body_impulse(dd38::falloff_scale(u::from_value<u::Length>(n.distance), r, f),
                               u::from_value<u::Impulse>(def.impulse_per_body))
                .value();
        if (j != 0.0)
            pushes.push_back({n.body, n.direction, n.point, j});
    }

    // The new velocities, all of them before any is stored: a light body struck hard refuses
    // the whole blast, as the next step would refuse its state.
    std::stable_sort(pushes.begin(), pushes.end(),
                     [](const Push& a, const Push& b) { return a.body < b.body; });
    struct Moved {
        std::uint32_t body;
        SolverBody after;
    };
    memory::vector<Moved> moved;
    for (const Push& p : pushes) {
        const Body& b = w.bodies.bodies[p.body];
        if (moved.empty() || moved.back().body != p.body)
            moved.push_back({p.body, SolverBody{b.v, b.w, b.inv_mass, b.inv_inertia, {}, 0.0}});
        SolverBody ground{};
        SolverBody& self = moved.back().after;
        // DD10 through IM3's impulse application: dv = J / m, domega = r x J / I.
        bridge::apply_impulse(ground, self, 0.0,
                              bridge::moment_arm(p.point - b.center, p.direction), p.direction,
                              p.magnitude);
        require_within("explosion: the velocity of " + w.bodies.label(p.body), self.v,
                       supported::state_max, "m s^-1");
        require_within("explosion: the angular velocity of " + w.bodies.label(p.body), self.w,
                       supported::state_max, "rad s^-1");
    }
    for (const Moved& m : moved) {
        Body& b = w.bodies.bodies[m.body];
        w.bodies.wake(m.body);
        b.v = m.after.v;
        b.w = m.after.w;
    }
    return moved.size();
}

} // namespace tamias2d
