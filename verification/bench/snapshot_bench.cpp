// tamias_snapshot_bench: the size of a snapshot and the time to take it and to restore it
// (World::snapshot, World::from_snapshot, World::restore) for large_pyramid and rain, beside
// Box2D v3's b2World_Snapshot, b2CreateWorldFromSnapshot and b2World_Restore in the same run
// when v3 is built (TAMIAS_BOX2D_V3_DIR: its worker, tamias_snapshot_bench_v3, is run for its
// lines). Wall-clock medians of snapshot_repeats runs on one thread. A verification program of
// the main job: the table and the ratios go into the report.
//   build/verification/bench/tamias_snapshot_bench [OUT_DIR]
#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "bench_report.hpp"
#include "snapshot_scenes.hpp"
#include "tamias2d/shape_def.hpp"
#include "tamias2d/world.hpp"
#include "verification_report.hpp"

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

/// One line of the table: an engine's figures for one scene.
struct Line {
    std::string engine, scene;
    int steps = 0;
    long long bodies = 0, bytes = 0;
    double snapshot_ms = 0, from_snapshot_ms = 0, restore_ms = 0;
    std::string note;
};

/// Box2D v3's lines, printed by its worker in the same run (empty when v3 is not built).
std::vector<Line> v3_lines() {
    std::vector<Line> out;
#ifdef TAMIAS_SNAPSHOT_BENCH_V3_WORKER
    const std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(TAMIAS_SNAPSHOT_BENCH_V3_WORKER, "r"),
                                                     pclose);
    if (!pipe)
        return out;
    std::array<char, 512> buf{};
    while (std::fgets(buf.data(), int(buf.size()), pipe.get())) {
        std::fputs(buf.data(), stdout);
        std::istringstream in(buf.data());
        Line l;
        in >> l.engine >> l.scene >> l.steps >> l.bodies >> l.bytes >> l.snapshot_ms >>
            l.from_snapshot_ms >> l.restore_ms;
        if (in) {
            std::getline(in, l.note);
            out.push_back(l);
        }
    }
#endif
    return out;
}

} // namespace

int main(int argc, char** argv) {
    tamias2d::evidence::Report report;
    std::vector<Line> lines;
    std::printf("engine    scene          steps  bodies  bytes     snapshot_ms  from_snapshot_ms  "
                "restore_ms\n");
    for (const SnapshotScene& sc : snapshot_scenes()) {
        tamias2d::World w = build(sc.desc);
        for (int s = 0; s < sc.steps; ++s)
            w.step(sc.desc.dt);
        // Into the same vector each time, as v3's b2World_Snapshot writes into the caller's
        // buffer (and as a game taking one every frame would).
        std::vector<std::byte> bytes;
        const double snap = median_ms([&] { w.snapshot(bytes); });
        const double load = median_ms([&] { (void)tamias2d::World::from_snapshot(bytes); });
        tamias2d::World target = build(sc.desc);
        const double restore = median_ms([&] { target.restore(bytes); });
        // Oracle: the world the snapshot was taken of (its state hash, and the next step's).
        const std::uint64_t h0 = w.state_hash();
        const bool same = target.state_hash() == h0;
        w.step(sc.desc.dt);
        target.step(sc.desc.dt);
        report.check("restored " + sc.desc.name + " continues as the original", {},
                     same && target.state_hash() == w.state_hash(),
                     "the original world's state hash, at the snapshot and one step later",
                     same ? "equal hashes" : "the restored world differs");
        lines.push_back({"tamias2d", sc.desc.name, sc.steps, (long long)w.body_count(),
                         (long long)bytes.size(), snap, load, restore, ""});
        std::printf("tamias2d  %-13s  %5d  %6zu  %8zu  %11.3f  %16.3f  %10.3f\n",
                    sc.desc.name.c_str(), sc.steps, w.body_count(), bytes.size(), snap, load,
                    restore);
    }
    std::fflush(stdout);
    const std::vector<Line> v3 = v3_lines();
    lines.insert(lines.end(), v3.begin(), v3.end());
    if (v3.empty())
        std::printf("box2d-v3  not measured: configure with TAMIAS_BOX2D_V3_DIR\n");

    using json = nlohmann::json;
    json rows = json::array();
    for (const Line& l : lines)
        rows.push_back({l.engine, l.scene, l.steps, l.bodies, l.bytes,
                        tamias_bench::num(l.snapshot_ms), tamias_bench::num(l.from_snapshot_ms),
                        tamias_bench::num(l.restore_ms)});
    report.tables.push_back(
        {{"name", "Snapshot size and time (median of " + std::to_string(snapshot_repeats) +
                      ", one thread, load " + tamias_bench::load_average() + ")"},
         {"columns",
          {"engine", "scene", "steps before", "bodies", "bytes", "snapshot (ms)",
           "from snapshot (ms)", "restore (ms)"}},
         {"rows", rows}});
    json ratios = json::array();
    for (const Line& t : lines) {
        for (const Line& o : v3) {
            if (t.engine == "tamias2d" && o.scene == t.scene)
                ratios.push_back({t.scene, tamias_bench::num(double(t.bytes) / double(o.bytes)),
                                  tamias_bench::num(t.snapshot_ms / o.snapshot_ms),
                                  tamias_bench::num(t.from_snapshot_ms / o.from_snapshot_ms),
                                  tamias_bench::num(t.restore_ms / o.restore_ms)});
        }
    }
    if (!ratios.empty())
        report.tables.push_back(
            {{"name", "Tamias2D / Box2D v3 (same run; above 1: Tamias2D larger "
                      "or slower)"},
             {"columns", {"scene", "bytes", "snapshot", "from snapshot", "restore"}},
             {"rows", ratios}});
    if (argc < 2)
        return report.failures == 0 ? 0 : 1;
    return report.write(argv[1], "snapshot_benchmark",
                        "Snapshot size and time for large_pyramid and rain beside Box2D v3's "
                        "b2World_Snapshot, b2CreateWorldFromSnapshot and b2World_Restore");
}
