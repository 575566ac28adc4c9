// Malformed scenes (R4): every class of defect (syntax, types, unknown or missing keys,
// duplicates, out-of-range values per data constraint, bad references, generator parameters)
// is a SceneError that names the place (JSON pointer, or line and column), the field and the
// constraint; nothing is half-loaded.
#include <boost/test/unit_test.hpp>

#include <filesystem>
#include <string>

#include "tamias2d/io/scene.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d::io;

namespace {

struct Expect {
    std::string pointer;    ///< JSON pointer ("" for syntax errors and the root)
    std::string field;      ///< "" when not checked
    std::string constraint; ///< data-constraint label, "" for rules of the format
    std::string text;       ///< a substring of what()
    int line = 0;           ///< syntax errors: line and column
    int column = 0;
};

void expect_error(const std::string& json, const Expect& x) {
    try {
        (void)parse_scene(json, "test.json");
        BOOST_ERROR("accepted: " << json);
    } catch (const SceneError& e) {
        const std::string what = e.what();
        BOOST_TEST(e.origin == "test.json");
        BOOST_TEST(e.pointer == x.pointer, "what(): " << what);
        if (!x.field.empty())
            BOOST_TEST(e.field == x.field, "what(): " << what);
        BOOST_TEST(e.constraint == x.constraint, "what(): " << what);
        BOOST_TEST(what.find(x.text) != std::string::npos,
                   "what(): " << what << "\nexpected to contain: " << x.text);
        BOOST_TEST(e.line == x.line, "what(): " << what);
        BOOST_TEST(e.column == x.column, "what(): " << what);
        BOOST_TEST(what.find('\n') == std::string::npos, "one line: " << what);
        const std::string place = x.line > 0 ? "test.json:" + std::to_string(x.line) + ":" +
                                                   std::to_string(x.column) + ": "
                                  : x.pointer.empty() ? std::string("test.json: (root): ")
                                                      : "test.json: " + x.pointer + ": ";
        BOOST_TEST(what.starts_with(place), "what(): " << what);
    } catch (const std::exception& e) {
        BOOST_ERROR("not a SceneError: " << e.what());
    }
}

/// A valid scene around `bodies` (the text of the bodies array's elements).
std::string with_bodies(const std::string& bodies, const std::string& extra = "") {
    return R"({"dt": 0.01, "steps": 10, )" + extra + R"("bodies": [)" + bodies + "]}";
}

const std::string circle = R"({"shapes": [{"type": "circle", "radius": 1}]})";

} // namespace

BOOST_AUTO_TEST_SUITE(scene_errors)

// Oracle: RFC 8259 JSON grammar, positions counted by hand in each text: 1-based line and
// column of the offending character (of the opening quote for an unexpected string, one past
// the last character for a premature end of input).
BOOST_AUTO_TEST_CASE(syntax_errors_give_line_and_column, *utf::label("scene")) {
    expect_error("{\n  \"dt\": 0.1,\n  \"steps\": 10,,\n}", {"", "", "", "syntax error", 3, 15});
    expect_error("{\"dt\": 0.1 \"steps\": 1}", {"", "", "", "syntax error", 1, 12});
    expect_error("", {"", "", "", "syntax error", 1, 1});
    expect_error("{\"dt\": 0.1}\n[]", {"", "", "", "syntax error", 2, 1}); // trailing content
    expect_error("{\"dt\": 0.1,\n \"steps\": [1, 2", {"", "", "", "end of input", 2, 16});
    expect_error("{\"dt\": 0x10}", {"", "", "", "syntax error", 1, 9});
    expect_error("{\"dt\": NaN}", {"", "", "", "syntax error", 1, 8});
    expect_error("{\"a\": \"\xff\"}", {"", "", "", "syntax error", 1, 8}); // invalid UTF-8
}

