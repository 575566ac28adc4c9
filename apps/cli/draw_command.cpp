// `tamias2d draw`: the options, the run and the SVG file.
#include "draw_command.hpp"

#include <charconv>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <string>
#include <system_error>
#include <vector>

#include "svg_draw.hpp"
#include "tamias2d/world.hpp"

namespace tamias2d::cli {

const char* const draw_usage = R"(Usage: tamias2d draw <scene.json | -> [options]

Simulate the scene as 'run' does and draw the world after the last step as one SVG picture
through World::draw (the debug draw interface): the shapes filled in their state's colour
(static, kinematic, awake, sleeping, sensor, bullet) and the joints; contact points and
normals, broad-phase boxes and centres of mass on request. y points up. A scene file of "-"
is read from standard input.

Options:
  --steps N           number of steps (default: the scene's "steps"); 0 draws the start
  --contacts          draw the touching contacts' points and normals
  --aabbs             draw each shape's broad-phase box
  --centers           draw each body's centre of mass and axes
  --no-joints         leave the joints out
  --bounds X0,Y0,X1,Y1
                      draw only what lies in this box (m)
  --width PX          the picture's width in pixels, in [16, 100000] (default 1000)
  -o, --out FILE      write to FILE instead of standard output ("-": standard output); no
                      partial file is left behind when the run fails
  --workers N         step on N threads, N in [1, 256] (default 1): the same picture for
                      every N
  -h, --help          print this text

After writing, prints one summary line on standard error: the primitives drawn by kind.

Exit status: 0 on success, 1 for an invalid scene or a failed run, 2 for a bad command line.
)";

namespace {

struct DrawOptions {
    bool help = false;
    std::string scene;
    std::optional<int> steps;
    bool contacts = false, aabbs = false, centers = false, joints = true;
    std::optional<Aabb> bounds;
    int width = 1000;
    std::string output;
    std::optional<int> workers;
};

int parse_int(std::string_view option, std::string_view text, int minimum) {
    int v = 0;
    const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
    if (r.ec != std::errc{} || r.ptr != text.data() + text.size() || v < minimum)
        throw UsageError(std::string(option) + " expects an integer >= " + std::to_string(minimum) +
                         ", got '" + std::string(text) + "'");
    return v;
}

/// "X0,Y0,X1,Y1" in metres; the world checks the box (finite, min <= max) when it draws.
Aabb parse_bounds(std::string_view text) {
    double v[4] = {};
    const char* p = text.data();
    const char* end = text.data() + text.size();
    for (int k = 0; k < 4; ++k) {
        const auto r = std::from_chars(p, end, v[k]);
        if (r.ec != std::errc{} || (k < 3 && (r.ptr == end || *r.ptr != ',')) ||
            (k == 3 && r.ptr != end))
            throw UsageError("--bounds expects four numbers X0,Y0,X1,Y1 (m), got '" +
                             std::string(text) + "'");
        p = r.ptr + 1;
    }
    return {v[0], v[1], v[2], v[3]};
}

DrawOptions parse(std::span<const std::string_view> args) {
    DrawOptions o;
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
        } else if (a == "--contacts") {
            o.contacts = true;
        } else if (a == "--aabbs") {
            o.aabbs = true;
        } else if (a == "--centers") {
            o.centers = true;
        } else if (a == "--no-joints") {
            o.joints = false;
        } else if (a == "--bounds") {
            o.bounds = parse_bounds(value());
        } else if (a == "--width") {
            o.width = parse_int(a, value(), 16);
            if (o.width > 100000)
                throw UsageError("--width expects an integer <= 100000, got '" +
                                 std::to_string(o.width) + "'");
        } else if (a == "--workers") {
            o.workers = parse_int(a, value(), 1);
        } else if (a == "--out" || a == "--output" || a == "-o") {
            o.output = value();
            if (o.output.empty())
                throw UsageError(std::string(a) + " needs a file name");
            if (o.output == "-")
                o.output.clear();
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

} // namespace

int draw_command(std::span<const std::string_view> args, const SceneSource& source) {
    const DrawOptions o = parse(args);
    if (o.help) {
        std::cout << draw_usage;
        return 0;
    }
    const io::Scene scene = source.load(o.scene);
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
        io::build_world(scene, world);
        const int steps = o.steps.value_or(scene.steps);
        for (int step = 1; step <= steps; ++step)
            world.step(scene.dt);
        SvgDraw svg(o.width);
        svg.draw_joints = o.joints;
        svg.draw_contacts = svg.draw_contact_normals = o.contacts;
        svg.draw_aabbs = o.aabbs;
        svg.draw_mass_centers = o.centers;
        svg.bounds = o.bounds;
        world.draw(svg);
        const std::string title =
            std::filesystem::path(source.display_name(o.scene)).stem().string();
        svg.write(out, title + " after " + std::to_string(steps) + " steps");
        out.flush();
        if (!out)
            throw std::runtime_error("writing the output failed");
        const SvgDraw::Counts& c = svg.counts();
        std::cerr << "drew " << c.solid_polygons << " polygons, " << c.circles << " circles, "
                  << c.capsules << " capsules, " << c.segments << " segments, " << c.polygons
                  << " boxes, " << c.points << " points, " << c.transforms << " frames\n";
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
