// One interface over the three engines the benchmark compares. Each adapter builds a
// SceneDesc (bench_scenes.hpp) in its engine with the benchmark's settings and nothing else:
//   Tamias2D  its WorldDef defaults (4 substeps, soft contacts and joints), gravity from the
//             scene;
//   Chipmunk  7.0.3, 10 iterations, default collision slop and bias, sleeping off (default);
//             joints: cpPivotJoint with its default error bias and unlimited max bias;
//   Box2D     2.4.1, 8 velocity and 3 position iterations, sleeping off; joints:
//             b2RevoluteJoint (no limit, no motor).
#pragma once

#include <memory>
#include <string>
#include <string_view>

#include "bench_scenes.hpp"

namespace tamias_bench {

enum class EngineId : int { tamias = 0, chipmunk = 1, box2d = 2 };
inline constexpr int engine_count = 3;

std::string_view engine_name(EngineId e);

/// Origin, linear velocity, angular velocity and angle of one body.
struct Probe {
    V2 p{};
    V2 v{};
    double w = 0.0;
    double angle = 0.0; ///< rad
};

class Engine {
  public:
    virtual ~Engine() = default;
    virtual void step() = 0;
    /// State of the scene's body `index` (index into SceneDesc::bodies).
    virtual Probe probe(int index) const = 0;
};

/// Builds the scene; throws (std::exception) if the engine rejects it.
std::unique_ptr<Engine> make_engine(EngineId id, const SceneDesc& scene);

} // namespace tamias_bench
