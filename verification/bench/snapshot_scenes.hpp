// The scenes tamias_snapshot_bench takes snapshots of (large_pyramid and rain, as the peer
// benchmark builds them), and how many steps each runs first: the pyramid settled into its
// contacts, the rain with its boxes piling in the container.
#pragma once

#include <string>
#include <vector>

#include "bench_scenes.hpp"

namespace tamias_bench {

struct SnapshotScene {
    SceneDesc desc;
    int steps; ///< steps before the snapshot
};

inline std::vector<SnapshotScene> snapshot_scenes() {
    return {{make_pyramid("large_pyramid", 100), 60}, {make_rain("rain", 2000), 600}};
}

/// Repetitions of each measurement; the median is reported.
inline constexpr int snapshot_repeats = 11;

} // namespace tamias_bench
