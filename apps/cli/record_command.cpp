// `tamias2d record` and `tamias2d replay` (record_command.hpp).
#include "record_command.hpp"

#include <charconv>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <optional>
#include <stdexcept>
#include <system_error>

#include "tamias2d/recorder.hpp"
#include "tamias2d/replay.hpp"
#include "tamias2d/world.hpp"

namespace tamias2d::cli {

const char* const record_usage = R"(Usage: tamias2d record <scene.json | -> -o FILE [options]

Simulate the scene as 'run' does and write the run as a recording: the world's snapshot before
the first step, then every step with its dt, the state hash after it and every body's position,
angle and velocities (docs/user-guide.md, "Recordings"). 'tamias2d replay FILE' checks it on
any machine; 'tamias2d view FILE' plays it. A scene with a load function ("loads") cannot be
recorded: a function is not data. A scene file of "-" is read from standard input.

Options:
  --steps N           number of steps (default: the scene's "steps")
  -o, --output FILE   the recording's file (required: a recording is binary)
  --no-body-states    record the state hash alone (8 bytes a step instead of 8 + 56 per body):
                      a replay then names the first diverging step, not the body
  --workers N         step on N threads, N in [1, 256] (default 1): the same bytes for every N
  -h, --help          print this text

Exit status: 0 on success, 1 for an invalid scene, a scene that cannot be recorded or a failed
run, 2 for a bad command line.
)";

const char* const replay_usage = R"(Usage: tamias2d replay <FILE> [options]

Replay a recording ('tamias2d record', or a program's Recorder): rebuild its world from its
snapshot, make its calls again and compare the world after every step with the recorded one,
bit for bit. Prints "FILE: OK: ..." when every step matches; otherwise the first difference:
"step 118: body 7 (index 7, generation 1): linear_velocity.x differs: recorded 0x...,
replayed 0x...".

Options:
  --workers N         step on N threads, N in [1, 256] (default 1)
  -h, --help          print this text

Exit status: 0 when every step matches, 1 for a file that is not a readable recording, 2 for a
bad command line, 3 when the replay departs from the recording.
)";

namespace {

int parse_int(std::string_view option, std::string_view text, int minimum) {
    int v = 0;
    const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
    if (r.ec != std::errc{} || r.ptr != text.data() + text.size() || v < minimum)
        throw UsageError(std::string(option) + " expects an integer >= " + std::to_string(minimum) +
                         ", got '" + std::string(text) + "'");
    return v;
}

struct Options {
    bool help = false;
    std::string input;
    std::optional<int> steps;
    std::string output;
    bool body_states = true;
    int workers = 1;
};

/// The options of `record` (with_output) or `replay`.
Options parse(std::span<const std::string_view> args, bool recording) {
    Options o;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string_view a = args[i];
        const auto value = [&]() -> std::string_view {
            if (i + 1 >= args.size())
                throw UsageError("option " + std::string(a) + " needs a value");
            return args[++i];
        };
        if (a == "--help" || a == "-h") {
            o.help = true;
        } else if (a == "--workers") {
            o.workers = parse_int(a, value(), 1);
        } else if (recording && a == "--steps") {
            o.steps = parse_int(a, value(), 0);
        } else if (recording && (a == "--output" || a == "-o")) {
            o.output = value();
            if (o.output.empty() || o.output == "-")
                throw UsageError(std::string(a) + " needs a file name (a recording is binary)");
        } else if (recording && a == "--no-body-states") {
            o.body_states = false;
        } else if (a.starts_with("-") && a.size() > 1) {
            throw UsageError("unknown option '" + std::string(a) + "'");
        } else if (o.input.empty()) {
            o.input = a;
        } else {
            throw UsageError("unexpected argument '" + std::string(a) + "'");
        }
    }
    if (!o.help && o.input.empty())
        throw UsageError(recording ? "missing scene file" : "missing recording file");
    if (!o.help && recording && o.output.empty())
        throw UsageError("record needs -o FILE");
    return o;
}

} // namespace

std::vector<std::byte> read_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw std::runtime_error("cannot read '" + path + "'");
    std::vector<char> chars((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad())
        throw std::runtime_error("reading '" + path + "' failed");
    std::vector<std::byte> bytes(chars.size());
    if (!chars.empty())
        std::memcpy(bytes.data(), chars.data(), chars.size());
    return bytes;
}

bool is_recording_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    char magic[8] = {};
    return in.read(magic, 8) && std::memcmp(magic, "T2D-RECD", 8) == 0;
}

int record_command(std::span<const std::string_view> args, const SceneSource& source) {
    const Options o = parse(args, true);
    if (o.help) {
        std::cout << record_usage;
        return 0;
    }
    const io::Scene scene = source.load(o.input);
    WorldDef def = scene.world;
    def.workers = o.workers;
    World world(def);
    io::build_world(scene, world);
    Recorder rec(world, RecordOptions{.body_states = o.body_states});
    const int steps = o.steps.value_or(scene.steps);
    for (int s = 0; s < steps; ++s)
        rec.step(scene.dt);
    const std::vector<std::byte> bytes = rec.bytes();
    {
        std::ofstream out(o.output, std::ios::binary | std::ios::trunc);
        if (!out)
            throw std::runtime_error("cannot write '" + o.output + "'");
        out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
        out.flush();
        if (!out) {
            out.close();
            std::error_code ec;
            std::filesystem::remove(o.output, ec);
            throw std::runtime_error("writing '" + o.output + "' failed");
        }
    }
    std::cout << o.output << ": " << rec.steps() << " steps of " << source.display_name(o.input)
              << ", " << world.body_count() << " bodies, " << bytes.size() << " bytes\n";
    return 0;
}

int replay_command(std::span<const std::string_view> args) {
    const Options o = parse(args, false);
    if (o.help) {
        std::cout << replay_usage;
        return 0;
    }
    const std::vector<std::byte> bytes = read_file(o.input);
    const ReplayReport r = replay(bytes, o.workers);
    if (r.divergence) {
        std::cerr << "tamias2d: replay: " << o.input << ": " << r.divergence->message << '\n';
        return diverged_status;
    }
    std::cout << o.input << ": OK: " << r.steps << " steps and " << r.calls
              << " calls replayed bit for bit\n";
    return 0;
}

} // namespace tamias2d::cli
