// Scene input that is hostile or merely huge (R4, docs/scene-format.md "Limits"): the size limit
// enforced while reading (an endless source is refused promptly, with bounded memory), NUL
// bytes, messages that quote at most a short escaped excerpt, the supported range (DCX_range)
// named at its key, integer conversions without undefined behaviour, self-crossing polygon
// outlines, and the round trip of scene_to_json for every box that loads.
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <sstream>
#include <streambuf>
#include <string>
#include <vector>

#if defined(__unix__)
#include <csignal>
#include <fcntl.h>
#include <sys/stat.h>
#include <thread>
#include <unistd.h>
#endif

#include "support/cpu_time.hpp"
#include "tamias2d/io/scene.hpp"
#include "tamias2d/io/scene_generators.hpp"
#include "tamias2d/world.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;
using namespace tamias2d::io;

namespace {

const std::string empty_scene = R"({"dt": 0.01, "steps": 1, "bodies": []})";

/// A valid scene around `bodies` (the text of the bodies array's elements).
std::string with_bodies(const std::string& bodies, const std::string& extra = "") {
    return R"({"dt": 0.01, "steps": 10, )" + extra + R"("bodies": [)" + bodies + "]}";
}

/// The SceneError of parsing `json` (a default one, and a test failure, if it loads).
SceneError error_of(const std::string& json) {
    try {
        (void)parse_scene(json, "test.json");
        BOOST_ERROR("accepted: " << json.substr(0, 200));
    } catch (const SceneError& e) {
        return e;
    }
    return SceneError("", "", 0, 0, "", "", "");
}

/// Rejected at `pointer` with `constraint`, the message containing `text` and on one line.
void expect_rejected(const std::string& json, const std::string& pointer,
                     const std::string& constraint, const std::string& text) {
    const SceneError e = error_of(json);
    const std::string what = e.what();
    BOOST_TEST(e.pointer == pointer, what);
    BOOST_TEST(e.constraint == constraint, what);
    BOOST_TEST(what.find(text) != std::string::npos, what << "\nexpected to contain: " << text);
    BOOST_TEST(what.find('\n') == std::string::npos, what);
}

/// An endless stream of a byte that counts what it hands out: what a reader consumed.
class Endless : public std::streambuf {
  public:
    explicit Endless(char c) : buffer_(4096, c) {}
    std::size_t handed_out = 0;

  protected:
    int_type underflow() override {
        handed_out += buffer_.size();
        setg(buffer_.data(), buffer_.data(), buffer_.data() + buffer_.size());
        return traits_type::to_int_type(buffer_[0]);
    }

  private:
    std::vector<char> buffer_;
};

} // namespace

BOOST_AUTO_TEST_SUITE(scene_limits)

// Oracle: docs/scene-format.md, Limits: a text beyond the size limit is refused with a message
// naming the limit; at the limit it is parsed (here: rejected for its content, not its size).
BOOST_AUTO_TEST_CASE(text_beyond_the_size_limit_is_refused, *utf::label("scene")) {
    const std::string padded = empty_scene + std::string(1000, ' ');
    try {
        (void)parse_scene(padded, "big.json", padded.size() - 1);
        BOOST_ERROR("a text one byte beyond the limit was parsed");
    } catch (const SceneError& e) {
        BOOST_TEST(std::string(e.what()).find("larger than the size limit of " +
                                              std::to_string(padded.size() - 1) + " bytes") !=
                   std::string::npos);
    }
    BOOST_CHECK_NO_THROW((void)parse_scene(padded, "big.json", padded.size()));
    BOOST_TEST(max_scene_bytes == std::size_t{64} << 20);
}

