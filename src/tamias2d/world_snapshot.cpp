// World::snapshot, World::from_snapshot, World::restore: a world's whole state as bytes and
// back. The format (docs/user-guide.md, "Determinism, snapshots and replays"):
//
//   offset  0: magic, the 8 bytes "T2D-SNAP"
//   offset  8: u32 format version (World::snapshot_format_version)
//   offset 12: u32 library version that wrote it, major << 16 | minor << 8 | patch
//   offset 16: u64 payload size in bytes
//   offset 24: u64 checksum: XXH64 of the payload, seeded with the XXH64 (seed 0) of the
//              header's first 24 bytes
//   offset 32: payload: the world's settings and time, then each store's section (BODY, SHAP
//              with the broad phase BRPH, CONT, JOIN, SENS, EVNT), each written and read by the
//              store itself beside its hash function.
//
// All little-endian (dynamics/snapshot_io.hpp). A snapshot is read into a new engine state
// first; only a snapshot read whole replaces the world's, so that a refused one changes nothing.
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "tamias2d/dynamics/snapshot_io.hpp"
#include "tamias2d/math/xxh64.hpp"
#include "tamias2d/memory/allocator.hpp"
#include "tamias2d/snapshot_error.hpp"
#include "tamias2d/validation.hpp"
#include "tamias2d/version.hpp"
#include "tamias2d/world.hpp"
#include "tamias2d/world_impl.hpp"

