// The same scenes in Tamias2D and in Chipmunk2D 7 (the engine behind Pymunk, SRS NFR2), and the
// figures compared. Shared by the verification program verify_chipmunk and the fast unit test
// tests/peer/test_chipmunk.cpp. docs/peer-differences.md explains every systematic difference.
//
// How the two are configured to solve the same problem:
//  * masses and moments of inertia are given explicitly to both (BodyDef overrides, cpBodyNew);
//  * restitution and friction: Chipmunk multiplies the two shapes' coefficients
//    (cpArbiterUpdate: e = e_a e_b, u = u_a u_b), Tamias takes the maximum restitution and the
//    geometric mean friction; each scene states the per-shape values that give the same pair
//    coefficient in both;
//  * Chipmunk's collision slop is set to Tamias's linear slop (its default, 0.1, is meant for
//    pixel units); its damping stays 1 (none), its iterations 10 (default), its bias default.
#pragma once

#include <chipmunk/chipmunk.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <numbers>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "tamias2d/math/vec2d.hpp"
#include "tamias2d/world.hpp"

namespace tamias2d::peer {

/// One body, described once for both engines. Centre of mass at the shape's centre.
struct BodyDesc {
    bool circle = false;
    double w = 1.0, h = 1.0; ///< box size (m); for a circle w is the radius
    double mass = 1.0;
    Vec2d p{}, v{};
    double angle = 0.0, omega = 0.0;
    double restitution = 0.0; ///< the pair coefficient wanted against a partner of the same kind
    double friction = 0.0;
    Vec2d force{};       ///< constant force (N)
    double torque = 0.0; ///< constant torque (N m)
    double inertia() const { return circle ? 0.5 * mass * w * w : mass * (w * w + h * h) / 12.0; }
};

/// A body's state as compared.
struct State {
    Vec2d p{}, v{};
    double phi = 0.0, omega = 0.0;
};

inline double norm(Vec2d v) {
    return std::sqrt(v.x * v.x + v.y * v.y);
}
inline double angle_diff(double a, double b) {
    return std::abs(std::remainder(a - b, 2.0 * std::numbers::pi));
}

// --- Tamias side -------------------------------------------------------------------------------

inline BodyId add_tamias(World& w, const BodyDesc& d) {
    BodyDef def;
    def.position = d.p;
    def.linear_velocity = d.v;
    def.angle = d.angle;
    def.angular_velocity = d.omega;
    def.mass = d.mass;
    def.inertia = d.inertia();
    def.force = d.force;
    def.torque = d.torque;
    const BodyId id = w.create_body(def);
    // Tamias combines restitution by max and friction by geometric mean: the same value on both
    // shapes of a pair gives that value.
    const Material mat{1.0, d.restitution, d.friction};
    w.create_shape(id, d.circle ? circle_shape(d.w, mat) : box_shape(d.w, d.h, mat));
    return id;
}

inline void add_tamias_static_box(World& w, Vec2d c, double width, double height,
                                  double restitution, double friction) {
    BodyDef def;
    def.type = BodyType::static_body;
    def.position = c;
    const BodyId id = w.create_body(def);
    w.create_shape(id, box_shape(width, height, Material{1.0, restitution, friction}));
}

inline State tamias_state(const World& w, BodyId b) {
    const BodyState s = w.state(b);
    return {s.position, s.velocity, s.orientation, s.angular_velocity};
}

// --- Chipmunk side ------------------------------------------------------------------------------

/// Owns a cpSpace and everything added to it.
class CpWorld {
  public:
    CpWorld(Vec2d gravity, double slop) : space_(cpSpaceNew()) {
        cpSpaceSetGravity(space_, cpv(gravity.x, gravity.y));
        cpSpaceSetCollisionSlop(space_, slop);
    }
    ~CpWorld() {
        for (cpShape* s : shapes_)
            cpSpaceRemoveShape(space_, s);
        for (cpBody* b : bodies_)
            cpSpaceRemoveBody(space_, b);
        for (cpShape* s : shapes_)
            cpShapeFree(s);
        for (cpBody* b : bodies_)
            cpBodyFree(b);
        cpSpaceFree(space_);
    }
    CpWorld(const CpWorld&) = delete;
    CpWorld& operator=(const CpWorld&) = delete;