// Oracle: the limit is enforced while reading, not after: from an endless stream the reader
// takes no more than the limit and one chunk (64 KiB) before it refuses.
BOOST_AUTO_TEST_CASE(an_endless_stream_is_refused_while_reading, *utf::label("scene")) {
    Endless zeros('\0');
    std::istream in(&zeros);
    constexpr std::size_t limit = std::size_t{1} << 20;
    try {
        (void)load_scene(in, "<endless>", limit);
        BOOST_ERROR("an endless stream was loaded");
    } catch (const SceneError& e) {
        BOOST_TEST(e.origin == "<endless>");
        BOOST_TEST(std::string(e.what()).find("size limit") != std::string::npos, e.what());
    }
    BOOST_TEST(zeros.handed_out <= limit + (std::size_t{1} << 16) + 4096);
    // A stream within the limit is read whole.
    std::istringstream small(empty_scene);
    BOOST_TEST(load_scene(small, "<small>").bodies.empty());
}

#if defined(__unix__)
// Oracle: `tamias2d validate /dev/zero` used never to end: /dev/zero is refused after the limit.
BOOST_AUTO_TEST_CASE(dev_zero_is_refused, *utf::label("scene")) {
    try {
        (void)load_scene("/dev/zero", std::size_t{1} << 20);
        BOOST_ERROR("/dev/zero was loaded");
    } catch (const SceneError& e) {
        BOOST_TEST(std::string(e.what()).find("size limit of 1048576 bytes (1 MiB)") !=
                   std::string::npos);
    }
}

// Oracle: a FIFO whose writer never stops is refused while reading: the writer, which would
// write 64 MiB, is cut off (EPIPE) after the limit plus what the pipe and one chunk hold.
BOOST_AUTO_TEST_CASE(an_endless_fifo_is_refused_while_reading, *utf::label("scene")) {
    const std::string path = "/tmp/tamias2d_scene_fifo_" + std::to_string(::getpid());
    ::unlink(path.c_str());
    BOOST_TEST_REQUIRE(::mkfifo(path.c_str(), 0600) == 0);
    const auto old_handler = std::signal(SIGPIPE, SIG_IGN); // EPIPE instead of a signal
    std::size_t written = 0;
    std::thread writer([&] {
        const int fd = ::open(path.c_str(), O_WRONLY);
        if (fd < 0)
            return;
        const std::string block(1 << 16, '[');
        while (written < (std::size_t{64} << 20)) {
            const ssize_t n = ::write(fd, block.data(), block.size());
            if (n <= 0)
                break;
            written += std::size_t(n);
        }
        ::close(fd);
    });
    constexpr std::size_t limit = std::size_t{1} << 20;
    BOOST_CHECK_THROW((void)load_scene(path, limit), SceneError);
    writer.join();
    std::signal(SIGPIPE, old_handler);
    ::unlink(path.c_str());
    BOOST_TEST(written <= limit + (std::size_t{4} << 20), "the writer got " << written << " out");
}
#endif

// Oracle: RFC 8259: JSON text contains no NUL. A valid scene followed by a NUL and garbage was
// accepted (the parser took the NUL for the end) while the same without the NUL was not: both
// are rejected now, the NUL at its line and column.
BOOST_AUTO_TEST_CASE(a_nul_byte_is_a_syntax_error, *utf::label("scene")) {
    const SceneError with_nul = error_of(empty_scene + std::string("\0garbage", 8));
    BOOST_TEST(std::string(with_nul.what()).find("NUL byte") != std::string::npos);
    BOOST_TEST(with_nul.line == 1);
    BOOST_TEST(with_nul.column == int(empty_scene.size()) + 1);
    const SceneError without = error_of(empty_scene + "garbage");
    BOOST_TEST(std::string(without.what()).find("syntax error") != std::string::npos);
    std::string nul_inside = "{\"dt\": 0.01,\n \"steps\"";
    nul_inside += '\0';
    nul_inside += ": 1}";
    const SceneError inside = error_of(nul_inside);
    BOOST_TEST(inside.line == 2);
    BOOST_TEST(inside.column == 9);
}

