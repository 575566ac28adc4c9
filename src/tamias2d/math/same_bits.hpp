#pragma once
#include <cstring>

namespace tamias2d::math {

/// Whether two doubles have the same bits: -0 and 0 differ, as they do to the state hash and to
/// a scene file's round trip, which are promised bit for bit. (memcmp, not std::bit_cast: the
/// WebAssembly build's libc++ has no bit_cast.)
inline bool same_bits(double a, double b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

} // namespace tamias2d::math
