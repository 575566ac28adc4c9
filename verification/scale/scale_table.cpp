// What the engine holds across scales and mass ratios (docs/user-guide.md, "Scales and mass
// ratios"): a stack of boxes at box sizes from 1e-12 to 1e12 m, a heavy box on a light one and a
// chain of alternating masses at mass ratios from 1 to 1e6. The oracle is geometry: boxes at
// rest on each other do not overlap (the soft contact's overlap is the error), and a revolute
// joint's two anchors are one point (their separation is the error). The tables give every
// measured figure; the checks gate only the envelope the user guide states.
//   scale_table <out_dir>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "tamias2d/tamias2d.hpp"
#include "verification_report.hpp"

using tamias2d::BodyDef;
using tamias2d::BodyId;
using tamias2d::BodyType;
using tamias2d::Vec2d;
using tamias2d::World;
using tamias2d::WorldDef;
using json = nlohmann::json;
using tamias2d::evidence::fmt;

namespace {

/// The supported range of every real input (docs/design.md, "Supported ranges").
constexpr double max_input = 1e12;

/// How a run ended and what it measured, each figure relative to the scene's length scale.
struct Outcome {
    bool refused = false; ///< a call threw (built or stepped): the message is kept
    bool finite = true;   ///< every state finite after every accepted step
    std::string error;    ///< the refusal's message
    double sag = 0.0;     ///< top box: how far below its resting height, / size
    double overlap = 0.0; ///< deepest contact overlap seen at any step, / size
    double drift = 0.0;   ///< largest anchor separation of any joint at any step, / link length
    double shift = 0.0;   ///< sideways displacement of the supporting (light) box, / size
    int steps_done = 0;
};

bool finite_state(const World& w, const std::vector<BodyId>& bodies) {
    for (BodyId b : bodies) {
        const Vec2d p = w.position(b);
        const Vec2d v = w.velocity(b);
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(v.x) ||
            !std::isfinite(v.y) || !std::isfinite(w.orientation(b)) ||
            !std::isfinite(w.angular_velocity(b)))
            return false;
    }
    return true;
}

/// The deepest overlap (m, >= 0) of the contacts the last step reported.
double deepest_overlap(const World& w) {
    double deepest = 0.0;
    for (const auto& c : w.contacts())
        for (int i = 0; i < c.point_count; ++i)
            deepest = std::max(deepest, -c.points[static_cast<std::size_t>(i)].separation);
    return deepest;
}

/// How the world's settings follow the box size L.
enum class Tolerances {
    defaults, ///< WorldDef{} and dt = 1/60 s, as a user who changes nothing
    lengths,  ///< the lengths scaled by L (speculative and manifold-reuse distances, push speed)
    similar,  ///< the 1 m scene in units of L and sqrt(L / 1 m) s: lengths by L, times (dt,
              ///< 1 / hertz) by sqrt(L), speeds by sqrt(L); gravity unchanged
};

const char* name_of(Tolerances t) {
    switch (t) {
    case Tolerances::defaults:
        return "defaults";
    case Tolerances::lengths:
        return "lengths scaled";
    case Tolerances::similar:
        return "similar scene";
    }
    return "?";
}

/// The world and time step for a scene of length scale L (m).
WorldDef world_for(Tolerances t, double L, double& dt) {
    WorldDef def;
    dt = 1.0 / 60.0;
    if (t == Tolerances::defaults)
        return def;
    def.speculative_distance *= L;
    def.manifold_reuse_distance *= L;
    def.linear_slop *= L;
    if (t == Tolerances::lengths) {
        def.contact_push_max_velocity *= L;
        return def;
    }
    const double time_scale = std::sqrt(L);
    dt *= time_scale;
    def.contact_hertz /= time_scale;
    def.joint_hertz /= time_scale;
    def.contact_push_max_velocity *= time_scale;
    def.restitution_threshold *= time_scale;
    return def;
}

constexpr int stack_steps = 120; // 2 s of the 1 m scene at 60 Hz

/// Up to 5 boxes of side L: fewer when 5 would put a position beyond the supported range.
int boxes_for(double L) {
    int boxes = 5;
    while (boxes > 1 && (boxes / 2.0 + 0.5) * L > max_input)
        --boxes;
    return boxes;
}

