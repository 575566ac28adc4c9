// A recording's layout (internal), written by Recorder (recorder.cpp) and read by Replayer
// (replay.cpp); docs/user-guide.md, "Recordings", has it as a table:
//
//   offset  0: magic, the 8 bytes "T2D-RECD"
//   offset  8: u32 format version (Recorder::format_version)
//   offset 12: u32 library version that wrote it, major << 16 | minor << 8 | patch
//   offset 16: u64 payload size in bytes
//   offset 24: u64 FNV-1a 64 of the header's first 24 bytes and then the payload
//   offset 32: payload:
//              u32 flags (bit 0: body states after each step, RecordOptions::body_states)
//              u64 snapshot size n, then the n bytes of World::snapshot() when recording began
//              records, to the end: u8 call code (recorded_calls.hpp), u32 size m, m bytes of
//              the call's arguments in its parameters' order (a step: f64 dt, then u64 the state
//              hash after it, and with body states u32 count and per live body, in slot order,
//              u32 index, u32 generation, f64 centre x, y, angle, velocity x, y, angular
//              velocity)
//
// All little-endian (dynamics/snapshot_io.hpp's writer and reader).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

#include "tamias2d/dynamics/snapshot_io.hpp"
#include "tamias2d/version.hpp"
#include "tamias2d/world.hpp"
#include "tamias2d/world_impl.hpp"

namespace tamias2d {

/// The engine state a recording reads (World's friend).
struct RecordingAccess {
    static const World::Impl& impl(const World& w) { return *w.impl_; }
};

namespace recording {

inline constexpr char magic[8] = {'T', '2', 'D', '-', 'R', 'E', 'C', 'D'};

/// FNV-1a, 64 bits (offset basis 0xcbf29ce484222325, prime 0x100000001b3), over `bytes`,
/// continuing from `h`: a recording's checksum, over its header before the checksum and then
/// its payload. (A recording is written once, at the end; a snapshot, taken every frame by some
/// games, has the faster XXH64.)
inline std::uint64_t fnv1a_64(std::span<const std::byte> bytes,
                              std::uint64_t h = 0xcbf29ce484222325ull) {
    for (const std::byte b : bytes) {
        h ^= std::uint64_t(b);
        h *= 0x100000001b3ull;
    }
    return h;
}
inline constexpr std::size_t header_size = 32;
inline constexpr std::uint32_t library_version_code = std::uint32_t(TAMIAS2D_VERSION_MAJOR) << 16 |
                                                      std::uint32_t(TAMIAS2D_VERSION_MINOR) << 8 |
                                                      std::uint32_t(TAMIAS2D_VERSION_PATCH);
inline constexpr std::uint32_t flag_body_states = 1;
/// A record's code and size before its arguments.
inline constexpr std::size_t record_head = 5;
/// A step record's dt and state hash.
inline constexpr std::size_t step_head = 16;
/// One body's state after a step: index, generation, six doubles.
inline constexpr std::size_t body_state_size = 8 + 6 * 8;

/// The fields of a body's state a recording holds, in order, with their names.
inline constexpr const char* body_fields[6] = {
    "position.x",        "position.y",        "angle",
    "linear_velocity.x", "linear_velocity.y", "angular_velocity"};

/// Writes the count and state of every live body (in slot order).
inline void write_body_states(SnapshotWriter& out, const World& world) {
    const World::Impl& w = RecordingAccess::impl(world);
    out.u32(std::uint32_t(w.bodies.count()));
    for (std::uint32_t i = 0; i < w.bodies.size(); ++i) {
        if (!w.bodies.alive(i))
            continue;
        const Body& b = w.bodies.bodies[i];
        out.u32(i);
        out.u32(w.bodies.slots.generation(i));
        for (const double x : {b.center.x, b.center.y, b.angle, b.v.x, b.v.y, b.w})
            out("body", x);
    }
}

/// Whether the world holds a function a recording cannot hold (a custom filter, a load).
inline const char* recorded_function(const World& world) {
    const World::Impl& w = RecordingAccess::impl(world);
    if (w.contacts.custom_filter)
        return "world.custom_filter";
    if (w.bodies.loaded_bodies > 0)
        return "body.load";
    if (w.contacts.pre_solve)
        return "world.pre_solve";
    if (w.contacts.friction_mixing)
        return "world.friction_mixing";
    if (w.contacts.restitution_mixing)
        return "world.restitution_mixing";
    return nullptr;
}

} // namespace recording
} // namespace tamias2d