    /// Chipmunk multiplies the two shapes' coefficients: a pair of shapes of the same kind with
    /// sqrt(c) each has the pair coefficient c. Against the static ground (coefficient 1 there)
    /// use `pair_with_static` to give the body c itself.
    cpBody* add(const BodyDesc& d, bool pair_with_static = false) {
        cpBody* b = cpBodyNew(d.mass, d.inertia());
        cpSpaceAddBody(space_, b);
        bodies_.push_back(b);
        cpBodySetPosition(b, cpv(d.p.x, d.p.y));
        cpBodySetVelocity(b, cpv(d.v.x, d.v.y));
        cpBodySetAngle(b, d.angle);
        cpBodySetAngularVelocity(b, d.omega);
        cpShape* s = d.circle ? cpCircleShapeNew(b, d.w, cpvzero) : cpBoxShapeNew(b, d.w, d.h, 0.0);
        cpShapeSetElasticity(s, pair_with_static ? d.restitution : std::sqrt(d.restitution));
        cpShapeSetFriction(s, pair_with_static ? d.friction : std::sqrt(d.friction));
        cpSpaceAddShape(space_, s);
        shapes_.push_back(s);
        return b;
    }

    /// A static box on the space's static body with the given per-shape coefficients.
    void add_static_box(Vec2d c, double width, double height, double elasticity, double friction) {
        cpShape* s = cpBoxShapeNew2(
            cpSpaceGetStaticBody(space_),
            cpBBNew(c.x - 0.5 * width, c.y - 0.5 * height, c.x + 0.5 * width, c.y + 0.5 * height),
            0.0);
        cpShapeSetElasticity(s, elasticity);
        cpShapeSetFriction(s, friction);
        cpSpaceAddShape(space_, s);
        shapes_.push_back(s);
    }

    void step(double dt) { cpSpaceStep(space_, dt); }
    cpSpace* space() { return space_; }

    /// Pairs of shapes with at least one contact point (cpArbiter with a non-zero count).
    int contact_count() {
        std::set<const cpArbiter*> arbiters;
        for (cpBody* b : bodies_) {
            cpBodyEachArbiter(
                b,
                [](cpBody*, cpArbiter* arb, void* data) {
                    if (cpArbiterGetCount(arb) > 0)
                        static_cast<std::set<const cpArbiter*>*>(data)->insert(arb);
                },
                &arbiters);
        }
        return int(arbiters.size());
    }

    double kinetic_energy() const {
        double e = 0.0;
        for (cpBody* b : bodies_)
            e += cpBodyKineticEnergy(b);
        return e;
    }
    double potential_energy() const {
        const cpVect g = cpSpaceGetGravity(space_);
        double e = 0.0;
        for (cpBody* b : bodies_) {
            const cpVect p = cpBodyGetPosition(b);
            e -= cpBodyGetMass(b) * (g.x * p.x + g.y * p.y);
        }
        return e;
    }

