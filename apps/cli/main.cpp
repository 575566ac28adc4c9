// tamias2d: runs and checks scene files (docs/scene-format.md) from the command line.
//
//   tamias2d run <scene.json | -> [--steps N] [--every K] [--format csv|json] [-o FILE]
//                [--workers N]
//   tamias2d validate <scene.json | ->
//   tamias2d view <scene.json | -> [--steps N] [--every K] [-o FILE] [--workers N]
//                (view_command.cpp)
//   tamias2d draw <scene.json | -> [--steps N] [--out FILE.svg] [...] (draw_command.cpp)
//   tamias2d record <scene.json | -> -o FILE [--steps N] [...] (record_command.cpp)
//   tamias2d replay <FILE> [--workers N] (record_command.cpp)
//   tamias2d info
//   tamias2d help [COMMAND] | --help | --version
//
// Exit codes: 0 success, 1 invalid scene or failed run, 2 bad command line. Every error is one
// line on stderr: "tamias2d: error: <file>: <JSON pointer or line:column>: <what is wrong>".
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <numbers>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "draw_command.hpp"
#include "record_command.hpp"
#include "tamias2d/build_info.hpp"
#include "tamias2d/errors.hpp"
#include "tamias2d/io/scene.hpp"
#include "tamias2d/world.hpp"
#include "view_command.hpp"

namespace {

using namespace tamias2d;

constexpr const char* usage = R"(Usage:
  tamias2d run <scene.json | -> [--steps N] [--every K] [--format csv|json] [-o FILE]
               [--workers N]
  tamias2d validate <scene.json | ->
  tamias2d view <scene.json | recording | -> [--steps N] [--every K] [-o FILE.html]
               [--workers N]
  tamias2d draw <scene.json | -> [--steps N] [--out FILE.svg] [--contacts] [--aabbs]
               [--centers] [--no-joints] [--bounds X0,Y0,X1,Y1] [--width PX] [--workers N]
  tamias2d record <scene.json | -> -o FILE [--steps N] [--no-body-states] [--workers N]
  tamias2d replay <FILE> [--workers N]
  tamias2d info
  tamias2d help [COMMAND]
  tamias2d --help | --version

Commands:
  run        Simulate a scene and write the bodies' states (SI units).
  validate   Parse and check a scene without running it; print a one-line summary.
  view       Simulate a scene (or replay a recording) and write a self-contained HTML page
             that plays the run.
  draw       Simulate a scene and draw its last state as an SVG picture (World::draw).
  record     Simulate a scene and write the run as a recording (snapshot, calls, per-step
             state hashes and body states).
  replay     Replay a recording and check every step bit for bit; name the first step, body
             and field that differ (exit status 3).
  info       Print the version, the solver's instruction set on this machine and the build.
  help       Print this text, or a command's own (also: tamias2d COMMAND --help).

A scene file of "-" is read from standard input.

Exit status: 0 on success, 1 for an invalid scene or a failed run, 2 for a bad command line,
3 when a replay departs from its recording.
Errors are one line on standard error: "tamias2d: error: <file>: <place>: <what is wrong>".
The scene format is described in docs/scene-format.md.
)";

constexpr const char* run_usage = R"(Usage: tamias2d run <scene.json | -> [options]

Simulate the scene and write body states: the initial state and every K steps, and always the
final state. Columns: step, time (s), body index, body name, x, y (m, centre of mass), vx, vy
(m/s), phi (rad, in [0, 2 pi)), omega (rad/s). Numbers are written in the shortest form that
reads back as the same double. A scene file of "-" is read from standard input.

Options:
  --steps N          number of steps (default: the scene's "steps")
  --every K          write states every K steps; 0 writes only the final state
                     (default: the scene's "output_every")
  --format F         csv (default) or json
  -o, --output FILE  write to FILE instead of standard output ("-": standard output); no
                     partial file is left behind when the run fails
  --workers N        step on N threads, N in [1, 256] (default 1); the states are bitwise
                     the same for every N. The contact passes run on several threads only in
                     a scene whose world sets "contact_regions" above 1
  -h, --help         print this text

Exit status: 0 on success, 1 for an invalid scene or a failed run (a state that is not finite
stops the run), 2 for a bad command line.
)";

constexpr const char* validate_usage = R"(Usage: tamias2d validate <scene.json | ->

Parse and check the scene (syntax, types, every data constraint, a dry build of every body and
shape) without running it, and print "<file>: OK: B bodies, S shapes, dt = T s, N steps".
A scene file of "-" is read from standard input.

Exit status: 0 for a valid scene, 1 for an invalid one (one line on standard error naming the
place, the field and the violated constraint), 2 for a bad command line.
)";

