// libFuzzer target: the input is a snapshot (World::from_snapshot, World::restore). Its first
// byte chooses how the rest is read: odd, its checksum is made right first (so that a change
// reaches the sections' reader, not only the checksum's refusal); even, as it is.
//
// Oracle: the library's stated promises (include/tamias2d/world.hpp, "snapshot";
// docs/user-guide.md, "Determinism, snapshots and replays"): no crash and no sanitizer report;
// a refused snapshot is a SnapshotError naming a field, and World::restore then leaves the world
// bitwise as it was (state_hash() and snapshot()); an accepted one is read whole: the world's
// own snapshot is the same bytes (but the writer's library version, the checksum and a body's
// has_load flag, since a load function is not data), and reads back as itself; restore
// into another world gives the same state, and a small one steps (or refuses a step with a
// library error) a few times.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "fuzz/libfuzzer/promise.hpp"
#include "tamias2d/errors.hpp"
#include "tamias2d/math/xxh64.hpp"
#include "tamias2d/world.hpp"

using namespace tamias2d;
using namespace tamias2d::fuzz;

namespace {

constexpr std::size_t max_bodies_stepped = 200;

/// The snapshot's checksum made right: XXH64 of the payload seeded with that of the header's
/// first 24 bytes.
void fix_checksum(std::vector<std::byte>& b) {
    if (b.size() < 32)
        return;
    const std::span<const std::byte> all(b);
    const std::uint64_t h = tamias2d::xxh64(all.subspan(32), tamias2d::xxh64(all.first(24)));
    for (int k = 0; k < 8; ++k)
        b[24 + std::size_t(k)] = std::byte(h >> (8 * k));
}

/// A world to restore into: one body on a ground, stepped once.
World& target() {
    static World w = [] {
        World t;
        BodyDef ground;
        ground.type = BodyType::static_body;
        t.create_shape(t.create_body(ground), box_shape(10.0, 1.0));
        BodyDef box;
        box.position = {0.0, 1.0};
        t.create_shape(t.create_body(box), box_shape(1.0, 1.0));
        t.step(1.0 / 60.0);
        return t;
    }();
    return w;
}

bool same_but_version(std::span<const std::byte> a, std::span<const std::byte> b) {
    if (a.size() != b.size() || a.size() < 32)
        return false;
    for (std::size_t k = 0; k < a.size(); ++k)
        if ((k < 12 || (k >= 16 && k < 24) || k >= 32) && a[k] != b[k])
            return false;
    return true;
}

/// Whether `again`, an accepted snapshot's write-back, differs from the snapshot `read` only
/// where the world cannot hold what it says: a body's has_load flag (a load function is code,
/// not data, and a world from from_snapshot has none: docs/user-guide.md, "What it does not
/// hold"), 1 read, 0 written, at most once per body. Anything else must be the same bytes (but
/// the writer's library version and the checksum).
bool same_but_loads(std::span<const std::byte> read, std::span<const std::byte> again,
                    std::size_t bodies) {
    if (read.size() != again.size() || read.size() < 32)
        return false;
    std::size_t dropped = 0;
    for (std::size_t k = 0; k < read.size(); ++k) {
        if ((k >= 12 && k < 16) || (k >= 24 && k < 32) || read[k] == again[k])
            continue;
        if (read[k] != std::byte{1} || again[k] != std::byte{0} || ++dropped > bodies)
            return false;
    }
    return true;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0)
        return 0;
    std::vector<std::byte> bytes(size - 1);
    for (std::size_t k = 1; k < size; ++k)
        bytes[k - 1] = std::byte(data[k]);
    if (data[0] & 1)
        fix_checksum(bytes);

    World& t = target();
    const std::uint64_t hash = t.state_hash();
    const std::vector<std::byte> before = t.snapshot();
    std::optional<World> w;
    try {
        w.emplace(World::from_snapshot(bytes));
    } catch (const SnapshotError& e) {
        if (e.field.empty() || std::string(e.what()).empty())
            broken_promise("SnapshotError without a field or message");
        try {
            t.restore(bytes);
            broken_promise("restore accepted what from_snapshot refused");
        } catch (const SnapshotError&) {
        }
        if (t.state_hash() != hash || t.snapshot() != before)
            broken_promise("a refused restore changed the world");
        return 0;
    } catch (const std::exception& e) {
        broken_promise(std::string("from_snapshot refused with a non-SnapshotError: ") + e.what());
    }
    const std::vector<std::byte> again = w->snapshot();
    if (!same_but_loads(bytes, again, w->body_count()))
        broken_promise("an accepted snapshot does not write back as the same bytes");
    // What it writes back reads back as itself (the load flags dropped once and for all).
    if (!same_but_version(again, World::from_snapshot(again).snapshot()))
        broken_promise("a written-back snapshot does not read back as the same bytes");
    World other;
    other.restore(bytes);
    if (other.state_hash() != w->state_hash())
        broken_promise("restore and from_snapshot give different worlds");
    if (w->body_count() <= max_bodies_stepped) {
        for (int s = 0; s < 3; ++s) {
            try {
                w->step(1.0 / 60.0);
            } catch (const std::exception&) { // a state the step refuses (ValidationError...)
                break;
            }
        }
    }
    return 0;
}
