// tamias2d: runs and checks scene files (docs/scene-format.md) from the command line.
//
//   tamias2d run <scene.json> [--steps N] [--every K] [--format csv|json] [--output FILE]
//   tamias2d validate <scene.json>
//   tamias2d --help | --version
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
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "tamias2d/errors.hpp"
#include "tamias2d/io/scene.hpp"
#include "tamias2d/world.hpp"

namespace {

using namespace tamias2d;

constexpr const char* usage = R"(Usage:
  tamias2d run <scene.json> [--steps N] [--every K] [--format csv|json] [--output FILE]
  tamias2d validate <scene.json>
  tamias2d --help | --version

Commands:
  run        Simulate the scene and write body states: the initial state and every K steps,
             and always the final state. Columns: step, time (s), body index, body name,
             x, y (m, centre of mass), vx, vy (m/s), phi (rad, in [0, 2 pi)), omega (rad/s).
  validate   Parse and check the scene without running it; prints a one-line summary.

Options (run):
  --steps N        number of steps (default: the scene's "steps")
  --every K        write states every K steps; 0 writes only the final state
                   (default: the scene's "output_every")
  --format F       csv (default) or json
  --output FILE    write to FILE instead of standard output

Exit status: 0 on success, 1 for an invalid scene or a failed run, 2 for a bad command line.
The scene format is described in docs/scene-format.md.
)";

/// A bad command line (exit status 2).
struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct Options {
    std::string command;
    std::string scene;
    std::optional<int> steps;
    std::optional<int> every;
    std::string format = "csv";
    std::string output;
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
        throw UsageError("missing command (run or validate)");
    o.command = args[0];
    if (o.command != "run" && o.command != "validate")
        throw UsageError("unknown command '" + o.command + "' (expected run or validate)");
    for (std::size_t i = 1; i < args.size(); ++i) {
        const std::string_view a = args[i];
        const auto value = [&]() -> std::string_view {
            if (o.command != "run")
                throw UsageError("option " + std::string(a) + " applies to 'run' only");
            if (i + 1 >= args.size())
                throw UsageError("option " + std::string(a) + " needs a value");
            return args[++i];
        };
        if (a == "--steps") {
            o.steps = parse_count(a, value());
        } else if (a == "--every") {
            o.every = parse_count(a, value());
        } else if (a == "--format") {
            o.format = value();
            if (o.format != "csv" && o.format != "json")
                throw UsageError("--format expects csv or json, got '" + o.format + "'");
        } else if (a == "--output") {
            o.output = value();
            if (o.output.empty())
                throw UsageError("--output needs a file name");
        } else if (a.starts_with("-") && a.size() > 1) {
            throw UsageError("unknown option '" + std::string(a) + "'");
        } else if (o.scene.empty()) {
            o.scene = a;
        } else {
            throw UsageError("unexpected argument '" + std::string(a) + "'");
        }
    }
    if (o.scene.empty())
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

int run(const Options& o) {
    const io::Scene scene = io::load_scene(o.scene);
    if (o.command == "validate") {
        std::size_t shapes = 0;
        for (const io::SceneBody& b : scene.bodies)
            shapes += b.shapes.size();
        std::cout << o.scene << ": OK: " << scene.bodies.size() << " bodies, " << shapes
                  << " shapes, dt = " << num(scene.dt) << " s, " << scene.steps << " steps\n";
        return 0;
    }
    const int steps = o.steps.value_or(scene.steps);
    const int every = o.every.value_or(scene.output_every);

    World world(scene.world);
    const std::vector<BodyId> ids = io::build_world(scene, world);

    std::ofstream file;
    if (!o.output.empty()) {
        file.open(o.output, std::ios::binary | std::ios::trunc);
        if (!file)
            throw std::runtime_error("cannot write '" + o.output + "'");
    }
    std::ostream& out = o.output.empty() ? std::cout : file;
    try {
        Writer w(out, o.format == "json", scene, o.scene, steps);
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
    if (!args.empty() && (args[0] == "--help" || args[0] == "-h" || args[0] == "help")) {
        std::cout << usage;
        return 0;
    }
    if (!args.empty() && args[0] == "--version") {
        std::cout << "tamias2d 0.1.0\n";
        return 0;
    }
    try {
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
