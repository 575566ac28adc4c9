// tamias_work_precision: work-precision diagrams. Each engine (Tamias2D, Box2D v3's SSE2 and AVX2
// builds when built, Box2D 2.4, Chipmunk 7) is swept over its own cost knob, substeps or
// iterations, on the benchmark's scenes (bench_scenes.hpp, bench_joint_scenes.hpp); each setting
// is a point, x its time per step, y an error defined outside every engine, from the poses the
// engine reports: the pyramids' top box against its built pose, the rain's deepest penetration
// between boxes and the boxes it lost, the joint scenes' anchor separation and energy drift.
// Speed is then compared at equal accuracy: for each point of v3's AVX2 build, Tamias2D's
// cheapest point at least as accurate. Method and the errors' definitions: docs/performance.md,
// "Work-precision diagrams". Data for a question, not a gate: no check judges speed.
//
//   tamias_work_precision [<out_dir>] [--quick] [--scenes a,b] [--engines a,b] [--reps N]
//                         [--settings 1,2,4] [--steps N] [--budget-seconds S]
//
// Scenes: pyramid40 large_pyramid rain joint_grid chain; engines: tamias chipmunk box2d v3_sse2
// v3_avx2 (v3: both). --settings replaces the swept counts (1,2,3,4,6,8; --quick: 1,2,4,8); each
// engine's default joins the sweep when the list leaves it out. --quick also shortens the runs
// and takes 3 repetitions instead of 5; --steps sets every scene's run length. Writes
// <out_dir>/work_precision.json.
//
// Measuring (as tamias_bench's transient scenes): each point is a fresh build, timed over its
// whole run in thread CPU time (the build untimed); the repetitions alternate the engines, the
// settings of one count together, in an order that rotates, and the time is the median over
// repetitions. Errors that need every step (the rain, the joint scenes) come from one more run,
// untimed, sampled after every step; the pyramids' from the end of the timed runs.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

#include "bench_engines.hpp"
#include "bench_joint_scenes.hpp"
#include "bench_report.hpp"
#include "bench_scenes.hpp"
#include "box_penetration.hpp"
#include "joint_drift.hpp"
#include "pareto_frontier.hpp"
#include "rain_exits.hpp"
#include "remote_engine.hpp"
#include "scene_energy.hpp"
#include "verification_report.hpp"

