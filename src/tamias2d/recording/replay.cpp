// Replayer and replay: a recording read whole (recording_format.hpp), its world built from its
// snapshot, its calls made again (recorded_calls.hpp decodes them), and after every step the
// world compared with the recorded outcome: the state hash, then the bodies' states to name
// the first body and field that differ.
#include "tamias2d/replay.hpp"
#include "tamias2d/memory/allocator.hpp"

#include <array>
#include <cstdio>
#include <cstring>
#include <exception>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "tamias2d/recorder.hpp"
#include "tamias2d/recording/recorded_calls.hpp"
#include "tamias2d/recording/recording_format.hpp"
#include "tamias2d/snapshot_error.hpp"

namespace tamias2d {

RecordingError::RecordingError(std::size_t offset_, std::string field_, std::string rule_)
    : std::invalid_argument("recording refused at byte " + decimal(std::uint64_t(offset_)) + ", " +
                            field_ + ": " + rule_),
      offset(offset_), field(std::move(field_)), rule(std::move(rule_)) {}

using recording::Call;

// Named, not anonymous: Replayer::Impl holds a Parsed, and a class with a member of an
// anonymous namespace's type is an error (-Wsubobject-linkage) where this file is compiled in a
// unity batch.
namespace replay_detail {

/// A record: its call, where its arguments are and their size.
struct Record {
    Call call;
    std::size_t offset; ///< of its arguments, in the recording
    std::size_t size;
    std::uint64_t step; ///< steps before it
};

/// A recording read whole: its flags, its snapshot and its records.
struct Parsed {
    std::uint32_t flags = 0;
    std::span<const std::byte> snapshot;
    std::size_t snapshot_offset = 0;
    memory::vector<Record> records;
    std::uint64_t steps = 0;
};

} // namespace replay_detail

using replay_detail::Parsed;
using replay_detail::Record;

namespace {

std::uint64_t read_le(std::span<const std::byte> b, std::size_t at, int n) {
    std::uint64_t v = 0;
    for (int k = 0; k < n; ++k)
        v |= std::uint64_t(b[at + std::size_t(k)]) << (8 * k);
    return v;
}

/// Runs `f`, turning the reader's SnapshotError into the recording's error.
template <class F> decltype(auto) as_recording_error(F&& f, const char* prefix = "") {
    try {
        return f();
    } catch (const SnapshotError& e) {
        throw RecordingError(e.offset, prefix + e.field, e.rule);
    }
}

/// Decodes call C's arguments from `r` (all of its bytes) into their values.
template <Call C> auto decode(SnapshotReader& r, std::size_t end) {
    constexpr auto member = recording::member_of<C>();
    using Args = typename recording::MemberTraits<std::remove_const_t<decltype(member)>>::Args;
    typename recording::HeldTuple<Args>::type held;
    std::apply([&](auto&... a) { (recording::argument_io(r, "argument", a), ...); }, held);
    if (r.offset() != end)
        r.fail("argument", "must end where the record ends (" + decimal(std::uint64_t(end)) +
                               "): " + decimal(std::uint64_t(end - r.offset())) +
                               " bytes left over");
    return held;
}

template <Call C> void check_call(SnapshotReader& r, std::size_t end) {
    decode<C>(r, end);
}
template <Call C> void apply_call(World& world, SnapshotReader& r, std::size_t end) {
    constexpr auto member = recording::member_of<C>();
    auto held = decode<C>(r, end);
    std::apply([&](auto&... a) { (world.*member)(a...); }, held);
}

using Checker = void (*)(SnapshotReader&, std::size_t);
using Applier = void (*)(World&, SnapshotReader&, std::size_t);
constexpr std::array<Checker, std::size_t(Call::count)> checkers{
#define TAMIAS2D_CALL_CHECKER(name, member) &check_call<Call::name>,
    TAMIAS2D_RECORDED_CALLS(TAMIAS2D_CALL_CHECKER)
#undef TAMIAS2D_CALL_CHECKER
};
constexpr std::array<Applier, std::size_t(Call::count)> appliers{
#define TAMIAS2D_CALL_APPLIER(name, member) &apply_call<Call::name>,
    TAMIAS2D_RECORDED_CALLS(TAMIAS2D_CALL_APPLIER)
#undef TAMIAS2D_CALL_APPLIER
};

/// A record's name for the errors: "records[3]".
std::string record_name(std::size_t k) {
    return "records[" + decimal(std::uint64_t(k)) + "]";
}

Parsed parse(std::span<const std::byte> bytes) {
    using recording::header_size;
    if (bytes.size() < header_size)
        throw RecordingError(0, "header",
                             "cut short: a recording has a 32-byte header, " +
                                 decimal(std::uint64_t(bytes.size())) + " bytes given (truncated)");
    for (std::size_t k = 0; k < 8; ++k)
        if (bytes[k] != std::byte(recording::magic[k]))
            throw RecordingError(k, "header.magic", "must be \"T2D-RECD\" (not a recording)");
    const std::uint64_t version = read_le(bytes, 8, 4);
    if (version != Recorder::format_version)
        throw RecordingError(8, "header.format_version",
                             "must be " + decimal(Recorder::format_version) + ", this library's (" +
                                 decimal(version) + " given)");
    const std::uint64_t size = read_le(bytes, 16, 8);
    if (size != bytes.size() - header_size)
        throw RecordingError(16, "header.payload_size",
                             "must be the bytes after the header, " +
                                 decimal(std::uint64_t(bytes.size() - header_size)) + " (" +
                                 decimal(size) + " given: truncated or extended)");
    const std::span<const std::byte> payload = bytes.subspan(header_size);
    if (read_le(bytes, 24, 8) != recording::fnv1a_64(payload, recording::fnv1a_64(bytes.first(24))))
        throw RecordingError(24, "header.checksum",
                             "must be the FNV-1a 64 of the header and the payload (the "
                             "recording was changed)");
    Parsed p;
    SnapshotReader r(payload, header_size, 0);
    as_recording_error([&] {
        const std::size_t at = r.offset();
        p.flags = r.u32("flags");
        r.require((p.flags & ~recording::flag_body_states) == 0, "flags",
                  "must hold only bit 0 (body states)", at);
        const std::size_t n = r.count("snapshot_size", 1);
        p.snapshot_offset = r.offset();
        p.snapshot = bytes.subspan(p.snapshot_offset, n);
        for (std::size_t k = 0; k < n; ++k)
            r.u8("snapshot");
        const bool body_states = (p.flags & recording::flag_body_states) != 0;
        for (std::size_t k = 0; r.left() > 0; ++k) {
            const std::string name = record_name(k);
            r.in(nullptr);
            const std::size_t code_at = r.offset();
            const std::uint8_t code = r.u8(name.c_str());
            if (code >= std::uint8_t(Call::count)) // (messages built only to fail)
                r.fail_at(code_at, name.c_str(),
                          "call code must be < " + decimal(std::uint64_t(Call::count)));
            const std::size_t size_at = r.offset();
            const std::size_t m = r.u32(name.c_str());
            if (m > r.left())
                r.fail_at(size_at, name.c_str(),
                          "size must fit in the " + decimal(std::uint64_t(r.left())) +
                              " bytes left (truncated)");
            const Record rec{Call(code), r.offset(), m, p.steps};
            const std::size_t end = rec.offset + m;
            SnapshotReader args(payload.subspan(rec.offset - header_size, m), rec.offset, 0);
            args.in(name.c_str());
            if (rec.call == Call::step) {
                double dt = 0.0;
                args("dt", dt);
                args.u64("state_hash");
                if (body_states) {
                    const std::size_t count_at = args.offset();
                    const std::uint32_t bodies = args.u32("body_count");
                    args.require(std::uint64_t(bodies) * recording::body_state_size == args.left(),
                                 "body_count",
                                 "must be the body states the record holds (56 bytes each)",
                                 count_at);
                }
                args.require(args.left() == 0 || body_states, "step",
                             "must end after its state hash (no body states recorded)",
                             args.offset());
                ++p.steps;
            } else {
                checkers[code](args, end);
            }
            p.records.push_back(rec);
            for (std::size_t b = 0; b < m; ++b) // (the record read: step over it)
                r.u8(name.c_str());
        }
    });
    return p;
}

std::string hex(std::uint64_t v) {
    char buf[24];
    std::snprintf(buf, sizeof buf, "0x%016llx", static_cast<unsigned long long>(v));
    return buf;
}
std::string number(double v) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

} // namespace

struct Replayer::Impl : memory::HookAllocated<Replayer::Impl> {
    memory::vector<std::byte> bytes; ///< the recording (a copy: the replayer may outlive it)
    Parsed parsed;
    World world;
    std::size_t next = 0;
    std::uint64_t steps = 0;
    std::uint64_t calls = 0;
    bool stopped = false;