constexpr const char* info_usage = R"(Usage: tamias2d info

Print the library's version, the instruction set the contact solver runs with on this machine
(x86-64-v4, avx2 or sse2 on x86-64, chosen when the program starts; all give bitwise the same
results), and the compiler that built it.

Exit status: 0.
)";

const char* usage_of(std::string_view command) {
    if (command == "run")
        return run_usage;
    if (command == "validate")
        return validate_usage;
    if (command == "info")
        return info_usage;
    if (command == "view")
        return cli::view_usage;
    if (command == "draw")
        return cli::draw_usage;
    if (command == "record")
        return cli::record_usage;
    if (command == "replay")
        return cli::replay_usage;
    return nullptr;
}

/// A bad command line (exit status 2); shared with view_command.cpp.
using UsageError = cli::UsageError;

struct Options {
    std::string command;
    bool help = false; ///< print the command's usage and stop
    std::string scene;
    std::optional<int> steps;
    std::optional<int> every;
    std::string format = "csv";
    std::string output;
    std::optional<int> workers; ///< WorldDef::workers; a scene file does not carry it
};

int parse_count(std::string_view option, std::string_view text) {
    int v = 0;
    const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
    if (r.ec != std::errc{} || r.ptr != text.data() + text.size() || v < 0)
        throw UsageError(std::string(option) + " expects an integer >= 0, got '" +
                         std::string(text) + "'");
    return v;
}

Options parse_args(const std::vector<std::string_view>& args) {
    Options o;
    if (args.empty())
        throw UsageError("missing command (run, validate, view, draw, info or help)");
    o.command = args[0];
    if (o.command == "help") {
        if (args.size() > 2)
            throw UsageError("help takes at most one command");
        if (args.size() == 2 && usage_of(args[1]) == nullptr)
            throw UsageError("no help for '" + std::string(args[1]) +
                             "' (commands: run, validate, view, draw, record, replay, info)");
        o.help = true;
        o.command = args.size() == 2 ? std::string(args[1]) : std::string{};
        return o;
    }
    if (usage_of(o.command) == nullptr)
        throw UsageError("unknown command '" + o.command +
                         "' (expected run, validate, view, draw or info)");
    for (std::size_t i = 1; i < args.size(); ++i) {
        const std::string_view a = args[i];
        const auto value = [&]() -> std::string_view {
            if (o.command != "run")
                throw UsageError("option " + std::string(a) + " applies to 'run' only");
            if (i + 1 >= args.size())
                throw UsageError("option " + std::string(a) + " needs a value");
            return args[++i];
        };
        if (a == "--help" || a == "-h") {
            o.help = true;
        } else if (a == "--steps") {
            o.steps = parse_count(a, value());
        } else if (a == "--every") {
            o.every = parse_count(a, value());
        } else if (a == "--format") {
            o.format = value();
            if (o.format != "csv" && o.format != "json")
                throw UsageError("--format expects csv or json, got '" + o.format + "'");
        } else if (a == "--workers") {
            o.workers = parse_count(a, value());
            if (*o.workers == 0)
                throw UsageError("--workers expects an integer >= 1, got '0'");
        } else if (a == "--output" || a == "-o") {
            o.output = value();
            if (o.output.empty())
                throw UsageError(std::string(a) + " needs a file name");
            if (o.output == "-")
                o.output.clear();
        } else if (a.starts_with("-") && a.size() > 1) {
            throw UsageError("unknown option '" + std::string(a) + "'");
        } else if (o.command == "info") {
            throw UsageError("info takes no argument, got '" + std::string(a) + "'");
        } else if (o.scene.empty()) {
            o.scene = a;
        } else {
            throw UsageError("unexpected argument '" + std::string(a) + "'");
        }
    }
    if (o.scene.empty() && !o.help && o.command != "info")
        throw UsageError("missing scene file");
    return o;
}

