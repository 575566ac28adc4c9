// A snapshot's encoding (internal): the writer and the reader each store's snapshot functions
// use (World::snapshot, World::restore). Every field is written in an explicit little-endian
// form, whatever the platform: integers byte by byte, doubles as the bits of their IEEE-754
// binary64 form, bools as one byte 0 or 1, enums as their underlying integer. A store describes
// each of its records once, in a function template over the writer and the reader alike
// (`io(name, field)` for every field), so that a field added to a record is added to the
// snapshot in that one place; counts, indices and the checks of what a record may hold are the
// store's read function's (beside its hash function, which feeds the state hash the same state).
//
// The reader never reads past its bytes: every read is bounds-checked, every count is checked
// against the bytes left before anything is allocated for it, every index against its range;
// a defect throws SnapshotError naming the byte offset, the field and the rule.
#pragma once

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "tamias2d/aabb.hpp"
#include "tamias2d/math/vec2d.hpp"
#include "tamias2d/memory/allocator.hpp"
#include "tamias2d/snapshot_error.hpp"

namespace tamias2d {

/// n in decimal: the snapshot messages' numbers (a loop of its own, so that no std::to_string
/// instantiation is emitted out of line and exported from the shared library).
inline std::string decimal(std::uint64_t n) {
    char buf[20];
    int k = 20;
    do {
        buf[--k] = char('0' + n % 10);
        n /= 10;
    } while (n != 0);
    return std::string(buf + k, buf + 20);
}

class SnapshotWriter {
  public:
    /// A writer into a buffer of its own, from the library's allocator (memory/allocator.hpp).
    SnapshotWriter() = default;
    /// A writer into the caller's `storage` (its contents are overwritten; finish() leaves the
    /// bytes in it): a caller that takes snapshots again and again (rollback) hands the last
    /// one's vector back, so that its pages are written, not allocated and zeroed anew.
    explicit SnapshotWriter(std::vector<std::byte>& storage) : user_(&storage) {
        resize(storage.capacity());
    }
    SnapshotWriter(SnapshotWriter&&) noexcept = default;
    SnapshotWriter& operator=(SnapshotWriter&&) noexcept = default;
    SnapshotWriter(const SnapshotWriter&) = delete;
    SnapshotWriter& operator=(const SnapshotWriter&) = delete;
    /// Room for `n` bytes in all, so that a writer that knows about how much it writes grows
    /// its buffer once.
    void reserve(std::size_t n) {
        if (n > size_)
            resize(n);
    }
    /// The number of bytes written.
    std::size_t size() const { return used_; }
    /// The bytes written so far (valid until the next write).
    std::span<std::byte> written() { return {data_, used_}; }
    std::span<const std::byte> written() const { return {data_, used_}; }
    /// Bytes as they are (a snapshot inside a recording).
    void append(std::span<const std::byte> b) {
        if (size_ - used_ < b.size())
            grow(b.size());
        std::copy(b.begin(), b.end(), data_ + used_);
        used_ += b.size();
    }
    /// The bytes written, handed over (a writer of its own buffer); the writer is empty after.
    memory::vector<std::byte> finish() {
        own_.resize(used_);
        used_ = 0;
        data_ = nullptr;
        size_ = 0;
        return std::move(own_);
    }
    /// The bytes written left in the caller's storage, of exactly their size (a writer into
    /// the caller's vector).
    void finish_in_storage() {
        user_->resize(used_);
        used_ = 0;
    }

    void u8(std::uint8_t v) { le(v, 1); }
    void u32(std::uint32_t v) { le(v, 4); }
    void u64(std::uint64_t v) { le(v, 8); }
    /// A section's tag, four letters: a reader names the section it expected.
    void section(const char (&tag)[5]) {
        for (int k = 0; k < 4; ++k)
            u8(std::uint8_t(tag[k]));
    }
    /// The number of records that follow.
    void count(const char*, std::size_t n) { u64(n); }

