// The project's sincos (src/tamias2d/math/sincos.hpp) against the C library's sin and cos
// (glibc's, as std::sin and std::cos of one argument, which GCC merges into one sincos call),
// Google Benchmark, on 4096 arguments drawn once from each range:
//   build/verification/trig/trig_speed --benchmark_repetitions=5
// [-pi, pi] is where the engine's orientations stay; [-2^20, 2^20] needs the reduction.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

#include "tamias2d/math/sincos.hpp"

namespace {

std::vector<double> arguments(double bound) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-bound, bound);
    std::vector<double> xs(4096);
    for (double& x : xs)
        x = u(rng);
    return xs;
}

template <class F> void run(benchmark::State& state, double bound, F f) {
    const std::vector<double> xs = arguments(bound);
    for (auto _ : state) {
        double sum = 0.0;
        for (double x : xs) {
            const auto [s, c] = f(x);
            sum += s + c;
        }
        benchmark::DoNotOptimize(sum);
    }
    state.SetItemsProcessed(state.iterations() * static_cast<long>(xs.size()));
}

struct Pair {
    double s, c;
};
Pair project(double x) {
    const tamias2d::math::SinCos r = tamias2d::math::sincos(x);
    return {r.sin, r.cos};
}
Pair libm(double x) {
    return {std::sin(x), std::cos(x)};
}

void project_pi(benchmark::State& s) {
    run(s, 3.141592653589793, project);
}
void libm_pi(benchmark::State& s) {
    run(s, 3.141592653589793, libm);
}
void project_2e20(benchmark::State& s) {
    run(s, 0x1p20, project);
}
void libm_2e20(benchmark::State& s) {
    run(s, 0x1p20, libm);
}

} // namespace

BENCHMARK(project_pi);
BENCHMARK(libm_pi);
BENCHMARK(project_2e20);
BENCHMARK(libm_2e20);
BENCHMARK_MAIN();
