// Soak (on request, not in the CTest run). Two scenes:
//   tamias_soak          the rain scene stepped for TAMIAS_SOAK_STEPS steps
//   (default 10 000)
//                        while a seeded churn destroys a random box and drops a
//                        new one every 10 steps. Fails (exit 1) when a state
//                        turns non-finite or memory grows.
//   tamias_soak --busy   rain with restitution and friction beside a pyramid
//   struck again and
//                        again by a heavy box, TAMIAS_SOAK_STEPS steps (default
//                        1 000 000), with bounds on speed and energy too
//                        (soak_busy.cpp).
//
// Oracle of the rain soak: the library's promises that every state after an
// accepted step is finite (DCO_p, DCO_v) and that a world of constant size
// holds constant memory: the resident set and the world's large blocks
// (tamias2d::large_array_stats) at the end may exceed their values after the
// first tenth of the run (the warm-up, when every array has reached its working
// size) by at most 10 % + 4 MiB.
//
//   TAMIAS_SOAK_STEPS=100000 build/tests/fuzz/tamias_soak
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "fuzz/fuzz_support.hpp"
#include "fuzz/soak_busy.hpp"
#include "support/reliability_support.hpp"
#include "tamias2d/io/scene.hpp"
#include "tamias2d/memory.hpp"
#include "tamias2d/world.hpp"

using namespace tamias2d;

namespace {

using reliability::resident_bytes;

constexpr double max_speed = 100.0; // m/s

bool grew(std::size_t start, std::size_t end) {
    return end > start + start / 10 + (std::size_t{4} << 20);
}

int run_rain(long steps) {
    const io::Scene scene = io::load_scene(TAMIAS_EXAMPLE_SCENES "/rain.json");
    World world(scene.world);
    io::build_world(scene, world);
    std::vector<BodyId> boxes;
    // New boxes fall in where the scene's boxes start: inside the container,
    // above it.
    double x_min = 1e300, x_max = -1e300, y_max = -1e300;
    for (const BodyId b : world.bodies())
        if (world.type(b) == BodyType::dynamic) {
            boxes.push_back(b);
            x_min = std::min(x_min, world.position(b).x);
            x_max = std::max(x_max, world.position(b).x);
            y_max = std::max(y_max, world.position(b).y);
        }
    const ShapeDef box = box_shape(0.5, 0.5, Material{1.0, 0.0, 0.6});
    const std::size_t count = world.body_count();
    std::printf("soak: rain, %zu bodies, %ld steps, a box replaced every 10 "
                "steps (x in [%g, %g] "
                "m, %g m up)\n",
                count, steps, x_min, x_max, y_max);

    fuzz::Rng r(20263000);
    long escaped = 0;
    std::size_t rss_warm = 0, blocks_warm = 0;
    const long warm = steps / 10;
    for (long s = 1; s <= steps; ++s) {
        world.step(scene.dt);
        if (s % 10 == 0) {
            // Churn: a box leaves (one splashed out over the walls first: outside the
            // open-top container nothing stops it), a new one falls in from above the
            // container.
            std::size_t i = r.below(boxes.size());
            for (std::size_t k = 0; k < boxes.size(); ++k)
                if (world.position(boxes[k]).y < -1.0) {
                    i = k;
                    ++escaped;
                    break;
                }
            world.destroy_body(boxes[i]);
            BodyDef d;
            d.position = {r.between(x_min, x_max), y_max + r.between(1.0, 5.0)};
            boxes[i] = world.create_body(d);
            world.create_shape(boxes[i], box);
        }
        if (s % 100 == 0 || s == steps) {
            if (const std::string bad = fuzz::non_finite_state(world); !bad.empty()) {
                std::printf("FAIL step %ld: non-finite state: %s\n", s, bad.c_str());
                return 1;
            }
            if (world.body_count() != count) {
                std::printf("FAIL step %ld: %zu bodies, expected %zu\n", s, world.body_count(),
                            count);
                return 1;
            }
        }
        if (s == warm) {
            rss_warm = resident_bytes();
            blocks_warm = large_array_stats().mapped_bytes;
        }
        if (s % 1000 == 0 || s == steps) {
            double y_low = 1e300, speed = 0.0;
            for (const BodyId b : boxes) {
                y_low = std::min(y_low, world.position(b).y);
                speed = std::max(speed, std::hypot(world.velocity(b).x, world.velocity(b).y));
            }
            std::printf("step %ld: lowest box y %.3g m, fastest %.3g m/s, %ld splashed out\n", s,
                        y_low, speed, escaped);
            // A box falling from the drop height lands at ~33 m/s; far faster is an
            // explosion.
            if (speed > max_speed) {
                std::printf("FAIL step %ld: a box at %g m/s (bound %g)\n", s, speed, max_speed);
                return 1;
            }
            std::printf("step %ld: resident %.1f MiB, large blocks %.1f MiB, kinetic "
                        "%.6g J\n",
                        s, static_cast<double>(resident_bytes()) / (1 << 20),
                        static_cast<double>(large_array_stats().mapped_bytes) / (1 << 20),
                        world.kinetic_energy());
        }
    }
    const std::size_t rss_end = resident_bytes(), blocks_end = large_array_stats().mapped_bytes;
    if (grew(rss_warm, rss_end) || grew(blocks_warm, blocks_end)) {
        std::printf("FAIL memory grew: resident %zu -> %zu bytes, large blocks %zu "
                    "-> %zu bytes "
                    "(from step %ld to the end)\n",
                    rss_warm, rss_end, blocks_warm, blocks_end, warm);
        return 1;
    }
    std::printf("soak passed: finite states, memory bounded (resident %zu -> %zu "
                "bytes, large "
                "blocks %zu -> %zu bytes from step %ld)\n",
                rss_warm, rss_end, blocks_warm, blocks_end, warm);
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    const bool busy = argc > 1 && std::string(argv[1]) == "--busy";
    if (argc > 2 || (argc == 2 && !busy)) {
        std::fprintf(stderr, "usage: tamias_soak [--busy]   (steps: TAMIAS_SOAK_STEPS)\n");
        return 2;
    }
    if (busy)
        return soak::run_busy(fuzz::iterations("TAMIAS_SOAK_STEPS", 1000000));
    return run_rain(fuzz::iterations("TAMIAS_SOAK_STEPS", 10000));
}
