// tamias_snapshot_bench_v3: Box2D v3's lines of tamias_snapshot_bench (b2World_Snapshot's size
// and time, b2CreateWorldFromSnapshot's and b2World_Restore's time) for the same scenes, built
// as Box2DV3Engine builds them (box2d_v3_engine.cpp), one worker. Run by tamias_snapshot_bench.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

#include <box2d/box2d.h>

#include "snapshot_scenes.hpp"

using namespace tamias_bench;

namespace {

b2Vec2 vec(V2 v) {
    return {float(v.x), float(v.y)};
}

b2Rot rotation(double angle) {
    return {float(std::cos(angle)), float(std::sin(angle))};
}

b2WorldId build(const SceneDesc& s) {
    b2WorldDef wd = b2DefaultWorldDef();
    wd.gravity = vec(s.gravity);
    wd.enableSleep = s.sleep;
    wd.workerCount = 1;
    const b2WorldId world = b2CreateWorld(&wd);
    for (const BodyDesc& d : s.bodies) {
        b2BodyDef bd = b2DefaultBodyDef();
        bd.type = d.dynamic ? b2_dynamicBody : b2_staticBody;
        bd.position = vec(d.position);
        bd.rotation = rotation(d.angle);
        bd.linearVelocity = vec(d.velocity);
        const b2BodyId body = b2CreateBody(world, &bd);
        for (const BoxPart& p : d.boxes) {
            const b2Polygon box =
                b2MakeOffsetBox(float(p.hx), float(p.hy), vec(p.center), rotation(p.angle));
            b2ShapeDef sd = b2DefaultShapeDef();
            sd.density = float(d.density);
            sd.material.friction = float(d.friction);
            sd.material.restitution = float(d.restitution);
            b2CreatePolygonShape(body, &sd, &box);
        }
    }
    return world;
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
    for (const SnapshotScene& sc : snapshot_scenes()) {
        const b2WorldId w = build(sc.desc);
        for (int s = 0; s < sc.steps; ++s)
            b2World_Step(w, float(sc.desc.dt), 4);
        const int size = b2World_Snapshot(w, nullptr, 0);
        std::vector<std::uint8_t> image(std::size_t(size > 0 ? size : 0));
        const double snap = median_ms([&] { b2World_Snapshot(w, image.data(), size); });
        const double load = median_ms([&] {
            const b2WorldId copy = b2CreateWorldFromSnapshot(image.data(), size, 1);
            b2DestroyWorld(copy);
        });
        const b2WorldId target = build(sc.desc);
        bool ok = true;
        const double restore =
            median_ms([&] { ok = b2World_Restore(target, image.data(), size) && ok; });
        const b2Counters c = b2World_GetCounters(w);
        std::printf("box2d-v3  %-13s  %5d  %6d  %8d  %11.3f  %16.3f  %10.3f%s\n",
                    sc.desc.name.c_str(), sc.steps, c.bodyCount, size, snap, load, restore,
                    ok ? "" : "  (restore refused)");
        b2DestroyWorld(target);
        b2DestroyWorld(w);
    }
    return 0;
}