  private:
    cpSpace* space_;
    std::vector<cpBody*> bodies_;
    std::vector<cpShape*> shapes_;
};

inline State chipmunk_state(const cpBody* b) {
    const cpVect p = cpBodyGetPosition(b), v = cpBodyGetVelocity(b);
    return {{p.x, p.y}, {v.x, v.y}, cpBodyGetAngle(b), cpBodyGetAngularVelocity(b)};
}

// --- 1. Integrators: Tamias (substeps = 1) against Chipmunk, step for step ----------------------

/// Load F(t), tau(t) for the integrator comparison (sampled at step starts by both engines).
using LoadFn = std::function<Load(double t)>;

struct IntegratorScene {
    std::string name;
    Vec2d gravity{};
    std::vector<BodyDesc> bodies; ///< far apart: no contacts
    LoadFn load;                  ///< optional time-varying load on every body
    int steps = 600;
    double dt = 1.0 / 60.0;
};

struct IntegratorResult {
    double p = 0.0, v = 0.0, phi = 0.0, omega = 0.0; ///< max differences over the history
    double p_scale = 0.0, v_scale = 0.0;             ///< max |p|, |v| seen (for relative figures)
    double phi_scale = 0.0, omega_scale = 0.0;       ///< max |phi| (unwrapped), |omega| seen
    int samples = 0;
};

namespace detail {
struct Recorder {
    std::vector<State> states;
};
/// Chipmunk's position update followed by a record of the state it leaves: Chipmunk's step is
/// "positions, then velocities" (cpSpaceStep), Tamias's is "velocities, then positions"; both run
/// the same interleaved sequence ... V P V P ... of symplectic Euler, so Chipmunk's state right
/// after a position update is Tamias's state after a step (with Chipmunk started one position
/// update behind, at p0 - v0 dt and phi0 - omega0 dt).
inline void record_position(cpBody* body, cpFloat dt) {
    cpBodyUpdatePosition(body, dt);
    static_cast<Recorder*>(cpBodyGetUserData(body))->states.push_back(chipmunk_state(body));
}
} // namespace detail

inline IntegratorResult compare_integrators(const IntegratorScene& sc) {
    const double dt = sc.dt;
    // Tamias with one substep: exactly semi-implicit Euler with step dt.
    WorldDef wd;
    wd.gravity = sc.gravity;
    wd.substeps = 1;
    World tw(wd);
    std::vector<BodyId> tids;
    for (const BodyDesc& d : sc.bodies) {
        tids.push_back(add_tamias(tw, d));
        if (sc.load)
            tw.set_load(tids.back(), sc.load);
    }
    // Chipmunk, one position update behind.
    CpWorld cw(sc.gravity, 0.005);
    std::vector<cpBody*> cids;
    std::vector<detail::Recorder> rec(sc.bodies.size());
    for (std::size_t i = 0; i < sc.bodies.size(); ++i) {
        BodyDesc d = sc.bodies[i];
        d.p = d.p - dt * d.v;
        d.angle -= dt * d.omega;
        cpBody* b = cw.add(d);
        cpBodySetUserData(b, &rec[i]);
        cpBodySetPositionUpdateFunc(b, detail::record_position);
        cids.push_back(b);
    }
    // Chipmunk step k applies the force set before it in its velocity update; it must be the
    // load Tamias samples at the start of its step k - 1, F(t_{k-1}) (Chipmunk clears forces
    // after every step, so they are set every time).
    for (int k = 1; k <= sc.steps + 1; ++k) {
        const double t = (k - 1) * dt;
        for (std::size_t i = 0; i < cids.size(); ++i) {
            Vec2d f = sc.bodies[i].force;
            double tau = sc.bodies[i].torque;
            if (sc.load) {
                const Load l = sc.load(t);
                f = f + l.force;
                tau += l.torque;
            }
            cpBodySetForce(cids[i], cpv(f.x, f.y));
            cpBodySetTorque(cids[i], tau);
        }
        cw.step(dt);
    }
    IntegratorResult r;
    for (int n = 0; n <= sc.steps; ++n) {
        if (n > 0)
            tw.step(dt);
        for (std::size_t i = 0; i < tids.size(); ++i) {
            const State a = tamias_state(tw, tids[i]);
            const State b = rec[i].states.at(std::size_t(n));
            r.p = std::max(r.p, norm(a.p - b.p));
            r.v = std::max(r.v, norm(a.v - b.v));
            r.phi = std::max(r.phi, angle_diff(a.phi, b.phi));
            r.omega = std::max(r.omega, std::abs(a.omega - b.omega));
            r.p_scale = std::max(r.p_scale, norm(a.p));
            r.v_scale = std::max(r.v_scale, norm(a.v));
            r.phi_scale = std::max(r.phi_scale, std::abs(b.phi));
            r.omega_scale = std::max(r.omega_scale, std::abs(a.omega));
            ++r.samples;
        }
    }
    return r;
}

inline std::vector<IntegratorScene> integrator_scenes() {
    std::vector<IntegratorScene> out;
    const auto bodies = [] {
        std::vector<BodyDesc> b(3);
        b[0] = {false, 1.0, 0.5, 2.0, {0.0, 0.0}, {3.0, -0.5}, 0.3, 1.2};
        b[1] = {true, 0.4, 0.0, 0.7, {0.0, 50.0}, {-2.0, 4.0}, -1.0, -3.0};
        b[2] = {false, 0.3, 2.0, 5.0, {0.0, 100.0}, {0.0, 1.5}, 2.0, 0.0};
        return b;
    };
    IntegratorScene free{"free flight", {0.0, 0.0}, bodies(), {}, 600, 1.0 / 60.0};
    out.push_back(free);
    IntegratorScene loaded{
        "gravity, constant force and torque", {0.0, -9.81}, bodies(), {}, 600, 1.0 / 60.0};
    loaded.bodies[0].force = {4.0, 1.0};
    loaded.bodies[0].torque = -0.5;
    loaded.bodies[1].force = {-1.0, 8.0};
    loaded.bodies[1].torque = 0.2;
    loaded.bodies[2].torque = 3.0;
    out.push_back(loaded);
    IntegratorScene varying{"gravity and sinusoidal load F(t), tau(t)",
                            {0.0, -9.81},
                            bodies(),
                            [](double t) {
                                return Load{{3.0 * std::sin(2.0 * t), -2.0 * std::cos(3.0 * t)},
                                            1.5 * std::sin(4.0 * t + 0.1)};
                            },
                            600,
                            1.0 / 60.0};
    out.push_back(varying);
    return out;
}

// --- 2. Single collisions ------------------------------------------------------------------------

struct CollisionOutcome {
    State a, b;             ///< right after the first impact (b unused against a static body)
    int contact_points = 0; ///< points of that impulsive contact
    int step = -1;          ///< the step (from 0) in which the impact was resolved
};

/// Runs until the first impact (at most `steps` steps of dt) with default settings (Tamias 4
/// substeps, Chipmunk 10 iterations) and reports the state right after it. Without `b`, body `a`
/// hits a static box 40 x 1 m whose top is y = 0 (pair restitution = the body's).
struct CollisionScene {
    std::string name;
    Vec2d gravity{};
    BodyDesc a, b;
    bool has_b = true; ///< false: `a` against the static ground
    int steps = 90;
    double dt = 1.0 / 60.0;
};

inline CollisionOutcome run_tamias(const CollisionScene& sc) {
    World w(WorldDef{.gravity = sc.gravity});
    const BodyId a = add_tamias(w, sc.a);
    BodyId b{};
    if (sc.has_b)
        b = add_tamias(w, sc.b);
    else
        add_tamias_static_box(w, {0.0, -0.5}, 40.0, 1.0, 0.0, 0.0); // max(e, 0) = e
    CollisionOutcome out;
    for (int n = 0; n < sc.steps && out.step < 0; ++n) {
        w.step(sc.dt);
        for (const ContactInfo& c : w.contacts()) {
            int active = 0;
            for (int j = 0; j < c.point_count; ++j)
                active += c.points[j].normal_impulse > 0.0;
            if (active > 0) {
                out.contact_points = active;
                out.step = n;
            }
        }
    }
    out.a = tamias_state(w, a);
    if (sc.has_b)
        out.b = tamias_state(w, b);
    return out;
}

inline CollisionOutcome run_chipmunk(const CollisionScene& sc) {
    CpWorld w(sc.gravity, 0.005);
    cpBody* a = w.add(sc.a, !sc.has_b);
    cpBody* b = nullptr;
    if (sc.has_b)
        b = w.add(sc.b);
    else
        w.add_static_box({0.0, -0.5}, 40.0, 1.0, 1.0, 1.0); // e_ground = 1: pair e = body's e
    CollisionOutcome out;
    for (int n = 0; n < sc.steps && out.step < 0; ++n) {
        w.step(sc.dt);
        cpBodyEachArbiter(
            a,
            [](cpBody*, cpArbiter* arb, void* data) {
                int& m = *static_cast<int*>(data);
                m = std::max(m, cpArbiterGetCount(arb));
            },
            &out.contact_points);
        if (out.contact_points > 0)
            out.step = n;
    }
    out.a = chipmunk_state(a);
    if (b)
        out.b = chipmunk_state(b);
    return out;
}

/// A ball dropped from rest onto the ground under gravity: the first bounce.
struct DropOutcome {
    double impact = 0.0;  ///< normal velocity at the start of the step that bounced (m/s, < 0)
    double rebound = 0.0; ///< normal velocity after that step
    double apex = 0.0;    ///< highest centre height after the bounce (m)
};

/// Ball: circle r = 0.5 m, 1 kg, restitution e, dropped with its bottom `drop` m above the floor.
inline DropOutcome drop_tamias(double e, double drop, double dt = 1.0 / 60.0) {
    World w(WorldDef{});
    add_tamias_static_box(w, {0.0, -0.5}, 40.0, 1.0, 0.0, 0.0);
    BodyDesc d{true, 0.5, 0.0, 1.0, {0.0, 0.5 + drop}};
    d.restitution = e;
    const BodyId b = add_tamias(w, d);
    DropOutcome out;
    bool bounced = false;
    for (int n = 0; n < 600; ++n) {
        const double before = w.velocity(b).y;
        w.step(dt);
        const double after = w.velocity(b).y;
        if (!bounced && before < 0.0 && after > 0.0) {
            bounced = true;
            out.impact = before;
            out.rebound = after;
        }
        if (bounced) {
            out.apex = std::max(out.apex, w.position(b).y);
            if (after < 0.0)
                break;
        }
    }
    return out;
}

inline DropOutcome drop_chipmunk(double e, double drop, double dt = 1.0 / 60.0) {
    CpWorld w({0.0, -9.81}, 0.005);
    w.add_static_box({0.0, -0.5}, 40.0, 1.0, 1.0, 0.0);
    BodyDesc d{true, 0.5, 0.0, 1.0, {0.0, 0.5 + drop}};
    d.restitution = e;
    cpBody* b = w.add(d, true);
    DropOutcome out;
    bool bounced = false;
    for (int n = 0; n < 600; ++n) {
        const double before = cpBodyGetVelocity(b).y;
        w.step(dt);
        const double after = cpBodyGetVelocity(b).y;
        if (!bounced && before < 0.0 && after > 0.0) {
            bounced = true;
            out.impact = before;
            out.rebound = after;
        }
        if (bounced) {
            out.apex = std::max(out.apex, cpBodyGetPosition(b).y);
            if (after < 0.0)
                break;
        }
    }
    return out;
}

// --- 3. Stacks and piles
// --------------------------------------------------------------------------

struct SettledFigures {
    std::vector<double> heights; ///< final y of every body, in creation order
    double mean_height = 0.0, max_height = 0.0;
    double kinetic = 0.0, potential = 0.0; ///< J, final
    int contacts = 0;                      ///< touching shape pairs
    std::vector<double> energy;            ///< total energy once per second
};

/// A container: floor (top at y = 0) and two walls with inner faces at x = +-half_width.
struct SettleScene {
    std::string name;
    std::vector<BodyDesc> bodies;
    double half_width = 10.0;
    double seconds = 4.0;
    double dt = 1.0 / 60.0;
};

inline void finish(SettledFigures& f) {
    double sum = 0.0;
    for (double h : f.heights) {
        sum += h;
        f.max_height = std::max(f.max_height, h);
    }
    f.mean_height = f.heights.empty() ? 0.0 : sum / double(f.heights.size());
}

/// Steps either engine's world `w` through the scene, sampling the total energy once a second,
/// and collects the settled figures: each body's height and the contact count at the end.
template <class W, class Id, class Height, class Contacts>
SettledFigures run_settling(W& w, const SettleScene& sc, const std::vector<Id>& ids, Height height,
                            Contacts contacts) {
    SettledFigures f;
    const int steps = int(std::lround(sc.seconds / sc.dt));
    const int per_second = int(std::lround(1.0 / sc.dt));
    for (int n = 0; n <= steps; ++n) {
        if (n > 0)
            w.step(sc.dt);
        if (n % per_second == 0)
            f.energy.push_back(w.kinetic_energy() + w.potential_energy());
    }
    for (const Id& b : ids)
        f.heights.push_back(height(b));
    f.kinetic = w.kinetic_energy();
    f.potential = w.potential_energy();
    f.contacts = contacts();
    finish(f);
    return f;
}

inline SettledFigures settle_tamias(const SettleScene& sc) {
    World w(WorldDef{});
    const double hw = sc.half_width;
    // The container carries the bodies' pair coefficients (max and geometric mean of equal
    // values give those values).
    const double e = sc.bodies.empty() ? 0.0 : sc.bodies.front().restitution;
    const double mu = sc.bodies.empty() ? 0.0 : sc.bodies.front().friction;
    add_tamias_static_box(w, {0.0, -0.5}, 2.0 * hw + 2.0, 1.0, e, mu);
    add_tamias_static_box(w, {-hw - 0.5, 10.0}, 1.0, 22.0, e, mu);
    add_tamias_static_box(w, {hw + 0.5, 10.0}, 1.0, 22.0, e, mu);
    std::vector<BodyId> ids;
    for (const BodyDesc& d : sc.bodies)
        ids.push_back(add_tamias(w, d));
    return run_settling(
        w, sc, ids, [&](BodyId b) { return w.position(b).y; },
        [&] { return int(w.contacts().size()); });
}

inline SettledFigures settle_chipmunk(const SettleScene& sc) {
    CpWorld w({0.0, -9.81}, 0.005);
    const double hw = sc.half_width;
    const double e = sc.bodies.empty() ? 0.0 : sc.bodies.front().restitution;
    const double mu = sc.bodies.empty() ? 0.0 : sc.bodies.front().friction;
    // Chipmunk multiplies: the container carries sqrt(e), sqrt(mu) like the bodies.
    w.add_static_box({0.0, -0.5}, 2.0 * hw + 2.0, 1.0, std::sqrt(e), std::sqrt(mu));
    w.add_static_box({-hw - 0.5, 10.0}, 1.0, 22.0, std::sqrt(e), std::sqrt(mu));
    w.add_static_box({hw + 0.5, 10.0}, 1.0, 22.0, std::sqrt(e), std::sqrt(mu));
    std::vector<cpBody*> ids;
    for (const BodyDesc& d : sc.bodies)
        ids.push_back(w.add(d));
    return run_settling(
        w, sc, ids, [](cpBody* b) { return cpBodyGetPosition(b).y; },
        [&] { return w.contact_count(); });
}

/// A stack of `n` boxes of side `s` (1 kg each) resting on the floor, friction mu.
inline SettleScene stack_scene(int n, double s, double mu) {
    SettleScene sc{"stack of " + std::to_string(n) + " boxes", {}, 5.0, 3.0, 1.0 / 60.0};
    for (int i = 0; i < n; ++i) {
        BodyDesc d;
        d.w = d.h = s;
        d.mass = 1.0;
        d.p = {0.0, 0.5 * s + s * i};
        d.friction = mu;
        sc.bodies.push_back(d);
    }
    return sc;
}

/// `n` boxes and circles (sizes 0.2-0.5 m, 0.5-3 kg) dropped from a grid into a 6 m container,
/// restitution 0.2, friction 0.4; positions from a fixed linear congruential sequence so the
/// scene is the same everywhere.
inline SettleScene pile_scene(int n) {
    SettleScene sc{"pile of " + std::to_string(n) + " bodies", {}, 3.0, 5.0, 1.0 / 60.0};
    std::uint64_t x = 0x9E3779B97F4A7C15ull;
    const auto next = [&x] {
        x = x * 6364136223846793005ull + 1442695040888963407ull;
        return double(x >> 11) * 0x1.0p-53;
    };
    for (int i = 0; i < n; ++i) {
        BodyDesc d;
        d.circle = next() < 0.4;
        d.w = 0.2 + 0.3 * next();
        d.h = d.circle ? 0.0 : 0.2 + 0.3 * next();
        if (d.circle)
            d.w *= 0.5; // radius 0.1-0.25 m
        d.mass = 0.5 + 2.5 * next();
        d.p = {-2.25 + 0.75 * (i % 7) + 0.1 * (next() - 0.5), 1.0 + 0.8 * (i / 7)};
        d.angle = 3.0 * next();
        d.v = {2.0 * (next() - 0.5), 0.0};
        d.restitution = 0.2;
        d.friction = 0.4;
        sc.bodies.push_back(d);
    }
    return sc;
}

} // namespace tamias2d::peer