namespace {

using namespace tamias_bench;
using json = nlohmann::ordered_json;
using Clock = std::chrono::steady_clock;
using tamias2d::evidence::fmt;

// ------------------------------------------------------------------------------- scenes
struct SceneSpec {
    std::string name;
    std::function<SceneDesc()> make;
    int steps = 0;       ///< steps per run
    int quick_steps = 0; ///< the same with --quick
};

std::vector<SceneSpec> all_scenes() {
    return {
        {"pyramid40", [] { return make_pyramid("pyramid40", 40); }, 600, 120},
        {"large_pyramid", [] { return make_pyramid("large_pyramid", 100); }, 300, 90},
        {"rain", [] { return make_rain("rain", 2000); }, 1000, 240},
        {"joint_grid", [] { return make_joint_grid("joint_grid", 100); }, 500, 30},
        {"chain", [] { return make_chain("chain", 100); }, 600, 600},
    };
}

// ----------------------------------------------------------------------------- settings
/// One point of an engine's sweep: the count swept and the knobs it sets.
struct Setting {
    EngineId engine = EngineId::tamias;
    int count = 0;
    SolverKnobs knobs;
    bool is_default = false; ///< the benchmark's setting (bench_engines.hpp)
    std::string text() const {
        switch (engine) {
        case EngineId::tamias:
        case EngineId::box2d_v3_sse2:
        case EngineId::box2d_v3_avx2:
            return std::to_string(knobs.substeps) + " substeps";
        case EngineId::chipmunk:
            return std::to_string(knobs.iterations) + " iterations";
        case EngineId::box2d:
            return std::to_string(knobs.iterations) + " velocity / " +
                   std::to_string(knobs.position_iterations) + " position iterations";
        }
        return "?";
    }
};

/// The benchmark's count of each engine (bench_engines.hpp): 4 substeps, Chipmunk's 10
/// iterations, Box2D 2.4's 8 velocity iterations (with 3 position iterations).
int default_count(EngineId e) {
    return e == EngineId::chipmunk ? 10 : e == EngineId::box2d ? 8 : 4;
}

/// Box2D 2.4 is swept over its velocity iterations with as many position iterations up to its
/// default 3, so that its sweep passes through its default (8, 3).
Setting setting(EngineId e, int count) {
    Setting s{e, count, {}, count == default_count(e)};
    switch (e) {
    case EngineId::tamias:
    case EngineId::box2d_v3_sse2:
    case EngineId::box2d_v3_avx2:
        s.knobs.substeps = count;
        break;
    case EngineId::chipmunk:
        s.knobs.iterations = count;
        break;
    case EngineId::box2d:
        s.knobs.iterations = count;
        s.knobs.position_iterations = std::min(count, 3);
        break;
    }
    return s;
}

/// The sweep in groups that alternate: the settings of one count, then each engine's default
/// when `counts` leaves it out.
std::vector<std::vector<Setting>> sweep(const std::vector<int>& counts,
                                        const std::vector<EngineId>& engines) {
    std::vector<std::vector<Setting>> groups;
    for (const int c : counts) {
        groups.emplace_back();
        for (const EngineId e : engines)
            groups.back().push_back(setting(e, c));
    }
    std::vector<Setting> defaults;
    for (const EngineId e : engines) {
        if (std::find(counts.begin(), counts.end(), default_count(e)) == counts.end())
            defaults.push_back(setting(e, default_count(e)));
    }
    if (!defaults.empty())
        groups.push_back(defaults);
    return groups;
}

// ------------------------------------------------------------------------------- errors
/// What one run of a point leaves: its errors (NaN where the scene has no such measure).
struct Errors {
    // Pyramids: the top box against its built pose, at the end of the run.
    double top_displacement = NAN; ///< m, |p - p_built|
    double sag = NAN;              ///< m, y_built - y (positive: lower)
    double drift = NAN;            ///< m, |x - x_built|
    // The rain, sampled after every step.
    double penetration = NAN; ///< m, the deepest overlap of two boxes (box_penetration.hpp)
    int penetration_step = 0;
    double penetration_end = NAN; ///< m, the same after the last step
    std::optional<RainExits> exits;
    // The joint scenes, sampled after every step.
    std::optional<JointDrift> joints;
    double energy_drift = NAN; ///< m: max |E - E_0| over the run, over the scene's weight
    int energy_step = 0;
    double energy_end = NAN; ///< m: (E - E_0) / weight after the last step (negative: lost)
    int nonfinite = 0;       ///< dynamic bodies with a NaN or infinite state after the last step
};

/// One plotted error measure of a scene kind.
struct Measure {
    std::string name;   ///< for tables and plots, with its unit
    std::string column; ///< the short form, for the plot's axis
    std::function<double(const Errors&)> of;
};

std::vector<Measure> measures(SceneKind k) {
    switch (k) {
    case SceneKind::pyramid:
        return {{"top box displacement from its built pose at the end (m)",
                 "top box displacement (m)", [](const Errors& e) { return e.top_displacement; }}};
    case SceneKind::rain:
        return {{"deepest penetration between two boxes over the run (m)",
                 "deepest penetration (m)", [](const Errors& e) { return e.penetration; }},
                {"deepest penetration between two boxes after the last step (m)",
                 "deepest penetration at the end (m)",
                 [](const Errors& e) { return e.penetration_end; }}};
    case SceneKind::joints:
        return {{"largest anchor separation over the run (m)", "largest anchor separation (m)",
                 [](const Errors& e) { return e.joints ? e.joints->max : NAN; }},
                {"energy drift: largest |E - E0| over the run / total weight (m)",
                 "energy drift (m)", [](const Errors& e) { return e.energy_drift; }}};
    case SceneKind::elastic:
        break;
    }
    return {};
}

std::vector<Probe> states(const SceneDesc& s, const Engine& e) {
    std::vector<Probe> out(s.bodies.size());
    for (std::size_t i = 0; i < s.bodies.size(); ++i)
        out[i] = e.probe(int(i));
    return out;
}

int count_nonfinite(const SceneDesc& s, const std::vector<Probe>& st) {
    int n = 0;
    for (std::size_t i = 0; i < s.bodies.size(); ++i)
        n += s.bodies[i].dynamic && !(finite(st[i]) && std::isfinite(st[i].angle)) ? 1 : 0;
    return n;
}

/// The pyramid's top box against its built pose, from the states after the run.
void top_box(const SceneDesc& s, const std::vector<Probe>& st, Errors& e) {
    const int top = s.tops.front();
    const V2 built = s.bodies[std::size_t(top)].position;
    const Probe& p = st[std::size_t(top)];
    e.sag = built.y - p.p.y;
    e.drift = std::abs(p.p.x - built.x);
    e.top_displacement = std::hypot(p.p.x - built.x, p.p.y - built.y);
    if (!std::isfinite(e.top_displacement))
        e.top_displacement = e.sag = e.drift = INFINITY;
}

/// The untimed run of a point whose errors need every step: the rain's and the joint scenes'.
Errors sampled_run(const SceneDesc& s, Engine& engine, int steps) {
    Errors e;
    if (s.kind == SceneKind::rain) {
        RainExitWatch exits(s);
        e.penetration = 0.0;
        for (int i = 1; i <= steps; ++i) {
            engine.step();
            exits.observe(s, engine);
            const double d = deepest_penetration(s, states(s, engine));
            if (!(d <= e.penetration)) {
                e.penetration = d;
                e.penetration_step = i;
            }
            e.penetration_end = d;
        }
        e.exits = exits.exits();
    } else if (s.kind == SceneKind::joints) {
        JointDriftWatch drift(s, steps);
        const double e0 = initial_energy(s), weight = total_weight(s);
        e.energy_drift = 0.0;
        for (int i = 1; i <= steps; ++i) {
            engine.step();
            drift.observe(s, engine);
            const double de = (mechanical_energy(s, states(s, engine)) - e0) / weight;
            if (!(std::abs(de) <= e.energy_drift)) {
                e.energy_drift = std::isfinite(de) ? std::abs(de) : INFINITY;
                e.energy_step = i;
            }
            e.energy_end = de;
        }
        e.joints = drift.outcome(s);
    }
    e.nonfinite = count_nonfinite(s, states(s, engine));
    return e;
}

// ---------------------------------------------------------------------------- measuring
struct Point {
    Setting setting;
    std::vector<double> cpu, wall; ///< ms/step, one per timed repetition
    Errors errors;
    int nonfinite = 0;  ///< the most NaN or infinite bodies after any run of the point
    std::string failed; ///< non-empty: an exception or the budget stopped it
    double cost() const { return failed.empty() ? median(cpu) : NAN; }
};

struct Options {
    std::string out_dir = ".";
    std::vector<std::string> scenes;
    std::vector<EngineId> engines{EngineId::tamias, EngineId::box2d_v3_sse2,
                                  EngineId::box2d_v3_avx2, EngineId::box2d, EngineId::chipmunk};
    std::vector<int> counts; ///< empty: 1, 2, 3, 4, 6, 8, or 1, 2, 4, 8 with --quick
    int steps = 0;           ///< > 0: every scene's steps per run instead of its own
    int reps = 0;            ///< 0: 5, or 3 with --quick
    bool quick = false;
    double budget_seconds = 0.0; ///< CPU seconds per run; 0: 300, or 60 with --quick
};

std::unique_ptr<Engine> build(const Setting& s, const SceneDesc& scene) {
    return is_remote(s.engine) ? make_remote_engine(s.engine, scene, 1, s.knobs.substeps)
                               : make_engine(s.engine, scene, s.knobs);
}

template <class T> std::vector<T> rotated(const std::vector<T>& v, std::size_t k) {
    std::vector<T> out(v.size());
    for (std::size_t i = 0; i < v.size(); ++i)
        out[i] = v[(i + k) % v.size()];
    return out;
}

struct SceneResult {
    std::string name;
    SceneKind kind = SceneKind::pyramid;
    int dynamic_bodies = 0, steps = 0;
    std::vector<Point> points; ///< by group, then engine (Options::engines' order)
};

SceneResult run_scene(const SceneSpec& spec, const Options& opt) {
    const SceneDesc scene = spec.make();
    const int steps = opt.steps > 0 ? opt.steps : opt.quick ? spec.quick_steps : spec.steps;
    const double budget_ms = 1000.0 * opt.budget_seconds;
    SceneResult res{spec.name, scene.kind, scene.dynamic_count, steps, {}};
    const std::vector<std::vector<Setting>> groups = sweep(opt.counts, opt.engines);
    std::vector<std::vector<std::size_t>> index(groups.size()); // group -> points
    for (std::size_t g = 0; g < groups.size(); ++g) {
        for (const Setting& s : groups[g]) {
            index[g].push_back(res.points.size());
            res.points.push_back({s, {}, {}, {}, 0, {}});
        }
    }
    if (scene.kind == SceneKind::rain || scene.kind == SceneKind::joints) {
        for (std::size_t g = 0; g < groups.size(); ++g) {
            for (const std::size_t k : rotated(index[g], g)) {
                Point& p = res.points[k];
                try {
                    const std::unique_ptr<Engine> e = build(p.setting, scene);
                    p.errors = sampled_run(scene, *e, steps);
                    p.nonfinite = p.errors.nonfinite;
                } catch (const std::exception& ex) {
                    p.failed = std::string("failed: ") + ex.what();
                }
            }
        }
    }
    constexpr int chunk = 10; // the budget is checked between chunks, untimed
    for (int rep = 0; rep < opt.reps; ++rep) {
        for (std::size_t g = 0; g < groups.size(); ++g) {
            for (const std::size_t k : rotated(index[g], std::size_t(rep) + g)) {
                Point& p = res.points[k];
                if (!p.failed.empty())
                    continue;
                try {
                    const std::unique_ptr<Engine> e = build(p.setting, scene);
                    StepTimes t;
                    int done = 0;
                    while (done < steps && t.cpu <= budget_ms) {
                        const int n = std::min(chunk, steps - done);
                        t += e->timed_steps(n);
                        done += n;
                    }
                    if (done < steps) {
                        p.failed = "over the " + fmt(opt.budget_seconds) +
                                   " s CPU budget: " + std::to_string(done) + " of " +
                                   std::to_string(steps) + " steps took " + fmt(t.cpu / 1000.0) +
                                   " s";
                        continue;
                    }
                    p.cpu.push_back(t.cpu / steps);
                    p.wall.push_back(t.wall / steps);
                    const std::vector<Probe> st = states(scene, *e);
                    p.nonfinite = std::max(p.nonfinite, count_nonfinite(scene, st));
                    if (scene.kind == SceneKind::pyramid) {
                        top_box(scene, st, p.errors);
                        p.errors.nonfinite = p.nonfinite;
                    }
                } catch (const std::exception& ex) {
                    p.failed = std::string("failed: ") + ex.what();
                }
            }
        }
    }
    return res;
}

// ------------------------------------------------------------------------------- report
std::vector<WorkPoint> work_points(const std::vector<const Point*>& pts, const Measure& m) {
    std::vector<WorkPoint> out;
    for (const Point* p : pts)
        out.push_back({p->cost(), p->nonfinite > 0 ? NAN : m.of(p->errors)});
    return out;
}

std::vector<const Point*> of_engine(const SceneResult& r, EngineId e) {
    std::vector<const Point*> out;
    for (const Point& p : r.points) {
        if (p.setting.engine == e)
            out.push_back(&p);
    }
    std::sort(out.begin(), out.end(),
              [](const Point* a, const Point* b) { return a->setting.count < b->setting.count; });
    return out;
}

/// Whether each of the engine's points is on its frontier for the measure.
std::vector<bool> on_frontier(const std::vector<const Point*>& pts, const Measure& m) {
    std::vector<bool> on(pts.size(), false);
    for (const std::size_t i : pareto_frontier(work_points(pts, m)))
        on[i] = true;
    return on;
}

std::string yes_no(bool b) {
    return b ? "yes" : "no";
}

json points_table(const SceneResult& r, const Options& opt) {
    const std::vector<Measure> ms = measures(r.kind);
    json columns = {"engine", "setting", "engine's default", "ms/step (median)",
                    "min",    "max",     "repetitions"};
    switch (r.kind) {
    case SceneKind::pyramid:
        for (const char* c : {"top box displacement (m)", "sag (m)", "drift (m)"})
            columns.push_back(c);
        break;
    case SceneKind::rain:
        for (const char* c : {"deepest penetration (m)", "at step", "at the end (m)", "boxes lost",
                              "through a wall or the floor", "over a wall"})
            columns.push_back(c);
        break;
    case SceneKind::joints:
        for (const char* c :
             {"largest anchor separation (m)", "at step", "outcome", "energy drift (m)",
              "energy drift at step", "energy change at the end (m)"})
            columns.push_back(c);
        break;
    case SceneKind::elastic:
        break;
    }
    columns.push_back("NaN bodies");
    for (const Measure& m : ms)
        columns.push_back("on the engine's frontier: " + m.column);
    columns.push_back("note");
    json rows = json::array();
    for (const EngineId id : opt.engines) {
        const std::vector<const Point*> pts = of_engine(r, id);
        std::vector<std::vector<bool>> front;
        for (const Measure& m : ms)
            front.push_back(on_frontier(pts, m));
        for (std::size_t i = 0; i < pts.size(); ++i) {
            const Point& p = *pts[i];
            const Errors& e = p.errors;
            double lo = NAN, hi = NAN;
            if (!p.cpu.empty()) {
                lo = *std::min_element(p.cpu.begin(), p.cpu.end());
                hi = *std::max_element(p.cpu.begin(), p.cpu.end());
            }
            json row = {std::string(engine_name(id)),
                        p.setting.text(),
                        yes_no(p.setting.is_default),
                        num(p.cost()),
                        num(lo),
                        num(hi),
                        int(p.cpu.size())};
            switch (r.kind) {
            case SceneKind::pyramid:
                row.push_back(num(e.top_displacement));
                row.push_back(num(e.sag));
                row.push_back(num(e.drift));
                break;
            case SceneKind::rain:
                row.push_back(num(e.penetration));
                row.push_back(e.penetration_step);
                row.push_back(num(e.penetration_end));
                row.push_back(e.exits ? json(e.exits->lost()) : json(nullptr));
                row.push_back(e.exits ? json(e.exits->through) : json(nullptr));
                row.push_back(e.exits ? json(e.exits->over) : json(nullptr));
                break;
            case SceneKind::joints:
                row.push_back(e.joints ? num(e.joints->max) : json(nullptr));
                row.push_back(e.joints ? json(e.joints->max_step) : json(nullptr));
                row.push_back(e.joints ? json(e.joints->outcome) : json(nullptr));
                row.push_back(num(e.energy_drift));
                row.push_back(e.energy_step);
                row.push_back(num(e.energy_end));
                break;
            case SceneKind::elastic:
                break;
            }
            row.push_back(p.nonfinite);
            for (const std::vector<bool>& f : front)
                row.push_back(yes_no(f[i]));
            row.push_back(p.failed);
            rows.push_back(row);
        }
    }
    return {{"name", "Points: " + r.name + " (" + std::to_string(r.dynamic_bodies) +
                         " dynamic bodies, " + std::to_string(r.steps) + " steps per run)"},
            {"columns", columns},
            {"rows", rows}};
}

/// Every point of the engine as markers (labelled with its count), and its frontier as a line of
/// the same colour without a legend entry.
json plot_lines(const SceneResult& r, const Measure& m, const Options& opt) {
    json lines = json::array();
    for (const EngineId id : opt.engines) {
        const std::vector<const Point*> pts = of_engine(r, id);
        const std::vector<WorkPoint> w = work_points(pts, m);
        json xs = json::array(), ys = json::array(), labels = json::array();
        for (std::size_t i = 0; i < pts.size(); ++i) {
            if (!w[i].valid())
                continue;
            xs.push_back(num(w[i].cost));
            ys.push_back(num(w[i].error));
            labels.push_back(std::to_string(pts[i]->setting.count));
        }
        if (xs.empty())
            continue;
        const std::string name(engine_name(id));
        lines.push_back({{"label", name},
                         {"x", xs},
                         {"y", ys},
                         {"style", "points"},
                         {"group", name},
                         {"point_labels", labels}});
        json fx = json::array(), fy = json::array();
        for (const std::size_t i : pareto_frontier(w)) {
            fx.push_back(num(w[i].cost));
            fy.push_back(num(w[i].error));
        }
        lines.push_back({{"label", ""}, {"x", fx}, {"y", fy}, {"style", "line"}, {"group", name}});
    }
    return lines;
}

/// For each point of v3's AVX2 build: Tamias2D's cheapest point at least as accurate, and the
/// time ratio; or, when none is, Tamias2D's most accurate point and how far it falls short.
struct Dominance {
    json rows = json::array();
    json summary; ///< one row for the scene and measure
};

Dominance dominance(const SceneResult& r, const Measure& m) {
    Dominance d;
    const std::vector<const Point*> v3 = of_engine(r, EngineId::box2d_v3_avx2);
    const std::vector<const Point*> ta = of_engine(r, EngineId::tamias);
    const std::vector<WorkPoint> wv = work_points(v3, m), wt = work_points(ta, m);
    const std::vector<bool> v3_front = on_frontier(v3, m);
    int frontier = 0, matched = 0, cheaper = 0;
    std::vector<double> factors;
    for (std::size_t i = 0; i < v3.size(); ++i) {
        if (!wv[i].valid())
            continue;
        json row = {r.name,          m.column,        v3[i]->setting.text(), yes_no(v3_front[i]),
                    num(wv[i].cost), num(wv[i].error)};
        const std::optional<std::size_t> at = cheapest_as_accurate(wt, wv[i].error);
        frontier += v3_front[i] ? 1 : 0;
        if (at) {
            const double factor = wv[i].cost / wt[*at].cost;
            row.insert(row.end(), {json(ta[*at]->setting.text()), num(wt[*at].cost),
                                   num(wt[*at].error), num(factor, 3), json(nullptr)});
            if (v3_front[i]) {
                ++matched;
                cheaper += factor >= 1.0 ? 1 : 0;
                factors.push_back(factor);
            }
        } else if (const std::optional<std::size_t> best = most_accurate(wt)) {
            row.insert(row.end(),
                       {json(ta[*best]->setting.text()), num(wt[*best].cost), num(wt[*best].error),
                        json(nullptr), num(wt[*best].error / wv[i].error, 3)});
        } else {
            row.insert(row.end(), {json("no valid point"), json(nullptr), json(nullptr),
                                   json(nullptr), json(nullptr)});
        }
        d.rows.push_back(row);
    }
    std::string verdict;
    if (frontier == 0)
        verdict = "no v3 AVX2 point";
    else if (matched == frontier && cheaper == frontier)
        verdict = "Tamias2D's frontier dominates";
    else if (matched == frontier)
        verdict = "as accurate everywhere, not cheaper everywhere";
    else
        verdict = "Tamias2D reaches " + std::to_string(matched) + " of " +
                  std::to_string(frontier) + " frontier points";
    // Where the two frontiers end: below 1, Tamias2D reaches an accuracy no v3 point does.
    const std::optional<std::size_t> best_t = most_accurate(wt), best_v = most_accurate(wv);
    d.summary = {r.name,
                 m.column,
                 frontier,
                 matched,
                 cheaper,
                 factors.empty() ? json(nullptr) : num(quantile(factors, 0.0), 3),
                 factors.empty() ? json(nullptr) : num(median(factors), 3),
                 factors.empty() ? json(nullptr) : num(quantile(factors, 1.0), 3),
                 best_t && best_v ? num(wt[*best_t].error / wv[*best_v].error, 3) : json(nullptr),
                 verdict};
    return d;
}

// ---------------------------------------------------------------------------------- main
[[noreturn]] void usage(const std::string& why) {
    std::cerr << "tamias_work_precision: " << why << "\n"
              << "usage: tamias_work_precision [<out_dir>] [--quick] [--scenes a,b]\n"
              << "           [--engines tamias,chipmunk,box2d,v3_sse2,v3_avx2] [--reps N]\n"
              << "           [--settings 1,2,3,4,6,8] [--steps N] [--budget-seconds S]\n";
    std::exit(2);
}

Options parse(int argc, char** argv) {
    Options o;
    bool have_dir = false;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        const auto value = [&]() -> std::string {
            if (i + 1 >= argc)
                usage("missing value after " + a);
            return argv[++i];
        };
        if (a == "--scenes") {
            o.scenes = split(value());
        } else if (a == "--reps") {
            o.reps = std::atoi(value().c_str());
            if (o.reps < 1)
                usage("--reps must be >= 1");
        } else if (a == "--quick") {
            o.quick = true;
        } else if (a == "--steps") {
            o.steps = std::atoi(value().c_str());
            if (o.steps < 1)
                usage("--steps must be >= 1");
        } else if (a == "--budget-seconds") {
            o.budget_seconds = std::atof(value().c_str());
            if (!(o.budget_seconds > 0.0))
                usage("--budget-seconds must be > 0");
        } else if (a == "--settings") {
            o.counts.clear();
            for (const std::string& c : split(value())) {
                const int n = std::atoi(c.c_str());
                if (n < 1 || n > 64)
                    usage("--settings: each count must be in [1, 64], not " + c);
                o.counts.push_back(n);
            }
            std::sort(o.counts.begin(), o.counts.end());
            o.counts.erase(std::unique(o.counts.begin(), o.counts.end()), o.counts.end());
            if (o.counts.empty())
                usage("--settings needs at least one count");
        } else if (a == "--engines") {
            o.engines.clear();
            const std::map<std::string, std::vector<EngineId>> names = {
                {"tamias", {EngineId::tamias}},
                {"chipmunk", {EngineId::chipmunk}},
                {"box2d", {EngineId::box2d}},
                {"v3_sse2", {EngineId::box2d_v3_sse2}},
                {"v3_avx2", {EngineId::box2d_v3_avx2}},
                {"v3", {EngineId::box2d_v3_sse2, EngineId::box2d_v3_avx2}}};
            for (const std::string& e : split(value())) {
                const auto it = names.find(e);
                if (it == names.end())
                    usage("unknown engine " + e);
                for (const EngineId id : it->second) {
                    if (std::find(o.engines.begin(), o.engines.end(), id) == o.engines.end())
                        o.engines.push_back(id);
                }
            }
        } else if (a == "-h" || a == "--help") {
            usage("help");
        } else if (!a.empty() && a[0] == '-') {
            usage("unknown option " + a);
        } else if (!have_dir) {
            o.out_dir = a;
            have_dir = true;
        } else {
            usage("more than one output directory");
        }
    }
    if (o.reps == 0)
        o.reps = o.quick ? 3 : 5;
    if (o.counts.empty())
        o.counts = o.quick ? std::vector<int>{1, 2, 4, 8} : std::vector<int>{1, 2, 3, 4, 6, 8};
    if (o.budget_seconds == 0.0)
        o.budget_seconds = o.quick ? 60.0 : 300.0;
    return o;
}