// Oracle: DCX_finite: a number beyond the double range (1e400) is not a finite real.
BOOST_AUTO_TEST_CASE(number_overflow_is_not_finite, *utf::label("R4") * utf::label("DCX_finite")) {
    expect_error("{\"dt\": 0.1,\n \"steps\": 1e400}",
                 {"", "", "DCX_finite", "number overflow", 2, 11});
}

// Oracle: docs/scene-format.md: nesting is limited (128 levels), so hostile input cannot
// exhaust the stack.
BOOST_AUTO_TEST_CASE(deep_nesting_is_rejected, *utf::label("scene")) {
    const std::string deep = "{\"dt\": " + std::string(500, '[') + std::string(500, ']') + "}";
    try {
        (void)parse_scene(deep, "deep");
        BOOST_ERROR("accepted 500 levels of nesting");
    } catch (const SceneError& e) {
        BOOST_TEST(std::string(e.what()).find("nesting deeper than 128") != std::string::npos);
        BOOST_TEST(e.pointer.starts_with("/dt/0/0/0"));
    }
}

// Oracle: docs/scene-format.md's types: each value below has the wrong JSON type.
BOOST_AUTO_TEST_CASE(wrong_types_are_named, *utf::label("scene")) {
    expect_error("[]", {"", "", "", "expected a scene object"});
    expect_error(R"({"dt": true, "steps": 1, "bodies": []})",
                 {"/dt", "dt", "", "dt: expected a number, got a boolean"});
    expect_error(R"({"dt": "fast", "steps": 1, "bodies": []})",
                 {"/dt", "dt", "", "fraction string such as \"1/60\""});
    expect_error(R"({"dt": 0.1, "steps": 2.5, "bodies": []})",
                 {"/steps", "steps", "", "must be an integer"});
    expect_error(R"({"dt": 0.1, "steps": 1, "bodies": {}})",
                 {"/bodies", "bodies", "", "expected an array of bodies and generators"});
    expect_error(with_bodies("3"), {"/bodies/0", "", "", "expected a body object"});
    expect_error(with_bodies(R"({"position": [0, null]})"),
                 {"/bodies/0/position/1", "position.y", "", "got null"});
    expect_error(with_bodies(R"({"position": 1})"),
                 {"/bodies/0/position", "position", "", "expected an array [x, y]"});
    expect_error(with_bodies(R"({"name": 7, "mass": 1})"),
                 {"/bodies/0/name", "name", "", "expected a string, got a number"});
    expect_error(with_bodies(R"({"fixed_rotation": 1, "mass": 1})"),
                 {"/bodies/0/fixed_rotation", "fixed_rotation", "", "expected true or false"});
    expect_error(with_bodies(R"({"shapes": {"type": "circle"}})"),
                 {"/bodies/0/shapes", "shapes", "", "expected an array of shapes"});
    expect_error(with_bodies(R"({"shapes": [{"type": "polygon", "points": [[0, 0], [1, 0], 5]}]})"),
                 {"/bodies/0/shapes/0/points/2", "points", "", "expected an array [x, y]"});
    expect_error(with_bodies(R"({"mass": 1, "loads": {"torque": "big"}})"),
                 {"/bodies/0/loads/torque", "torque", "", "expected a number or a load object"});
    expect_error(with_bodies(circle, R"("materials": {"m": 1}, )"),
                 {"/materials/m", "material", "", "expected a material object"});
}

