// Tamias2D's step on 1, 2, ... workers (WorldDef::workers, the World's own pool) beside Box2D v3's
// on as many (b2WorldDef::workerCount, v3's own scheduler): wall-clock ms/step on the benchmark's
// scenes (bench_scenes.hpp), and Tamias2D's final state hash for each worker count, which must be
// one and the same. The peer benchmark times one thread's CPU time; a step shared by threads is
// timed by the wall clock (std::chrono::steady_clock), beside Tamias2D's process CPU time per step
// (all threads: what the workers' waiting and spinning cost).
//
//   tamias_thread_bench [--scenes pyramid40,large_pyramid,rain,joint_grid,chain] [--threads 1,2]
//                       [--reps 7]
//                       [--engines tamias,v3_sse2,v3_avx2] [--v3-recycle-distance D]
//                       [--manifold-reuse D] [--contact-regions 1,2]
//
// Box2D v3 runs in its engine workers (remote_engine.hpp), one process per build and worker
// count, which time their steps themselves; `v3` names both builds, and a build that was not made
// (TAMIAS_BOX2D_V3_DIR unset, no AVX2) is reported and left out. Steady scenes (the pyramids) are
// built once per engine and worker count, stepped 10 times untimed, then timed in blocks that
// alternate between all of them, repetition by repetition; the rain is rebuilt for every
// repetition and timed over its whole run (1000 steps), alternating the same way. The figure is
// the median over the repetitions. --v3-recycle-distance sets v3's contact recycling distance
// (m; 0: off; b2World_SetContactRecycleDistance) in place of its default (0.05 m), to measure
// what that reuse of manifolds gives it (docs/performance.md, "Against Box2D v3");
// --manifold-reuse sets Tamias2D's WorldDef::manifold_reuse_distance (m; 0: off) likewise.
// --contact-regions lists the WorldDef::contact_regions Tamias2D runs with (default 1,2), each on
// every worker count: its hashes must agree across worker counts for one setting, its speed-up is
// against the same setting on the first worker count, and its time over v3's on n workers is
// taken with n regions where that setting is listed (the user guide's advice), else with the
// first listed.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <functional>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "bench/bench_engines.hpp"
#include "bench/bench_joint_scenes.hpp"
#include "bench/bench_report.hpp"
#include "bench/bench_scenes.hpp"
#include "bench/remote_engine.hpp"

using namespace tamias_bench;

namespace {

struct Scene {
    std::string name;
    std::function<SceneDesc()> make;
    bool steady;
    int steps; ///< per timed block (steady) or per run (transient)
};

const std::vector<Scene> scenes = {
    {"pyramid20", [] { return make_pyramid("pyramid20", 20); }, true, 100},
    {"pyramid40", [] { return make_pyramid("pyramid40", 40); }, true, 100},
    {"large_pyramid", [] { return make_pyramid("large_pyramid", 100); }, true, 40},
    {"rain", [] { return make_rain("rain", 2000); }, false, 1000},
    // The peer benchmark's joint scenes (bench_joint_scenes.hpp), over as many steps.
    {"joint_grid", [] { return make_joint_grid("joint_grid", 100); }, false, 500},
    {"chain", [] { return make_chain("chain", 100); }, false, 600},
};

double process_cpu_ms() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

struct Times {
    std::vector<double> wall, cpu; ///< ms/step per repetition
};

/// Steps n times; returns {wall, process CPU} ms per step. The engine times the wall itself
/// (in its worker for v3); the process's CPU time is this process's, so only Tamias2D's counts.
std::pair<double, double> timed(Engine& e, int n) {
    const double c0 = process_cpu_ms();
    const StepTimes t = e.timed_steps(n);
    const double c1 = process_cpu_ms();
    return {t.wall / n, (c1 - c0) / n};
}

/// One engine on one worker count.
struct Run {
    EngineId engine;
    int threads;
    double manifold_reuse; ///< Tamias2D's, -1: the default
    int regions;           ///< Tamias2D's WorldDef::contact_regions (0 for v3)
    std::unique_ptr<Engine> make(const SceneDesc& d) const {
        return engine == EngineId::tamias ? make_tamias_engine(d, threads, manifold_reuse, regions)
                                          : make_remote_engine(engine, d, threads);
    }
};

[[noreturn]] void usage() {
    std::fprintf(stderr, "usage: tamias_thread_bench [--scenes a,b] [--threads 1,2] [--reps N] "
                         "[--engines tamias,v3_sse2,v3_avx2] [--v3-recycle-distance D] "
                         "[--manifold-reuse D] [--contact-regions 1,2]\n");
    std::exit(2);
}

} // namespace

