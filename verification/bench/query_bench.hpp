// The query benchmark's workload (docs/performance.md, "Queries"): closest-hit rays and shape
// casts into a scene, drawn from a seed and the scene's bounds, so that every engine (Box2D
// v3 in its worker, which rebuilds the same workload from the same scene and seed) casts the
// same rays and shapes. Each engine answers them with its own closest-hit queries: Tamias2D's
// World::ray_cast(origin, translation, QueryFilter) and World::shape_cast, Box2D v3's
// b2World_CastRayClosest and b2World_CastShape with a callback clipping at each hit.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "bench_scenes.hpp"

namespace tamias_bench {

/// One ray or shape cast: from `origin` along `translation` (m).
struct Cast {
    V2 origin{};
    V2 translation{};
};

/// The shapes cast: a disc of radius 0.25 m (even casts) and a 0.5 m square (odd casts), the
/// size of the rain's boxes, unturned.
inline constexpr double cast_radius = 0.25;
inline constexpr double cast_half_side = 0.25;

struct QueryLoad {
    int ray_count = 0;
    int cast_count = 0;
    std::uint64_t seed = 0;
    std::vector<Cast> rays;
    std::vector<Cast> casts;
};

/// The work: `rays` rays and `casts` shape casts from points drawn uniformly in the box that
/// holds the scene's bodies' origins, in directions drawn uniformly, a ray up to a quarter and
/// a cast up to an eighth of the box's diagonal long (uniformly).
inline QueryLoad make_query_load(const SceneDesc& s, int rays, int casts, std::uint64_t seed) {
    QueryLoad load;
    load.ray_count = rays;
    load.cast_count = casts;
    load.seed = seed;
    double lo_x = INFINITY, lo_y = INFINITY, hi_x = -INFINITY, hi_y = -INFINITY;
    for (const BodyDesc& b : s.bodies) {
        lo_x = std::min(lo_x, b.position.x);
        lo_y = std::min(lo_y, b.position.y);
        hi_x = std::max(hi_x, b.position.x);
        hi_y = std::max(hi_y, b.position.y);
    }
    const double diagonal = std::hypot(hi_x - lo_x, hi_y - lo_y);
    std::mt19937_64 rng(seed);
    const auto unit = [&] { return double(rng() >> 11) * 0x1.0p-53; };
    const auto draw = [&](double reach) {
        const double a = 6.283185307179586 * unit(), len = reach * unit();
        return Cast{{lo_x + (hi_x - lo_x) * unit(), lo_y + (hi_y - lo_y) * unit()},
                    {len * std::cos(a), len * std::sin(a)}};
    };
    for (int i = 0; i < rays; ++i)
        load.rays.push_back(draw(0.25 * diagonal));
    for (int i = 0; i < casts; ++i)
        load.casts.push_back(draw(0.125 * diagonal));
    return load;
}

/// What one pass over a workload took (thread CPU time, ms) and found.
struct QueryTimes {
    double ray_ms = 0.0;
    double cast_ms = 0.0;
    std::int32_t ray_hits = 0;  ///< rays that hit a shape
    std::int32_t cast_hits = 0; ///< casts that touched a shape
};

} // namespace tamias_bench