/// A stack of `boxes` boxes of side L on a static ground box, started touching (the resting
/// geometry), stepped for stack_steps steps.
Outcome run_stack(Tolerances t, double L, int boxes) {
    Outcome out;
    try {
        double dt = 0.0;
        World w(world_for(t, L, dt));
        const double y0 = -boxes / 2.0 * L; // the ground's top
        BodyDef gd;
        gd.type = BodyType::static_body;
        gd.position = {0.0, y0 - 0.5 * L};
        const BodyId ground = w.create_body(gd);
        w.create_shape(ground, tamias2d::box_shape(std::min(4.0 * L, max_input), L));
        std::vector<BodyId> stack;
        for (int i = 0; i < boxes; ++i) {
            BodyDef bd;
            bd.position = {0.0, y0 + (i + 0.5) * L};
            const BodyId b = w.create_body(bd);
            w.create_shape(b, tamias2d::box_shape(L, L));
            stack.push_back(b);
        }
        const double rest_top = y0 + (boxes - 0.5) * L;
        for (int s = 0; s < stack_steps; ++s) {
            w.step(dt);
            ++out.steps_done;
            if (!finite_state(w, stack)) {
                out.finite = false;
                break;
            }
            out.overlap = std::max(out.overlap, deepest_overlap(w) / L);
        }
        if (out.finite)
            out.sag = (rest_top - w.position(stack.back()).y) / L;
    } catch (const std::exception& e) {
        out.refused = true;
        out.error = e.what();
    }
    return out;
}

/// A box of mass `ratio` kg (1 m side) resting on one of 1 kg on a static ground, defaults,
/// 2 s: the overlap of the light box with the ground and the heavy box, / its height.
Outcome run_heavy_on_light(double ratio) {
    Outcome out;
    try {
        World w;
        BodyDef gd;
        gd.type = BodyType::static_body;
        gd.position = {0.0, -0.5};
        const BodyId ground = w.create_body(gd);
        w.create_shape(ground, tamias2d::box_shape(4.0, 1.0));
        BodyDef light;
        light.position = {0.0, 0.5};
        light.mass = 1.0;
        const BodyId lb = w.create_body(light);
        w.create_shape(lb, tamias2d::box_shape(1.0, 1.0));
        BodyDef heavy;
        heavy.position = {0.0, 1.5};
        heavy.mass = ratio;
        const BodyId hb = w.create_body(heavy);
        w.create_shape(hb, tamias2d::box_shape(1.0, 1.0));
        const std::vector<BodyId> bodies{lb, hb};
        for (int s = 0; s < stack_steps; ++s) {
            w.step(1.0 / 60.0);
            ++out.steps_done;
            if (!finite_state(w, bodies)) {
                out.finite = false;
                break;
            }
            out.overlap = std::max(out.overlap, deepest_overlap(w));
        }
        if (out.finite) {
            out.sag = 1.5 - w.position(hb).y; // both layers' overlap, / the 1 m height
            out.shift = std::abs(w.position(lb).x);
        }
    } catch (const std::exception& e) {
        out.refused = true;
        out.error = e.what();
    }
    return out;
}