// Oracle: docs/scene-format.md's key lists: each object below has a key the format does not
// define; the nearest defined key is suggested when it is within edit distance 2.
BOOST_AUTO_TEST_CASE(unknown_keys_are_rejected, *utf::label("scene")) {
    expect_error(R"({"dt": 0.1, "step": 1, "bodies": []})",
                 {"/step", "step", "", "unknown key 'step' in a scene (did you mean 'steps'?)"});
    expect_error(with_bodies(R"({"positon": [0, 0], "mass": 1})"),
                 {"/bodies/0/positon", "positon", "", "(did you mean 'position'?)"});
    expect_error(with_bodies(R"({"shapes": [{"type": "circle", "raduis": 1}]})"),
                 {"/bodies/0/shapes/0/raduis", "raduis", "", "did you mean 'radius'?"});
    expect_error(with_bodies(R"({"shapes": [{"type": "circle", "radius": 1, "width": 1}]})"),
                 {"/bodies/0/shapes/0/width", "width", "", "unknown key 'width' in a circle"});
    expect_error(with_bodies(circle, R"("world": {"gravity": [0, 0], "colour": 1}, )"),
                 {"/world/colour", "colour", "", "in world settings"});
    expect_error(with_bodies(R"({"generator": "pyramid", "bsae": 3})"),
                 {"/bodies/0/bsae", "bsae", "", "did you mean 'base'?"});
    expect_error(with_bodies(R"({"mass": 1, "loads": {"force_z": 1}})"),
                 {"/bodies/0/loads/force_z", "force_z", "", "allowed: force_x, force_y, torque"});
    expect_error(with_bodies(circle, R"("materials": {"m": {"elasticity": 1}}, )"),
                 {"/materials/m/elasticity", "elasticity", "", "in a material"});
}

// Oracle: docs/scene-format.md's required keys.
BOOST_AUTO_TEST_CASE(missing_required_keys_are_named, *utf::label("scene")) {
    expect_error(R"({"steps": 1, "bodies": []})", {"/dt", "dt", "", "missing required key 'dt'"});
    expect_error(R"({"dt": 0.1, "bodies": []})", {"/steps", "steps", "", "missing required"});
    expect_error(R"({"dt": 0.1, "steps": 1})", {"/bodies", "bodies", "", "missing required"});
    expect_error(with_bodies(R"({"shapes": [{"radius": 1}]})"),
                 {"/bodies/0/shapes/0/type", "type", "", "missing required key 'type'"});
    expect_error(with_bodies(R"({"shapes": [{"type": "box", "width": 1}]})"),
                 {"/bodies/0/shapes/0/height", "height", "", "(a box shape)"});
    expect_error(with_bodies(R"({"shapes": [{"type": "polygon"}]})"),
                 {"/bodies/0/shapes/0/points", "points", "", "missing required key 'points'"});
    expect_error(
        with_bodies(R"({"mass": 1, "loads": {"force_x": {"kind": "sinusoid", "amplitude": 1}}})"),
        {"/bodies/0/loads/force_x/omega", "omega", "", "(sinusoid load)"});
    expect_error(with_bodies(R"({"mass": 1, "loads": {"force_x": {"value": 1}}})"),
                 {"/bodies/0/loads/force_x/kind", "kind", "", "missing required key 'kind'"});
    // A dynamic body needs a mass from somewhere (DCI_m).
    expect_error(with_bodies(R"({"name": "ghost"})"),
                 {"/bodies/0/shapes", "shapes", "DCI_m", "needs at least one shape or a \"mass\""});
}

