// One interface over the engines the benchmark compares. Each adapter builds a SceneDesc
// (bench_scenes.hpp) in its engine with the benchmark's settings and nothing else:
//   Tamias2D  its WorldDef defaults (4 substeps, soft contacts and joints), gravity from the
//             scene;
//   Chipmunk  7.0.3, 10 iterations, default collision slop and bias, sleeping off (default);
//             joints: cpPivotJoint with its default error bias and unlimited max bias;
//   Box2D     2.4.1, 8 velocity and 3 position iterations, sleeping off; joints:
//             b2RevoluteJoint (no limit, no motor);
//   Box2D v3  b2DefaultWorldDef, 4 substeps, one worker thread, sleeping as the scene says;
//             joints: b2RevoluteJoint with its defaults (box2d_v3_engine.cpp). Its SSE2 and AVX2
//             builds each run in an executable of their own (remote_engine.hpp).
// SolverKnobs replaces these substep and iteration counts (the work-precision sweep).
#pragma once

#include <chrono>
#include <cmath>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>

#include "bench_scenes.hpp"
#include "query_bench.hpp"
#include "thread_cpu_time.hpp"

namespace tamias_bench {

enum class EngineId : int {
    tamias = 0,
    chipmunk = 1,
    box2d = 2,
    box2d_v3_sse2 = 3,
    box2d_v3_avx2 = 4
};
inline constexpr int engine_count = 5;

std::string_view engine_name(EngineId e);

/// Origin, linear velocity, angular velocity and angle of one body.
struct Probe {
    V2 p{};
    V2 v{};
    double w = 0.0;
    double angle = 0.0; ///< rad
};

/// Whether the body's position and velocities are finite (a NaN or infinite state is not).
inline bool finite(const Probe& p) {
    return std::isfinite(p.p.x) && std::isfinite(p.p.y) && std::isfinite(p.v.x) &&
           std::isfinite(p.v.y) && std::isfinite(p.w);
}

/// The time a block of steps took (ms): the thread's CPU time (the benchmark's measure), wall
/// time, and the kernel's part of the CPU time.
struct StepTimes {
    double cpu = 0.0, wall = 0.0, system = 0.0;
    StepTimes& operator+=(StepTimes o) {
        cpu += o.cpu;
        wall += o.wall;
        system += o.system;
        return *this;
    }
};

class Engine {
  public:
    virtual ~Engine() = default;
    virtual void step() = 0;
    /// State of the scene's body `index` (index into SceneDesc::bodies).
    virtual Probe probe(int index) const = 0;
    /// World::state_hash() for Tamias2D (equal hashes: bitwise-equal worlds); 0 for the peers.
    virtual std::uint64_t state_hash() const { return 0; }
    /// Casts the workload's rays, then its shapes (query_bench.hpp), each pass timed by the
    /// thread that casts: Tamias2D and Box2D v3 only (the others throw).
    virtual QueryTimes timed_queries(const QueryLoad& load) {
        (void)load;
        throw std::runtime_error("no query benchmark for this engine");
    }
    /// Steps `n` times, timed by the thread that steps: an engine in another process times its
    /// steps there, so the pipe to it is never in the time.
    virtual StepTimes timed_steps(int n) {
        const double s0 = system_ms();
        const double w0 = wall_ms(), c0 = cpu_ms();
        for (int i = 0; i < n; ++i)
            step();
        const double c1 = cpu_ms(), w1 = wall_ms();
        const double s1 = system_ms();
        return {c1 - c0, w1 - w0, s1 - s0};
    }

  private:
    static double wall_ms() {
        return std::chrono::duration<double, std::milli>(
                   std::chrono::steady_clock::now().time_since_epoch())
            .count();
    }
};

/// The solver's cost knobs, each engine reading its own; 0 keeps the benchmark's setting (above).
/// Every other setting stays the benchmark's: the knobs trade accuracy for time, nothing else.
struct SolverKnobs {
    int substeps = 0;   ///< Tamias2D (WorldDef::substeps) and Box2D v3 (b2World_Step's count)
    int iterations = 0; ///< Chipmunk 7 (cpSpaceSetIterations), Box2D 2.4's velocity iterations
    int position_iterations = 0; ///< Box2D 2.4
};

/// Builds the scene; throws (std::exception) if the engine rejects it or is not available.
std::unique_ptr<Engine> make_engine(EngineId id, const SceneDesc& scene,
                                    const SolverKnobs& knobs = {});
/// Tamias2D with WorldDef::workers = `workers` (the thread benchmark, thread_bench.cpp) and,
/// when `manifold_reuse` >= 0, that WorldDef::manifold_reuse_distance instead of the default,
/// with WorldDef::contact_regions = `regions`.
std::unique_ptr<Engine> make_tamias_engine(const SceneDesc& scene, int workers,
                                           double manifold_reuse = -1.0, int regions = 1);

} // namespace tamias_bench