/// A chain of 10 links (1 m x 0.1 m boxes) pinned at one end to a static body, started
/// horizontal, links of 1 kg and `ratio` kg alternating, swinging down for 2 s under gravity
/// (defaults): the largest separation of a joint's two anchors, / the link length.
Outcome run_chain(double ratio) {
    Outcome out;
    constexpr int links = 10;
    try {
        World w;
        const BodyId pivot = w.create_body(BodyDef{.type = BodyType::static_body});
        std::vector<BodyId> chain;
        struct Pin {
            BodyId a, b;
            Vec2d local_a, local_b; // the anchor in each body's frame
        };
        std::vector<Pin> pins;
        for (int i = 0; i < links; ++i) {
            BodyDef bd;
            bd.position = {i + 0.5, 0.0};
            bd.mass = (i % 2 == 0) ? 1.0 : ratio;
            const BodyId b = w.create_body(bd);
            w.create_shape(b, tamias2d::box_shape(1.0, 0.1));
            const BodyId a = i == 0 ? pivot : chain.back();
            tamias2d::RevoluteJointDef jd;
            jd.body_a = a;
            jd.body_b = b;
            jd.anchor = {static_cast<double>(i), 0.0};
            w.create_joint(jd);
            pins.push_back({a, b, i == 0 ? Vec2d{0.0, 0.0} : Vec2d{0.5, 0.0}, Vec2d{-0.5, 0.0}});
            chain.push_back(b);
        }
        const auto world_point = [&w](BodyId b, Vec2d local) {
            const Vec2d o = w.origin(b);
            const double c = std::cos(w.orientation(b)), s = std::sin(w.orientation(b));
            return Vec2d{o.x + c * local.x - s * local.y, o.y + s * local.x + c * local.y};
        };
        for (int s = 0; s < stack_steps; ++s) {
            w.step(1.0 / 60.0);
            ++out.steps_done;
            if (!finite_state(w, chain)) {
                out.finite = false;
                break;
            }
            for (const Pin& p : pins) {
                const Vec2d pa = world_point(p.a, p.local_a);
                const Vec2d pb = world_point(p.b, p.local_b);
                out.drift = std::max(out.drift, std::hypot(pa.x - pb.x, pa.y - pb.y));
            }
        }
    } catch (const std::exception& e) {
        out.refused = true;
        out.error = e.what();
    }
    return out;
}

/// A table cell: the figure, or why there is none.
json cell(const Outcome& o, double v) {
    if (o.refused)
        return "refused";
    if (!o.finite)
        return "non-finite";
    return fmt(v, 3);
}

std::string status(const Outcome& o) {
    if (o.refused)
        return "refused after " + std::to_string(o.steps_done) + " steps: " + o.error;
    if (!o.finite)
        return "non-finite after " + std::to_string(o.steps_done) + " steps";
    return "ok";
}

