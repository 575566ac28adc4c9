#include "tamias2d/io/scene_generators.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "box_polygon.hpp"
#include "tamias2d/errors.hpp"
#include "tamias2d/io/scene_read.hpp"
#include "tamias2d/validation.hpp"

namespace tamias2d::io {
namespace {

using scene_detail::format_rule;

void require_finite(const std::string& field, double v) {
    if (!std::isfinite(v))
        throw ValidationError(field, v, "must be a finite number", "DCX_finite");
}

/// DCX_shape and DCX_range: a size > 0 within the supported sizes (the library's check).
void require_length(const std::string& field, double v) {
    validate_size(field, v);
}

void require_count(const std::string& field, int v, int lo, int hi) {
    if (v < lo || v > hi)
        throw ValidationError(field, double(v),
                              "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]",
                              format_rule);
}

void require_material(const Material& m) {
    require_finite("material.density", m.density);
    if (!(m.density > 0.0))
        throw ValidationError("material.density", m.density, "must be > 0", "DCX_density");
    require_finite("material.restitution", m.restitution);
    if (!(m.restitution >= 0.0 && m.restitution <= 1.0))
        throw ValidationError("material.restitution", m.restitution, "must be in [0, 1]", "DCI_CR");
    require_finite("material.friction", m.friction);
    if (!(m.friction >= 0.0))
        throw ValidationError("material.friction", m.friction, "must be >= 0", "DCX_friction");
}

SceneBody make_body(std::string name, BodyType type, Vec2d position) {
    SceneBody b;
    b.def.name = std::move(name);
    b.def.type = type;
    b.def.position = position;
    return b;
}

} // namespace

std::uint64_t SplitMix64::next() {
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

double SplitMix64::uniform() {
    return double(next() >> 11) * 0x1.0p-53;
}

std::vector<SceneBody> generate_pyramid(const PyramidParams& p) {
    require_count("base", p.base, 1, PyramidParams::max_base);
    require_length("box", p.box);
    require_within("gap", p.gap, supported::input_max, "m");
    if (!(p.gap >= 0.0))
        throw ValidationError("gap", p.gap, "must be >= 0", format_rule);
    require_within("origin", p.origin, supported::input_max, "m");
    require_within("ground_width", p.ground_width, supported::input_max, "m");
    require_within("ground_height", p.ground_height, supported::input_max, "m");
    if (p.ground_width < 0.0)
        throw ValidationError("ground_width", p.ground_width, "must be > 0 (0: automatic)",
                              "DCX_shape");
    if (p.ground_height < 0.0)
        throw ValidationError("ground_height", p.ground_height, "must be > 0 (0: automatic)",
                              "DCX_shape");
    require_material(p.material);

    const double ground_w =
        p.ground_width > 0.0 ? p.ground_width : 2.0 * p.base * p.box + 10.0 * p.box;
    const double ground_h = p.ground_height > 0.0 ? p.ground_height : p.box;
    const double pitch = p.box + p.gap;

    std::vector<SceneBody> out;
    out.reserve(std::size_t(p.base) * std::size_t(p.base + 1) / 2 + 1);
    SceneBody ground = make_body(p.name + "/ground", BodyType::static_body,
                                 {p.origin.x, p.origin.y - 0.5 * ground_h});
    ground.shapes.push_back(box_polygon(box_shape(ground_w, ground_h, p.material)));
    out.push_back(std::move(ground));

    for (int row = 0; row < p.base; ++row) {
        const int n = p.base - row;
        const double y = p.origin.y + p.gap + 0.5 * p.box + row * pitch;
        for (int col = 0; col < n; ++col) {
            const double x = p.origin.x + (col - 0.5 * (n - 1)) * pitch;
            SceneBody b = make_body(p.name + "/r" + std::to_string(row) + "c" + std::to_string(col),
                                    BodyType::dynamic, {x, y});
            b.shapes.push_back(box_polygon(box_shape(p.box, p.box, p.material)));
            out.push_back(std::move(b));
        }
    }
    return out;
}

std::vector<SceneBody> generate_rain(const RainParams& p) {
    require_count("count", p.count, 0, RainParams::max_count);
    require_length("box", p.box);
    const double spacing = p.spacing == 0.0 ? 1.5 * p.box : p.spacing;
    const double jitter = p.jitter < 0.0 ? 0.2 * p.box : p.jitter;
    require_within("spacing", p.spacing, supported::input_max, "m");
    if (!(spacing > p.box))
        throw ValidationError("spacing", spacing, "must be > box (0: automatic)", "DCX_shape");
    require_within("jitter", p.jitter, supported::input_max, "m");
    if (!(2.0 * jitter < spacing - p.box))
        throw ValidationError("jitter", jitter, "must be < (spacing - box) / 2", format_rule);
    require_within("drop_height", p.drop_height, supported::input_max, "m");
    if (!(p.drop_height >= 0.0))
        throw ValidationError("drop_height", p.drop_height, "must be >= 0", format_rule);
    require_length("container.width", p.container.width);
    require_length("container.height", p.container.height);
    require_length("container.wall", p.container.wall);
    require_within("container.origin", p.container.origin, supported::input_max, "m");
    if (!(p.container.width >= spacing))
        throw ValidationError("container.width", p.container.width, "must be >= spacing",
                              "DCX_shape");
    require_material(p.material);

    const ContainerParams& c = p.container;
    std::vector<SceneBody> out;
    out.reserve(std::size_t(p.count) + 1);
    SceneBody box = make_body(p.name + "/container", BodyType::static_body, c.origin);
    const double half_w = 0.5 * c.width;
    box.shapes.push_back(
        box_polygon(box_shape(c.width + 2.0 * c.wall, c.wall, p.material, {0.0, -0.5 * c.wall})));
    box.shapes.push_back(box_polygon(
        box_shape(c.wall, c.height, p.material, {-(half_w + 0.5 * c.wall), 0.5 * c.height})));
    box.shapes.push_back(box_polygon(
        box_shape(c.wall, c.height, p.material, {half_w + 0.5 * c.wall, 0.5 * c.height})));
    out.push_back(std::move(box));

    // In doubles: a wide container holds more columns than an int counts (width / spacing up to
    // 1e24), and the conversion would be undefined. Rows and columns are whole numbers below
    // 2^53, so the grid is the integer one exactly.
    const double columns = std::max(1.0, std::floor(c.width / spacing));
    SplitMix64 rng{p.seed};
    const double y0 = c.origin.y + c.height + p.drop_height + 0.5 * p.box;
    for (int i = 0; i < p.count; ++i) {
        const double row = std::floor(i / columns);
        const double col = i - row * columns;
        const double dx = jitter * (2.0 * rng.uniform() - 1.0);
        const double x = c.origin.x + (col - 0.5 * (columns - 1)) * spacing + dx;
        const double y = y0 + row * spacing;
        SceneBody b = make_body(p.name + "/" + std::to_string(i), BodyType::dynamic, {x, y});
        b.shapes.push_back(box_polygon(box_shape(p.box, p.box, p.material)));
        out.push_back(std::move(b));
    }
    return out;
}

std::vector<SceneBody> generate_elastic_pair(const ElasticPairParams& p) {
    require_length("box", p.box);
    require_within("speed", p.speed, supported::input_max, "m s^-1");
    require_within("distance", p.distance, supported::input_max, "m");
    if (!(p.distance > p.box))
        throw ValidationError("distance", p.distance, "must be > box (no initial overlap)",
                              "DCX_shape");
    require_finite("density", p.density);
    if (!(p.density > 0.0))
        throw ValidationError("density", p.density, "must be > 0", "DCX_density");
    require_finite("restitution", p.restitution);
    if (!(p.restitution >= 0.0 && p.restitution <= 1.0))
        throw ValidationError("restitution", p.restitution, "must be in [0, 1]", "DCI_CR");
    const Material m{p.density, p.restitution, 0.0};

    std::vector<SceneBody> out;
    for (const int side : {-1, 1}) {
        SceneBody b = make_body(p.name + (side < 0 ? "/left" : "/right"), BodyType::dynamic,
                                {0.5 * side * p.distance, 0.0});
        b.def.linear_velocity = {-side * p.speed, 0.0};
        b.def.gravity_scale = 0.0;
        b.shapes.push_back(box_polygon(box_shape(p.box, p.box, m)));
        out.push_back(std::move(b));
    }
    return out;
}

} // namespace tamias2d::io
