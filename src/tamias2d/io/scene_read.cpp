#include "scene_read.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "tamias2d/validation.hpp"

namespace tamias2d::io {

namespace {

using scene_detail::printable;
using scene_detail::shown_pointer;

std::string where(const std::string& origin, const std::string& pointer, int line, int column) {
    const std::string file = printable(origin, 256);
    if (line > 0)
        return file + ":" + std::to_string(line) + ":" + std::to_string(column);
    return file + ": " + (pointer.empty() ? std::string("(root)") : shown_pointer(pointer));
}

} // namespace

SceneError::SceneError(std::string origin_, std::string pointer_, int line_, int column_,
                       std::string field_, std::string constraint_, std::string detail_)
    : std::runtime_error(where(origin_, pointer_, line_, column_) + ": " + detail_),
      origin(std::move(origin_)), pointer(std::move(pointer_)), line(line_), column(column_),
      field(std::move(field_)), constraint(std::move(constraint_)), detail(std::move(detail_)) {}

namespace scene_detail {

std::string child(const std::string& ptr, std::string_view key) {
    return ptr + "/" + escape_token(key);
}
std::string child(const std::string& ptr, std::size_t index) {
    return ptr + "/" + std::to_string(index);
}

void fail(const Ctx& ctx, const std::string& ptr, std::string field, std::string message,
          std::string constraint) {
    throw SceneError(ctx.origin, ptr, 0, 0, std::move(field),
                     constraint == format_rule ? std::string{} : std::move(constraint),
                     std::move(message));
}

void fail_value(const Ctx& ctx, const std::string& ptr, const std::string& field, double value,
                const std::string& rule, const std::string& constraint) {
    fail(ctx, ptr, field, detail::validation_message(field, value, rule, constraint), constraint);
}

std::string field_pointer(std::string ptr, std::string f) {
    if (f.empty()) // the value at base itself
        return ptr;
    for (const std::string_view suffix : {".x", ".y"}) {
        if (f.size() > suffix.size() && f.ends_with(suffix)) {
            f.resize(f.size() - suffix.size());
            return child(ptr, f) + (suffix == ".x" ? "/0" : "/1");
        }
    }
    std::size_t start = 0;
    for (std::size_t dot; (dot = f.find('.', start)) != std::string::npos; start = dot + 1)
        ptr = child(ptr, std::string_view(f).substr(start, dot - start));
    return child(ptr, std::string_view(f).substr(start));
}

void fail_from(const Ctx& ctx, const std::string& base, const ValidationError& e, bool map_field) {
    fail(ctx, map_field ? field_pointer(base, e.field) : base, e.field, e.what(), e.constraint);
}

void fail_as_library(const Ctx& ctx, const std::string& base, std::string_view prefix,
                     const ValidationError& e) {
    std::string key = e.field;
    if (key.starts_with(prefix))
        key.erase(0, prefix.size());
    if (key.starts_with("linear_velocity")) // BodyDef's name of the scene's "velocity"
        key.replace(0, 15, "velocity");
    fail(ctx, field_pointer(base, key), e.field, e.what(), e.constraint);
}

namespace {

const char* type_name(const ojson& v) {
    switch (v.type()) {
    case ojson::value_t::null:
        return "null";
    case ojson::value_t::boolean:
        return "a boolean";
    case ojson::value_t::string:
        return "a string";
    case ojson::value_t::array:
        return "an array";
    case ojson::value_t::object:
        return "an object";
    case ojson::value_t::number_integer:
    case ojson::value_t::number_unsigned:
    case ojson::value_t::number_float:
        return "a number";
    default:
        return "an unsupported value";
    }
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j)
        row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diag = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t up = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] != b[j - 1] ? 1 : 0)});
            diag = up;
        }
    }
    return row[b.size()];
}

} // namespace

void fail_type(const Ctx& ctx, const std::string& ptr, const std::string& field, const ojson& v,
               const std::string& expected) {
    fail(ctx, ptr, field,
         (field.empty() ? std::string{} : field + ": ") + "expected " + expected + ", got " +
             type_name(v),
         format_rule);
}

void check_keys_in(const Ctx& ctx, const ojson& obj, const std::string& ptr,
                   std::span<const std::string_view> allowed, const std::string& what) {
    for (const auto& [key, value] : obj.items()) {
        if (std::find(allowed.begin(), allowed.end(), key) != allowed.end())
            continue;
        std::string best;
        std::size_t best_d = 3;
        std::string list;
        for (const std::string_view a : allowed) {
            list += (list.empty() ? "" : ", ") + std::string(a);
            const std::size_t d = edit_distance(key, a);
            if (d < best_d) {
                best_d = d;
                best = a;
            }
        }
        fail(ctx, child(ptr, key), key,
             "unknown key " + quote(key) + " in " + what +
                 (best.empty() ? std::string{} : " (did you mean '" + best + "'?)") +
                 "; allowed: " + list,
             format_rule);
    }
}
void check_keys(const Ctx& ctx, const ojson& obj, const std::string& ptr,
                std::initializer_list<std::string_view> allowed, const std::string& what) {
    check_keys_in(ctx, obj, ptr, std::span(allowed.begin(), allowed.size()), what);
}

