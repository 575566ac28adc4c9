// Engines that run in a worker process of their own (engine_worker.cpp): Box2D v3, whose SSE2
// and AVX2 builds define the same C symbols and whose headers clash with Box2D 2.4's.
//
// Each worker is started once, when the run begins, and kept until it ends; tamias_bench drives
// it over a pipe exactly where it drives an engine of its own (build, blocks of timed steps,
// probes), so the engines still alternate block by block and repetition by repetition as one
// process would have them. The worker times its steps itself (thread CPU time), so the pipe is
// never in the time. Spawning a worker per repetition would instead time a cold process each
// time and could not alternate the steady scenes' blocks.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "bench_engines.hpp"

namespace tamias_bench {

/// Whether the engine runs in a worker process.
bool is_remote(EngineId id);

/// Starts the engine's worker, whose engine runs on `threads` threads (v3's workerCount;
/// tamias_bench measures 1, tamias_thread_bench more). Returns an empty string when it runs,
/// otherwise why the engine is not measured (not built, no AVX2 on this machine, the worker failed
/// to start).
std::string start_remote_engine(EngineId id, int threads = 1);

/// Arguments added to every worker started from now on (tamias_thread_bench's
/// --v3-recycle-distance: "--recycle-distance D").
void set_remote_engine_arguments(std::vector<std::string> arguments);

/// The one-thread worker's live heap (bytes) after its last command; 0 when it is not running.
double remote_heap_bytes(EngineId id);

/// Builds the scene in the engine's worker for `threads` (which holds one engine at a time),
/// stepping with `substeps` substeps (0: the benchmark's); throws (std::exception) when the worker
/// fails or rejects the scene.
std::unique_ptr<Engine> make_remote_engine(EngineId id, const SceneDesc& scene, int threads = 1,
                                           int substeps = 0);

/// What the workers' engines are and how they were built (the report's set-up table).
std::string remote_engines_description();

/// Stops every worker.
void stop_remote_engines();

} // namespace tamias_bench