// Oracle: SRS Table 1 and the project's constraints (srs/data_constraints.yaml): each value
// below breaks the named constraint; the message has "<field> = <value>: <rule> (<label>)".
BOOST_AUTO_TEST_CASE(out_of_range_values_name_their_constraint,
                     *utf::label("R4") * utf::label("DCI_CR") * utf::label("DCI_I") *
                         utf::label("DCI_L") * utf::label("DCI_m") * utf::label("DCX_dt") *
                         utf::label("DCX_shape") * utf::label("DCX_density") *
                         utf::label("DCX_friction")) {
    expect_error(R"({"dt": -0.01, "steps": 1, "bodies": []})",
                 {"/dt", "dt", "DCX_dt", "dt = -0.01: must be > 0 (DCX_dt)"});
    expect_error(R"({"dt": "1/0", "steps": 1, "bodies": []})", {"/dt", "dt", "", "fraction"});
    expect_error(R"({"dt": "-1/60", "steps": 1, "bodies": []})",
                 {"/dt", "dt", "DCX_dt", "must be > 0 (DCX_dt)"});
    expect_error(with_bodies(circle, R"("world": {"substeps": 0}, )"),
                 {"/world/substeps", "substeps", "DCX_dt", "(DCX_dt)"});
    expect_error(with_bodies(R"({"mass": -5})"),
                 {"/bodies/0/mass", "mass", "DCI_m", "mass = -5: must be > 0 (DCI_m)"});
    expect_error(with_bodies(R"({"mass": 1, "inertia": 0})"),
                 {"/bodies/0/inertia", "inertia", "DCI_I", "inertia = 0: must be > 0 (DCI_I)"});
    expect_error(with_bodies(R"({"shapes": [{"type": "circle", "radius": 0}]})"),
                 {"/bodies/0/shapes/0/radius", "radius", "DCX_shape", "radius = 0: must be > 0"});
    expect_error(with_bodies(R"({"shapes": [{"type": "box", "width": 1, "height": -2}]})"),
                 {"/bodies/0/shapes/0/height", "height", "DCX_shape", "height = -2"});
    expect_error(
        with_bodies(R"({"shapes": [{"type": "polygon", "points": [[0, 0], [1, 0], [2, 0]]}]})"),
        {"/bodies/0/shapes/0/points", "", "DCX_shape", "collinear"});
    expect_error(with_bodies(R"({"shapes": [{"type": "polygon", "points": [[0, 0], [1, 0]]}]})"),
                 {"/bodies/0/shapes/0/points", "points.size", "DCX_shape", "must be >= 3"});
    expect_error(
        with_bodies(
            R"({"shapes": [{"type": "circle", "radius": 1, "material": {"restitution": -0.5}}]})"),
        {"/bodies/0/shapes/0/material/restitution", "restitution", "DCI_CR", "in [0, 1] (DCI_CR)"});
    expect_error(with_bodies(circle, R"("materials": {"lead": {"density": -11.3}}, )"),
                 {"/materials/lead/density", "density", "DCX_density", "(DCX_density)"});
    expect_error(with_bodies(circle, R"("materials": {"ice": {"friction": -0.01}}, )"),
                 {"/materials/ice/friction", "friction", "DCX_friction", "(DCX_friction)"});
    expect_error(R"({"dt": 0.1, "steps": -1, "bodies": []})",
                 {"/steps", "steps", "", "steps = -1: must be an integer in [0,"});
    expect_error(R"({"version": 2, "dt": 0.1, "steps": 1, "bodies": []})",
                 {"/version", "version", "", "must be an integer in [1, 1]"});
    expect_error(
        with_bodies(
            R"({"mass": 1, "loads": {"torque": {"kind": "ramp", "t0": 2, "t1": 1, "to": 1}}})"),
        {"/bodies/0/loads/torque/t1", "t1", "", "must be > t0"});
}

