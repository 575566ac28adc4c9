// Tamias2D's step on 1, 2, ... workers (WorldDef::workers, the World's own pool): wall-clock
// ms/step on the benchmark's scenes (bench_scenes.hpp), and the final state hash of each worker
// count, which must be one and the same. The peer benchmark times one thread's CPU time; a step
// shared by threads is timed by the wall clock (std::chrono::steady_clock), beside the process's
// CPU time per step (all threads: what the workers' waiting and spinning cost).
//
//   tamias_thread_bench [--scenes pyramid40,large_pyramid,rain] [--threads 1,2] [--reps 7]
//
// Steady scenes (the pyramids) are built once per worker count, stepped 10 times untimed, then
// timed in blocks that alternate between the worker counts, repetition by repetition; the rain is
// rebuilt for every repetition and timed over its whole run (1000 steps), the worker counts
// alternating. The figure is the median over the repetitions.
#include <algorithm>
#include <chrono>
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
#include "bench/bench_scenes.hpp"

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
};

double wall_ms() {
    return std::chrono::duration<double, std::milli>(
               std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

double process_cpu_ms() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

struct Times {
    std::vector<double> wall, cpu; ///< ms/step per repetition
};

/// Steps n times; returns {wall, process CPU} ms per step.
std::pair<double, double> timed(Engine& e, int n) {
    const double c0 = process_cpu_ms(), w0 = wall_ms();
    for (int i = 0; i < n; ++i)
        e.step();
    const double w1 = wall_ms(), c1 = process_cpu_ms();
    return {(w1 - w0) / n, (c1 - c0) / n};
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

std::vector<std::string> split(const std::string& s) {
    std::vector<std::string> out;
    std::stringstream ss(s);
    for (std::string item; std::getline(ss, item, ',');)
        if (!item.empty())
            out.push_back(item);
    return out;
}

[[noreturn]] void usage() {
    std::fprintf(stderr, "usage: tamias_thread_bench [--scenes a,b] [--threads 1,2] [--reps N]\n");
    std::exit(2);
}

} // namespace

int main(int argc, char** argv) {
    std::vector<std::string> names = {"pyramid40", "large_pyramid", "rain"};
    std::vector<int> threads = {1, 2};
    int reps = 7;
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
        } else {
            usage();
        }
    }
    if (reps < 1 || threads.empty())
        usage();
    std::printf("%-14s %7s %12s %12s %9s %18s\n", "scene", "workers", "wall ms/step", "cpu ms/step",
                "speed-up", "state hash");
    for (const std::string& name : names) {
        const auto it = std::find_if(scenes.begin(), scenes.end(),
                                     [&](const Scene& s) { return s.name == name; });
        if (it == scenes.end()) {
            std::fprintf(stderr, "unknown scene %s\n", name.c_str());
            return 2;
        }
        const SceneDesc desc = it->make();
        const std::size_t n = threads.size();
        std::vector<Times> times(n);
        std::vector<std::uint64_t> hashes(n);
        std::vector<std::unique_ptr<Engine>> engines(n);
        if (it->steady) {
            for (std::size_t k = 0; k < n; ++k) {
                engines[k] = make_tamias_engine(desc, threads[k]);
                for (int i = 0; i < 10; ++i)
                    engines[k]->step();
            }
        }
        for (int r = 0; r < reps; ++r) {
            for (std::size_t j = 0; j < n; ++j) {
                const std::size_t k = (j + std::size_t(r)) % n; // the order rotates
                if (!it->steady)
                    engines[k] = make_tamias_engine(desc, threads[k]);
                const auto [wall, cpu] = timed(*engines[k], it->steps);
                times[k].wall.push_back(wall);
                times[k].cpu.push_back(cpu);
                hashes[k] = engines[k]->state_hash();
                if (!it->steady)
                    engines[k].reset();
            }
        }
        const double base = median(times[0].wall);
        for (std::size_t k = 0; k < n; ++k) {
            const double w = median(times[k].wall);
            std::printf("%-14s %7d %12.4f %12.4f %8.3fx %018llx%s\n", name.c_str(), threads[k], w,
                        median(times[k].cpu), base / w, (unsigned long long)hashes[k],
                        hashes[k] == hashes[0] ? "" : "  DIFFERS");
        }
        std::fflush(stdout);
    }
}
