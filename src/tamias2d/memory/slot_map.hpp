// Generational slots (internal), the one handle scheme of the body, shape and joint stores:
// which slots are live, each slot's generation, the free slots, and the tag of the world whose
// handles they are. A store keeps its elements in arrays of its own indexed by slot (grown to
// size() after acquire); the slot map issues and checks the handles. Box2D keeps the same
// concerns in id_pool.c and its handles' world0 and generation fields.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "tamias2d/errors.hpp"
#include "tamias2d/handles.hpp"
#include "tamias2d/memory/allocator.hpp"

namespace tamias2d {

/// How messages name a handle's type.
constexpr const char* handle_type_name(BodyId) {
    return "BodyId";
}
constexpr const char* handle_type_name(ShapeId) {
    return "ShapeId";
}
constexpr const char* handle_type_name(JointId) {
    return "JointId";
}

/// How messages name a handle: "BodyId 3:2" (index and generation).
template <class Id> std::string handle_text(Id id) {
    return std::string(handle_type_name(id)) + " " + std::to_string(id.index) + ":" +
           std::to_string(id.generation);
}

template <class Id> class SlotMap {
  public:
    /// Room for n slots, and n freed ones, without growing (WorldDef::capacity).
    void reserve(std::size_t n) {
        slots_.reserve(n);
        free_.reserve(n);
    }
    /// The slots of the world tagged `world` (never 0: a default handle names no world).
    explicit SlotMap(std::uint32_t world) : world_(world) {}

    std::uint32_t world() const { return world_; }
    /// The slots ever used, live or free: the size of the store's arrays.
    std::uint32_t size() const { return std::uint32_t(slots_.size()); }
    std::uint32_t live_count() const { return live_count_; }
    bool live(std::uint32_t i) const { return slots_[i].live; }
    /// Which use of slot i this is (0: never used); a new use of a slot counts one more.
    std::uint32_t generation(std::uint32_t i) const { return slots_[i].generation; }

    /// A slot for a new element, live from now on under a new generation: the last one freed,
    /// or else a new slot at the end (index size() - 1: the store grows its arrays to size()).
    std::uint32_t acquire() {
        std::uint32_t i;
        if (!free_.empty()) {
            i = free_.back();
            free_.pop_back();
        } else {
            i = size();
            slots_.push_back({});
        }
        ++slots_[i].generation;
        slots_[i].live = true;
        ++live_count_;
        return i;
    }
    /// Frees live slot i: its handles are no longer valid, and the slot is acquired next.
    void release(std::uint32_t i) {
        slots_[i].live = false;
        free_.push_back(i);
        --live_count_;
    }

    /// The handle of live slot i.
    Id id(std::uint32_t i) const { return Id{i, slots_[i].generation, world_}; }
    /// \srs{R1} A handle names one element of this world, and only while it lives: a destroyed
    /// element's handle, one of a reused slot's earlier generation, one never issued and one
    /// of another world are not valid.
    bool is_valid(Id id) const {
        return id.world == world_ && id.index < size() && slots_[id.index].live &&
               slots_[id.index].generation == id.generation;
    }
    /// Throws WrongWorld for a handle another world issued, InvalidHandle for any other handle
    /// that is not valid (is_valid).
    void check(Id id) const {
        if (is_valid(id))
            return;
        if (id.world != 0 && id.world != world_)
            throw WrongWorld(handle_text(id), id.world, world_);
        throw InvalidHandle("stale or unknown " + handle_text(id));
    }

    // --- snapshot (World::snapshot, World::restore; dynamics/snapshot_io.hpp) ---
    // The world tag is not written: it is the world's, not the simulation's, so that handles
    // issued before a snapshot stay valid in the world restored from it, and a world built
    // from it issues handles of its own tag.
    /// Writes each slot's life and generation, then the free slots in their order.
    template <class Writer> void write(Writer& out) const {
        out.count("slots", slots_.size());
        for (const Slot& s : slots_) {
            out("slot.live", s.live);
            out("slot.generation", s.generation);
        }
        out.count("free_slots", free_.size());
        for (const std::uint32_t f : free_)
            out.index("free_slot", f, size());
    }
    /// Reads what write wrote into these slots (the tag kept); throws SnapshotError for a live
    /// slot of generation 0, or free slots that are not the dead slots, each once.
    template <class Reader> void read(Reader& in) {
        // At most 0xFFFFFFFE slots: every index stays below null_index.
        const std::size_t n = in.count("slots", 5, 0xFFFFFFFEu);
        slots_.assign(n, Slot{});
        live_count_ = 0;
        for (Slot& s : slots_) {
            const std::size_t at = in.offset();
            in("slot.live", s.live);
            in("slot.generation", s.generation);
            in.require(s.generation != 0, "slot.generation",
                       "must be at least 1 (a slot is in use from its first generation on)", at);
            live_count_ += s.live ? 1 : 0;
        }
        const std::size_t free = in.count("free_slots", 4, n);
        free_.resize(free);
        memory::vector<std::uint8_t> listed(n, 0);
        for (std::uint32_t& f : free_) {
            const std::size_t at = in.offset();
            in.index("free_slot", f, size());
            in.require(!slots_[f].live && !listed[f], "free_slot",
                       "must list dead slots, each once", at);
            listed[f] = 1;
        }
        in.require(free == n - live_count_, "free_slots", "must list every dead slot", in.offset());
    }

  private:
    struct Slot {
        std::uint32_t generation = 0;
        bool live = false;
    };
    memory::vector<Slot> slots_;
    memory::vector<std::uint32_t> free_; ///< freed slots, the last freed last
    std::uint32_t live_count_ = 0;
    std::uint32_t world_;
};

} // namespace tamias2d