/// Shortest text that reads back as the same double.
std::string num(double v) {
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, r.ptr);
}

std::string csv_field(const std::string& s) {
    if (s.find_first_of(",\"\n\r") == std::string::npos)
        return s;
    std::string q = "\"";
    for (const char c : s)
        q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
}

/// Writes frames as CSV rows or as one JSON document, streaming.
class Writer {
  public:
    Writer(std::ostream& out, bool json, const io::Scene& scene, const std::string& scene_name,
           int steps)
        : out_(out), json_(json) {
        if (json_) {
            out_ << "{\"scene\": " << nlohmann::json(scene_name).dump()
                 << ", \"dt\": " << num(scene.dt) << ", \"steps\": " << steps << ", \"frames\": [";
        } else {
            out_ << "step,time,index,name,x,y,vx,vy,phi,omega\n";
        }
    }
    void frame(int step, const World& world, const std::vector<BodyId>& ids,
               const io::Scene& scene) {
        if (json_)
            out_ << (first_frame_ ? "\n" : ",\n") << "{\"step\": " << step
                 << ", \"time\": " << num(world.time()) << ", \"bodies\": [";
        first_frame_ = false;
        for (std::size_t i = 0; i < ids.size(); ++i) {
            const BodyState s = world.state(ids[i]);
            check_outputs(s, step, i, scene.bodies[i].def.name);
            const std::string& name = scene.bodies[i].def.name;
            if (json_) {
                out_ << (i == 0 ? "\n  " : ",\n  ") << "{\"index\": " << i
                     << ", \"name\": " << nlohmann::json(name).dump()
                     << ", \"x\": " << num(s.position.x) << ", \"y\": " << num(s.position.y)
                     << ", \"vx\": " << num(s.velocity.x) << ", \"vy\": " << num(s.velocity.y)
                     << ", \"phi\": " << num(s.orientation)
                     << ", \"omega\": " << num(s.angular_velocity) << "}";
            } else {
                out_ << step << ',' << num(world.time()) << ',' << i << ',' << csv_field(name)
                     << ',' << num(s.position.x) << ',' << num(s.position.y) << ','
                     << num(s.velocity.x) << ',' << num(s.velocity.y) << ',' << num(s.orientation)
                     << ',' << num(s.angular_velocity) << '\n';
            }
        }
        if (json_)
            out_ << "]}";
    }
    void finish() {
        if (json_)
            out_ << "\n]}\n";
        out_.flush();
    }

  private:
    /// Table 2 (DCO_p, DCO_v, DCO_phi, DCO_omega): outputs are finite and phi is in [0, 2 pi).
    static void check_outputs(const BodyState& s, int step, std::size_t index,
                              const std::string& name) {
        const double values[] = {s.position.x, s.position.y,  s.velocity.x,
                                 s.velocity.y, s.orientation, s.angular_velocity};
        const bool finite = std::all_of(std::begin(values), std::end(values),
                                        [](double v) { return std::isfinite(v); });
        const bool phi_ok = s.orientation >= 0.0 && s.orientation < 2.0 * std::numbers::pi;
        if (!finite || !phi_ok)
            throw std::runtime_error("step " + std::to_string(step) + ": body " +
                                     std::to_string(index) +
                                     (name.empty() ? std::string{} : " '" + name + "'") +
                                     (finite ? " has phi outside [0, 2 pi) (DCO_phi)"
                                             : " has a non-finite state (DCO_p, DCO_v, "
                                               "DCO_phi, DCO_omega)"));
    }

    std::ostream& out_;
    bool json_;
    bool first_frame_ = true;
};

/// The build's facts: version, solver instruction set, compiler.
void print_info() {
    std::cout << "tamias2d " << library_version() << "\n"
              << "solver instruction set: " << solver_instruction_set() << "\n"
              << "compiler: "
#if defined(__clang__)
              << "clang " << __clang_major__ << '.' << __clang_minor__ << '.'
              << __clang_patchlevel__
#elif defined(__GNUC__)
              << "gcc " << __GNUC__ << '.' << __GNUC_MINOR__ << '.' << __GNUC_PATCHLEVEL__
#else
              << "unknown"
#endif
              << ", C++ " << __cplusplus << "\n"
              << "floating point: IEEE 754 double, no fused multiply-add in the library\n";
}

