// verify_chipmunk <out_dir>: the same scenes in Tamias2D and Chipmunk2D 7.0.3 (Pymunk's engine;
// SRS NFR2 "compared to Pymunk"). Writes <out_dir>/chipmunk_comparison.json
// (docs/traceability.md) and exits non-zero when a check fails. The differences found are
// explained in docs/peer-differences.md.
//
//  1. Integrators: free flight, constant loads, a time-varying load; Tamias with one substep
//     against Chipmunk step for step: round-off agreement (the schemes are the same).
//  2. Single collisions against IM3/DD8/DD12 closed forms, in both engines.
//  3. A dropped ball (restitution under gravity): rebound, impact timing, apex.
//  4. A stack and a pile: summary figures (heights, energy, contact counts).
//  5. Energy in the random scenes of the property tests (tests/properties): how often the total
//     energy rises from one step to the next, in both engines.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <numbers>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "peer_chipmunk/peer_scenes.hpp"
#include "properties/random_scenes.hpp"
#include "verification_report.hpp"

using json = nlohmann::json;
using namespace tamias2d;
using namespace tamias2d::peer;
using tamias2d::evidence::fmt;
using tamias2d::evidence::Report;

namespace {

/// Velocities after a collision from the closed forms, for scene a (and b).
struct Expected {
    State a, b;
};

double cross2(Vec2d a, Vec2d b) {
    return a.x * b.y - a.y * b.x;
}

/// IM3 with DD8 against an immovable body (1/m_B = 0), normal n, contact point P.
State im3_against_static(const BodyDesc& d, Vec2d P, Vec2d n) {
    const double m = d.mass, I = d.inertia(), e = d.restitution;
    const Vec2d r = P - d.p;
    const Vec2d vp = d.v + d.omega * Vec2d{-r.y, r.x}; // DD9
    const double vn = dot(vp, n);
    const double rn = cross2(r, n);
    const double j = -(1.0 + e) * vn / (1.0 / m + rn * rn / I); // DD8
    return {{}, d.v + (j / m) * n, 0.0, d.omega + rn * j / I};
}

struct RiseStats {
    long steps = 0, rising = 0;
    int scenes = 0;
    double worst = 0.0;
};

/// Both engines on the energy scenes of tests/properties (seeds 1000...): gravity, a floor and
/// two walls, 2-12 bodies, no friction. Chipmunk multiplies restitutions; per-shape sqrt(e) gives
/// the pair sqrt(e_a e_b) <= max(e_a, e_b) (Tamias's rule), never bouncier than Tamias.
std::pair<RiseStats, RiseStats> energy_rises(int count) {
    using namespace tamias2d::property_test;
    RiseStats ts, cs;
    for (int i = 0; i < count; ++i) {
        Rng r(1000 + std::uint64_t(i));
        const double e_floor = r.uniform(0.0, 1.0), e_left = r.uniform(0.0, 1.0),
                     e_right = r.uniform(0.0, 1.0);
        const int n = r.integer(2, 12);
        std::vector<BodySpec> specs;
        for (const Vec2d p : grid_positions(r, n, 8, {-5.25, 1.0}))
            specs.push_back(random_body(r, p, 4.0, 1.0, 0.0));
        const int steps = r.integer(60, 200);
        World tw(WorldDef{});
        add_static_box(tw, {0.0, -0.5}, 16.0, 1.0, e_floor);
        add_static_box(tw, {-8.0, 10.0}, 1.0, 22.0, e_left);
        add_static_box(tw, {8.0, 10.0}, 1.0, 22.0, e_right);
        CpWorld cw({0.0, -9.81}, 0.005);
        cw.add_static_box({0.0, -0.5}, 16.0, 1.0, std::sqrt(e_floor), 0.0);
        cw.add_static_box({-8.0, 10.0}, 1.0, 22.0, std::sqrt(e_left), 0.0);
        cw.add_static_box({8.0, 10.0}, 1.0, 22.0, std::sqrt(e_right), 0.0);
        for (const BodySpec& s : specs) {
            const BodyId b = add_body(tw, s);
            BodyDesc d;
            d.circle = s.circle;
            d.w = s.circle ? s.a : 2.0 * s.a;
            d.h = 2.0 * s.b;
            d.mass = tw.mass(b);
            d.p = s.p;
            d.v = s.v;
            d.angle = s.angle;
            d.omega = s.omega;
            d.restitution = s.restitution;
            cw.add(d);
        }
        double et = tw.kinetic_energy() + tw.potential_energy();
        double ec = cw.kinetic_energy() + cw.potential_energy();
        bool rt = false, rc = false;
        for (int k = 0; k < steps; ++k) {
            tw.step(1.0 / 60.0);
            cw.step(1.0 / 60.0);
            const double et1 = tw.kinetic_energy() + tw.potential_energy();
            const double ec1 = cw.kinetic_energy() + cw.potential_energy();
            // A rise beyond round-off (1e-9 of the energy scale).
            const bool up_t = et1 - et > 1e-9 * (std::abs(et1) + 100.0);
            const bool up_c = ec1 - ec > 1e-9 * (std::abs(ec1) + 100.0);
            ts.rising += up_t;
            cs.rising += up_c;
            rt = rt || up_t;
            rc = rc || up_c;
            ts.worst = std::max(ts.worst, et1 - et);
            cs.worst = std::max(cs.worst, ec1 - ec);
            et = et1;
            ec = ec1;
        }
        ts.steps += steps;
        cs.steps += steps;
        ts.scenes += rt;
        cs.scenes += rc;
    }
    return {ts, cs};
}

} // namespace