    void operator()(const char*, double v) {
        std::uint64_t bits = 0;
        std::memcpy(&bits, &v, sizeof bits); // (no std::bit_cast in the WebAssembly libc++)
        u64(bits);
    }
    void operator()(const char*, bool v) { u8(v ? 1 : 0); }
    void operator()(const char*, std::uint8_t v) { u8(v); }
    void operator()(const char*, std::int8_t v) { u8(std::uint8_t(v)); }
    void operator()(const char*, std::uint16_t v) { le(v, 2); }
    void operator()(const char*, std::uint32_t v) { u32(v); }
    void operator()(const char*, std::int32_t v) { u32(std::uint32_t(v)); }
    void operator()(const char*, std::uint64_t v) { u64(v); }
    void operator()(const char* f, Vec2d v) {
        (*this)(f, v.x);
        (*this)(f, v.y);
    }
    void operator()(const char* f, Rot q) {
        (*this)(f, q.c);
        (*this)(f, q.s);
    }
    void operator()(const char* f, const Transform& t) {
        (*this)(f, t.p);
        (*this)(f, t.q);
    }
    void operator()(const char* f, const Aabb& b) {
        for (const double x : {b.min_x, b.min_y, b.max_x, b.max_y})
            (*this)(f, x);
    }
    void operator()(const char* f, const std::optional<double>& v) {
        (*this)(f, v.has_value());
        if (v)
            (*this)(f, *v);
    }
    void operator()(const char* f, const std::optional<Vec2d>& v) {
        (*this)(f, v.has_value());
        if (v)
            (*this)(f, *v);
    }
    /// A UserData (pointer-sized) as 64 bits.
    void user_data(const char*, std::uintptr_t v) { u64(std::uint64_t(v)); }
    void operator()(const char*, const std::string& s) {
        u64(s.size());
        for (const char c : s)
            u8(std::uint8_t(c));
    }
    /// An enum as its underlying integer; `last` is its largest value (the reader's check).
    template <class E> void enumeration(const char* f, E v, E /*last*/) {
        (*this)(f, static_cast<std::underlying_type_t<E>>(v));
    }
    /// An index (or null_index, with `null` true), checked by the reader against `limit`.
    void index(const char*, std::uint32_t v, std::uint32_t /*limit*/, bool /*null*/ = false) {
        u32(v);
    }
    /// A handle (BodyId, ShapeId, JointId) as its index and generation: its world tag is the
    /// world's, not the simulation's (the reader gives it the reading world's).
    template <class Id> void handle(const char*, const Id& id) {
        u32(id.index);
        u32(id.generation);
    }

  private:
    /// The n low bytes of v, least significant first (on a little-endian host, as they lie).
    /// Every field passes here: a cursor into a buffer grown by doubling, so that a write is a
    /// comparison and a store (a vector's resize per field was most of a snapshot's time).
    void le(std::uint64_t v, int n) {
        if (size_ - used_ < std::size_t(n)) [[unlikely]]
            grow(std::size_t(n));
        std::byte* at = data_ + used_;
        if constexpr (std::endian::native == std::endian::little) {
            std::memcpy(at, &v, std::size_t(n));
        } else {
            for (int k = 0; k < n; ++k)
                at[k] = std::byte(v >> (8 * k));
        }
        used_ += std::size_t(n);
    }
    [[gnu::noinline]] void grow(std::size_t n) {
        resize(std::max({2 * size_, used_ + n, std::size_t{4096}}));
    }
    /// The buffer (the caller's or its own) holding n bytes, the written ones kept.
    void resize(std::size_t n) {
        if (user_ != nullptr) {
            user_->resize(n);
            data_ = user_->data();
        } else {
            own_.resize(n);
            data_ = own_.data();
        }
        size_ = n;
    }

    std::vector<std::byte>* user_ = nullptr; ///< the caller's storage, or none: own_
    memory::vector<std::byte> own_;
    std::byte* data_ = nullptr; ///< the buffer: written bytes, then room
    std::size_t size_ = 0;      ///< the buffer's size
    std::size_t used_ = 0;      ///< bytes written
};

class SnapshotReader {
  public:
    /// The payload `bytes`, which start at byte `base` of the snapshot (for the offsets the
    /// errors name).
    SnapshotReader(std::span<const std::byte> bytes, std::size_t base, std::uint32_t world)
        : world_(world), bytes_(bytes), base_(base) {}