// Oracle: docs/scene-format.md: a key appears once per object; body names are unique; names of
// materials, shape types, body types, load kinds and generators come from fixed lists.
BOOST_AUTO_TEST_CASE(duplicates_and_bad_references_are_rejected, *utf::label("scene")) {
    expect_error(R"({"dt": 0.1, "dt": 0.2, "steps": 1, "bodies": []})",
                 {"/dt", "", "", "duplicate key 'dt'"});
    expect_error(with_bodies(R"({"shapes": [{"type": "circle", "radius": 1, "radius": 2}]})"),
                 {"/bodies/0/shapes/0/radius", "", "", "duplicate key 'radius'"});
    expect_error(with_bodies(R"({"name": "a", "mass": 1}, {"name": "a", "mass": 1})"),
                 {"/bodies/1/name", "name", "", "already used by /bodies/0/name"});
    expect_error(
        with_bodies(
            R"({"name": "pyramid/ground", "mass": 1}, {"generator": "pyramid", "base": 2})"),
        {"/bodies/1", "name", "", "'pyramid/ground' is already used by /bodies/0/name"});
    expect_error(
        with_bodies(R"({"shapes": [{"type": "circle", "radius": 1, "material": "gold"}]})"),
        {"/bodies/0/shapes/0/material", "material", "", "unknown material 'gold'"});
    expect_error(with_bodies(R"({"shapes": [{"type": "ellipse"}]})"),
                 {"/bodies/0/shapes/0/type", "type", "",
                  "unknown shape type 'ellipse'; allowed: box, circle, polygon, capsule, "
                  "segment, chain, chain_segment"});
    expect_error(with_bodies(R"({"type": "ghost", "mass": 1})"),
                 {"/bodies/0/type", "type", "", "allowed: dynamic, static, kinematic"});
    expect_error(with_bodies(R"({"generator": "tower"})"),
                 {"/bodies/0/generator", "generator", "", "unknown generator 'tower'"});
    expect_error(with_bodies(R"({"mass": 1, "loads": {"torque": {"kind": "square"}}})"),
                 {"/bodies/0/loads/torque/kind", "kind", "", "unknown load kind 'square'"});
}

