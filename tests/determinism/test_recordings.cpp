// Recordings across builds: the recordings committed in recordings/ (written on x86-64 by
// tests/recording/make_recordings.cpp: example scenes with an impulse, a gravity change, a new
// body, a motor speed and an explosion mid-run) must replay bit for bit, every step's state hash
// and every body's state, on one worker and on four; and the same recording with one bit of its
// impulse flipped must depart at the impulse's step, on every build.
//
// Oracle: the recorded run's own state hashes and body states, written by another build (the
// committed files do not change with the build), so a pass proves that a recording made on
// x86-64 replays with the same bits here (aarch64, riscv64, WebAssembly, every x86-64 lane).
// For the perturbed copy, the step before which the impulse was given (10).
//
// Regenerate after an intended change of the physics or of the recording format (and say why in
// the commit):
//   build/tests/recording/make_test_recordings examples/scenes tests/determinism/recordings
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "tamias2d/replay.hpp"
#include "tamias2d/task_system.hpp"

namespace utf = boost::unit_test;
namespace fs = std::filesystem;
using namespace tamias2d;

namespace {

std::vector<fs::path> recordings() {
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(TAMIAS_RECORDINGS))
        if (e.path().extension() == ".t2drec")
            files.push_back(e.path());
    std::sort(files.begin(), files.end());
    return files;
}

std::vector<std::byte> read(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    const std::vector<char> chars((std::istreambuf_iterator<char>(in)),
                                  std::istreambuf_iterator<char>());
    std::vector<std::byte> bytes(chars.size());
    std::memcpy(bytes.data(), chars.data(), chars.size());
    return bytes;
}

#if defined(__EMSCRIPTEN__) && !defined(__EMSCRIPTEN_PTHREADS__)
/// No threads: each loop's pieces run at once, in order, on the calling thread.
void* run_now(TaskCallback task, int items, void* task_context, void*) {
    task(0, items, 0, task_context);
    return nullptr;
}
void nothing_to_wait_for(void*, void*) {}
const TaskSystem four_workers_tasks{run_now, nothing_to_wait_for, nullptr};
#else
const TaskSystem four_workers_tasks{};
#endif

} // namespace

BOOST_AUTO_TEST_SUITE(determinism_recordings)

// Oracle: the state hashes and body states in the committed files, written by another build
// (x86-64, tests/recording/make_recordings.cpp) and not changed by this one: each recording must
// replay with the same bits, all 55 steps, on one worker and on four (determinism across
// builds and worker counts: the same inputs give the same bits).
BOOST_AUTO_TEST_CASE(committed_recordings_replay_bit_for_bit, *utf::label("determinism")) {
    const std::vector<fs::path> files = recordings();
    BOOST_TEST_REQUIRE(files.size() >= 3u);
    for (const fs::path& file : files) {
        const std::vector<std::byte> bytes = read(file);
        for (const int workers : {1, 4}) {
            const ReplayReport r =
                replay(bytes, workers, workers > 1 ? four_workers_tasks : TaskSystem{});
            BOOST_TEST(r.matched(), file.filename().string()
                                        << " on " << workers << " workers: "
                                        << (r.divergence ? r.divergence->message : ""));
            BOOST_TEST(r.steps == 55u, file.filename().string());
            BOOST_TEST(r.recorded_steps == 55u, file.filename().string());
        }
    }
}

// Oracle: the recording's own calls: its impulse is recorded before step 10 (kick_step in
// make_recordings.cpp), so with one bit of it flipped, and the checksum made right by FNV-1a 64
// written in the test (the documented format, docs/user-guide.md), the replay must depart at
// step 10 at a body, with the recorded and replayed bits different.
BOOST_AUTO_TEST_CASE(a_flipped_impulse_bit_departs_at_its_step, *utf::label("determinism")) {
    std::vector<std::byte> bytes = read(fs::path(TAMIAS_RECORDINGS) / "car.t2drec");
    // The impulse's x component, bit 24 of its mantissa (its arguments: the body's 8 bytes,
    // then impulse.x); then the documented checksum, FNV-1a 64 of the header's first 24 bytes
    // and the payload, made right.
    for (const RecordedCall& c : recorded_calls(bytes))
        if (c.name == "apply_impulse") {
            BOOST_TEST(c.step == 9u); // recorded before step 10
            bytes[c.offset + 8 + 3] ^= std::byte{1};
        }
    std::uint64_t h = 0xcbf29ce484222325ull;
    for (std::size_t k = 0; k < bytes.size(); ++k) {
        if (k >= 24 && k < 32)
            continue;
        h = (h ^ std::uint64_t(bytes[k])) * 0x100000001b3ull;
    }
    for (int k = 0; k < 8; ++k)
        bytes[std::size_t(24 + k)] = std::byte(h >> (8 * k));
    const ReplayReport r = replay(bytes);
    BOOST_TEST_REQUIRE(!r.matched());
    BOOST_TEST(r.divergence->step == 10u);
    BOOST_TEST(r.divergence->body.has_value(), r.divergence->message);
    BOOST_TEST(r.divergence->recorded_bits != r.divergence->replayed_bits);
}

BOOST_AUTO_TEST_SUITE_END()
