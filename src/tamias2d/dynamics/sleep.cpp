#include "tamias2d/dynamics/sleep.hpp"

#include <numeric>
#include <utility>

namespace tamias2d {

void Islands::reset(std::size_t n) {
    parent_.resize(n);
    std::iota(parent_.begin(), parent_.end(), std::uint32_t(0));
}

std::uint32_t Islands::find(std::uint32_t a) {
    while (parent_[a] != a) {
        parent_[a] = parent_[parent_[a]]; // path halving
        a = parent_[a];
    }
    return a;
}

void Islands::unite(std::uint32_t a, std::uint32_t b) {
    a = find(a);
    b = find(b);
    if (a == b)
        return;
    if (b < a)
        std::swap(a, b);
    parent_[b] = a;
}

} // namespace tamias2d