bool held(const Outcome& o) {
    return !o.refused && o.finite;
}

} // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::cerr << "usage: scale_table <out_dir>\n";
        return 2;
    }
    tamias2d::evidence::Report rep;
    const std::vector<double> sizes{1e-12, 1e-9, 1e-6, 1e-3, 1.0, 1e3, 1e6, 1e9, 1e12};
    const std::vector<double> ratios{1.0, 10.0, 1e2, 1e3, 1e4, 1e5, 1e6};
    const std::string reliability = "reliability";

    // --- the stack against size, three ways of setting the world ---
    json stack_table = {{"name", "Stack of boxes against size (2 s of the 1 m scene)"},
                        {"columns",
                         {"box side (m)", "world settings", "boxes", "top box sag / side",
                          "deepest overlap / side", "outcome"}},
                        {"rows", json::array()}};
    struct Row {
        Tolerances t;
        double L;
        int boxes;
        Outcome o;
    };
    std::vector<Row> rows;
    for (Tolerances t : {Tolerances::defaults, Tolerances::lengths, Tolerances::similar})
        for (double L : sizes) {
            const int boxes = boxes_for(L);
            const Outcome o = run_stack(t, L, boxes);
            rows.push_back({t, L, boxes, o});
            stack_table["rows"].push_back(
                {fmt(L, 3), name_of(t), boxes, cell(o, o.sag), cell(o, o.overlap), status(o)});
        }
    rep.tables.push_back(stack_table);

    // The guarantee the user guide states, 1: the similar scene (lengths by L, times by sqrt(L))
    // holds at every size from 1e-12 to 1e12 m: accepted, finite, and its overlap and sag / L
    // those of the 1 m scene of as many boxes (the dynamics are the same in units of L: only
    // rounding differs, bound 1e-6 of the side).
    {
        bool ok = true;
        std::string details;
        double worst = 0.0;
        for (const Row& r : rows) {
            if (r.t != Tolerances::similar)
                continue;
            const Outcome one = run_stack(Tolerances::similar, 1.0, r.boxes);
            if (!held(r.o) || !held(one)) {
                ok = false;
                details += fmt(r.L) + " m: " + status(r.o) + "; ";
                continue;
            }
            worst =
                std::max({worst, std::abs(r.o.overlap - one.overlap), std::abs(r.o.sag - one.sag)});
        }
        ok = ok && worst <= 1e-6;
        rep.check("similar scenes hold from 1e-12 to 1e12 m", {reliability}, ok,
                  "geometry: the scene in units of L is the 1 m scene of as many boxes, so its "
                  "overlap and sag / L are that scene's",
                  details + "largest difference from the 1 m scene's overlap or sag / side: " +
                      fmt(worst) + " (bound 1e-6)");
    }
    // 2: at the default settings, boxes of 1 m to 1e12 m rest with an overlap under 1e-2 of their
    // side (the soft contact's overlap is about g / (2 pi contact_hertz)^2 in metres, whatever
    // the size: below 1 m it grows against the side, and at 1e-3 m the stack collapses).
    {
        bool ok = true;
        std::string details;
        for (const Row& r : rows) {
            if (r.t != Tolerances::defaults || r.L < 1.0)
                continue;
            ok = ok && held(r.o) && r.o.overlap < 1e-2 && std::abs(r.o.sag) < 1e-2 * 5;
            details += fmt(r.L) + " m: overlap/side " + fmt(r.o.overlap) + ", sag/side " +
                       fmt(r.o.sag) + " (" + status(r.o) + "); ";
        }
        rep.check("default settings hold stacks of 1 m to 1e12 m boxes", {reliability}, ok,
                  "geometry: boxes at rest do not overlap; bound 1e-2 of the side per contact, "
                  "5e-2 for the top of 5 boxes",
                  details);
    }

    // --- mass ratios ---
    json ratio_table = {{"name", "Mass ratios (1 m boxes and links, default settings, 2 s)"},
                        {"columns",
                         {"mass ratio", "heavy on light: deepest overlap / height",
                          "heavy on light: heavy box sag / height",
                          "heavy on light: light box shift sideways / height",
                          "alternating chain: largest joint drift / link length", "outcome"}},
                        {"rows", json::array()}};
    std::vector<std::pair<Outcome, Outcome>> by_ratio;
    for (double r : ratios) {
        const Outcome stack = run_heavy_on_light(r);
        const Outcome chain = run_chain(r);
        by_ratio.emplace_back(stack, chain);
        ratio_table["rows"].push_back({fmt(r, 3), cell(stack, stack.overlap),
                                       cell(stack, stack.sag), cell(stack, stack.shift),
                                       cell(chain, chain.drift),
                                       status(stack) + " / " + status(chain)});
    }
    rep.tables.push_back(ratio_table);
    // 3: mass ratios up to 10 at the default settings: a heavy box on a light one overlaps by
    // under 1e-2 of its height and stays on it (its sag under 1e-2: without friction, at 1e2 the
    // light box is squeezed out sideways), and the swinging chain's joints stay together within
    // 5e-2 of a link.
    {
        bool ok = true;
        std::string details;
        for (std::size_t i = 0; i < ratios.size(); ++i) {
            if (ratios[i] > 10.0)
                continue;
            const auto& [stack, chain] = by_ratio[i];
            ok = ok && held(stack) && held(chain) && stack.overlap < 1e-2 &&
                 std::abs(stack.sag) < 1e-2 && chain.drift < 5e-2;
            details += "ratio " + fmt(ratios[i]) + ": overlap/height " + fmt(stack.overlap) +
                       ", sag/height " + fmt(stack.sag) + ", drift/link " + fmt(chain.drift) + "; ";
        }
        rep.check("mass ratios up to 10 hold at the default settings", {reliability}, ok,
                  "geometry: resting boxes do not overlap, a revolute joint's anchors coincide; "
                  "bounds 1e-2 of the height (overlap, sag), 5e-2 of the link length (drift)",
                  details);
    }
    // 4: every run of the tables ends accepted and finite or refused with an error: never a
    // non-finite state after an accepted step.
    {
        bool ok = true;
        for (const Row& r : rows)
            ok = ok && r.o.finite;
        for (const auto& [stack, chain] : by_ratio)
            ok = ok && stack.finite && chain.finite;
        rep.check("no run leaves a non-finite state after an accepted step", {reliability}, ok,
                  "DCX_finite's promise: a step either refuses or leaves finite states",
                  ok ? "every run finite or refused" : "a run went non-finite (tables)");
    }
    return rep.write(argv[1], "scale_table",
                     "Overlap, sag and joint drift against box size (1e-12 to 1e12 m) and mass "
                     "ratio (1 to 1e6): docs/user-guide.md, \"Scales and mass ratios\"");
}