/// The scene file's name in messages and outputs.
std::string display_name(const std::string& scene) {
    return scene == "-" ? std::string("<stdin>") : scene;
}

/// The scene named on the command line; "-" is standard input. Both are read in chunks up to
/// the scene size limit (io::max_scene_bytes), so an endless input is refused promptly.
io::Scene load(const std::string& scene) {
    if (scene != "-")
        return io::load_scene(scene);
    return io::load_scene(std::cin, display_name(scene));
}

int run(const Options& o) {
    if (o.help) {
        const char* text = usage_of(o.command);
        std::cout << (text != nullptr ? text : usage);
        return 0;
    }
    if (o.command == "info") {
        print_info();
        return 0;
    }
    const io::Scene scene = load(o.scene);
    if (o.command == "validate") {
        std::size_t shapes = 0;
        for (const io::SceneBody& b : scene.bodies)
            shapes += b.shapes.size();
        std::cout << display_name(o.scene) << ": OK: " << scene.bodies.size() << " bodies, "
                  << shapes << " shapes, dt = " << num(scene.dt) << " s, " << scene.steps
                  << " steps\n";
        return 0;
    }
    const int steps = o.steps.value_or(scene.steps);
    const int every = o.every.value_or(scene.output_every);

    WorldDef def = scene.world;
    // (Its upper bound is the world's rule, reported as a failed run with the field named.)
    def.workers = o.workers.value_or(def.workers);
    World world(def);
    const std::vector<BodyId> ids = io::build_world(scene, world);

    std::ofstream file;
    if (!o.output.empty()) {
        file.open(o.output, std::ios::binary | std::ios::trunc);
        if (!file)
            throw std::runtime_error("cannot write '" + o.output + "'");
    }
    std::ostream& out = o.output.empty() ? std::cout : file;
    try {
        Writer w(out, o.format == "json", scene, display_name(o.scene), steps);
        if (every > 0)
            w.frame(0, world, ids, scene);
        for (int step = 1; step <= steps; ++step) {
            world.step(scene.dt);
            if ((every > 0 && step % every == 0) || step == steps)
                w.frame(step, world, ids, scene);
        }
        if (steps == 0 && every == 0)
            w.frame(0, world, ids, scene);
        w.finish();
        if (!out)
            throw std::runtime_error("writing the output failed");
    } catch (...) {
        if (!o.output.empty()) { // no partial output file
            file.close();
            std::error_code ec;
            std::filesystem::remove(o.output, ec);
        }
        throw;
    }
    return 0;
}

/// Error messages stay on one line whatever the scene's strings contain.
std::string one_line(std::string s) {
    std::replace(s.begin(), s.end(), '\n', ' ');
    std::replace(s.begin(), s.end(), '\r', ' ');
    return s;
}

} // namespace

int main(int argc, char** argv) {
    std::vector<std::string_view> args(argv + 1, argv + argc);
    if (!args.empty() && (args[0] == "--help" || args[0] == "-h")) {
        std::cout << usage;
        return 0;
    }
    if (!args.empty() && args[0] == "--version") {
        std::cout << "tamias2d " << library_version() << '\n';
        return 0;
    }
    try {
        if (!args.empty() && args[0] == "view") // its own options (view_command.cpp)
            return cli::view_command(std::span(args).subspan(1), {load, display_name});
        if (!args.empty() && args[0] == "draw") // its own options (draw_command.cpp)
            return cli::draw_command(std::span(args).subspan(1), {load, display_name});
        if (!args.empty() && args[0] == "record") // its own options (record_command.cpp)
            return cli::record_command(std::span(args).subspan(1), {load, display_name});
        if (!args.empty() && args[0] == "replay")
            return cli::replay_command(std::span(args).subspan(1));
        return run(parse_args(args));
    } catch (const UsageError& e) {
        std::cerr << "tamias2d: error: " << one_line(e.what()) << " (see tamias2d --help)\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "tamias2d: error: " << one_line(e.what()) << '\n';
        return 1;
    } catch (...) {
        std::cerr << "tamias2d: error: unknown failure\n";
        return 1;
    }
}