int main(int argc, char** argv) {
    std::vector<std::string> names = {"pyramid40", "large_pyramid", "rain", "joint_grid", "chain"};
    std::vector<int> threads = {1, 2};
    std::vector<std::string> engine_names = {"tamias"};
    int reps = 7;
    double manifold_reuse = -1.0; // the default
    std::vector<int> regions = {1, 2};
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (i + 1 >= argc)
            usage();
        const std::string v = argv[++i];
        if (a == "--scenes") {
            names = split(v);
        } else if (a == "--threads") {
            threads.clear();
            for (const std::string& t : split(v))
                threads.push_back(std::atoi(t.c_str()));
        } else if (a == "--reps") {
            reps = std::atoi(v.c_str());
        } else if (a == "--engines") {
            engine_names = split(v);
        } else if (a == "--manifold-reuse") {
            manifold_reuse = std::atof(v.c_str());
        } else if (a == "--contact-regions") {
            regions.clear();
            for (const std::string& r : split(v))
                regions.push_back(std::atoi(r.c_str()));
        } else if (a == "--v3-recycle-distance") {
            set_remote_engine_arguments({"--recycle-distance", v});
        } else {
            usage();
        }
    }
    if (reps < 1 || threads.empty() || regions.empty() ||
        std::any_of(threads.begin(), threads.end(), [](int t) { return t < 1; }) ||
        std::any_of(regions.begin(), regions.end(), [](int r) { return r < 1 || r > 8; }))
        usage();
    std::vector<EngineId> engines;
    for (const std::string& e : engine_names) {
        if (e == "tamias") {
            engines.push_back(EngineId::tamias);
        } else if (e == "v3" || e == "v3_sse2" || e == "v3_avx2") {
            for (const EngineId id : {EngineId::box2d_v3_sse2, EngineId::box2d_v3_avx2}) {
                if (e != "v3" && e != (id == EngineId::box2d_v3_sse2 ? "v3_sse2" : "v3_avx2"))
                    continue;
                std::string why;
                for (const int t : threads)
                    if (why.empty())
                        why = start_remote_engine(id, t);
                if (why.empty())
                    engines.push_back(id);
                else
                    std::printf("%s: %s\n", std::string(engine_name(id)).c_str(), why.c_str());
            }
        } else {
            usage();
        }
    }
    std::vector<Run> runs;
    for (const EngineId e : engines) {
        for (const int r : e == EngineId::tamias ? regions : std::vector<int>{0})
            for (const int t : threads)
                runs.push_back({e, t, manifold_reuse, r});
    }
    std::printf("%-14s %-14s %7s %7s %12s %19s %12s %9s %12s %18s\n", "scene", "engine", "regions",
                "workers", "wall ms/step", "wall range", "cpu ms/step", "speed-up", "Tamias2D/it",
                "state hash");
    for (const std::string& name : names) {
        const auto it = std::find_if(scenes.begin(), scenes.end(),
                                     [&](const Scene& s) { return s.name == name; });
        if (it == scenes.end()) {
            std::fprintf(stderr, "unknown scene %s\n", name.c_str());
            return 2;
        }
        const SceneDesc desc = it->make();
        const std::size_t n = runs.size();
        std::vector<Times> times(n);
        std::vector<std::uint64_t> hashes(n);
        std::vector<std::unique_ptr<Engine>> live(n);
        if (it->steady) {
            for (std::size_t k = 0; k < n; ++k) {
                live[k] = runs[k].make(desc);
                for (int i = 0; i < 10; ++i)
                    live[k]->step();
            }
        }
        for (int r = 0; r < reps; ++r) {
            for (std::size_t j = 0; j < n; ++j) {
                const std::size_t k = (j + std::size_t(r)) % n; // the order rotates
                if (!it->steady)
                    live[k] = runs[k].make(desc);
                const auto [wall, cpu] = timed(*live[k], it->steps);
                times[k].wall.push_back(wall);
                times[k].cpu.push_back(cpu);
                hashes[k] = live[k]->state_hash();
                if (!it->steady)
                    live[k].reset();
            }
        }
        live.clear();
        // Speed-up: against the same engine and regions on the first worker count; Tamias2D/it:
        // Tamias2D's time over this engine's on the same worker count (above 1: Tamias2D is
        // slower), with as many regions as workers where that setting ran, else the first.
        const auto wall_of = [&](EngineId e, int r, int t) {
            for (std::size_t k = 0; k < n; ++k)
                if (runs[k].engine == e && runs[k].regions == r && runs[k].threads == t)
                    return median(times[k].wall);
            return 0.0;
        };
        const auto ours_on = [&](int t) {
            const bool listed = std::find(regions.begin(), regions.end(), t) != regions.end();
            return wall_of(EngineId::tamias, listed ? t : regions[0], t);
        };
        std::uint64_t first_hash = 0;
        for (std::size_t k = 0; k < n; ++k) {
            const Run& run = runs[k];
            const bool own = run.engine == EngineId::tamias;
            if (own && run.threads == threads[0])
                first_hash = hashes[k];
            const double w = median(times[k].wall);
            const double ours = ours_on(run.threads);
            char cpu[32] = "-", ratio[32] = "-", hash[40] = "-";
            if (own) {
                std::snprintf(cpu, sizeof cpu, "%.4f", median(times[k].cpu));
                std::snprintf(hash, sizeof hash, "%018llx%s", (unsigned long long)hashes[k],
                              hashes[k] == first_hash ? "" : "  DIFFERS");
            } else if (ours > 0.0) {
                std::snprintf(ratio, sizeof ratio, "%.3f", ours / w);
            }
            char regions_text[16] = "-";
            if (own)
                std::snprintf(regions_text, sizeof regions_text, "%d", run.regions);
            // The spread of the repetitions, beside their median: the machine's noise.
            const auto [lo, hi] = std::minmax_element(times[k].wall.begin(), times[k].wall.end());
            char range[40];
            std::snprintf(range, sizeof range, "%.4f-%.4f", *lo, *hi);
            std::printf("%-14s %-14s %7s %7d %12.4f %19s %12s %8.3fx %12s %18s\n", name.c_str(),
                        std::string(engine_name(run.engine)).c_str(), regions_text, run.threads, w,
                        range, cpu, wall_of(run.engine, run.regions, threads[0]) / w, ratio, hash);
        }
        std::fflush(stdout);
    }
    stop_remote_engines();
}