const ojson& require_object(const Ctx& ctx, const ojson& v, const std::string& ptr,
                            const std::string& field, const std::string& what) {
    if (!v.is_object())
        fail_type(ctx, ptr, field, v, what);
    return v;
}

const ojson* find(const ojson& obj, std::string_view key) {
    const auto it = obj.find(std::string(key));
    return it == obj.end() ? nullptr : &*it;
}

const ojson& require_key(const Ctx& ctx, const ojson& obj, const std::string& ptr,
                         std::string_view key, const std::string& what) {
    if (const ojson* v = find(obj, key))
        return *v;
    fail(ctx, child(ptr, key), std::string(key),
         "missing required key '" + std::string(key) + "' (" + what + ")", format_rule);
}

double as_number(const Ctx& ctx, const ojson& v, const std::string& ptr, const std::string& field) {
    if (!v.is_number())
        fail_type(ctx, ptr, field, v, "a number");
    const double d = v.get<double>();
    if (!std::isfinite(d))
        fail_value(ctx, ptr, field, d, "must be a finite number", "DCX_finite");
    return d;
}

Vec2d as_vec2(const Ctx& ctx, const ojson& v, const std::string& ptr, const std::string& field) {
    if (!v.is_array() || v.size() != 2)
        fail(ctx, ptr, field,
             field + ": expected an array [x, y] of two numbers, got " +
                 (v.is_array() ? "an array of " + std::to_string(v.size()) + " elements"
                               : std::string(type_name(v))),
             format_rule);
    return {as_number(ctx, v[0], child(ptr, std::size_t{0}), field + ".x"),
            as_number(ctx, v[1], child(ptr, std::size_t{1}), field + ".y")};
}

long long as_integer(const Ctx& ctx, const ojson& v, const std::string& ptr,
                     const std::string& field, long long lo, long long hi) {
    if (!v.is_number())
        fail_type(ctx, ptr, field, v, "an integer");
    const std::string range =
        "must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
    if (v.is_number_unsigned()) {
        const auto u = v.get<unsigned long long>();
        if (u > static_cast<unsigned long long>(hi) ||
            (lo > 0 && u < static_cast<unsigned long long>(lo)))
            fail_value(ctx, ptr, field, double(u), range, format_rule);
        return static_cast<long long>(u);
    }
    if (v.is_number_integer()) {
        const auto i = v.get<long long>();
        if (i < lo || i > hi)
            fail_value(ctx, ptr, field, double(i), range, format_rule);
        return i;
    }
    // A double converts to long long only below 2^63: double(LLONG_MAX) is 2^63 itself, so
    // the range is checked on the integer, after the conversion is known to be defined.
    const double d = v.get<double>();
    if (!(d == std::floor(d)) || !(d >= -0x1p63 && d < 0x1p63))
        fail_value(ctx, ptr, field, d, range, format_rule);
    const auto i = static_cast<long long>(d);
    if (i < lo || i > hi)
        fail_value(ctx, ptr, field, d, range, format_rule);
    return i;
}

std::string as_string(const Ctx& ctx, const ojson& v, const std::string& ptr,
                      const std::string& field) {
    if (!v.is_string())
        fail_type(ctx, ptr, field, v, "a string");
    return v.get<std::string>();
}

bool as_bool(const Ctx& ctx, const ojson& v, const std::string& ptr, const std::string& field) {
    if (!v.is_boolean())
        fail_type(ctx, ptr, field, v, "true or false");
    return v.get<bool>();
}

void opt_number(const Ctx& ctx, const ojson& obj, const std::string& ptr, std::string_view key,
                double& out) {
    if (const ojson* v = find(obj, key))
        out = as_number(ctx, *v, child(ptr, key), std::string(key));
}
void opt_vec2(const Ctx& ctx, const ojson& obj, const std::string& ptr, std::string_view key,
              Vec2d& out) {
    if (const ojson* v = find(obj, key))
        out = as_vec2(ctx, *v, child(ptr, key), std::string(key));
}
double req_number(const Ctx& ctx, const ojson& obj, const std::string& ptr, std::string_view key,
                  const std::string& what) {
    return as_number(ctx, require_key(ctx, obj, ptr, key, what), child(ptr, key), std::string(key));
}

double req_length(const Ctx& ctx, const ojson& obj, const std::string& ptr, std::string_view key,
                  const std::string& what) {
    const double v = req_number(ctx, obj, ptr, key, what);
    check_as_library(ctx, ptr, "", [&] { validate_size(key, v); });
    return v;
}

} // namespace scene_detail
} // namespace tamias2d::io
