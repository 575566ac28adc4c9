// tamias_snapshot_bench: the size of a snapshot and the time to take it and to restore it
// (World::snapshot, World::from_snapshot, World::restore) for large_pyramid and rain, beside
// Box2D v3's b2World_Snapshot, b2CreateWorldFromSnapshot and b2World_Restore in the same run
// when v3 is built (TAMIAS_BOX2D_V3_DIR: its worker, tamias_snapshot_bench_v3, is run for its
// lines). Wall-clock medians of snapshot_repeats runs on one thread. Printed, not run by the job.
//   build/verification/bench/tamias_snapshot_bench
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "snapshot_scenes.hpp"
#include "tamias2d/shape_def.hpp"
#include "tamias2d/world.hpp"

using namespace tamias_bench;

namespace {

/// The scene as TamiasEngine builds it (bench_engines.cpp): boxes, the scene's gravity and
/// sleeping, one worker.
tamias2d::World build(const SceneDesc& s) {
    tamias2d::WorldDef def;
    def.gravity = {s.gravity.x, s.gravity.y};
    def.enable_sleep = s.sleep;
    tamias2d::World w(def);
    for (const BodyDesc& d : s.bodies) {
        tamias2d::BodyDef bd;
        bd.type = d.dynamic ? tamias2d::BodyType::dynamic : tamias2d::BodyType::static_body;
        bd.position = {d.position.x, d.position.y};
        bd.angle = d.angle;
        bd.linear_velocity = {d.velocity.x, d.velocity.y};
        const tamias2d::BodyId id = w.create_body(bd);
        const tamias2d::Material m{d.density, d.restitution, d.friction};
        for (const BoxPart& p : d.boxes)
            w.create_shape(id, tamias2d::box_shape(2.0 * p.hx, 2.0 * p.hy, m,
                                                   {p.center.x, p.center.y}, p.angle));
    }
    return w;
}

template <class F> double median_ms(F&& f) {
    std::vector<double> t;
    for (int k = 0; k < snapshot_repeats; ++k) {
        const auto t0 = std::chrono::steady_clock::now();
        f();
        const auto t1 = std::chrono::steady_clock::now();
        t.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
    }
    std::sort(t.begin(), t.end());
    return t[t.size() / 2];
}

} // namespace

int main() {
    std::printf("engine    scene          steps  bodies  bytes     snapshot_ms  from_snapshot_ms  "
                "restore_ms\n");
    for (const SnapshotScene& sc : snapshot_scenes()) {
        tamias2d::World w = build(sc.desc);
        for (int s = 0; s < sc.steps; ++s)
            w.step(sc.desc.dt);
        std::vector<std::byte> bytes;
        const double snap = median_ms([&] { bytes = w.snapshot(); });
        const double load = median_ms([&] { (void)tamias2d::World::from_snapshot(bytes); });
        tamias2d::World target = build(sc.desc);
        const double restore = median_ms([&] { target.restore(bytes); });
        if (target.state_hash() != w.state_hash()) {
            std::fprintf(stderr, "%s: the restored world differs\n", sc.desc.name.c_str());
            return 1;
        }
        std::printf("tamias2d  %-13s  %5d  %6zu  %8zu  %11.3f  %16.3f  %10.3f\n",
                    sc.desc.name.c_str(), sc.steps, w.body_count(), bytes.size(), snap, load,
                    restore);
    }
    std::fflush(stdout);
#ifdef TAMIAS_SNAPSHOT_BENCH_V3_WORKER
    return std::system(TAMIAS_SNAPSHOT_BENCH_V3_WORKER) == 0 ? 0 : 1;
#else
    std::printf("box2d-v3  not measured: configure with TAMIAS_BOX2D_V3_DIR\n");
    return 0;
#endif
}
