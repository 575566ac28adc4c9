// The state hash's accumulator (internal): FNV-1a over the bytes each store feeds it, in the
// order World::state_hash calls the stores (each store hashes its own state).
#pragma once

#include <cstddef>
#include <cstdint>

#include "tamias2d/math/vec2d.hpp"

namespace tamias2d {

struct StateHasher {
    std::uint64_t h = 1469598103934665603ull;
    void bytes(const void* p, std::size_t n) {
        const auto* c = static_cast<const unsigned char*>(p);
        for (std::size_t i = 0; i < n; ++i) {
            h ^= c[i];
            h *= 1099511628211ull;
        }
    }
    void operator()(double v) { bytes(&v, sizeof v); }
    void operator()(Vec2d v) {
        (*this)(v.x);
        (*this)(v.y);
    }
    void operator()(std::uint64_t v) { bytes(&v, sizeof v); }
};

} // namespace tamias2d
