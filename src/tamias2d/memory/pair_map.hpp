// The world's index of contacts by shape pair: a hash map from a 64-bit pair key to a 32-bit
// contact index, open addressing with linear probing in one flat array. std::unordered_map
// allocated a node per contact and chased two pointers per lookup; at 16k boxes the broad
// phase looks up about 1500 new pairs a step, each a cache miss or more (docs/performance.md).
// Deletion shifts the following entries back (no tombstones), so a steady state never rehashes
// and never allocates. Iteration order is not offered: nothing may depend on it.
#pragma once

#include <cstddef>
#include <cstdint>

#include "tamias2d/math/prefetch.hpp"
#include "tamias2d/memory/large_array.hpp"

namespace tamias2d {

class PairMap {
  public:
    /// Room for n keys without growing (the probing is the same at any size: a key's contact
    /// never depends on it).
    void reserve(std::size_t n);
    static constexpr std::uint32_t npos = ~std::uint32_t{0};
    /// The one key a pair never makes (Contact::key puts the smaller index first).
    static constexpr std::uint64_t empty_key = ~std::uint64_t{0};

    /// The value stored for `key`, or npos.
    std::uint32_t find(std::uint64_t key) const;
    bool contains(std::uint64_t key) const { return find(key) != npos; }
    /// A cache hint for a coming lookup of `key`: its home slot.
    void prefetch(std::uint64_t key) const {
        if (!slots_.empty())
            tamias2d::prefetch(&slots_[home(key)]);
    }
    /// Adds `key` (absent; not empty_key) with `value`.
    void insert(std::uint64_t key, std::uint32_t value);
    /// Replaces the value of `key` (present).
    void assign(std::uint64_t key, std::uint32_t value);
    /// Removes `key` if present.
    void erase(std::uint64_t key);
    std::size_t size() const { return count_; }

  private:
    struct Slot {
        std::uint64_t key = empty_key;
        std::uint32_t value = 0;
    };
    /// Fibonacci hashing: the top bits of key * 2^64 / phi, spread whatever the pair's pattern.
    std::size_t home(std::uint64_t key) const {
        return std::size_t((key * 0x9E3779B97F4A7C15ULL) >> shift_);
    }
    std::size_t mask() const { return slots_.size() - 1; }
    /// The slot holding `key`, or the empty slot where its probe ends.
    std::size_t probe(std::uint64_t key) const;
    /// Twice the slots (64 at first), or `size` (a power of two) if that is more.
    void grow(std::size_t size = 0);

    LargeArray<Slot> slots_; ///< a power of two, at most half full
    std::size_t count_ = 0;
    int shift_ = 64;
};

} // namespace tamias2d
