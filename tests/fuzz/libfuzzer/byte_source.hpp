// The fuzz input read as a stream of choices and numbers, for the libFuzzer targets. Written here
// rather than taken from Clang's <fuzzer/FuzzedDataProvider.h> so that the GCC build can replay
// the corpus through the same decoding. An exhausted input reads as zeros, so every byte string
// is a valid program of calls.
#pragma once

#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <iterator>

#include "fuzz/fuzz_support.hpp"

namespace tamias2d::fuzz {

class ByteSource {
  public:
    ByteSource(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}

    bool empty() const { return at_ >= size_; }

    std::uint8_t byte() { return at_ < size_ ? data_[at_++] : std::uint8_t{0}; }

    std::uint16_t word() {
        const auto hi = static_cast<std::uint16_t>(byte() << 8);
        return static_cast<std::uint16_t>(hi | byte());
    }

    /// In [0, n), n > 0 (n <= 256: one byte).
    std::size_t below(std::size_t n) { return n <= 256 ? byte() % n : word() % n; }

    bool flag() { return (byte() & 1u) != 0; }

    /// A double of any kind, chosen by one byte: a quarter of the time one of the values that
    /// break arithmetic (fuzz_support.hpp's extremes: NaN, infinities, denormals, 1e308, the
    /// supported range's bounds), half the time an ordinary value in [-128, 128) (a world that
    /// runs), else a value of any magnitude 1e-15..1e15, or any 64-bit pattern (every NaN
    /// payload and denormal).
    double real() {
        const std::uint8_t kind = byte();
        if (kind < 64)
            return extremes[kind % std::size(extremes)];
        if (kind < 192)
            return static_cast<double>(static_cast<std::int16_t>(word())) / 256.0;
        if (kind < 240) {
            const double mantissa = static_cast<double>(static_cast<std::int16_t>(word())) / 64.0;
            return mantissa * std::pow(10.0, static_cast<double>(byte() % 31) - 15.0);
        }
        std::uint64_t bits = 0;
        for (int i = 0; i < 8; ++i)
            bits = (bits << 8) | byte();
        return std::bit_cast<double>(bits);
    }

    /// Mostly in [0, 4) m (a size that makes a world run), sometimes any double.
    double size() {
        const std::uint8_t kind = byte();
        if (kind < 200)
            return 0.05 + static_cast<double>(kind) / 50.0;
        return real();
    }

    Vec2d vec() {
        const double x = real();
        return {x, real()};
    }

    /// Mostly a point near the origin ([-8, 8) m), sometimes any vector.
    Vec2d point() {
        if (flag())
            return vec();
        const double x = static_cast<double>(static_cast<std::int8_t>(byte())) / 16.0;
        return {x, static_cast<double>(static_cast<std::int8_t>(byte())) / 16.0};
    }

  private:
    const std::uint8_t* data_;
    std::size_t size_;
    std::size_t at_ = 0;
};

} // namespace tamias2d::fuzz
