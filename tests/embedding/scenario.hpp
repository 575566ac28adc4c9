// The embedding tests' scenario: a world that exercises the library broadly (every shape kind
// and joint kind, contacts, sleeping, events, sensors, continuous collision, the queries'
// callback forms, a snapshot into the caller's vector and a restore, a Recorder and a Replayer
// of its recording, destruction)
// without a Boost.Test call and without allocating on the test's side, so that what it
// allocates while it runs is the library's. Its results go into preallocated storage, checked
// after the counting window closes.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "tamias2d/shape_def.hpp"
#include "tamias2d/task_system.hpp"

namespace tamias2d::test {

/// What the scenario needs made before it runs (the caller's allocations).
struct ScenarioInput {
    int workers = 1;
    TaskSystem task_system{};      ///< the game's job system, if any (WorldDef::task_system)
    std::vector<ShapeDef> chain;   ///< the ground's chain segments (chain_shapes)
    std::vector<std::byte> buffer; ///< snapshot storage, reserved
};
ScenarioInput scenario_input(int workers);

/// What the scenario saw.
struct ScenarioResult {
    std::array<std::uint64_t, 16> hashes{}; ///< the state hash at fixed points
    std::size_t hash_count = 0;
    std::size_t begin_events = 0, end_events = 0, sensor_begins = 0, hit_events = 0;
    std::size_t move_events = 0, joint_events = 0;
    std::size_t ray_hits = 0, aabb_hits = 0, point_hits = 0, overlap_hits = 0, cast_hits = 0;
    std::size_t span_hits = 0;
    double distance = -1.0;
    bool crate_slept = false;    ///< the crate on the ground fell asleep
    bool bullet_held = false;    ///< the bullet stayed in front of the thin wall
    bool restored_equal = false; ///< the restored world's hash equals the snapshot's
    std::size_t snapshot_size = 0;
    std::uint64_t recorder_steps = 0;
    std::uint64_t replayed_steps = 0; ///< advances of the Replayer that matched
    std::size_t chain_ids = 0;        ///< the handles create_chain returned
    std::size_t pre_solve_calls = 0, filter_calls = 0;
};

/// Runs the scenario (the world is made and destroyed within).
ScenarioResult run_scenario(ScenarioInput& in);

/// The number of containers the scenario takes by value from the library (the caller's,
/// std::allocator): create_chain's vector of handles and Recorder::bytes()'s recording.
inline constexpr std::size_t scenario_by_value_results = 2;

} // namespace tamias2d::test
