// An engine worker: runs one engine in a process of its own for tamias_bench, which starts it
// once and drives it over a pipe (worker_wire.hpp: commands on stdin, replies on stdout). Each
// Box2D v3 build is linked into such a worker (tamias_bench_v3_sse2, tamias_bench_v3_avx2): the
// two define the same C symbols, and v3's headers clash with Box2D 2.4's.
//
// The worker times its own steps with its thread's CPU clock (Engine::timed_steps, the same code
// as for the engines inside tamias_bench) and reports its live heap after every command.
//
//   tamias_bench_v3_<build> [--workers N] [--recycle-distance D]
//
// N (default 1) is v3's worker count (b2WorldDef::workerCount); tamias_thread_bench starts a
// worker per count it measures, and reads the wall time of Engine::timed_steps. D (m) replaces
// v3's contact recycling distance (0: off), to measure what recycling gives it.
#include <malloc.h>
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <memory>

#include "box2d_v3_engine.hpp"
#include "worker_wire.hpp"

namespace {

using namespace tamias_bench;

/// Live heap bytes: all the engine's memory comes from malloc.
double live_heap_bytes() {
    const struct mallinfo2 mi = mallinfo2();
    return double(mi.uordblks) + double(mi.hblkhd);
}

/// Runs one command and writes its results after the status byte.
void run(wire::Op op, wire::Reader& in, wire::Writer& results, std::unique_ptr<Engine>& engine,
         SceneDesc& scene, int& substeps, int workers, double recycle_distance) {
    const auto engine_ref = [&]() -> Engine& {
        if (!engine)
            throw std::runtime_error("no engine built");
        return *engine;
    };
    switch (op) {
    case wire::Op::build:
        engine.reset();
        scene = wire::get_scene(in);
        engine = make_box2d_v3_engine(scene, workers, recycle_distance, substeps);
        return;
    case wire::Op::substeps:
        substeps = in.get<std::int32_t>();
        if (substeps < 0)
            throw std::runtime_error("substeps must be >= 0");
        return;
    case wire::Op::timed: {
        const int n = in.get<std::int32_t>();
        results.put(engine_ref().timed_steps(n));
        return;
    }
    case wire::Op::steps: {
        const int n = in.get<std::int32_t>();
        Engine& e = engine_ref();
        for (int i = 0; i < n; ++i)
            e.step();
        return;
    }
    case wire::Op::probes: {
        const Engine& e = engine_ref();
        results.put(std::int32_t(scene.bodies.size()));
        for (std::size_t i = 0; i < scene.bodies.size(); ++i)
            results.put(e.probe(int(i)));
        return;
    }
    case wire::Op::queries: {
        const int rays = in.get<std::int32_t>();
        const int casts = in.get<std::int32_t>();
        const auto seed = in.get<std::uint64_t>();
        results.put(engine_ref().timed_queries(make_query_load(scene, rays, casts, seed)));
        return;
    }
    case wire::Op::release:
        engine.reset();
        return;
    }
    throw std::runtime_error("unknown command");
}

} // namespace

int main(int argc, char** argv) {
    int workers = 1;
    double recycle_distance = -1.0; // v3's default
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--workers") == 0 && i + 1 < argc) {
            workers = std::atoi(argv[++i]);
        } else if (std::strcmp(argv[i], "--recycle-distance") == 0 && i + 1 < argc) {
            recycle_distance = std::atof(argv[++i]);
        } else {
            std::fprintf(stderr, "usage: %s [--workers N] [--recycle-distance D]\n", argv[0]);
            return 2;
        }
    }
    if (workers < 1) {
        std::fprintf(stderr, "engine worker: --workers must be at least 1\n");
        return 2;
    }
    // Replies go to the pipe that was stdout; stdout itself goes to stderr, so that nothing the
    // engine prints (v3 logs with printf) can fall into a reply.
    const int reply_fd = ::dup(STDOUT_FILENO);
    if (reply_fd < 0 || ::dup2(STDERR_FILENO, STDOUT_FILENO) < 0) {
        std::perror("engine worker");
        return 2;
    }
    wire::Reader in(STDIN_FILENO);
    std::unique_ptr<Engine> engine;
    SceneDesc scene;
    int substeps = 0; // the benchmark's
    try {
        while (in.more()) {
            const auto op = in.get<wire::Op>();
            wire::Writer results;
            std::uint8_t status = 0;
            std::string error;
            try {
                run(op, in, results, engine, scene, substeps, workers, recycle_distance);
            } catch (const std::exception& ex) {
                status = 1;
                error = ex.what();
            }
            wire::Writer reply;
            reply.put(status);
            if (status != 0)
                reply.put_string(error);
            reply.put(live_heap_bytes());
            reply.send(reply_fd);
            if (status == 0)
                results.send(reply_fd);
        }
    } catch (const std::exception& ex) {
        std::fprintf(stderr, "engine worker: %s\n", ex.what());
        return 1;
    }
    return 0;
}