    /// The record the fields read next belong to, for the errors' field names: "bodies", 3
    /// makes field "v" "bodies[3].v". A null record: top-level fields.
    void in(const char* record, std::size_t index = 0) {
        record_ = record;
        index_ = index;
    }
    std::size_t offset() const { return base_ + at_; }
    std::size_t left() const { return bytes_.size() - at_; }

    [[noreturn]] void fail(const char* field, const std::string& rule) const {
        fail_at(offset(), field, rule);
    }
    [[noreturn]] void fail_at(std::size_t offset, const char* field,
                              const std::string& rule) const {
        std::string name =
            record_ ? std::string(record_) + "[" + decimal(std::uint64_t(index_)) + "]" : "";
        if (field && *field)
            name += (name.empty() ? "" : ".") + std::string(field);
        throw SnapshotError(offset, name, rule);
    }
    /// Throws (naming `field` at the offset where its value began) unless `ok`.
    void require(bool ok, const char* field, const std::string& rule, std::size_t at) const {
        if (!ok)
            fail_at(at, field, rule);
    }
    /// The same for a rule that is a literal: no string is made unless it fails (the checks
    /// run per record).
    void require(bool ok, const char* field, const char* rule, std::size_t at) const {
        if (!ok) [[unlikely]]
            fail_at(at, field, rule);
    }

    std::uint8_t u8(const char* f) { return std::uint8_t(le(f, 1)); }
    std::uint32_t u32(const char* f) { return std::uint32_t(le(f, 4)); }
    std::uint64_t u64(const char* f) { return le(f, 8); }
    void section(const char (&tag)[5]) {
        const std::size_t at = offset();
        for (int k = 0; k < 4; ++k)
            if (u8("section") != std::uint8_t(tag[k])) {
                // Spelled into a buffer: GCC 12 takes std::string("...") + tag, inlined in
                // the ThreadSanitizer build, for a write past the string (-Warray-bounds).
                char rule[] = "must be the section '....'";
                std::copy(tag, tag + 4, rule + sizeof "must be the section '" - 1);
                fail_at(at, "section", rule);
            }
    }
    /// A count of records of at least `bytes_each` bytes each: no more than the bytes left
    /// can hold (so that a forged count allocates nothing), nor more than `most`.
    std::size_t count(const char* f, std::size_t bytes_each, std::size_t most = ~std::size_t{0}) {
        const std::size_t at = offset();
        const std::uint64_t n = u64(f);
        if (n > most)
            fail_at(at, f, "must be <= " + decimal(std::uint64_t(most)));
        if (bytes_each > 0 && n > left() / bytes_each)
            fail_at(at, f,
                    "must fit in the " + decimal(std::uint64_t(left())) + " bytes left (" +
                        decimal(std::uint64_t(bytes_each)) + " bytes or more each)");
        return std::size_t(n);
    }

