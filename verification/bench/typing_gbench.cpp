// Google Benchmark view of the typing kernel (typing_kernel.hpp): the same loop through
// tamias2d::bridge and on plain doubles. tamias_bench reports the same comparison in
// benchmark.json; this binary is for interactive runs, e.g.
//   build/verification/bench/tamias_typing_gbench --benchmark_repetitions=10
#include <benchmark/benchmark.h>

#include "typing_kernel.hpp"

namespace {

using namespace tamias_bench::typing;

template <void (*Run)(KernelData&, int, double)> void bm_kernel(benchmark::State& state) {
    const KernelData initial = make_kernel_data(40);
    for (auto _ : state) {
        state.PauseTiming();
        KernelData d = initial;
        state.ResumeTiming();
        Run(d, 10, 1.0 / 60.0);
        benchmark::DoNotOptimize(d.bodies.data());
        benchmark::ClobberMemory();
    }
}

BENCHMARK(bm_kernel<run_plain>)
    ->Name("contact_solver/plain_doubles")
    ->Unit(benchmark::kMillisecond);
BENCHMARK(bm_kernel<run_bridge>)->Name("contact_solver/bridge")->Unit(benchmark::kMillisecond);

} // namespace

BENCHMARK_MAIN();
