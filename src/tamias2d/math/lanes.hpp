// Packs of doubles for compilers without GCC/Clang vector extensions (MSVC), or for any compiler
// when TAMIAS_PORTABLE_LANES is defined (the CMake option of that name: a GCC build of the
// portable path, to show that it gives the same bits). Plain structures of arrays with the
// operators the solver (math/wide.hpp) and the narrow phase (Duo) use: every operation is the
// vector extension's lane-wise IEEE operation, lane by lane, so the results are bit for bit
// those of the vector build.
#pragma once

#include <cstddef>
#include <cstdint>

/// 1: the packs are GCC/Clang vector extensions; 0: the portable structures below.
#if defined(TAMIAS_PORTABLE_LANES) || !defined(__GNUC__)
#define TAMIAS_GNU_LANES 0
#else
#define TAMIAS_GNU_LANES 1
#endif

namespace tamias2d::lanes {

/// N lane-wise comparison results: all bits set (true) or clear (false) per lane, as a vector
/// comparison gives them.
template <int N> struct alignas(N * sizeof(std::int64_t)) Mask {
    std::int64_t lane[N];

    constexpr std::int64_t& operator[](int l) { return lane[l]; }
    constexpr std::int64_t operator[](int l) const { return lane[l]; }

    friend constexpr Mask operator&(Mask a, Mask b) {
        Mask r{};
        for (int l = 0; l < N; ++l)
            r.lane[l] = a.lane[l] & b.lane[l];
        return r;
    }
    friend constexpr Mask operator|(Mask a, Mask b) {
        Mask r{};
        for (int l = 0; l < N; ++l)
            r.lane[l] = a.lane[l] | b.lane[l];
        return r;
    }
    friend constexpr Mask operator^(Mask a, Mask b) {
        Mask r{};
        for (int l = 0; l < N; ++l)
            r.lane[l] = a.lane[l] ^ b.lane[l];
        return r;
    }
    friend constexpr Mask operator~(Mask a) {
        Mask r{};
        for (int l = 0; l < N; ++l)
            r.lane[l] = ~a.lane[l];
        return r;
    }
    Mask& operator&=(Mask b) { return *this = *this & b; }
    Mask& operator|=(Mask b) { return *this = *this | b; }
    Mask& operator^=(Mask b) { return *this = *this ^ b; }
};

/// N doubles, aligned to their size like a vector of N doubles; brace-initialised from N values
/// ({} is all +0.0), lanes read and written with [].
template <int N> struct alignas(N * sizeof(double)) Doubles {
    double lane[N];

    constexpr double& operator[](int l) { return lane[l]; }
    constexpr double operator[](int l) const { return lane[l]; }

    friend constexpr Doubles operator+(Doubles a, Doubles b) {
        Doubles r{};
        for (int l = 0; l < N; ++l)
            r.lane[l] = a.lane[l] + b.lane[l];
        return r;
    }
    friend constexpr Doubles operator-(Doubles a, Doubles b) {
        Doubles r{};
        for (int l = 0; l < N; ++l)
            r.lane[l] = a.lane[l] - b.lane[l];
        return r;
    }
    friend constexpr Doubles operator*(Doubles a, Doubles b) {
        Doubles r{};
        for (int l = 0; l < N; ++l)
            r.lane[l] = a.lane[l] * b.lane[l];
        return r;
    }
    friend constexpr Doubles operator/(Doubles a, Doubles b) {
        Doubles r{};
        for (int l = 0; l < N; ++l)
            r.lane[l] = a.lane[l] / b.lane[l];
        return r;
    }
    /// The sign flipped (-0.0 for +0.0), as the vector negation.
    friend constexpr Doubles operator-(Doubles a) {
        Doubles r{};
        for (int l = 0; l < N; ++l)
            r.lane[l] = -a.lane[l];
        return r;
    }
    friend constexpr Doubles operator+(Doubles a) { return a; }
    // With a scalar, as the vector extensions do: x in every lane, then the lane-wise operation
    // (Boost.Units divides a quantity of packs by one radian, a quantity of double).
    static constexpr Doubles fill(double x) {
        Doubles r{};
        for (int l = 0; l < N; ++l)
            r.lane[l] = x;
        return r;
    }
    friend constexpr Doubles operator+(Doubles a, double x) { return a + fill(x); }
    friend constexpr Doubles operator-(Doubles a, double x) { return a - fill(x); }
    friend constexpr Doubles operator*(Doubles a, double x) { return a * fill(x); }
    friend constexpr Doubles operator/(Doubles a, double x) { return a / fill(x); }
    friend constexpr Doubles operator+(double x, Doubles a) { return fill(x) + a; }
    friend constexpr Doubles operator-(double x, Doubles a) { return fill(x) - a; }
    friend constexpr Doubles operator*(double x, Doubles a) { return fill(x) * a; }
    friend constexpr Doubles operator/(double x, Doubles a) { return fill(x) / a; }
    Doubles& operator+=(Doubles b) { return *this = *this + b; }
    Doubles& operator-=(Doubles b) { return *this = *this - b; }
    Doubles& operator*=(Doubles b) { return *this = *this * b; }
    Doubles& operator/=(Doubles b) { return *this = *this / b; }

    friend constexpr Mask<N> operator<(Doubles a, Doubles b) {
        Mask<N> r{};
        for (int l = 0; l < N; ++l)
            r.lane[l] = a.lane[l] < b.lane[l] ? -1 : 0;
        return r;
    }
    friend constexpr Mask<N> operator<=(Doubles a, Doubles b) {
        Mask<N> r{};
        for (int l = 0; l < N; ++l)
            r.lane[l] = a.lane[l] <= b.lane[l] ? -1 : 0;
        return r;
    }
    friend constexpr Mask<N> operator>(Doubles a, Doubles b) {
        Mask<N> r{};
        for (int l = 0; l < N; ++l)
            r.lane[l] = a.lane[l] > b.lane[l] ? -1 : 0;
        return r;
    }
    friend constexpr Mask<N> operator>=(Doubles a, Doubles b) {
        Mask<N> r{};
        for (int l = 0; l < N; ++l)
            r.lane[l] = a.lane[l] >= b.lane[l] ? -1 : 0;
        return r;
    }
    friend constexpr Mask<N> operator==(Doubles a, Doubles b) {
        Mask<N> r{};
        for (int l = 0; l < N; ++l)
            r.lane[l] = a.lane[l] == b.lane[l] ? -1 : 0;
        return r;
    }
    friend constexpr Mask<N> operator!=(Doubles a, Doubles b) {
        Mask<N> r{};
        for (int l = 0; l < N; ++l)
            r.lane[l] = a.lane[l] != b.lane[l] ? -1 : 0;
        return r;
    }
};

/// Lane by lane if_true where m is set, else if_false (the vector m ? if_true : if_false).
template <int N> constexpr Doubles<N> select(Mask<N> m, Doubles<N> if_true, Doubles<N> if_false) {
    Doubles<N> r{};
    for (int l = 0; l < N; ++l)
        r.lane[l] = m.lane[l] != 0 ? if_true.lane[l] : if_false.lane[l];
    return r;
}

} // namespace tamias2d::lanes
