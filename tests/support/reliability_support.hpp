// Shared pieces of the reliability tests (tests/reliability, tests/memory, the soaks of
// tests/fuzz): the process's resident set, whether a sanitizer that keeps freed memory (and so
// makes resident-set bounds meaningless) is in this build, and a small busy world built without
// scene files.
#pragma once

#include <cstddef>
#include <fstream>

#include <unistd.h>

#include "tamias2d/world.hpp"

namespace tamias2d::reliability {

/// Resident set size in bytes (Linux: /proc/self/statm, second field in pages), 0 elsewhere.
inline std::size_t resident_bytes() {
    std::ifstream statm("/proc/self/statm");
    std::size_t pages = 0, resident = 0;
    if (!(statm >> pages >> resident))
        return 0;
    return resident * static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
}

/// AddressSanitizer (its quarantine holds freed blocks) or ThreadSanitizer (its shadow memory
/// grows with the addresses touched): resident-set figures do not measure the library there.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
inline constexpr bool memory_sanitizer_build = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
inline constexpr bool memory_sanitizer_build = true;
#else
inline constexpr bool memory_sanitizer_build = false;
#endif
#else
inline constexpr bool memory_sanitizer_build = false;
#endif

/// A ground, a pyramid of `rows` rows of 1 m boxes and a heavy box flying at it: contacts begin
/// and end, the solver and the broad phase grow their arrays in the first steps.
inline World busy_world(int rows = 6) {
    WorldDef def;
    World world(def);
    BodyDef ground;
    ground.type = BodyType::static_body;
    ground.position = {0.0, -0.5};
    world.create_shape(world.create_body(ground), box_shape(60.0, 1.0, Material{1.0, 0.0, 0.6}));
    const Material wood{1.0, 0.5, 0.6};
    for (int row = 0; row < rows; ++row)
        for (int i = 0; i < rows - row; ++i) {
            BodyDef d;
            d.position = {(i - (rows - row - 1) * 0.5) * 1.05, 0.5 + row * 1.0};
            world.create_shape(world.create_body(d), box_shape(1.0, 1.0, wood));
        }
    BodyDef striker;
    striker.position = {-12.0, 2.0};
    striker.linear_velocity = {40.0, 0.0};
    world.create_shape(world.create_body(striker), box_shape(1.0, 1.0, Material{20.0, 0.0, 0.6}));
    return world;
}

} // namespace tamias2d::reliability