    /// The body's label in the messages: "body 7 (index 7, generation 1, 'crate')".
    std::string body_label(std::uint32_t index, std::uint32_t generation) const {
        std::string s = "body " + decimal(index) + " (index " + decimal(index) + ", generation " +
                        decimal(generation);
        const BodyId id{index, generation, world.tag()};
        if (world.is_valid(id) && !world.name(id).empty())
            s += ", '" + world.name(id) + "'";
        return s + ")";
    }

    ReplayDivergence stop(ReplayDivergence d) {
        stopped = true;
        return d;
    }

    /// The step's outcome compared: the state hash, then (if recorded and the hash differs)
    /// the bodies in slot order.
    std::optional<ReplayDivergence> compare(SnapshotReader& r) {
        const std::uint64_t recorded = r.u64("state_hash");
        const std::uint64_t replayed = world.state_hash();
        if (recorded == replayed)
            return std::nullopt;
        const std::string at = "step " + decimal(steps) + ": ";
        if ((parsed.flags & recording::flag_body_states) != 0) {
            const World::Impl& w = RecordingAccess::impl(world);
            const std::uint32_t n = r.u32("body_count");
            std::uint32_t slot = 0; // the replay's next live slot to match
            auto extra = [&](std::uint32_t below) -> std::optional<ReplayDivergence> {
                for (; slot < below && slot < w.bodies.size(); ++slot)
                    if (w.bodies.alive(slot)) {
                        const std::uint32_t g = w.bodies.slots.generation(slot);
                        return ReplayDivergence{
                            steps,
                            BodyId{slot, g, world.tag()},
                            "exists",
                            0,
                            1,
                            at + body_label(slot, g) + ": exists in the replay, not in the recording"};
                    }
                return std::nullopt;
            };
            for (std::uint32_t k = 0; k < n; ++k) {
                const std::uint32_t index = r.u32("index");
                const std::uint32_t generation = r.u32("generation");
                double fields[6];
                for (double& x : fields)
                    r("body", x);
                if (auto d = extra(index))
                    return d;
                slot = index + 1;
                const BodyId id{index, generation, world.tag()};
                if (!w.bodies.is_valid(id))
                    return ReplayDivergence{
                        steps,
                        id,
                        "exists",
                        1,
                        0,
                        at + body_label(index, generation) + ": exists in the recording, not in the replay"};
                const Body& b = w.bodies.bodies[index];
                const double now[6] = {b.center.x, b.center.y, b.angle, b.v.x, b.v.y, b.w};
                for (int f = 0; f < 6; ++f) {
                    std::uint64_t rb = 0, pb = 0; // (no std::bit_cast in the WebAssembly libc++)
                    std::memcpy(&rb, &fields[f], sizeof rb);
                    std::memcpy(&pb, &now[f], sizeof pb);
                    if (rb != pb)
                        return ReplayDivergence{
                            steps,
                            id,
                            recording::body_fields[f],
                            rb,
                            pb,
                            at + body_label(index, generation) + ": " + recording::body_fields[f] +
                                " differs: recorded " + hex(rb) + " (" + number(fields[f]) +
                                "), replayed " + hex(pb) + " (" + number(now[f]) + ")"};
                }
            }
            if (auto d = extra(w.bodies.size()))
                return d;
        }
        return ReplayDivergence{steps,
                                std::nullopt,
                                "state_hash",
                                recorded,
                                replayed,
                                at + "state hash differs: recorded " + hex(recorded) +
                                    ", replayed " + hex(replayed) +
                                    ((parsed.flags & recording::flag_body_states) != 0
                                         ? " (every body's position, angle and velocities "
                                           "agree: the difference is in other state: "
                                           "contacts, joints, sleep, settings)"
                                         : " (the recording holds no body states)")};
    }
};

namespace {

Replayer::Impl make_impl(std::span<const std::byte> recording, int workers,
                         const TaskSystem& task_system) {
    Parsed p = parse(recording);
    memory::vector<std::byte> bytes(recording.begin(), recording.end());
    p.snapshot = std::span<const std::byte>(bytes).subspan(p.snapshot_offset, p.snapshot.size());
    const std::size_t base = p.snapshot_offset;
    World world = [&] {
        try {
            return World::from_snapshot(p.snapshot, workers, task_system);
        } catch (const SnapshotError& e) {
            throw RecordingError(base + e.offset, "snapshot." + e.field, e.rule);
        }
    }();
    return Replayer::Impl{{}, std::move(bytes), std::move(p), std::move(world)};
}

} // namespace

Replayer::Replayer(std::span<const std::byte> recording, int workers, const TaskSystem& task_system)
    : impl_(std::make_unique<Impl>(make_impl(recording, workers, task_system))) {}
Replayer::~Replayer() = default;
Replayer::Replayer(Replayer&&) noexcept = default;
Replayer& Replayer::operator=(Replayer&&) noexcept = default;

const World& Replayer::world() const {
    return impl_->world;
}
bool Replayer::done() const {
    return impl_->stopped || impl_->next == impl_->parsed.records.size();
}
std::uint64_t Replayer::steps() const {
    return impl_->steps;
}
std::uint64_t Replayer::calls() const {
    return impl_->calls;
}
std::uint64_t Replayer::recorded_steps() const {
    return impl_->parsed.steps;
}

std::optional<ReplayDivergence> Replayer::advance() {
    Impl& s = *impl_;
    while (!done()) {
        const Record& rec = s.parsed.records[s.next++];
        ++s.calls;
        SnapshotReader r(std::span<const std::byte>(s.bytes).subspan(rec.offset, rec.size),
                         rec.offset, s.world.tag());
        const std::string_view name = recording::call_names[std::size_t(rec.call)];
        if (rec.call == Call::step) {
            double dt = 0.0;
            r("dt", dt);
            ++s.steps;
            try {
                s.world.step(dt);
            } catch (const std::exception& e) {
                return s.stop({s.steps, std::nullopt, "call", 0, 0,
                               "step " + decimal(s.steps) + ": the recorded step (dt " +
                                   number(dt) + ") was refused in the replay: " + e.what()});
            }
            if (auto d = s.compare(r))
                return s.stop(std::move(*d));
            return std::nullopt;
        }
        try {
            appliers[std::size_t(rec.call)](s.world, r, rec.offset + rec.size);
        } catch (const std::exception& e) {
            return s.stop({s.steps + 1, std::nullopt, "call", 0, 0,
                           "step " + decimal(s.steps + 1) + ": call " + decimal(s.calls) + " (" +
                               std::string(name) + ", before the step) was refused in the " +
                               "replay: " + e.what()});
        }
    }
    return std::nullopt;
}

ReplayReport replay(std::span<const std::byte> recording, int workers,
                    const TaskSystem& task_system) {
    Replayer r(recording, workers, task_system);
    ReplayReport report;
    report.recorded_steps = r.recorded_steps();
    while (!r.done()) {
        if (auto d = r.advance()) {
            report.divergence = std::move(d);
            break;
        }
    }
    report.steps = r.steps();
    report.calls = r.calls();
    return report;
}

std::vector<RecordedCall> recorded_calls(std::span<const std::byte> recording) {
    const Parsed p = parse(recording);
    std::vector<RecordedCall> out;
    out.reserve(p.records.size());
    for (const Record& rec : p.records)
        out.push_back(
            {recording::call_names[std::size_t(rec.call)], rec.step, rec.offset, rec.size});
    return out;
}

} // namespace tamias2d
