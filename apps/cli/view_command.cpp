// `tamias2d view`: the options, the run (the schedule of `tamias2d run`) and the output file.
#include "view_command.hpp"

#include <algorithm>
#include <charconv>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <system_error>
#include <vector>

#include "record_command.hpp"
#include "tamias2d/io/scene_from_world.hpp"
#include "tamias2d/replay.hpp"
#include "tamias2d/world.hpp"
#include "view_html.hpp"

namespace tamias2d::cli {

const char* const view_usage = R"(Usage: tamias2d view <scene.json | recording | -> [options]

Simulate the scene as 'run' does and write one self-contained HTML page (no network, no
server, no other file) that plays the run back in a browser: the bodies' shapes, their states
at every recorded frame, the joints, the contact points and normals, and the energy (DD15,
DD16) as a plot. The page has play/pause, step, a scrub bar, speed, zoom (wheel) and pan
(drag), toggles for contacts, AABBs, velocities, trails and joints, and shows the state of the
body under the cursor in SI units. A scene file of "-" is read from standard input.

A recording ('tamias2d record', a program's Recorder: a file starting "T2D-RECD") is replayed
instead, checked step by step as 'tamias2d replay' checks it, and its states are played: the
bodies it has when recording begins, with their shapes then (a body destroyed later ends the
page there: view the steps before it with --steps). A replay that departs from its recording
fails.

Options:
  --steps N           number of steps (default: the scene's "steps", a recording's steps)
  --every K           record a frame every K >= 1 steps, plus the initial and the final state
                      (default: the scene's "output_every", or 1 when it is 0); --every 1
                      plays smoothly, a larger K makes a smaller file
  --max-contacts N    record at most N contact points over the run (default 1000000); a run
                      with more records none; 0 records none
  -o, --output FILE   write to FILE instead of standard output ("-": standard output); no
                      partial file is left behind when the run fails
  --workers N         step on N threads, N in [1, 256] (default 1), as 'run' does: the page
                      is the same byte for byte for every N
  -h, --help          print this text

Positions are stored to 1e-4 m, angles to 1e-4 rad, velocities to 1e-3 m/s and rad/s; the
file's size and how it is kept small are in docs/viewer.md.

Exit status: 0 on success, 1 for an invalid scene or a failed run (a state that is not finite
stops the run), 2 for a bad command line.
)";

namespace {

/// At most this many body states per page: the page holds them decoded, 48 bytes each.
constexpr long long max_body_frames = 10'000'000;
/// At most this many frames: each has its step, time and energies as JSON numbers (~70 bytes).
constexpr long long max_frames = 100'000;

struct ViewOptions {
    bool help = false;
    std::string scene;
    std::optional<int> steps;
    std::optional<int> every;
    std::size_t max_contacts = 1000000;
    std::string output;
    std::optional<int> workers; ///< WorldDef::workers; a scene file does not carry it
};

int parse_int(std::string_view option, std::string_view text, int minimum) {
    int v = 0;
    const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
    if (r.ec != std::errc{} || r.ptr != text.data() + text.size() || v < minimum)
        throw UsageError(std::string(option) + " expects an integer >= " + std::to_string(minimum) +
                         ", got '" + std::string(text) + "'");
    return v;
}

ViewOptions parse(std::span<const std::string_view> args) {
    ViewOptions o;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string_view a = args[i];
        const auto value = [&]() -> std::string_view {
            if (i + 1 >= args.size())
                throw UsageError("option " + std::string(a) + " needs a value");
            return args[++i];
        };
        if (a == "--help" || a == "-h") {
            o.help = true;
        } else if (a == "--steps") {
            o.steps = parse_int(a, value(), 0);
        } else if (a == "--every") {
            o.every = parse_int(a, value(), 1);
        } else if (a == "--workers") {
            o.workers = parse_int(a, value(), 1);
        } else if (a == "--max-contacts") {
            o.max_contacts = static_cast<std::size_t>(parse_int(a, value(), 0));
        } else if (a == "--output" || a == "-o") {
            o.output = value();
            if (o.output.empty())
                throw UsageError(std::string(a) + " needs a file name");
            if (o.output == "-")
                o.output.clear();
        } else if (a == "--format") {
            throw UsageError("--format applies to 'run' only ('view' writes HTML)");
        } else if (a.starts_with("-") && a.size() > 1) {
            throw UsageError("unknown option '" + std::string(a) + "'");
        } else if (o.scene.empty()) {
            o.scene = a;
        } else {
            throw UsageError("unexpected argument '" + std::string(a) + "'");
        }
    }
    if (o.scene.empty() && !o.help)
        throw UsageError("missing scene file");
    return o;
}

/// The output stream: the file (opened before the run, so that a wrong path fails at once) or
/// standard output; `run` writes to it, and the file is removed again when the run fails.
template <class Run> void write_output(const std::string& output, Run&& run) {
    std::ofstream file;
    if (!output.empty()) {
        file.open(output, std::ios::binary | std::ios::trunc);
        if (!file)
            throw std::runtime_error("cannot write '" + output + "'");
    }
    std::ostream& out = output.empty() ? std::cout : file;
    try {
        run(out);
        out.flush();
        if (!out)
            throw std::runtime_error("writing the output failed");
    } catch (...) {
        if (!output.empty()) {
            file.close();
            std::error_code ec;
            std::filesystem::remove(output, ec);
        }
        throw;
    }
}

/// `view` of a recording: its world replayed (Replayer), checked at every step, and its states
/// played for the bodies it has when recording begins (the scene of that world,
/// io::scene_from_world, gives their shapes and joints).
int view_recording(const ViewOptions& o, const std::string& name) {
    Replayer replayer(read_file(o.scene), o.workers.value_or(1));
    const World& world = replayer.world();
    const io::Scene scene = io::scene_from_world(world);
    const std::vector<BodyId> ids = world.bodies();
    const int recorded = int(replayer.recorded_steps());
    const int steps = o.steps ? std::min(*o.steps, recorded) : recorded;
    const int every = o.every.value_or(1);
    const long long frames = 1LL + steps / every + (steps % every != 0 ? 1 : 0);
    if (frames > max_frames || frames * static_cast<long long>(ids.size()) > max_body_frames)
        throw std::runtime_error(name + ": " + std::to_string(frames) + " frames of " +
                                 std::to_string(ids.size()) +
                                 " bodies are more than the player holds: use a larger --every "
                                 "or fewer --steps");
    write_output(o.output, [&](std::ostream& out) {
        const std::string title = std::filesystem::path(name).stem().string();
        Recording recording(scene, world, ids,
                            {.title = title, .every = every, .max_contact_points = o.max_contacts});
        recording.add_frame(0, world);
        for (int step = 1; step <= steps; ++step) {
            if (const auto d = replayer.advance())
                throw std::runtime_error(name +
                                         ": the replay departs from the recording: " + d->message);
            for (const BodyId id : ids)
                if (!world.is_valid(id))
                    throw std::runtime_error(
                        name + ": step " + std::to_string(step) + ": body " +
                        std::to_string(id.index) +
                        " was destroyed; the page plays the bodies of the first frame: view the "
                        "steps before it with --steps " +
                        std::to_string(step - 1));
            if (step % every == 0 || step == steps)
                recording.add_frame(step, world);
        }
        recording.write_html(out);
    });
    return 0;
}

} // namespace

int view_command(std::span<const std::string_view> args, const SceneSource& source) {
    const ViewOptions o = parse(args);
    if (o.help) {
        std::cout << view_usage;
        return 0;
    }
    if (o.scene != "-" && is_recording_file(o.scene))
        return view_recording(o, source.display_name(o.scene));
    const io::Scene scene = source.load(o.scene);
    // The schedule of `run --every K`: frame 0, every K steps, and the final step, so that
    // the page's frames are the rows `run` writes with the same options.
    const int steps = o.steps.value_or(scene.steps);
    const int every = o.every.value_or(scene.output_every > 0 ? scene.output_every : 1);
    const long long frames = 1LL + steps / every + (steps % every != 0 ? 1 : 0);
    if (frames > max_frames ||
        frames * static_cast<long long>(scene.bodies.size()) > max_body_frames)
        throw std::runtime_error(
            source.display_name(o.scene) + ": " + std::to_string(frames) + " frames of " +
            std::to_string(scene.bodies.size()) + " bodies are more than the player holds (" +
            std::to_string(max_frames) + " frames, " + std::to_string(max_body_frames) +
            " body states): use a larger --every or fewer --steps");

    // As `run`: the output is opened before the run (a wrong path fails at once), and removed
    // again when the run or the write fails.
    std::ofstream file;
    if (!o.output.empty()) {
        file.open(o.output, std::ios::binary | std::ios::trunc);
        if (!file)
            throw std::runtime_error("cannot write '" + o.output + "'");
    }
    std::ostream& out = o.output.empty() ? std::cout : file;
    try {
        WorldDef def = scene.world;
        def.workers = o.workers.value_or(def.workers);
        World world(def);
        const std::vector<BodyId> ids = io::build_world(scene, world);
        const std::string title =
            std::filesystem::path(source.display_name(o.scene)).stem().string();
        Recording recording(scene, world, ids,
                            {.title = title, .every = every, .max_contact_points = o.max_contacts});
        recording.add_frame(0, world);
        for (int step = 1; step <= steps; ++step) {
            world.step(scene.dt);
            if (step % every == 0 || step == steps)
                recording.add_frame(step, world);
        }
        recording.write_html(out);
        out.flush();
        if (!out)
            throw std::runtime_error("writing the output failed");
    } catch (...) {
        if (!o.output.empty()) {
            file.close();
            std::error_code ec;
            std::filesystem::remove(o.output, ec);
        }
        throw;
    }
    return 0;
}

} // namespace tamias2d::cli