std::string counts_text(const std::vector<int>& counts) {
    std::string s;
    for (const int c : counts)
        s += (s.empty() ? "" : ", ") + std::to_string(c);
    return s;
}

} // namespace

int main(int argc, char** argv) {
    Options opt = parse(argc, argv);
    const std::vector<SceneSpec> specs = all_scenes();
    std::vector<const SceneSpec*> chosen;
    if (opt.scenes.empty()) {
        for (const SceneSpec& s : specs)
            chosen.push_back(&s);
    } else {
        for (const std::string& n : opt.scenes) {
            const auto it = std::find_if(specs.begin(), specs.end(),
                                         [&](const SceneSpec& s) { return s.name == n; });
            if (it == specs.end())
                usage("unknown scene " + n);
            chosen.push_back(&*it);
        }
    }
    // Box2D v3's builds run in worker processes, as in tamias_bench; one not built leaves the
    // sweep, and the set-up table says why.
    std::map<EngineId, std::string> not_measured;
    for (const EngineId id : {EngineId::box2d_v3_sse2, EngineId::box2d_v3_avx2}) {
        const auto it = std::find(opt.engines.begin(), opt.engines.end(), id);
        if (it == opt.engines.end()) {
            not_measured[id] = "not measured: not among --engines";
            continue;
        }
        std::string why = start_remote_engine(id);
        if (why.empty())
            continue;
        std::printf("%s %s\n", std::string(engine_name(id)).c_str(), why.c_str());
        opt.engines.erase(it);
        not_measured[id] = std::move(why);
    }
    const std::string load_before = load_average();
    const auto t_start = Clock::now();
    std::printf("tamias_work_precision: %zu scenes, counts %s, %d repetitions%s\n", chosen.size(),
                counts_text(opt.counts).c_str(), opt.reps, opt.quick ? ", quick" : "");
    std::vector<SceneResult> results;
    for (const SceneSpec* spec : chosen) {
        const auto t0 = Clock::now();
        SceneResult r = run_scene(*spec, opt);
        std::printf("\n%s: %d bodies, %d steps per run (%.0f s)\n", r.name.c_str(),
                    r.dynamic_bodies, r.steps,
                    std::chrono::duration<double>(Clock::now() - t0).count());
        const std::vector<Measure> ms = measures(r.kind);
        for (const EngineId id : opt.engines) {
            for (const Point* p : of_engine(r, id)) {
                std::printf("  %-13s %-38s %9.4f ms/step", std::string(engine_name(id)).c_str(),
                            p->setting.text().c_str(), p->cost());
                for (const Measure& m : ms)
                    std::printf("  %s %.4g", m.column.c_str(), m.of(p->errors));
                std::printf("%s%s\n", p->nonfinite ? "  NaN bodies" : "", p->failed.c_str());
            }
        }
        std::fflush(stdout);
        results.push_back(std::move(r));
    }
    stop_remote_engines();
    const double total_s = std::chrono::duration<double>(Clock::now() - t_start).count();
    const std::string load_after = load_average();

    // ------------------------------------------------------------------------- the report
    json checks = json::array();
    for (const SceneResult& r : results) {
        std::string bad;
        int n = 0;
        for (const Point& p : r.points) {
            ++n;
            if (p.failed.empty() && p.nonfinite == 0 && int(p.cpu.size()) == opt.reps)
                continue;
            bad += (bad.empty() ? "" : "; ") + std::string(engine_name(p.setting.engine)) + " " +
                   p.setting.text() + ": " +
                   (p.failed.empty() ? std::to_string(p.nonfinite) + " NaN bodies" : p.failed);
        }
        checks.push_back(tamias2d::evidence::check_entry<json>(
            r.name + ": every engine's every point completed without NaN", {"performance"},
            bad.empty(),
            "each engine's own run: every repetition finishes and every dynamic body's state is "
            "finite",
            bad.empty()
                ? std::to_string(n) + " points, each " + std::to_string(opt.reps) + " timed runs" +
                      (r.kind == SceneKind::pyramid ? "" : " and a sampled one")
                : bad));
    }

    json tables = json::array();
    json dom_rows = json::array(), dom_summary = json::array();
    const bool have_pair =
        std::find(opt.engines.begin(), opt.engines.end(), EngineId::tamias) != opt.engines.end() &&
        std::find(opt.engines.begin(), opt.engines.end(), EngineId::box2d_v3_avx2) !=
            opt.engines.end();
    for (const SceneResult& r : results) {
        if (!have_pair)
            break;
        for (const Measure& m : measures(r.kind)) {
            Dominance d = dominance(r, m);
            for (json& row : d.rows)
                dom_rows.push_back(std::move(row));
            dom_summary.push_back(std::move(d.summary));
        }
    }
    const std::string method =
        "thread CPU time per step over whole runs from a fresh build, median of " +
        std::to_string(opt.reps) +
        " repetitions, engines alternating in one process (Box2D v3: "
        "a worker process per build)";
    if (have_pair) {
        tables.push_back(
            {{"name", "Frontier dominance by scene: over Box2D v3 AVX2's frontier points, how "
                      "many Tamias2D matches in accuracy, how many of those at no more time, and "
                      "the time ratios v3 / Tamias2D (above 1: Tamias2D is faster at equal or "
                      "better accuracy); and the two engines' smallest errors (below 1: Tamias2D "
                      "reaches an accuracy no v3 AVX2 point does)"},
             {"columns",
              {"scene", "error", "v3 AVX2 frontier points", "Tamias2D as accurate",
               "of those at no more time", "time ratio min", "median", "max",
               "smallest error: Tamias2D / v3 AVX2", "reading"}},
             {"rows", dom_summary}});
        tables.push_back(
            {{"name", "Frontier dominance: for every Box2D v3 AVX2 point, the cheapest Tamias2D "
                      "point at least as accurate and the time ratio v3 / Tamias2D (above 1: "
                      "Tamias2D is faster); where none is as accurate, Tamias2D's most accurate "
                      "point and its error over v3's (the shortfall, above 1)"},
             {"columns",
              {"scene", "error", "v3 AVX2 setting", "on v3's frontier", "v3 ms/step", "v3 error",
               "Tamias2D setting", "Tamias2D ms/step", "Tamias2D error", "time ratio v3 / Tamias2D",
               "shortfall (Tamias2D error / v3 error)"}},
             {"rows", dom_rows}});
    } else {
        tables.push_back(
            {{"name", "Frontier dominance"},
             {"columns", {"note"}},
             {"rows", json::array({json::array({"not measured: needs Tamias2D and Box2D v3 AVX2 ("
                                                "v3 AVX2: " +
                                                (not_measured.count(EngineId::box2d_v3_avx2)
                                                     ? not_measured[EngineId::box2d_v3_avx2]
                                                     : std::string("not among --engines")) +
                                                ")"})})}});
    }
    for (const SceneResult& r : results)
        tables.push_back(points_table(r, opt));
    {
        // tamias_bench's description, whose substeps the sweep replaces.
        std::string v3_setup =
            "as tamias_bench, but for the substeps swept here: " + remote_engines_description();
        for (const auto& [id, why] : not_measured)
            v3_setup += "; " + std::string(engine_name(id)) + ": " + why;
        std::string lengths;
        for (const SceneResult& r : results)
            lengths += (lengths.empty() ? "" : ", ") + r.name + " " + std::to_string(r.steps);
        const std::vector<std::pair<std::string, std::string>> setup = {
            {"mode", opt.quick ? "quick (--quick)" : "full"},
            {"machine", cpu_model() + ", " + std::to_string(std::thread::hardware_concurrency()) +
                            " hardware threads (each engine runs on one)"},
            {"load average (1, 5, 15 min) before and after the run",
             load_before + "; " + load_after},
            {"time", method},
            {"steps per run (dt 1/60 s)", lengths},
            {"sweep",
             "counts " + counts_text(opt.counts) +
                 " and each engine's default: Tamias2D substeps (WorldDef::substeps; it has no "
                 "iteration count), Box2D v3 substeps (b2World_Step), Box2D 2.4 velocity "
                 "iterations with min(count, 3) position iterations, Chipmunk 7 iterations "
                 "(cpSpaceSetIterations); every other setting as tamias_bench's"},
            {"Box2D v3", v3_setup},
            {"errors", "docs/performance.md, \"Work-precision diagrams\": measured from the poses "
                       "each engine reports, the same code for all"},
            {"total wall time (s)", fmt(total_s, 4)}};
        json rows = json::array();
        for (const auto& [k, v] : setup)
            rows.push_back(json::array({k, v}));
        tables.push_back({{"name", "Set-up"}, {"columns", {"item", "value"}}, {"rows", rows}});
    }

    json series = json::array();
    for (const SceneResult& r : results) {
        for (const Measure& m : measures(r.kind)) {
            // Marks: every setting, labelled with its count; lines: each engine's frontier.
            series.push_back(
                log_log_series(r.name + ": " + m.column + " vs time (lines: frontiers)",
                               "ms per step (thread CPU time)", m.column, plot_lines(r, m, opt)));
        }
    }

    json raw = json::object();
    for (const SceneResult& r : results) {
        json pts = json::array();
        for (const Point& p : r.points) {
            pts.push_back({{"engine", engine_name(p.setting.engine)},
                           {"setting", p.setting.text()},
                           {"cpu_ms_per_step", p.cpu},
                           {"wall_ms_per_step", p.wall},
                           {"failed", p.failed}});
        }
        raw[r.name] = {{"steps", r.steps}, {"points", pts}};
    }

    const json doc = {
        {"program", "work_precision"},
        {"description",
         "Work-precision diagrams: Tamias2D, Box2D v3 (SSE2 and AVX2 builds, when built), Box2D "
         "2.4 and Chipmunk 7, each swept over its own substeps or iterations on identical scenes, "
         "time per step against an error measured the same way for every engine, and Tamias2D's "
         "cost at Box2D v3 AVX2's accuracy. Data, no verdict on speed. Method: "
         "docs/performance.md, \"Work-precision diagrams\"."},
        {"provenance", tamias2d::evidence::provenance()},
        {"checks", checks},
        {"tables", tables},
        {"series", series},
        {"raw", raw}};
    std::filesystem::create_directories(opt.out_dir);
    const std::filesystem::path out = std::filesystem::path(opt.out_dir) / "work_precision.json";
    std::ofstream(out) << doc.dump(2) << "\n";

    int failed = 0;
    std::printf("\nfrontier dominance by scene (v3 AVX2 frontier points; time ratio v3 / "
                "Tamias2D):\n");
    for (const json& row : dom_summary)
        std::printf("  %s\n", row.dump().c_str());
    std::printf("\nchecks:\n");
    for (const json& c : checks) {
        const bool ok = c["passed"].get<bool>();
        failed += ok ? 0 : 1;
        std::printf("  [%s] %s: %s\n", ok ? "pass" : "FAIL", c["name"].get<std::string>().c_str(),
                    c["details"].get<std::string>().c_str());
    }
    std::printf("\nload average before %s, after %s\nwrote %s (%.0f s)\n", load_before.c_str(),
                load_after.c_str(), out.c_str(), total_s);
    return failed == 0 ? 0 : 1;
}
