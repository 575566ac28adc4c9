// Google Benchmark views of a step's stages, for interactive profiling (not run by the job:
// tamias_bench is the evidence): the broad phase's pair search, the narrow phase on a pair of
// boxes, whole steps of the benchmark's scenes, of a pyramid with sleeping off and asleep, and
// of a jointed grid of each joint kind with its solve and preparation stages. The
// contact solver's loop has its own binary (tamias_typing_gbench). For example:
//   build/verification/bench/tamias_stage_gbench --benchmark_repetitions=5
//   build/verification/bench/tamias_stage_gbench --benchmark_filter=broad_phase
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "bench_engines.hpp"
#include "bench_scenes.hpp"
#include "tamias2d/collision/broad_phase.hpp"
#include "tamias2d/collision/collider.hpp"
#include "tamias2d/collision/narrow_phase.hpp"
#include "tamias2d/geometry/shape_factory.hpp"
#include "tamias2d/io/scene.hpp"
#include "tamias2d/io/scene_generators.hpp"
#include "tamias2d/world.hpp"
#include "tamias2d/world_def.hpp"

namespace {

using namespace tamias2d;

/// Boxes of 0.5 m in 10 rows at a 0.55 m pitch, as a settled rain (their fat boxes overlap their
/// neighbours'). Each iteration every box, or every 2nd ... 128th (the second argument), leaves
/// its fat box, alternately right and left, and the pairs of the moved boxes are found: the
/// tree's partial rebuild and the pair search (which of its two searches update_pairs chooses
/// depends on how scattered the moved boxes are).
void broad_phase_update_pairs(benchmark::State& state) {
    const int n = static_cast<int>(state.range(0));
    const int stride = static_cast<int>(state.range(1));
    const int columns = n / 10;
    constexpr double pitch = 0.55, half = 0.25;
    BroadPhase broad_phase;
    std::vector<int> proxies;
    std::vector<Aabb> boxes;
    for (int i = 0; i < n; ++i) {
        const double x = pitch * (i % columns), y = pitch * (i / columns);
        boxes.push_back({x - half, y - half, x + half, y + half});
        proxies.push_back(broad_phase.create_proxy(boxes.back(), std::uint32_t(i)));
    }
    memory::vector<BroadPhase::Pair> pairs;
    broad_phase.update_pairs(pairs);
    std::vector<BroadPhase::ProxyMove> moves;
    double shift = 0.15; // beyond the 0.1 m margin
    for (auto _ : state) {
        moves.clear();
        for (int i = 0; i < n; i += stride) {
            boxes[i].min_x += shift;
            boxes[i].max_x += shift;
            moves.push_back({proxies[i], broad_phase.fattened(boxes[i])});
        }
        shift = -shift;
        broad_phase.move_proxies(moves);
        pairs.clear();
        broad_phase.update_pairs(pairs);
        benchmark::DoNotOptimize(pairs.data());
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * (n / stride)); // moved boxes
    state.counters["pairs"] = double(pairs.size());
    state.counters["tree_height"] = broad_phase.dynamic_tree().height();
    state.counters["tree_area_ratio"] = broad_phase.dynamic_tree().area_ratio();
}
BENCHMARK(broad_phase_update_pairs)
    ->Name("broad_phase/update_pairs/boxes")
    ->ArgsProduct({{1000, 16000}, {1, 2, 4, 8, 32, 128}})
    ->Unit(benchmark::kMicrosecond);

/// Two unit boxes as the world's narrow phase sees them: B above A, turned by 0.01 rad, its
/// lowest corner `gap` (m) above A's top face (negative: overlapping). The manifold and the
/// separation hint are kept across iterations, as a contact keeps them across steps.
void narrow_phase_boxes(benchmark::State& state, double gap) {
    const Collider a = make_collider(make_box(0.5, 0.5));
    const Collider b = make_collider(make_box(0.5, 0.5));
    const double angle = 0.01;
    const double lowest = 0.5 * (std::cos(angle) + std::sin(angle)); // below B's centre
    const Transform xf_a{{0.0, 0.0}, Rot{}};
    const Transform xf_b{{0.1, 0.5 + gap + lowest}, Rot::from_angle(angle)};
    const CollideInput in{xf_a, xf_a.p, xf_b, xf_b.p, WorldDef{}.speculative_distance};
    Manifold m;
    SeparationHint hint;
    for (auto _ : state) {
        collide(a, b, in, m, &hint);
        benchmark::DoNotOptimize(m);
    }
    state.counters["points"] = m.count;
}
BENCHMARK_CAPTURE(narrow_phase_boxes, resting, -0.005)->Name("narrow_phase/box_box/resting");
BENCHMARK_CAPTURE(narrow_phase_boxes, apart, 0.2)->Name("narrow_phase/box_box/apart_hinted");

/// Whole steps of a steady scene in Tamias2D, after the same 10 untimed steps as tamias_bench.
void world_step(benchmark::State& state, tamias_bench::SceneDesc scene) {
    auto engine = tamias_bench::make_engine(tamias_bench::EngineId::tamias, scene);
    for (int i = 0; i < 10; ++i)
        engine->step();
    for (auto _ : state)
        engine->step();
}
BENCHMARK_CAPTURE(world_step, pyramid20, tamias_bench::make_pyramid("pyramid20", 20))
    ->Name("world/step/pyramid20")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(world_step, pyramid40, tamias_bench::make_pyramid("pyramid40", 40))
    ->Name("world/step/pyramid40")
    ->Unit(benchmark::kMillisecond);

/// Whole steps of the library's base-40 pyramid (io::generate_pyramid) with sleeping off, or on
/// and after the pyramid has fallen asleep: what a settled scene costs when it sleeps.
void world_step_sleep(benchmark::State& state, bool sleep) {
    tamias2d::WorldDef def;
    def.enable_sleep = sleep;
    tamias2d::World world(def);
    tamias2d::io::PyramidParams p;
    p.base = 40;
    tamias2d::io::Scene scene;
    scene.world = def;
    scene.bodies = tamias2d::io::generate_pyramid(p);
    tamias2d::io::build_world(scene, world);
    int awake = 1;
    for (int i = 0; i < 1200 && (awake > 0 || i < 10); ++i) {
        world.step(1.0 / 60.0);
        awake = 0;
        for (tamias2d::BodyId b : world.bodies())
            awake += world.is_awake(b) && world.type(b) == tamias2d::BodyType::dynamic;
    }
    for (auto _ : state)
        world.step(1.0 / 60.0);
    state.counters["awake"] = awake;
}
BENCHMARK_CAPTURE(world_step_sleep, off, false)
    ->Name("world/step/generated_pyramid40/sleep_off")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(world_step_sleep, asleep, true)
    ->Name("world/step/generated_pyramid40/asleep")
    ->Unit(benchmark::kMicrosecond);

} // namespace

