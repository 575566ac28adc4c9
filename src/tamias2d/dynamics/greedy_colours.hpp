// Greedy colours of constraints by the bodies they join: each constraint in turn takes the
// lowest of 64 colours that no earlier one on its moving bodies took, so that constraints of one
// colour share no moving body. ConstraintGraph colours the manifolds between contact regions
// with it, PinPacks the pin joints' levels.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>

#include "tamias2d/memory/allocator.hpp"

namespace tamias2d {

class GreedyColours {
  public:
    static constexpr std::uint32_t colours = 64;

    /// Room for bodies [0, body_count); every body's colours are free between colourings.
    void cover(std::size_t body_count) {
        if (taken_.size() < body_count)
            taken_.resize(body_count, 0);
    }

    /// The lowest colour that neither body has taken, now taken on both; `colours` when all
    /// are (then none is taken). Body 0 stands for every immovable body: it takes no colour,
    /// so it bars none, and any number of constraints may hold it at once.
    std::uint32_t take(std::uint32_t a, std::uint32_t b) {
        const std::uint64_t used = (a != 0 ? taken_[a] : 0) | (b != 0 ? taken_[b] : 0);
        const auto c = std::uint32_t(std::countr_one(used));
        if (c < colours) {
            const std::uint64_t bit = std::uint64_t{1} << c;
            if (a != 0)
                taken_[a] |= bit;
            if (b != 0)
                taken_[b] |= bit;
        }
        return c;
    }

    /// Frees both bodies' colours: called for every constraint coloured, once the colouring is
    /// done, so that the next one starts free.
    void release(std::uint32_t a, std::uint32_t b) { taken_[a] = taken_[b] = 0; }

  private:
    memory::vector<std::uint64_t> taken_; ///< per body: the colours its constraints took
};

} // namespace tamias2d
