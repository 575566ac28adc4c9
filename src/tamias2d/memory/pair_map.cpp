#include "tamias2d/memory/pair_map.hpp"

#include <algorithm>
#include <bit>
#include <utility>

namespace tamias2d {

std::size_t PairMap::probe(std::uint64_t key) const {
    std::size_t i = home(key);
    while (slots_[i].key != key && slots_[i].key != empty_key)
        i = (i + 1) & mask();
    return i;
}

std::uint32_t PairMap::find(std::uint64_t key) const {
    if (count_ == 0)
        return npos;
    const Slot& s = slots_[probe(key)];
    return s.key == key ? s.value : npos;
}

void PairMap::insert(std::uint64_t key, std::uint32_t value) {
    if (2 * (count_ + 1) > slots_.size())
        grow();
    Slot& s = slots_[probe(key)];
    s.key = key;
    s.value = value;
    ++count_;
}

void PairMap::assign(std::uint64_t key, std::uint32_t value) {
    slots_[probe(key)].value = value;
}

void PairMap::erase(std::uint64_t key) {
    if (count_ == 0)
        return;
    std::size_t gap = probe(key);
    if (slots_[gap].key != key)
        return;
    --count_;
    // Shift back every following entry of the run whose home is not after the gap (cyclically),
    // so that each stays reachable from its home without crossing an empty slot.
    for (std::size_t j = (gap + 1) & mask(); slots_[j].key != empty_key; j = (j + 1) & mask()) {
        const std::size_t dist_home = (j - home(slots_[j].key)) & mask();
        const std::size_t dist_gap = (j - gap) & mask();
        if (dist_home >= dist_gap) {
            slots_[gap] = slots_[j];
            gap = j;
        }
    }
    slots_[gap] = Slot{};
}

void PairMap::reserve(std::size_t n) {
    if (2 * n > slots_.size())
        grow(std::bit_ceil(2 * n));
}

void PairMap::grow(std::size_t size) {
    // The new array first: if it cannot be had (bad_alloc), the map is as it was.
    LargeArray<Slot> old;
    old.assign(std::max({size, slots_.empty() ? 64 : 2 * slots_.size()}), Slot{});
    std::swap(old, slots_);
    shift_ = 64 - std::countr_zero(slots_.size());
    for (const Slot& s : old) {
        if (s.key != empty_key)
            slots_[probe(s.key)] = s;
    }
}

} // namespace tamias2d
