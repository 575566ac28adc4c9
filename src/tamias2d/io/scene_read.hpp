/// \file
/// The scene reader's parts shared by its files: the parser's state, the errors it throws
/// (SceneError at a JSON pointer) and the typed reading of JSON values. A check the library
/// makes is run through the library (check_as_library), so each criterion is stated once.
#pragma once

#include <cstddef>
#include <initializer_list>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "json_dom.hpp"
#include "tamias2d/errors.hpp"
#include "tamias2d/io/scene.hpp"

namespace tamias2d::io::scene_detail {

/// Rules of the scene format that are no SRS data constraint carry this in place of a label.
inline constexpr const char* format_rule = "scene format";

/// The pointer of a member or element of the value at `ptr`.
std::string child(const std::string& ptr, std::string_view key);
std::string child(const std::string& ptr, std::size_t index);

/// The parser's state: the origin for messages and the named materials.
struct Ctx {
    std::string origin;
    std::map<std::string, Material> materials;
    std::optional<Material> default_material;    // materials["default"]
    std::map<std::string, std::string> names;    // body name -> pointer of first use
    std::size_t chain_budget = max_chain_points; // chain points the scene may still have
};

/// Throws the SceneError at `ptr` (a `constraint` of format_rule is reported as none).
[[noreturn]] void fail(const Ctx& ctx, const std::string& ptr, std::string field,
                       std::string message, std::string constraint = {});

/// "radius = -1: must be > 0 (DCX_shape)"
[[noreturn]] void fail_value(const Ctx& ctx, const std::string& ptr, const std::string& field,
                             double value, const std::string& rule, const std::string& constraint);

/// The pointer of a library field name under `base`, whose keys it names ("container.width" ->
/// base/container/width, "center.x" -> base/center/0).
std::string field_pointer(std::string ptr, std::string f);

/// Maps a ValidationError from the library or a generator to the scene: `base` is the pointer
/// of the object whose keys the error's field names (see field_pointer).
[[noreturn]] void fail_from(const Ctx& ctx, const std::string& base, const ValidationError& e,
                            bool map_field);

/// Reports a library error at the key its field names, less `prefix` ("body.").
[[noreturn]] void fail_as_library(const Ctx& ctx, const std::string& base, std::string_view prefix,
                                  const ValidationError& e);

/// Runs the library's own check of what was read at `base` (validation.hpp: each criterion in
/// one place), reporting a violation at the key its field names, less `prefix` ("body.").
template <class Check>
void check_as_library(const Ctx& ctx, const std::string& base, std::string_view prefix,
                      Check&& check) {
    try {
        check();
    } catch (const ValidationError& e) {
        fail_as_library(ctx, base, prefix, e);
    }
}

/// "field: expected <expected>, got <the value's type>"
[[noreturn]] void fail_type(const Ctx& ctx, const std::string& ptr, const std::string& field,
                            const ojson& v, const std::string& expected);

/// Rejects keys outside `allowed` (in document order), suggesting the nearest allowed key.
void check_keys_in(const Ctx& ctx, const ojson& obj, const std::string& ptr,
                   std::span<const std::string_view> allowed, const std::string& what);
void check_keys(const Ctx& ctx, const ojson& obj, const std::string& ptr,
                std::initializer_list<std::string_view> allowed, const std::string& what);

const ojson& require_object(const Ctx& ctx, const ojson& v, const std::string& ptr,
                            const std::string& field, const std::string& what);
/// The member `key` of an object, nullptr if it has none.
const ojson* find(const ojson& obj, std::string_view key);
const ojson& require_key(const Ctx& ctx, const ojson& obj, const std::string& ptr,
                         std::string_view key, const std::string& what);

/// Typed values (DCX_finite for numbers); `field` names the value in messages.
double as_number(const Ctx& ctx, const ojson& v, const std::string& ptr, const std::string& field);
Vec2d as_vec2(const Ctx& ctx, const ojson& v, const std::string& ptr, const std::string& field);
long long as_integer(const Ctx& ctx, const ojson& v, const std::string& ptr,
                     const std::string& field, long long lo, long long hi);
std::string as_string(const Ctx& ctx, const ojson& v, const std::string& ptr,
                      const std::string& field);
bool as_bool(const Ctx& ctx, const ojson& v, const std::string& ptr, const std::string& field);

/// Optional members: leave `out` unchanged when the key is absent.
void opt_number(const Ctx& ctx, const ojson& obj, const std::string& ptr, std::string_view key,
                double& out);
void opt_vec2(const Ctx& ctx, const ojson& obj, const std::string& ptr, std::string_view key,
              Vec2d& out);
double req_number(const Ctx& ctx, const ojson& obj, const std::string& ptr, std::string_view key,
                  const std::string& what);
/// DCX_shape (the SRS's DCI_L, corrected): a shape dimension is > 0; DCX_range: within the
/// supported sizes.
double req_length(const Ctx& ctx, const ojson& obj, const std::string& ptr, std::string_view key,
                  const std::string& what);

// The readers of materials, loads and shapes (scene_shapes.cpp).

Material parse_material_object(const Ctx& ctx, const ojson& v, const std::string& ptr, Material m);
/// A "material" member: a name from "materials" or an inline object (missing fields take the
/// defaults in `base`).
Material parse_material_ref(const Ctx& ctx, const ojson& v, const std::string& ptr,
                            const Material& base);
Material generator_default_material(const Ctx& ctx);
SceneLoads parse_loads(const Ctx& ctx, const ojson& v, const std::string& ptr);
/// A "shapes" entry: one shape, or a chain's segments, each with the entry's filter and sensor.
std::vector<ShapeDef> parse_shape(Ctx& ctx, const ojson& v, const std::string& ptr);

} // namespace tamias2d::io::scene_detail
