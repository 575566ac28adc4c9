// Box2D v3 behind the benchmark's engine interface. Its C API names its types as Box2D 2.4's C++
// classes (b2Vec2, b2BodyDef, ...), so it lives in a translation unit of its own, linked only
// into the engine workers (engine_worker.cpp), never beside Box2D 2.4.
#pragma once

#include <memory>

#include "bench_engines.hpp"

namespace tamias_bench {

/// Builds the scene in Box2D v3 with `workers` worker threads (b2WorldDef::workerCount; above 1,
/// v3's own scheduler runs them), when `recycle_distance` >= 0 that contact recycling distance
/// (b2World_SetContactRecycleDistance; 0: off) instead of v3's default, and stepping with
/// `substeps` substeps (0: the benchmark's 4); throws (std::exception) if v3 rejects it.
std::unique_ptr<Engine> make_box2d_v3_engine(const SceneDesc& scene, int workers = 1,
                                             double recycle_distance = -1.0, int substeps = 0);

} // namespace tamias_bench
