// The xxHash project's own XXH64 (libxxhash.so.0, Debian's libxxhash0, which apt itself depends
// on), loaded at run time: an implementation of the snapshot's checksum apart from the
// library's (src/tamias2d/math/xxh64.hpp), for tests that check it or forge a right checksum.
#pragma once

#include <dlfcn.h>

#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>

namespace tamias_test {

/// XXH64(bytes, seed) as libxxhash computes it; throws when the library cannot be loaded.
inline std::uint64_t reference_xxh64(std::span<const std::byte> bytes, std::uint64_t seed) {
    using Fn = unsigned long long (*)(const void*, std::size_t, unsigned long long);
    static const Fn fn = [] {
        void* lib = dlopen("libxxhash.so.0", RTLD_NOW | RTLD_LOCAL);
        if (lib == nullptr)
            throw std::runtime_error("libxxhash.so.0 (Debian's libxxhash0) cannot be loaded");
        void* sym = dlsym(lib, "XXH64");
        if (sym == nullptr)
            throw std::runtime_error("libxxhash.so.0 has no XXH64");
        return reinterpret_cast<Fn>(sym);
    }();
    return fn(bytes.data(), bytes.size(), seed);
}

} // namespace tamias_test