namespace tamias2d {

namespace {

constexpr char magic[8] = {'T', '2', 'D', '-', 'S', 'N', 'A', 'P'};
constexpr std::size_t header_size = 32;
constexpr std::uint32_t library_version_code = std::uint32_t(TAMIAS2D_VERSION_MAJOR) << 16 |
                                               std::uint32_t(TAMIAS2D_VERSION_MINOR) << 8 |
                                               std::uint32_t(TAMIAS2D_VERSION_PATCH);

/// The world's settings in the snapshot's order (the writer and the reader both call it): the
/// one place a setting added to WorldDef is added to snapshots. The workers and the task system
/// are the host's, not the simulation's: they are not written.
template <class IO, class D> void world_def_fields(IO& io, D& d) {
    io("gravity", d.gravity);
    io("substeps", d.substeps);
    io("contact_hertz", d.contact_hertz);
    io("contact_damping_ratio", d.contact_damping_ratio);
    io("contact_push_max_velocity", d.contact_push_max_velocity);
    io("joint_hertz", d.joint_hertz);
    io("joint_damping_ratio", d.joint_damping_ratio);
    io("linear_slop", d.linear_slop);
    io("speculative_distance", d.speculative_distance);
    io("manifold_reuse_distance", d.manifold_reuse_distance);
    io("contact_regions", d.contact_regions);
    io("enable_continuous", d.enable_continuous);
    io("restitution_threshold", d.restitution_threshold);
    io("hit_event_threshold", d.hit_event_threshold);
    io("enable_sleep", d.enable_sleep);
    io("time_to_sleep", d.time_to_sleep);
    io("linear_sleep_tolerance", d.linear_sleep_tolerance);
    io("angular_sleep_tolerance", d.angular_sleep_tolerance);
    io("maximum_linear_speed", d.maximum_linear_speed);
    io("enable_warm_starting", d.enable_warm_starting);
    io.user_data("user_data", d.user_data);
}

/// The checksum of a snapshot whose header is in place: XXH64 of the payload, seeded with the
/// XXH64 of the header up to the checksum.
std::uint64_t checksum(std::span<const std::byte> bytes) {
    return xxh64(bytes.subspan(header_size), xxh64(bytes.first(24)));
}

std::uint64_t read_le(std::span<const std::byte> b, std::size_t at, int n) {
    std::uint64_t v = 0;
    for (int k = 0; k < n; ++k)
        v |= std::uint64_t(b[at + std::size_t(k)]) << (8 * k);
    return v;
}

/// The engine state a snapshot describes, read whole, with the host's workers and task system,
/// its handles tagged `tag` (the world's it is read into, World::tag); the bodies that had a
/// load function listed in `had_load`. Throws SnapshotError. Its tasks are the default (one
/// thread): the caller moves the host world's in, so that no pool is started twice.
std::unique_ptr<World::Impl> read_snapshot(std::span<const std::byte> bytes, int workers,
                                           const TaskSystem& task_system, std::uint32_t tag,
                                           memory::vector<std::uint32_t>& had_load) {
    if (bytes.size() < header_size)
        throw SnapshotError(bytes.size(), "header",
                            "cut short: a snapshot starts with a " +
                                decimal(std::uint64_t(header_size)) + "-byte header, " +
                                decimal(std::uint64_t(bytes.size())) + " bytes given (truncated)");
    for (std::size_t k = 0; k < sizeof magic; ++k)
        if (bytes[k] != std::byte(magic[k]))
            throw SnapshotError(0, "header.magic",
                                "must be \"T2D-SNAP\" (not a Tamias2D snapshot)");
    const auto format = std::uint32_t(read_le(bytes, 8, 4));
    if (format != World::snapshot_format_version)
        throw SnapshotError(8, "header.format_version",
                            "is " + decimal(std::uint64_t(format)) + ", must be " +
                                decimal(std::uint64_t(World::snapshot_format_version)) +
                                " (the format this library reads)");
    const std::uint64_t payload_size = read_le(bytes, 16, 8);
    if (payload_size != bytes.size() - header_size)
        throw SnapshotError(16, "header.payload_size",
                            "is " + decimal(std::uint64_t(payload_size)) + ", but " +
                                decimal(std::uint64_t(bytes.size() - header_size)) +
                                " bytes follow the header (truncated or extended)");
    const std::span<const std::byte> payload = bytes.subspan(header_size);
    if (checksum(bytes) != read_le(bytes, 24, 8))
        throw SnapshotError(24, "header.checksum",
                            "disagrees with the XXH64 of the bytes (they changed since they "
                            "were written)");

    SnapshotReader in(payload, header_size, tag);
    in.section("WRLD");
    WorldDef def;
    const std::size_t def_at = in.offset();
    world_def_fields(in, def);
    def.workers = workers;
    def.task_system = task_system;
    try {
        validate(def);
    } catch (const ValidationError& e) {
        in.fail_at(def_at, "world", std::string("the settings are refused: ") + e.what());
    }
    // The tasks (and a pool's threads) are the host world's, moved in by the caller: none is
    // started here.
    auto w = std::make_unique<World::Impl>(def, tag);
    in("time", w->time);
    in("time_error", w->time_error);
    w->bodies.read(in, had_load, def.enable_sleep);
    w->shapes.read(in);
    w->bodies.check_links(in, w->shapes);
    w->contacts.read(in, w->bodies, w->shapes);
    w->joints.read(in, w->bodies);
    w->sensors.read(in, w->shapes);
    w->events.read(in, w->bodies, w->shapes);
    if (in.left() != 0)
        in.fail("payload", "must end after the last section (" + decimal(std::uint64_t(in.left())) +
                               " bytes more)");
    return w;
}

} // namespace

std::vector<std::byte> World::snapshot() const {
    std::vector<std::byte> bytes;
    snapshot(bytes);
    return bytes;
}

void World::snapshot(std::vector<std::byte>& bytes) const {
    SnapshotWriter out(bytes);
    write_snapshot(*impl_, out);
    out.finish_in_storage();
}

void write_snapshot(const World::Impl& w, SnapshotWriter& out) {
    w.bodies.settle(); // (the same bits as when the next step would settle them)
    // About 25 % above the bytes a body with its shape and a contact take, so that the buffer
    // is not grown (a doubling and a copy) for typical worlds; the slack stays with the bytes.
    out.reserve(header_size + 640 * (w.bodies.size() + w.shapes.shapes.size()) +
                400 * std::size_t(w.contacts.size()));
    for (const char c : magic)
        out.u8(std::uint8_t(c));
    out.u32(World::snapshot_format_version);
    out.u32(library_version_code);
    out.u64(0); // payload size and checksum: below
    out.u64(0);
    out.section("WRLD");
    world_def_fields(out, w.def);
    out("time", w.time);
    out("time_error", w.time_error);
    w.bodies.write(out);
    w.shapes.write(out);
    w.contacts.write(out);
    w.joints.write(out);
    w.sensors.write(out);
    w.events.write(out);
    const std::span<std::byte> b = out.written();
    const std::uint64_t size = b.size() - header_size;
    for (int k = 0; k < 8; ++k)
        b[16 + std::size_t(k)] = std::byte(size >> (8 * k));
    const std::uint64_t sum = checksum(b);
    for (int k = 0; k < 8; ++k)
        b[24 + std::size_t(k)] = std::byte(sum >> (8 * k));
}

World World::from_snapshot(std::span<const std::byte> snapshot, int workers,
                           const TaskSystem& task_system) {
    memory::vector<std::uint32_t> had_load;
    WorldDef host;
    host.workers = workers;
    host.task_system = task_system;
    World world(host); // (validates the workers and the task system)
    std::unique_ptr<Impl> w = read_snapshot(snapshot, workers, task_system, world.tag(), had_load);
    w->tasks = std::move(world.impl_->tasks);
    world.impl_ = std::move(w);
    return world;
}

void World::restore(std::span<const std::byte> snapshot) {
    Impl& old = *impl_;
    memory::vector<std::uint32_t> had_load;
    std::unique_ptr<Impl> w = read_snapshot(snapshot, old.def.workers, old.def.task_system,
                                            old.bodies.slots.world(), had_load);
    // The world's capacity hints are its own, not the snapshot's: kept, the stores sized for
    // them again (no result depends on it).
    w->def.capacity = old.def.capacity;
    w->reserve(old.def.capacity);
    // Nothing below throws: the world changes only now.
    // A body that had a load function keeps the one its handle names in this world, if any.
    for (const std::uint32_t i : had_load) {
        if (old.bodies.is_valid(w->bodies.id(i)) && old.bodies.settings[i].load) {
            w->bodies.settings[i].load = std::move(old.bodies.settings[i].load);
            ++w->bodies.loaded_bodies;
        }
    }
    w->contacts.custom_filter = std::move(old.contacts.custom_filter);
    w->tasks = std::move(old.tasks);
    w->profiler.enabled = old.profiler.enabled;
    impl_ = std::move(w);
}

} // namespace tamias2d