    void operator()(const char* f, double& v) {
        const std::uint64_t bits = le(f, 8);
        std::memcpy(&v, &bits, sizeof v); // (no std::bit_cast in the WebAssembly libc++)
    }
    void operator()(const char* f, bool& v) {
        const std::size_t at = offset();
        const std::uint8_t b = u8(f);
        if (b > 1)
            fail_at(at, f, "must be 0 or 1 (a bool)");
        v = b == 1;
    }
    void operator()(const char* f, std::uint8_t& v) { v = u8(f); }
    void operator()(const char* f, std::int8_t& v) { v = std::int8_t(u8(f)); }
    void operator()(const char* f, std::uint16_t& v) { v = std::uint16_t(le(f, 2)); }
    void operator()(const char* f, std::uint32_t& v) { v = u32(f); }
    void operator()(const char* f, std::int32_t& v) { v = std::int32_t(u32(f)); }
    void operator()(const char* f, std::uint64_t& v) { v = u64(f); }
    void operator()(const char* f, Vec2d& v) {
        (*this)(f, v.x);
        (*this)(f, v.y);
    }
    void operator()(const char* f, Rot& q) {
        (*this)(f, q.c);
        (*this)(f, q.s);
    }
    void operator()(const char* f, Transform& t) {
        (*this)(f, t.p);
        (*this)(f, t.q);
    }
    void operator()(const char* f, Aabb& b) {
        for (double* x : {&b.min_x, &b.min_y, &b.max_x, &b.max_y})
            (*this)(f, *x);
    }
    void operator()(const char* f, std::optional<double>& v) {
        bool has = false;
        (*this)(f, has);
        v.reset();
        if (has) {
            double x = 0.0;
            (*this)(f, x);
            v = x;
        }
    }
    void operator()(const char* f, std::optional<Vec2d>& v) {
        bool has = false;
        (*this)(f, has);
        v.reset();
        if (has) {
            Vec2d x{};
            (*this)(f, x);
            v = x;
        }
    }
    /// A UserData written as 64 bits; refused if it does not fit this platform's UserData.
    void user_data(const char* f, std::uintptr_t& v) {
        const std::size_t at = offset();
        const std::uint64_t u = u64(f);
        if (u > std::uint64_t(std::numeric_limits<std::uintptr_t>::max()))
            fail_at(at, f, "must fit in a UserData (std::uintptr_t) of this platform");
        v = std::uintptr_t(u);
    }
    void operator()(const char* f, std::string& s) {
        const std::size_t n = count(f, 1);
        s.resize(n);
        for (std::size_t k = 0; k < n; ++k)
            s[k] = char(u8(f));
    }
    template <class E> void enumeration(const char* f, E& v, E last) {
        using U = std::underlying_type_t<E>;
        const std::size_t at = offset();
        U u{};
        (*this)(f, u);
        if (u < U{} || u > static_cast<U>(last))
            fail_at(at, f,
                    "must be an enum value in [0, " + decimal(std::uint64_t(int(last))) + "]");
        v = static_cast<E>(u);
    }
    /// An index < `limit` (or null_index if `null`).
    void index(const char* f, std::uint32_t& v, std::uint32_t limit, bool null = false) {
        const std::size_t at = offset();
        v = u32(f);
        if (!(v < limit || (null && v == 0xFFFFFFFFu)))
            fail_at(at, f,
                    "must be < " + decimal(std::uint64_t(limit)) +
                        (null ? " or null (4294967295)" : ""));
    }
    std::uint32_t index(const char* f, std::uint32_t limit, bool null = false) {
        std::uint32_t v = 0;
        index(f, v, limit, null);
        return v;
    }
    /// A handle written by SnapshotWriter::handle, tagged with the reading world's tag.
    template <class Id> void handle(const char* f, Id& id) {
        id.index = u32(f);
        id.generation = u32(f);
        id.world = world_;
    }

  private:
    std::uint64_t le(const char* f, int n) {
        if (left() < std::size_t(n)) [[unlikely]]
            cut_short(f, n);
        std::uint64_t v = 0;
        if constexpr (std::endian::native == std::endian::little) {
            std::memcpy(&v, bytes_.data() + at_, std::size_t(n));
        } else {
            for (int k = 0; k < n; ++k)
                v |= std::uint64_t(bytes_[at_ + std::size_t(k)]) << (8 * k);
        }
        at_ += std::size_t(n);
        return v;
    }

    /// Out of line, so that every field's read stays a bounds check and a load.
    [[noreturn, gnu::cold, gnu::noinline]] void cut_short(const char* f, int n) const {
        fail(f, "cut short: " + decimal(std::uint64_t(n)) + " bytes needed, " +
                    decimal(std::uint64_t(left())) + " left (truncated)");
    }

    std::uint32_t world_; ///< the tag of the world read into (its handles')
    std::span<const std::byte> bytes_;
    std::size_t base_;
    std::size_t at_ = 0;
    const char* record_ = nullptr;
    std::size_t index_ = 0;
};

} // namespace tamias2d