int main(int argc, char** argv) {
    const std::filesystem::path out_dir = argc > 1 ? argv[1] : "reports/data";
    Report rep;
    const double dt = 1.0 / 60.0;

    // 1. Integrators.
    json itable = {
        {"name", "Integrators: Tamias (substeps = 1) against Chipmunk, 600 steps of 1/60 s"},
        {"columns",
         {"scene", "max |dp| (m)", "max |dv| (m/s)", "max |dphi| (rad)", "max |domega| (rad/s)",
          "max |p| (m)", "max |v| (m/s)"}},
        {"rows", json::array()}};
    for (const IntegratorScene& sc : integrator_scenes()) {
        const IntegratorResult r = compare_integrators(sc);
        itable["rows"].push_back({sc.name, r.p, r.v, r.phi, r.omega, r.p_scale, r.v_scale});
        // Round-off: 600 steps of additions at 1e-16 relative to the largest magnitudes (the load
        // is sampled at Tamias's accumulated clock and at (k - 1) dt for Chipmunk: a few ulps).
        const double tol_p = 1e-12 * r.p_scale, tol_v = 1e-12 * r.v_scale;
        const double tol_phi = 1e-12 * std::max(1.0, r.phi_scale);
        const double tol_omega = 1e-12 * std::max(1.0, r.omega_scale);
        const bool ok = r.p <= tol_p && r.v <= tol_v && r.phi <= tol_phi && r.omega <= tol_omega;
        rep.check("same integrator as Chipmunk: " + sc.name, {"NFR2", "IM1", "IM2", "R5", "R6"}, ok,
                  "Chipmunk 7.0.3 cpSpaceStep (cpBodyUpdatePosition, cpBodyUpdateVelocity), "
                  "started one position update behind",
                  "max |dp| " + fmt(r.p) + " m (round-off bound " + fmt(tol_p) + "), |dv| " +
                      fmt(r.v) + " m/s, |dphi| " + fmt(r.phi) + " rad, |domega| " + fmt(r.omega) +
                      " rad/s over " + std::to_string(r.samples) + " samples");
    }
    rep.tables.push_back(itable);

    // 2. Single collisions against closed forms.
    json ctable = {{"name", "Single collisions: velocities after the impact"},
                   {"columns",
                    {"scene", "quantity", "closed form", "Tamias", "Chipmunk", "|Tamias - closed|",
                     "|Chipmunk - closed|", "contact points (Tamias/Chipmunk)",
                     "impact step (Tamias/Chipmunk)"}},
                   {"rows", json::array()}};
    const auto collision = [&](const CollisionScene& sc, const Expected& ex,
                               std::vector<std::string> labels) {
        const CollisionOutcome t = run_tamias(sc);
        const CollisionOutcome c = run_chipmunk(sc);
        const double scale = norm(sc.a.v - (sc.has_b ? sc.b.v : Vec2d{}));
        double et = 0.0, ec = 0.0;
        const auto row = [&](const std::string& q, double want, double gt, double gc) {
            et = std::max(et, std::abs(gt - want));
            ec = std::max(ec, std::abs(gc - want));
            ctable["rows"].push_back(
                {sc.name, q, want, gt, gc, std::abs(gt - want), std::abs(gc - want),
                 std::to_string(t.contact_points) + "/" + std::to_string(c.contact_points),
                 std::to_string(t.step) + "/" + std::to_string(c.step)});
        };
        row("v_a.x", ex.a.v.x, t.a.v.x, c.a.v.x);
        row("v_a.y", ex.a.v.y, t.a.v.y, c.a.v.y);
        row("omega_a", ex.a.omega, t.a.omega, c.a.omega);
        if (sc.has_b) {
            row("v_b.x", ex.b.v.x, t.b.v.x, c.b.v.x);
            row("v_b.y", ex.b.v.y, t.b.v.y, c.b.v.y);
        }
        const double tol = 1e-9 * scale;
        rep.check("Tamias matches the closed form: " + sc.name, labels, et <= tol,
                  "IM3 / DD8 / DD12 closed form",
                  "max velocity error " + fmt(et) + " (tolerance " + fmt(tol) + ")");
        // The peer's own agreement makes it a fit reference; it verifies nothing of Tamias2D's,
        // so it carries no SRS label.
        rep.check("Chipmunk matches the closed form: " + sc.name, {}, ec <= tol,
                  "IM3 / DD8 / DD12 closed form; Chipmunk 7.0.3 (10 iterations, slop 0.005 m)",
                  "max velocity error " + fmt(ec) + " (tolerance " + fmt(tol) +
                      "); contact points " + std::to_string(t.contact_points) + " (Tamias) / " +
                      std::to_string(c.contact_points) + " (Chipmunk)");
    };
    {
        // Head-on, centred: 1 kg against 100 kg, C_R = 1 (TC10).
        CollisionScene sc{
            "head-on circles 1 kg / 100 kg, C_R = 1", {0.0, 0.0}, {}, {}, true, 60, dt};
        sc.a = {true, 0.5, 0.0, 1.0, {-3.0, 0.0}, {4.0, 0.0}};
        sc.a.restitution = 1.0;
        sc.b = {true, 1.0, 0.0, 100.0, {0.0, 0.0}, {0.0, 0.0}};
        sc.b.restitution = 1.0;
        const double m1 = 1.0, m2 = 100.0, v1 = 4.0, v2 = 0.0;
        Expected ex;
        ex.a.v = {((m1 - m2) * v1 + 2.0 * m2 * v2) / (m1 + m2), 0.0};
        ex.b.v = {((m2 - m1) * v2 + 2.0 * m1 * v1) / (m1 + m2), 0.0};
        collision(sc, ex, {"IM3", "R8", "GD1", "DD12"});
    }
    {
        // A ball against the static ground, no gravity, C_R = 0.5 (TC11).
        CollisionScene sc{"ball on static ground, C_R = 0.5", {0.0, 0.0}, {}, {}, false, 60, dt};
        sc.a = {true, 0.5, 0.0, 2.0, {0.0, 2.0}, {1.0, -5.0}};
        sc.a.restitution = 0.5;
        Expected ex;
        ex.a.v = {1.0, 2.5};
        collision(sc, ex, {"IM3", "R8", "DD12", "DD10"});
    }
    {
        // A box corner (A5 vertex-edge) against the static ground, no gravity, C_R = 0.5.
        CollisionScene sc{
            "box corner on static ground (A5), C_R = 0.5", {0.0, 0.0}, {}, {}, false, 60, dt};
        sc.a = {false, 1.0, 0.6, 2.0, {0.0, 1.5}, {0.5, -3.0}, 0.5, 0.0};
        sc.a.restitution = 0.5;
        // The lowest corner: body frame (+-0.5, +-0.3) rotated by 0.5 rad.
        const Rot q = Rot::from_angle(sc.a.angle);
        Vec2d low{0.0, 1e9};
        for (const Vec2d c :
             {Vec2d{0.5, 0.3}, Vec2d{-0.5, 0.3}, Vec2d{0.5, -0.3}, Vec2d{-0.5, -0.3}}) {
            const Vec2d w = sc.a.p + rotate(q, c);
            if (w.y < low.y)
                low = w;
        }
        // Without rotation before the impact, the corner meets y = 0 straight below.
        const Vec2d P{low.x + sc.a.v.x * (low.y / -sc.a.v.y), 0.0};
        BodyDesc at_contact = sc.a;
        at_contact.p = sc.a.p + (low.y / -sc.a.v.y) * sc.a.v;
        const Expected ex{im3_against_static(at_contact, P, {0.0, 1.0}), {}};
        collision(sc, ex, {"IM3", "R8", "DD8", "DD12", "A5"});
    }
    rep.tables.push_back(ctable);

    // 3. Dropped ball under gravity.
    json dtable = {{"name", "Ball (r = 0.5 m) dropped 2 m onto the ground: first bounce"},
                   {"columns",
                    {"C_R", "engine", "impact (m/s)", "rebound (m/s)", "rebound / impact",
                     "apex after bounce (m)"}},
                   {"rows", json::array()}};
    for (const double e : {0.5, 0.8}) {
        const DropOutcome t = drop_tamias(e, 2.0);
        const DropOutcome c = drop_chipmunk(e, 2.0);
        dtable["rows"].push_back({e, "Tamias", t.impact, t.rebound, -t.rebound / t.impact, t.apex});
        dtable["rows"].push_back(
            {e, "Chipmunk", c.impact, c.rebound, -c.rebound / c.impact, c.apex});
        const double g = 9.81;
        rep.check("restitution on the pre-impact speed, C_R = " + fmt(e), {"NFR2", "DD12", "R8"},
                  std::abs(t.rebound + e * t.impact) <= 1e-9 * std::abs(t.impact) &&
                      std::abs(c.rebound + e * c.impact) <= 1e-9 * std::abs(c.impact),
                  "DD12: v' = -C_R v at the start of the impact step, in both engines",
                  "Tamias " + fmt(-t.rebound / t.impact, 12) + ", Chipmunk " +
                      fmt(-c.rebound / c.impact, 12));
        // The impact is processed in a step that starts at most one step apart in the two
        // engines (Tamias sees the contact speculatively, Chipmunk once it overlaps): the impact
        // speeds differ by at most g dt, the rebounds by e g dt.
        const double tol_v = g * dt * (1.0 + 1e-9);
        const bool timing = std::abs(t.impact - c.impact) <= tol_v;
        // Apex: v'^2 / (2 g) above the contact height; a rebound difference dv' moves it by
        // v' dv' / g, and the schemes (4 substeps vs 1) differ by the first-order v' dt / 2.
        const double vr = std::max(t.rebound, c.rebound);
        const double tol_apex = vr * e * dt + vr * dt;
        const bool apex = std::abs(t.apex - c.apex) <= tol_apex;
        rep.check("impact timing and apex agree, C_R = " + fmt(e), {"NFR2", "R8", "IM1"},
                  timing && apex, "Chipmunk 7.0.3 on the same drop",
                  "impact speeds " + fmt(t.impact, 6) + " / " + fmt(c.impact, 6) +
                      " m/s (within g dt = " + fmt(tol_v) + "), apex " + fmt(t.apex, 6) + " / " +
                      fmt(c.apex, 6) + " m (within " + fmt(tol_apex) + " m)");
    }
    rep.tables.push_back(dtable);

    // 4. Stack and pile.
    json stable = {{"name", "Settled scenes: summary figures"},
                   {"columns",
                    {"scene", "engine", "mean height (m)", "max height (m)", "kinetic energy (J)",
                     "potential energy (J)", "touching pairs"}},
                   {"rows", json::array()}};
    json energy_lines = json::array();
    // Both engines on one scene, each one's summary row added to the table.
    const auto settle_both = [&](const SettleScene& sc) {
        std::pair<SettledFigures, SettledFigures> tc{settle_tamias(sc), settle_chipmunk(sc)};
        for (const auto& [engine, f] : {std::pair{"Tamias", &tc.first}, {"Chipmunk", &tc.second}})
            stable["rows"].push_back({sc.name, engine, f->mean_height, f->max_height, f->kinetic,
                                      f->potential, f->contacts});
        return tc;
    };
    {
        const SettleScene sc = stack_scene(6, 0.5, 0.6);
        const auto [t, c] = settle_both(sc);
        // Box k rests on k + 1 contacts. Under a weight W a contact overlaps by at most its slop
        // (0.005 m in both engines) plus its static deflection: Tamias's soft contact is a spring
        // of stiffness m_eff omega^2 (omega = 2 pi contact_hertz), so W / (m_eff omega^2), with
        // m_eff = m on the floor and m / 2 between equal boxes; Chipmunk's (rigid, with bias) is
        // stiffer. The heights of the two engines therefore agree within the sum over the
        // contacts below of (2 slop + W / (m_eff omega^2)).
        const double omega_c = 2.0 * std::numbers::pi * WorldDef{}.contact_hertz;
        const int n = int(t.heights.size());
        bool heights = true;
        double worst = 0.0, bound = 0.0, worst_bound = 0.0;
        for (int k = 0; k < n; ++k) {
            const double weight = double(n - k) * 9.81; // N carried by the contact below box k
            const double m_eff = k == 0 ? 1.0 : 0.5;
            bound += 2.0 * 0.005 + weight / (m_eff * omega_c * omega_c);
            const double d = std::abs(t.heights[std::size_t(k)] - c.heights[std::size_t(k)]);
            if (d > worst) {
                worst = d;
                worst_bound = bound;
            }
            heights = heights && d <= bound;
        }
        rep.check("stack of 6 boxes: resting heights agree", {"NFR2", "R8", "R7"}, heights,
                  "Chipmunk 7.0.3 on the same stack; ideal heights 0.25 + 0.5 k m",
                  "max |y_Tamias - y_Chipmunk| = " + fmt(worst) + " m (bound there " +
                      fmt(worst_bound) + " m); top box " + fmt(t.heights.back(), 5) + " / " +
                      fmt(c.heights.back(), 5) + " m (ideal " + fmt(0.25 + 0.5 * (n - 1)) + ")");
        rep.check("stack of 6 boxes: at rest, same contact count", {"NFR2", "R7"},
                  t.kinetic < 1e-3 && c.kinetic < 1e-3 && t.contacts == 6 && c.contacts == 6,
                  "closed form, the stack's geometry: a settled stack touches in 6 pairs "
                  "(floor + 5); at rest: kinetic energy below 1e-3 J, in both engines",
                  "kinetic energy " + fmt(t.kinetic) + " / " + fmt(c.kinetic) + " J, pairs " +
                      std::to_string(t.contacts) + " / " + std::to_string(c.contacts));
    }
    {
        const SettleScene sc = pile_scene(30);
        const auto [t, c] = settle_both(sc);
        std::vector<double> secs;
        for (std::size_t k = 0; k < t.energy.size(); ++k)
            secs.push_back(double(k));
        energy_lines.push_back({{"label", "Tamias"}, {"x", secs}, {"y", t.energy}});
        energy_lines.push_back({{"label", "Chipmunk"}, {"x", secs}, {"y", c.energy}});
        // A pile is chaotic: individual bodies end anywhere, so only statistics compare. The
        // largest body is 0.5 m: the mean heights must agree within it, the tallest body within
        // two sizes, and both piles must have settled (kinetic energy below 1% of the initial
        // potential energy).
        const double e0 = t.energy.front();
        const bool ok = std::abs(t.mean_height - c.mean_height) <= 0.5 &&
                        std::abs(t.max_height - c.max_height) <= 1.0 && t.kinetic < 0.01 * e0 &&
                        c.kinetic < 0.01 * e0;
        rep.check("pile of 30 bodies: settled figures agree", {"NFR2", "R7", "R8"}, ok,
                  "Chipmunk 7.0.3 on the same pile",
                  "mean height " + fmt(t.mean_height) + " / " + fmt(c.mean_height) +
                      " m, max height " + fmt(t.max_height) + " / " + fmt(c.max_height) +
                      " m, kinetic " + fmt(t.kinetic) + " / " + fmt(c.kinetic) + " J, pairs " +
                      std::to_string(t.contacts) + " / " + std::to_string(c.contacts));
    }
    rep.tables.push_back(stable);
    // 5. Energy rises in the property-test scenes.
    {
        const int count = 300;
        const auto [t, c] = energy_rises(count);
        rep.tables.push_back(
            {{"name", "Energy rising from one step to the next: random scenes of tests/properties"},
             {"columns",
              {"engine", "scenes", "steps", "rising steps", "scenes with a rise",
               "worst rise (J)"}},
             {"rows",
              {{"Tamias", count, t.steps, t.rising, t.scenes, t.worst},
               {"Chipmunk", count, c.steps, c.rising, c.scenes, c.worst}}}});
        rep.check("energy rises no more often than in Chipmunk", {"NFR2", "DD15", "DD16"},
                  t.rising <= c.rising,
                  "Chipmunk 7.0.3 on the same " + std::to_string(count) +
                      " scenes (SRS 5.2.7: energy constant or decreasing)",
                  "rising steps " + std::to_string(t.rising) + " (Tamias) / " +
                      std::to_string(c.rising) + " (Chipmunk) of " + std::to_string(t.steps) +
                      "; worst rise " + fmt(t.worst) + " / " + fmt(c.worst) + " J");
    }

    rep.series.push_back({{"name", "Pile of 30 bodies: total energy, Tamias and Chipmunk"},
                          {"x_label", "t (s)"},
                          {"y_label", "kinetic + potential energy (J)"},
                          {"log_x", false},
                          {"log_y", false},
                          {"lines", energy_lines}});

    return rep.write(out_dir, "chipmunk_comparison",
                     "Tamias2D against Chipmunk2D 7.0.3 (the engine of Pymunk, SRS NFR2) on the "
                     "same scenes: integrators step for step, single collisions against "
                     "IM3/DD8/DD12, a dropped ball, a stack and a pile. See "
                     "docs/peer-differences.md.");
}