/// The joint solver by kind: a hanging n x n grid (joint_grid's layout, n = 40: 1600 bodies of
/// 0.5 kg, the middle three of the top row static) whose pins are all of one kind, each at the
/// midpoint of its two bodies. The counters are the step's stages (World::profile) averaged
/// over the iterations: `solve` is the substeps (the joints' warm starts and iterations and the
/// relax), `prepare` the state checks, the solver bodies and the joints' records.
enum class GridJoint { revolute, revolute_motor_limit_spring, weld, prismatic, wheel, distance };

void joint_grid_by_kind(benchmark::State& state, GridJoint kind) {
    using namespace tamias2d;
    constexpr int n = 40;
    World world(WorldDef{});
    std::vector<BodyId> body(n * n);
    for (int k = 0; k < n; ++k) {
        for (int i = 0; i < n; ++i) {
            BodyDef d;
            d.type = i == 0 && std::abs(k - n / 2) <= 1 ? BodyType::static_body : BodyType::dynamic;
            d.position = {double(k), double(-i)};
            if (d.type == BodyType::dynamic) {
                d.mass = 0.5;
                d.inertia = 0.04;
            }
            body[std::size_t(k * n + i)] = world.create_body(d);
        }
    }
    const auto join = [&](BodyId a, BodyId b, Vec2d pa, Vec2d pb) {
        const Vec2d mid = 0.5 * (pa + pb);
        const Vec2d axis = pb - pa;
        switch (kind) {
        case GridJoint::revolute:
        case GridJoint::revolute_motor_limit_spring: {
            RevoluteJointDef j{.body_a = a, .body_b = b, .anchor = mid};
            if (kind == GridJoint::revolute_motor_limit_spring) {
                j.enable_limit = true;
                j.lower_angle = -1.0;
                j.upper_angle = 1.0;
                j.enable_motor = true;
                j.max_motor_torque = 0.1;
                j.enable_spring = true;
                j.hertz = 2.0;
                j.damping_ratio = 0.5;
            }
            world.create_joint(j);
            break;
        }
        case GridJoint::weld:
            world.create_joint(WeldJointDef{.body_a = a, .body_b = b, .anchor = mid});
            break;
        case GridJoint::prismatic:
            world.create_joint(
                PrismaticJointDef{.body_a = a, .body_b = b, .anchor = mid, .axis = axis});
            break;
        case GridJoint::wheel:
            world.create_joint(
                WheelJointDef{.body_a = a, .body_b = b, .anchor = mid, .axis = axis});
            break;
        case GridJoint::distance:
            world.create_joint(
                DistanceJointDef{.body_a = a, .body_b = b, .anchor_a = pa, .anchor_b = pb});
            break;
        }
    };
    for (int k = 0; k < n; ++k) {
        for (int i = 0; i < n; ++i) {
            const std::size_t at = std::size_t(k * n + i);
            const bool fixed = world.type(body[at]) == BodyType::static_body;
            if (i > 0 && !(fixed && world.type(body[at - 1]) == BodyType::static_body))
                join(body[at - 1], body[at], {double(k), double(1 - i)}, {double(k), double(-i)});
            if (k > 0 && !(fixed && world.type(body[at - n]) == BodyType::static_body))
                join(body[at - n], body[at], {double(k - 1), double(-i)}, {double(k), double(-i)});
        }
    }
    world.set_profiling(true);
    for (int i = 0; i < 10; ++i)
        world.step(1.0 / 60.0);
    double solve = 0.0, prepare = 0.0;
    for (auto _ : state) {
        world.step(1.0 / 60.0);
        const StepProfile p = world.profile();
        solve += p.solve;
        prepare += p.prepare;
    }
    const double steps = double(state.iterations());
    state.counters["solve_ms"] = 1e3 * solve / steps;
    state.counters["prepare_ms"] = 1e3 * prepare / steps;
}
[[maybe_unused]] const bool joint_grids_registered = [] {
    for (const auto& [name, kind] :
         {std::pair{"revolute", GridJoint::revolute},
          {"revolute_motor_limit_spring", GridJoint::revolute_motor_limit_spring},
          {"weld", GridJoint::weld},
          {"prismatic", GridJoint::prismatic},
          {"wheel", GridJoint::wheel},
          {"distance", GridJoint::distance}})
        benchmark::RegisterBenchmark(("joints/grid40/" + std::string(name)).c_str(),
                                     joint_grid_by_kind, kind)
            ->Unit(benchmark::kMillisecond);
    return true;
}();

BENCHMARK_MAIN();