// Oracle: docs/scene-format.md, Errors: a pointer is shown by its first and last six levels,
// so 100 000 levels of nesting give a short message; the pointer member stays whole.
BOOST_AUTO_TEST_CASE(deep_pointers_are_shortened_in_messages, *utf::label("scene")) {
    const SceneError e = error_of(std::string(100000, '['));
    const std::string what = e.what();
    BOOST_TEST(what.size() < 160, what);
    BOOST_TEST(what.find("/0/0/0/0/0/0/[... 115 levels ...]/0/0/0/0/0/0") != std::string::npos,
               what);
    BOOST_TEST(e.pointer.size() == 2 * 127u); // "/0" per level below the root
}

// Oracle: a message quotes a user's string escaped as JSON writes it (no raw control character
// reaches a terminal or breaks the one-line format) and at most 64 bytes of it.
BOOST_AUTO_TEST_CASE(quoted_user_text_is_escaped_and_short, *utf::label("scene")) {
    const SceneError key =
        error_of(R"({"dt": 0.01, "steps": 1, "bodies": [], "a\nb\u0001\u001b[2J": 1})");
    const std::string what = key.what();
    BOOST_TEST(what.find("unknown key 'a\\nb\\u0001\\u001b[2J'") != std::string::npos, what);
    for (const char c : what)
        BOOST_TEST((static_cast<unsigned char>(c) >= 0x20 && c != 0x7f), "control character");
    BOOST_TEST(key.field == "a\nb\x01\x1b[2J"); // the member keeps the key as it is
    const std::string long_key(100000, 'k');
    const SceneError long_error = error_of("{\"" + long_key + "\": 1}");
    BOOST_TEST(std::string(long_error.what()).size() < 400);
    BOOST_TEST(std::string(long_error.what()).find("... (100000 bytes)") != std::string::npos);
    const SceneError name =
        error_of(with_bodies(R"({"name": "x\ty", "mass": 1}, {"name": "x\ty", "mass": 1})"));
    BOOST_TEST(std::string(name.what()).find("body name 'x\\ty' is already used") !=
               std::string::npos);
    // A long string token in a syntax error is quoted by its start only.
    const SceneError token = error_of("{\"dt\": \"" + std::string(100000, 'z') + "\x01\"}");
    BOOST_TEST(std::string(token.what()).size() < 400, token.what());
    // A multi-byte character is not cut in the middle.
    const SceneError utf8 = error_of("{\"" + std::string(63, 'k') + "\xc3\xa9tude\": 1}");
    BOOST_TEST(std::string(utf8.what()).find("k... (") != std::string::npos, utf8.what());
}

// Oracle: DCX_range (docs/design.md, "Supported ranges"), named at the key in the file: the
// issue's box 1e300 m wide and 1e-300 m high, dt 1e300, a force of 1e308, a velocity of 1e300,
// a radius of 1e-200 and a density of 1e-320, which loaded (or failed with a message about a
// normal) before.
BOOST_AUTO_TEST_CASE(values_beyond_the_supported_range_are_named,
                     *utf::label("R4") * utf::label("DCX_range")) {
    const auto box = [](const std::string& w, const std::string& h) {
        return with_bodies(R"({"shapes": [{"type": "box", "width": )" + w + R"(, "height": )" + h +
                           "}]}");
    };
    expect_rejected(box("1e300", "1"), "/bodies/0/shapes/0/width", "DCX_range",
                    "width = 1e+300: must be in [1e-12, 1e+12] m, the supported range");
    expect_rejected(box("1", "1e-300"), "/bodies/0/shapes/0/height", "DCX_range",
                    "height = 1e-300: must be in [1e-12, 1e+12] m");
    expect_rejected(R"({"dt": 1e300, "steps": 1, "bodies": []})", "/dt", "DCX_range",
                    "dt = 1e+300: must be in [1e-12, 1e+12] s");
    expect_rejected(R"({"dt": "1/1e-300", "steps": 1, "bodies": []})", "/dt", "DCX_range",
                    "dt = 9.99");
    const std::string circle = R"("shapes": [{"type": "circle", "radius": 1}])";
    expect_rejected(with_bodies(R"({"force": [1e308, 0], )" + circle + "}"), "/bodies/0/force/0",
                    "DCX_range", "body.force.x = 1e+308");
    expect_rejected(with_bodies(R"({"velocity": [1e300, 1e300], )" + circle + "}"),
                    "/bodies/0/velocity/0", "DCX_range", "body.linear_velocity.x = 1e+300");
    expect_rejected(with_bodies(R"({"angle": 1e300, )" + circle + "}"), "/bodies/0/angle",
                    "DCX_range", "body.angle = 1e+300");
    expect_rejected(with_bodies(R"({"mass": 1e-300, )" + circle + "}"), "/bodies/0/mass",
                    "DCX_range", ": mass = 1e-300: must be in [1e-36, 1e+36] kg");
    expect_rejected(with_bodies(R"({"shapes": [{"type": "circle", "radius": 1e-200}]})"),
                    "/bodies/0/shapes/0/radius", "DCX_range", "radius = 1e-200");
    expect_rejected(
        with_bodies(R"({"shapes": [{"type": "circle", "radius": 1, "center": [0, 1e300]}]})"),
        "/bodies/0/shapes/0/center/1", "DCX_range", "shape.center.y = 1e+300");
    expect_rejected(
        with_bodies(
            R"({"shapes": [{"type": "circle", "radius": 1, "material": {"density": 1e-320}}]})"),
        "/bodies/0/shapes/0/material/density", "DCX_range", "material.density = 1e-320");
    expect_rejected(
        with_bodies(R"({"shapes": [{"type": "polygon", "points": [[0, 0], [1e300, 0], [0, 1]]}]})"),
        "/bodies/0/shapes/0/points/1/0", "DCX_range", "points.x = 1e+300");
    expect_rejected(with_bodies(R"({"loads": {"force_y": 1e300}, )" + circle + "}"),
                    "/bodies/0/loads/force_y", "DCX_range", "force_y = 1e+300");
    expect_rejected(
        with_bodies(R"({"loads": {"torque": {"kind": "sinusoid", "amplitude": 7e11, "omega": 1, )"
                    R"("offset": 7e11}}, )" +
                    circle + "}"),
        "/bodies/0/loads/torque/amplitude", "DCX_range", "|offset| + |amplitude|");
    expect_rejected(R"({"dt": 0.01, "steps": 1, "world": {"gravity": [0, -1e300]}, "bodies": []})",
                    "/world/gravity/1", "DCX_range", "world.gravity.y = -1e+300");
    expect_rejected(with_bodies(R"({"name": "a", "type": "static"}, {"name": "b", "mass": 1})",
                                R"("joints": [{"type": "revolute", "body_a": "a", "body_b": "b", )"
                                R"("anchor": [1e300, 0]}], )"),
                    "/joints/0/anchor/0", "DCX_range", "joint.anchor.x = 1e+300");
    expect_rejected(with_bodies(R"({"generator": "elastic_pair", "speed": 1e300})"),
                    "/bodies/0/speed", "DCX_range", "speed = 1e+300");
    // The bounds themselves load.
    BOOST_CHECK_NO_THROW((void)parse_scene(box("1e12", "1e12")));
    BOOST_CHECK_NO_THROW((void)parse_scene(R"({"dt": 1e12, "steps": 1, "bodies": []})"));
    BOOST_CHECK_NO_THROW((void)parse_scene(R"({"dt": 1e-12, "steps": 1, "bodies": []})"));
}

// Oracle: RFC 8259 numbers and C++ [conv.fpint]: 9223372036854775808.0 is 2^63, which no long
// long holds; it passed the range check because double(LLONG_MAX) is 2^63, and converted with
// undefined behaviour. It is rejected now; the largest double below 2^63 is accepted.
BOOST_AUTO_TEST_CASE(a_seed_of_2_to_the_63_is_rejected, *utf::label("scene")) {
    const auto rain = [](const std::string& seed) {
        return with_bodies(R"({"generator": "rain", "count": 2, "seed": )" + seed + "}");
    };
    expect_rejected(rain("9223372036854775808.0"), "/bodies/0/seed", "",
                    "must be an integer in [0, 9223372036854775807]");
    expect_rejected(rain("9223372036854775808"), "/bodies/0/seed", "",
                    "must be an integer in [0, 9223372036854775807]");
    expect_rejected(rain("1e300"), "/bodies/0/seed", "", "must be an integer");
    expect_rejected(rain("-1.0"), "/bodies/0/seed", "", "must be an integer");
    BOOST_CHECK_NO_THROW((void)parse_scene(rain("9223372036854774784.0")));
    BOOST_CHECK_NO_THROW((void)parse_scene(rain("9223372036854775807")));
}

// Oracle: the rain generator's grid (docs/scene-format.md): in a container 1e10 m wide every box
// has a column of its own, left to right at the pitch, inside the walls. The column count used
// to be converted to int with undefined behaviour (in Release every box landed in one column).
BOOST_AUTO_TEST_CASE(a_very_wide_rain_container_keeps_the_grid, *utf::label("scene")) {
    RainParams p;
    p.count = 50;
    p.container.width = 1e10;
    p.jitter = 0.0;
    const std::vector<SceneBody> bodies = generate_rain(p);
    BOOST_TEST_REQUIRE(bodies.size() == 51u);
    const double spacing = 1.5 * p.box;
    for (std::size_t i = 2; i < bodies.size(); ++i) {
        const Vec2d a = bodies[i - 1].def.position, b = bodies[i].def.position;
        BOOST_TEST(b.x - a.x == spacing); // one row, one column each
        BOOST_TEST(b.y == a.y);
    }
    BOOST_TEST(bodies[1].def.position.x > -0.5 * p.container.width);
    // Loaded: with a floor thick enough not to be a sliver (1e-6 of its width), it passes the
    // dry run too.
    const std::string wide =
        R"({"generator": "rain", "count": 10, "container": {"width": 1e10, "wall": 2e4}})";
    BOOST_TEST(parse_scene(with_bodies(wide)).bodies.size() == 11u);
}

// Oracle: DCX_shape: a polygon whose points, read in order, cross themselves (a bow tie) is
// rejected at its points instead of being replaced by its hull; the same points in order, a
// concave outline and a cloud listed around its hull load (as their hull).
BOOST_AUTO_TEST_CASE(a_self_crossing_outline_is_rejected,
                     *utf::label("R4") * utf::label("DCX_shape")) {
    const auto polygon = [](const std::string& points) {
        return with_bodies(R"({"shapes": [{"type": "polygon", "points": )" + points + "}]}");
    };
    expect_rejected(polygon("[[0, 0], [1, 1], [1, 0], [0, 1]]"), "/bodies/0/shapes/0/points",
                    "DCX_shape", "the outline crosses itself (edge 0-1 crosses edge 2-3)");
    expect_rejected(polygon("[[0, 0], [2, 0], [2, 2], [0, 2], [1, -1]]"),
                    "/bodies/0/shapes/0/points", "DCX_shape", "crosses itself");
    for (const char* ok : {"[[0, 0], [1, 0], [1, 1], [0, 1]]", "[[0, 1], [1, 1], [1, 0], [0, 0]]",
                           "[[0, 0], [2, 0], [1, 0.5], [2, 2], [0, 2]]",
                           "[[0, 0], [1, 0], [1, 0], [1, 1], [0, 1]]"}) {
        BOOST_TEST_CONTEXT(ok) {
            const Scene s = parse_scene(polygon(ok));
            BOOST_TEST(s.bodies[0].shapes[0].geometry.polygon.count == 4);
        }
    }
}

// Oracle: docs/scene-format.md, Limits: a scene holds at most max_scene_bodies bodies, written
// and generated; the generator that passes the limit is refused, before a World is built. Two
// pyramids of base 500 hold 2 (500 * 501 / 2 + 1) = 250 502 bodies (boxes and a ground each),
// the count the message names; the first alone (125 251) is within the limit.
BOOST_AUTO_TEST_CASE(bodies_beyond_the_scene_limit_are_refused, *utf::label("scene")) {
    const std::string pyramid = R"({"generator": "pyramid", "base": 500})";
    const std::string second = R"({"generator": "pyramid", "base": 500, "name": "other"})";
    const std::size_t one = 500 * 501 / 2 + 1;
    static_assert(max_scene_bodies >= 125251 && max_scene_bodies < 2 * 125251);
    expect_rejected(with_bodies(pyramid + ", " + second), "/bodies/1", "",
                    "the scene's bodies number " + std::to_string(2 * one) +
                        " with this entry: at most " + std::to_string(max_scene_bodies));
}

// Oracle: docs/scene-format.md, Limits: the chains of a scene have at most max_chain_points
// points in all, counted across entries and bodies; one more is refused at the entry that
// exceeds the limit, before its points are read. A hand-made Scene beyond the limit is
// written with its excess chains segment by segment ("chain_segment", not counted), so its
// written form loads and builds the same world (World::state_hash()).
BOOST_AUTO_TEST_CASE(chain_points_beyond_the_limit_are_refused, *utf::label("scene")) {
    const auto chain = [](std::size_t n) {
        std::string pts;
        for (std::size_t i = 0; i < n; ++i)
            pts += (i ? ", [" : "[") + std::to_string(i) + ", " + std::to_string(i % 3) + "]";
        return R"({"type": "chain", "points": [)" + pts + "]}";
    };
    const std::size_t half = max_chain_points / 2;
    (void)parse_scene(
        with_bodies(R"({"type": "static", "shapes": [)" + chain(half) + ", " + chain(half) + "]}"));
    expect_rejected(with_bodies(R"({"type": "static", "shapes": [)" + chain(half) + "]}, " +
                                R"({"type": "static", "shapes": [)" + chain(half + 1) + "]}"),
                    "/bodies/1/shapes/0/points", "",
                    "points.size = " + std::to_string(half + 1) +
                        ": the scene's chains may have at most " +
                        std::to_string(max_chain_points) + " points in all");

    Scene s;
    std::vector<Vec2d> points;
    for (std::size_t i = 0; i < half + 1; ++i)
        points.push_back({double(i), double(i % 3)});
    for (int b = 0; b < 2; ++b) {
        SceneBody body;
        body.def.type = BodyType::static_body;
        body.shapes = chain_shapes(points, b == 1);
        s.bodies.push_back(body);
    }
    const std::string written = scene_to_json(s, -1);
    BOOST_TEST(written.find(R"({"type":"chain","points")") != std::string::npos);
    BOOST_TEST(written.find(R"({"type":"chain_segment")") != std::string::npos);
    const Scene back = parse_scene(written, "written");
    BOOST_TEST_REQUIRE(back.bodies.size() == 2u);
    BOOST_TEST(back.bodies[1].shapes.size() == half + 1); // the loop, segment by segment
    World a(s.world), b(back.world);
    build_world(s, a);
    build_world(back, b);
    BOOST_TEST(a.state_hash() == b.state_hash());
}

// Oracle: the round trip promised in scene.hpp, parse_scene(scene_to_json(s)) ~ s: a box loads
// exactly when its written form (a polygon) does, over aspect ratios across the sliver rule's
// 1e-6 and several angles. The 1e-7 x 1 box loaded and its written form was rejected.
BOOST_AUTO_TEST_CASE(every_box_that_loads_loads_again_from_its_written_form,
                     *utf::label("R4") * utf::label("DCX_shape")) {
    int loaded = 0, rejected = 0;
    for (const char* height : {"1e-7", "9.99e-7", "1e-6", "1.0001e-6", "2e-6", "0.5"}) {
        for (const char* angle : {"0", "0.3", "0.7853981633974483", "2"}) {
            BOOST_TEST_CONTEXT("height " << height << ", angle " << angle) {
                const std::string json = with_bodies(
                    std::string(R"({"shapes": [{"type": "box", "width": 1, "height": )") + height +
                    R"(, "angle": )" + angle + "}]}");
                try {
                    const Scene s = parse_scene(json);
                    ++loaded;
                    const std::string written = scene_to_json(s);
                    BOOST_CHECK_NO_THROW((void)parse_scene(written));
                } catch (const SceneError& e) {
                    ++rejected;
                    BOOST_TEST(e.pointer == "/bodies/0/shapes/0", e.what());
                    BOOST_TEST(e.constraint == "DCX_shape", e.what());
                }
            }
        }
    }
    BOOST_TEST(loaded > 0);
    BOOST_TEST(rejected > 0);
    expect_rejected(with_bodies(R"({"shapes": [{"type": "box", "width": 1, "height": 1e-7}]})"),
                    "/bodies/0/shapes/0", "DCX_shape", "polygon.thickness");
}

// Oracle: complexity, not a time: an object of N keys is read in time linear in N (a duplicate
// found by hashing, each member appended in order), so 8N keys take about 8 times as long as N,
// where a linear search per key (the ordered object's own lookup) takes 64 times as long. The
// scene's root object with N, 2N and 8N keys more than it allows: the whole document is read
// (the duplicate check runs on every key) before the first unknown key is refused; each the
// least CPU time of seven parses; the bound 24 lies between the two, with room for a shared
// machine's and a sanitizer's noise. (With the linear search, 40 000
// keys took 4.5 s.) A "materials" object of 4N named materials loads, and a duplicate among
// them is found at its key.
BOOST_AUTO_TEST_CASE(an_objects_keys_parse_in_time_linear_in_their_number, *utf::label("scene")) {
    const auto object_of = [](std::size_t n, const std::string& value) {
        std::string json;
        for (std::size_t i = 0; i < n; ++i)
            json += (i ? R"(, "k)" : R"("k)") + std::to_string(i) + R"(": )" + value;
        return json;
    };
    const auto seconds = [](const std::string& json) {
        double best = 1e300;
        for (int run = 0; run < 7; ++run) {
            const double start = test::process_cpu_seconds();
            const SceneError e = error_of(json);
            const double took = test::process_cpu_seconds() - start;
            BOOST_TEST_REQUIRE(e.pointer == "/k0", e.what());
            best = std::min(best, took);
        }
        return best;
    };
    constexpr std::size_t n = 1000;
    const auto root_of = [&](std::size_t keys) {
        return "{" + object_of(keys, "0") + R"(, "dt": 0.01, "steps": 1, "bodies": []})";
    };
    const double t1 = seconds(root_of(n));
    const double t2 = seconds(root_of(2 * n));
    const double t8 = seconds(root_of(8 * n));
    BOOST_TEST_MESSAGE("parse of " << n << ", " << 2 * n << ", " << 8 * n << " keys: " << t1
                                   << " s, " << t2 << " s, " << t8 << " s");
    BOOST_TEST(t8 / t1 < 24.0, "8N keys took " << t8 / t1 << " times as long as N");

    const std::string materials = R"({"dt": 0.01, "steps": 1, "materials": {)" +
                                  object_of(4 * n, R"({"density": 1})") + R"(}, "bodies": []})";
    BOOST_TEST(parse_scene(materials).materials.size() == 4 * n);
    std::string dup = materials;
    dup.insert(dup.find(R"(}, "bodies")"), R"(, "k7": {"density": 2})");
    expect_rejected(dup, "/materials/k7", "", "duplicate key 'k7'");
}

BOOST_AUTO_TEST_SUITE_END()
