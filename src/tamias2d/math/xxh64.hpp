// XXH64 (internal): the 64-bit xxHash of Yann Collet, written from its published specification
// (xxHash fast digest algorithm, "doc/xxhash_spec.md", version 0.1.1: the five primes, the
// 32-byte stripe of four accumulators, the merge, the tail and the avalanche). The snapshot's
// checksum: it reads 8 bytes per multiplication in four independent lanes, where FNV-1a's one
// dependent multiplication per byte made the checksum most of a snapshot's time. It guards
// against accidents (truncation, a flipped bit, bytes of something else), not an attacker.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>

namespace tamias2d {

namespace xxh64_detail {

inline constexpr std::uint64_t prime1 = 0x9E3779B185EBCA87ull;
inline constexpr std::uint64_t prime2 = 0xC2B2AE3D27D4EB4Full;
inline constexpr std::uint64_t prime3 = 0x165667B19E3779F9ull;
inline constexpr std::uint64_t prime4 = 0x85EBCA77C2B2AE63ull;
inline constexpr std::uint64_t prime5 = 0x27D4EB2F165667C5ull;

/// Little-endian reads, whatever the host (the specification reads lanes little-endian).
inline std::uint64_t read64(const std::byte* p) {
    std::uint64_t v = 0;
    if constexpr (std::endian::native == std::endian::little) {
        std::memcpy(&v, p, 8);
    } else {
        for (int k = 0; k < 8; ++k)
            v |= std::uint64_t(p[k]) << (8 * k);
    }
    return v;
}

inline std::uint64_t read32(const std::byte* p) {
    std::uint64_t v = 0;
    for (int k = 0; k < 4; ++k)
        v |= std::uint64_t(p[k]) << (8 * k);
    return v;
}

inline std::uint64_t round(std::uint64_t acc, std::uint64_t lane) {
    return std::rotl(acc + lane * prime2, 31) * prime1;
}

inline std::uint64_t merge(std::uint64_t acc, std::uint64_t lane_acc) {
    return (acc ^ round(0, lane_acc)) * prime1 + prime4;
}

} // namespace xxh64_detail

/// XXH64 of `bytes` with `seed`.
inline std::uint64_t xxh64(std::span<const std::byte> bytes, std::uint64_t seed = 0) {
    using namespace xxh64_detail;
    const std::byte* p = bytes.data();
    std::size_t n = bytes.size();
    std::uint64_t acc;
    if (n >= 32) {
        std::uint64_t v1 = seed + prime1 + prime2, v2 = seed + prime2, v3 = seed,
                      v4 = seed - prime1;
        for (; n >= 32; n -= 32, p += 32) {
            v1 = round(v1, read64(p));
            v2 = round(v2, read64(p + 8));
            v3 = round(v3, read64(p + 16));
            v4 = round(v4, read64(p + 24));
        }
        acc = std::rotl(v1, 1) + std::rotl(v2, 7) + std::rotl(v3, 12) + std::rotl(v4, 18);
        acc = merge(merge(merge(merge(acc, v1), v2), v3), v4);
    } else {
        acc = seed + prime5;
    }
    acc += std::uint64_t(bytes.size());
    for (; n >= 8; n -= 8, p += 8)
        acc = std::rotl(acc ^ round(0, read64(p)), 27) * prime1 + prime4;
    if (n >= 4) {
        acc = std::rotl(acc ^ (read32(p) * prime1), 23) * prime2 + prime3;
        n -= 4;
        p += 4;
    }
    for (; n > 0; --n, ++p)
        acc = std::rotl(acc ^ (std::uint64_t(*p) * prime5), 11) * prime1;
    acc ^= acc >> 33;
    acc *= prime2;
    acc ^= acc >> 29;
    acc *= prime3;
    acc ^= acc >> 32;
    return acc;
}

} // namespace tamias2d