// Oracle: docs/scene-format.md's capsule, segment and chain keys and the library's shape
// constraints (DCX_shape: a radius > 0, distinct ends, a chain of >= 2 points, >= 3 for a loop,
// consecutive points distinct; DCX_range): each value below breaks one, and the error names
// the key or the point at fault.
BOOST_AUTO_TEST_CASE(capsule_segment_and_chain_defects_are_named,
                     *utf::label("R4") * utf::label("DCX_shape") * utf::label("DCX_range") *
                         utf::label("DCI_m")) {
    const auto shape = [](const std::string& s) {
        return with_bodies(R"({"type": "static", "shapes": [)" + s + "]}");
    };
    // Capsules.
    expect_error(
        shape(R"({"type": "capsule", "center1": [0, 0], "center2": [1, 0], "radius": -1})"),
        {"/bodies/0/shapes/0/radius", "radius", "DCX_shape", "radius = -1: must be > 0"});
    expect_error(shape(R"({"type": "capsule", "center1": [0, 0], "center2": [1, 0], "radius": 0})"),
                 {"/bodies/0/shapes/0/radius", "radius", "DCX_shape", "radius = 0: must be > 0"});
    expect_error(
        shape(R"({"type": "capsule", "center1": [2, 1], "center2": [2, 1], "radius": 0.5})"),
        {"/bodies/0/shapes/0/center2", "capsule.length", "DCX_shape",
         "capsule.length = 0: must be > 0 (the two ends coincide) (DCX_shape)"});
    expect_error(
        shape(R"({"type": "capsule", "center1": [0, 2e12], "center2": [1, 0], "radius": 1})"),
        {"/bodies/0/shapes/0/center1/1", "capsule.center1.y", "DCX_range", "the supported range"});
    expect_error(shape(R"({"type": "capsule", "center1": [0, 0], "radius": 1})"),
                 {"/bodies/0/shapes/0/center2", "center2", "", "missing required key 'center2'"});
    expect_error(
        shape(
            R"({"type": "capsule", "center1": [0, 0], "center2": [1, 0], "radius": 1, "width": 1})"),
        {"/bodies/0/shapes/0/width", "width", "", "unknown key 'width' in a capsule shape"});
    // Segments.
    expect_error(shape(R"({"type": "segment", "point1": [3, -1], "point2": [3, -1]})"),
                 {"/bodies/0/shapes/0/point2", "segment.length", "DCX_shape",
                  "segment.length = 0: must be > 0 (the two ends coincide) (DCX_shape)"});
    expect_error(shape(R"({"type": "segment", "point1": [0, 0], "point2": [1e-13, 0]})"),
                 {"/bodies/0/shapes/0/point2", "segment.length", "DCX_range",
                  "must be in [1e-12, 2e+12] m"});
    expect_error(shape(R"({"type": "segment", "point1": [0, 0], "point2": [1, "a"]})"),
                 {"/bodies/0/shapes/0/point2/1", "point2.y", "", "expected a number"});
    // Chains.
    expect_error(shape(R"({"type": "chain", "points": [[0, 0]]})"),
                 {"/bodies/0/shapes/0/points", "chain.points.size", "DCX_shape",
                  "chain.points.size = 1: must be >= 2 (DCX_shape)"});
    expect_error(shape(R"({"type": "chain", "points": []})"),
                 {"/bodies/0/shapes/0/points", "chain.points.size", "DCX_shape", "must be >= 2"});
    expect_error(shape(R"({"type": "chain", "points": [[0, 0], [1, 0]], "loop": true})"),
                 {"/bodies/0/shapes/0/points", "chain.points.size", "DCX_shape",
                  "chain.points.size = 2: must be >= 3 (a loop) (DCX_shape)"});
    expect_error(shape(R"({"type": "chain", "points": [[0, 0], [1, 0], [1, 0], [2, 1]]})"),
                 {"/bodies/0/shapes/0/points/2", "chain.points[2].length", "DCX_shape",
                  "chain.points[2].length = 0: must be > 0 (the two ends coincide)"});
    // A loop also joins its last point to its first: here they coincide.
    expect_error(
        shape(R"({"type": "chain", "points": [[0, 0], [1, 0], [1, 1], [0, 0]], "loop": true})"),
        {"/bodies/0/shapes/0/points/0", "chain.points[0].length", "DCX_shape", "coincide"});
    expect_error(shape(R"({"type": "chain", "points": [[0, 0], [1, 0], [1, 1e-13]]})"),
                 {"/bodies/0/shapes/0/points/2", "chain_segment.length", "DCX_range",
                  "chain_segment.length = 1e-13: must be in [1e-12, 2e+12] m"});
    expect_error(shape(R"({"type": "chain", "points": [[0, 0], [-1e13, 0]]})"),
                 {"/bodies/0/shapes/0/points/1/0", "points.x", "DCX_range", "the supported range"});
    expect_error(shape(R"({"type": "chain", "points": [[0, 0], [1, 0]], "loop": "no"})"),
                 {"/bodies/0/shapes/0/loop", "loop", "", "loop: expected true or false"});
    expect_error(shape(R"({"type": "chain", "points": [[0, 0], [1]]})"),
                 {"/bodies/0/shapes/0/points/1", "points", "", "expected an array [x, y]"});
    expect_error(shape(R"({"type": "chain", "loop": true})"),
                 {"/bodies/0/shapes/0/points", "points", "", "missing required key 'points'"});
    expect_error(shape(R"({"type": "chain", "points": [[0, 0], [1, 0]], "closed": true})"),
                 {"/bodies/0/shapes/0/closed", "closed", "", "unknown key 'closed' in a chain"});
    // A chain segment written with its ghosts.
    expect_error(
        shape(R"({"type": "chain_segment", "ghost1": [-1, 0], "point1": [0, 0],
                           "point2": [1, 0], "ghost2": [1, 0]})"),
        {"/bodies/0/shapes/0/ghost2", "chain_segment.ghost2.length", "DCX_shape", "coincide"});
    expect_error(shape(R"({"type": "chain_segment", "point1": [0, 0], "point2": [1, 0]})"),
                 {"/bodies/0/shapes/0/ghost1", "ghost1", "", "missing required key 'ghost1'"});
    // The body keys.
    expect_error(with_bodies(R"({"bullet": 1, "shapes": [{"type": "circle", "radius": 1}]})"),
                 {"/bodies/0/bullet", "bullet", "", "bullet: expected true or false"});
    // Segments and chains have no area: a dynamic body of only those needs a mass (DCI_m).
    expect_error(with_bodies(R"({"shapes": [{"type": "segment", "point1": [0, 0], "point2": [1, 0]},
                                            {"type": "chain", "points": [[0, 1], [1, 1]]}]})"),
                 {"/bodies/0/shapes", "shapes", "DCI_m",
                  "shapes are all segments or chains (no area, so no mass) needs a \"mass\""});
}

