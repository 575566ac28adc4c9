// libFuzzer target: the input is a recording (Replayer, replay, recorded_calls). Its first byte
// chooses how the rest is read: odd, its checksum is made right first (so that a change reaches
// the records' reader and the replay, not only the checksum's refusal); even, as it is.
//
// Oracle: the library's stated promises (include/tamias2d/replay.hpp; docs/user-guide.md,
// "Recordings"): no crash and no sanitizer report; a refused recording is a RecordingError
// naming a field, refused alike by recorded_calls; an accepted one lists as many records as it
// replays at most, and its replay reports any departure as a value (a divergence with a
// message), never as an exception, for up to a few dozen records of a small world.
#include <cstddef>
#include <cstdint>
#include <exception>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "fuzz/libfuzzer/promise.hpp"
#include "tamias2d/replay.hpp"

using namespace tamias2d;
using namespace tamias2d::fuzz;

namespace {

constexpr std::size_t max_bodies_stepped = 200;
constexpr int max_advances = 40;

/// FNV-1a 64 over the header's first 24 bytes and the payload (the recording's checksum).
void fix_checksum(std::vector<std::byte>& b) {
    if (b.size() < 32)
        return;
    std::uint64_t h = 0xcbf29ce484222325ull;
    for (std::size_t k = 0; k < b.size(); ++k)
        if (k < 24 || k >= 32)
            h = (h ^ std::uint64_t(b[k])) * 0x100000001b3ull;
    for (int k = 0; k < 8; ++k)
        b[24 + std::size_t(k)] = std::byte(h >> (8 * k));
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

    std::optional<Replayer> replayer;
    try {
        replayer.emplace(bytes);
    } catch (const RecordingError& e) {
        if (e.field.empty() || std::string(e.what()).empty())
            broken_promise("RecordingError without a field or message");
        try {
            recorded_calls(bytes);
            // (recorded_calls does not read the snapshot: a defective snapshot is the
            // Replayer's refusal alone)
            if (e.field.rfind("snapshot.", 0) != 0)
                broken_promise("recorded_calls accepted what Replayer refused");
        } catch (const RecordingError&) {
        }
        return 0;
    } catch (const std::exception& e) {
        broken_promise(std::string("Replayer refused with a non-RecordingError: ") + e.what());
    }
    const std::size_t records = recorded_calls(bytes).size();
    for (int k = 0; k < max_advances && !replayer->done(); ++k) {
        if (replayer->world().body_count() > max_bodies_stepped)
            break;
        std::optional<ReplayDivergence> d;
        try {
            d = replayer->advance();
        } catch (const std::exception& e) {
            broken_promise(std::string("advance threw instead of reporting: ") + e.what());
        }
        if (d && d->message.empty())
            broken_promise("a divergence without a message");
        if (d && !replayer->done())
            broken_promise("the replay goes on after a divergence");
    }
    if (replayer->calls() > records)
        broken_promise("more calls replayed than the recording lists");
    return 0;
}