// Oracle: docs/scene-format.md's generator parameters, each out of its range.
BOOST_AUTO_TEST_CASE(generator_parameters_are_validated,
                     *utf::label("R4") * utf::label("DCX_shape")) {
    expect_error(with_bodies(R"({"generator": "pyramid", "base": 501})"),
                 {"/bodies/0/base", "base", "", "must be an integer in [1, 500]"});
    expect_error(with_bodies(R"({"generator": "pyramid", "box": 0})"),
                 {"/bodies/0/box", "box", "DCX_shape", "box = 0: must be > 0 (DCX_shape)"});
    expect_error(with_bodies(R"({"generator": "pyramid", "gap": -0.001})"),
                 {"/bodies/0/gap", "gap", "", "gap = -0.001: must be >= 0"});
    expect_error(with_bodies(R"({"generator": "rain", "count": -1})"),
                 {"/bodies/0/count", "count", "", "must be an integer in [0, 200000]"});
    expect_error(with_bodies(R"({"generator": "rain", "spacing": 0.4, "box": 0.5})"),
                 {"/bodies/0/spacing", "spacing", "DCX_shape", "must be > box"});
    expect_error(with_bodies(R"({"generator": "rain", "jitter": 0.2, "box": 0.5})"),
                 {"/bodies/0/jitter", "jitter", "", "must be < (spacing - box) / 2"});
    expect_error(with_bodies(R"({"generator": "rain", "container": {"height": 0}})"),
                 {"/bodies/0/container/height", "container.height", "DCX_shape", "must be > 0"});
    expect_error(with_bodies(R"({"generator": "rain", "container": {"origin": [0]}})"),
                 {"/bodies/0/container/origin", "origin", "", "got an array of 1 elements"});
    expect_error(with_bodies(R"({"generator": "elastic_pair", "distance": 0.5})"),
                 {"/bodies/0/distance", "distance", "DCX_shape", "must be > box"});
    expect_error(with_bodies(R"({"generator": "elastic_pair", "restitution": 2})"),
                 {"/bodies/0/restitution", "restitution", "DCI_CR", "(DCI_CR)"});
}

// Oracle: a file that does not exist cannot be read; the message names it.
BOOST_AUTO_TEST_CASE(missing_file_is_reported, *utf::label("scene")) {
    try {
        (void)load_scene("no/such/scene.json");
        BOOST_ERROR("loaded a missing file");
    } catch (const SceneError& e) {
        BOOST_TEST(e.origin == "no/such/scene.json");
        BOOST_TEST(std::string(e.what()).find("cannot open the scene file") != std::string::npos);
    }
}

// Oracle: every file in tests/io/data/malformed is malformed by construction (each breaks one
// rule, see apps/cli/CMakeLists.txt for the expected messages): load_scene must reject each
// with a SceneError, never crash or return a Scene.
BOOST_AUTO_TEST_CASE(every_malformed_file_is_rejected, *utf::label("scene")) {
    int files = 0;
    for (const auto& entry : std::filesystem::directory_iterator(TAMIAS_MALFORMED_SCENES)) {
        if (entry.path().extension() != ".json")
            continue;
        ++files;
        BOOST_TEST_CONTEXT(entry.path().filename().string()) {
            BOOST_CHECK_THROW((void)load_scene(entry.path()), SceneError);
        }
    }
    BOOST_TEST(files >= 20);
}

BOOST_AUTO_TEST_SUITE_END()
