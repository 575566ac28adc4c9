// The recorded run behind `tamias2d view` and the page it is written into (docs/viewer.md).
#include "view_html.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <ostream>
#include <stdexcept>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <unordered_map>
#include <utility>
#include <variant>

#include <nlohmann/json.hpp>

#include "player_assets.hpp" // generated from apps/cli/player/ by embed_player.cmake
#include "view_deflate.hpp"
#include "view_geometry.hpp"

namespace tamias2d::cli {
namespace {

using nlohmann::json;

constexpr double two_pi = 2.0 * std::numbers::pi;
/// Quantised values stay within 2^50 steps so that the page's doubles hold them (and the
/// residuals between them) exactly.
constexpr double max_steps = 1125899906842624.0;

/// A value the player cannot hold at its quantum (a body more than 10^11 m away).
struct OutOfRange {};

std::int64_t quantise(double value, double quantum) {
    const double n = std::floor(value / quantum + 0.5);
    if (!(std::abs(n) <= max_steps))
        throw OutOfRange{};
    return static_cast<std::int64_t>(n);
}

void put_varint(std::vector<std::uint8_t>& out, std::uint64_t v) {
    while (v >= 0x80) {
        out.push_back(static_cast<std::uint8_t>(v | 0x80));
        v >>= 7;
    }
    out.push_back(static_cast<std::uint8_t>(v));
}

/// Small magnitudes of either sign become small unsigned numbers: 0, -1, 1, -2 -> 0, 1, 2, 3.
std::uint64_t zigzag(std::int64_t v) {
    return v >= 0 ? static_cast<std::uint64_t>(v) << 1
                  : (static_cast<std::uint64_t>(-(v + 1)) << 1) | 1U;
}

std::string base64(const std::vector<std::uint8_t>& in) {
    static constexpr char alphabet[] =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((in.size() + 2) / 3 * 4);
    std::size_t i = 0;
    for (; i + 2 < in.size(); i += 3) {
        const unsigned v = unsigned(in[i]) << 16 | unsigned(in[i + 1]) << 8 | in[i + 2];
        out += alphabet[v >> 18];
        out += alphabet[(v >> 12) & 63];
        out += alphabet[(v >> 6) & 63];
        out += alphabet[v & 63];
    }
    if (i + 1 == in.size()) {
        const unsigned v = unsigned(in[i]) << 16;
        out += alphabet[v >> 18];
        out += alphabet[(v >> 12) & 63];
        out += "==";
    } else if (i + 2 == in.size()) {
        const unsigned v = unsigned(in[i]) << 16 | unsigned(in[i + 1]) << 8;
        out += alphabet[v >> 18];
        out += alphabet[(v >> 12) & 63];
        out += alphabet[(v >> 6) & 63];
        out += '=';
    }
    return out;
}

std::string html_escape(std::string_view s) {
    std::string out;
    for (const char c : s) {
        switch (c) {
        case '&':
            out += "&amp;";
            break;
        case '<':
            out += "&lt;";
            break;
        case '>':
            out += "&gt;";
            break;
        case '"':
            out += "&quot;";
            break;
        default:
            out += c;
        }
    }
    return out;
}

using view::to_body_frame;

json pair(Vec2d v) {
    return view::point_json(v);
}

/// Table 2 (DCO_p, DCO_v, DCO_phi, DCO_omega): the check `run` makes on every row it writes.
void check_outputs(const BodyState& s, int step, std::size_t index, const std::string& name) {
    const double values[] = {s.position.x, s.position.y,  s.velocity.x,
                             s.velocity.y, s.orientation, s.angular_velocity};
    const bool finite = std::all_of(std::begin(values), std::end(values),
                                    [](double v) { return std::isfinite(v); });
    const bool phi_ok = s.orientation >= 0.0 && s.orientation < two_pi;
    if (!finite || !phi_ok)
        throw std::runtime_error("step " + std::to_string(step) + ": body " +
                                 std::to_string(index) +
                                 (name.empty() ? std::string{} : " '" + name + "'") +
                                 (finite ? " has phi outside [0, 2 pi) (DCO_phi)"
                                         : " has a non-finite state (DCO_p, DCO_v, DCO_phi, "
                                           "DCO_omega)"));
}

} // namespace

void ResidualStream::add(std::size_t body, std::int64_t value) {
    const std::int64_t p1 = previous_[body];
    const std::int64_t p2 = before_previous_[body];
    const std::int64_t predicted = frames_ == 0 ? 0 : frames_ == 1 ? p1 : 2 * p1 - p2;
    before_previous_[body] = p1;
    previous_[body] = value;
    const std::uint64_t z = zigzag(value - predicted);
    if (z == 0) {
        ++zero_run_;
        return;
    }
    if (zero_run_ > 0) { // token 0, then the run's length less one
        bytes_.push_back(0);
        put_varint(bytes_, zero_run_ - 1);
        zero_run_ = 0;
    }
    put_varint(bytes_, z);
}

std::vector<std::uint8_t> ResidualStream::bytes() const {
    std::vector<std::uint8_t> out = bytes_;
    if (zero_run_ > 0) {
        out.push_back(0);
        put_varint(out, zero_run_ - 1);
    }
    return out;
}

void Recording::Box::add(double x, double y, double r) {
    if (empty) {
        min_x = x - r, min_y = y - r, max_x = x + r, max_y = y + r;
        empty = false;
        return;
    }
    min_x = std::min(min_x, x - r), min_y = std::min(min_y, y - r);
    max_x = std::max(max_x, x + r), max_y = std::max(max_y, y + r);
}

Recording::Recording(const io::Scene& scene, const World& world, std::vector<BodyId> ids,
                     Options options)
    : ids_(std::move(ids)), options_(std::move(options)), radius_(ids_.size(), 0.0),
      unwrapped_angle_(ids_.size(), 0.0), last_omega_(ids_.size(), 0.0),
      channels_(6, ResidualStream(ids_.size())) {
    // Shapes are stored once per distinct geometry: a rain or a pyramid has one box for all.
    json geoms = json::array();
    std::map<std::string, std::size_t> geom_index;
    json bodies = json::array();
    std::unordered_map<std::string, std::size_t> index_of;
    for (std::size_t i = 0; i < ids_.size(); ++i) {
        const io::SceneBody& body = scene.bodies[i];
        const Vec2d lc = world.local_center(ids_[i]);
        names_.push_back(body.def.name);
        index_of.emplace(body.def.name, i);
        json shapes = json::array();
        for (const ShapeDef& shape : body.shapes) {
            const Geometry& g = shape.geometry;
            json item = view::geometry_json(g);
            // The farthest point of the shape from the centre of mass: of a disc about `c`.
            const auto reach = [&](Vec2d c, double r) {
                radius_[i] = std::max(radius_[i], std::hypot(c.x - lc.x, c.y - lc.y) + r);
            };
            switch (g.type) {
            case ShapeType::circle:
                reach(g.circle.center, g.circle.radius);
                break;
            case ShapeType::polygon:
                for (int k = 0; k < g.polygon.count; ++k)
                    reach(g.polygon.vertices[static_cast<std::size_t>(k)], 0.0);
                break;
            case ShapeType::capsule:
                reach(g.capsule.center1, g.capsule.radius);
                reach(g.capsule.center2, g.capsule.radius);
                break;
            case ShapeType::segment:
                reach(g.segment.point1, 0.0);
                reach(g.segment.point2, 0.0);
                break;
            case ShapeType::chain_segment:
                reach(g.chain_segment.point1, 0.0);
                reach(g.chain_segment.point2, 0.0);
                break;
            }
            const auto [it, added] = geom_index.try_emplace(item.dump(), geoms.size());
            if (added)
                geoms.push_back(std::move(item));
            shapes.push_back(it->second);
        }
        bodies.push_back({{"name", body.def.name},
                          {"type", std::string(to_string(world.type(ids_[i])))},
                          {"m", world.mass(ids_[i])},
                          {"I", world.inertia(ids_[i])},
                          {"lc", pair(lc)},
                          {"shapes", std::move(shapes)}});
    }

    // Joint anchors in each body's frame, taken where the joint was made (frame 0); the page
    // moves them with the bodies.
    json joints = json::array();
    for (const io::SceneJoint& joint : scene.joints) {
        const auto a = index_of.find(joint.body_a);
        const auto b = index_of.find(joint.body_b);
        if (a == index_of.end() || b == index_of.end())
            continue; // build_world has already rejected such a scene
        const BodyId ia = ids_[a->second], ib = ids_[b->second];
        const auto [kind, la, lb] = std::visit(
            [&](const auto& d) -> std::tuple<const char*, Vec2d, Vec2d> {
                using D = std::decay_t<decltype(d)>;
                if constexpr (std::is_same_v<D, DistanceJointDef>)
                    return {"distance", to_body_frame(world, ia, d.anchor_a),
                            to_body_frame(world, ib, d.anchor_b)};
                else if constexpr (std::is_same_v<D, MotorJointDef>)
                    return {"motor", d.linear_offset, Vec2d{}}; // B's origin's target in A
                else if constexpr (std::is_same_v<D, FilterJointDef>)
                    return {"filter", Vec2d{}, Vec2d{}}; // no anchor: drawn between origins
                else {
                    const char* name = std::is_same_v<D, RevoluteJointDef>    ? "revolute"
                                       : std::is_same_v<D, PrismaticJointDef> ? "prismatic"
                                       : std::is_same_v<D, WeldJointDef>      ? "weld"
                                                                              : "wheel";
                    return {name, to_body_frame(world, ia, d.anchor),
                            to_body_frame(world, ib, d.anchor)};
                }
            },
            joint.def);
        joints.push_back({{"type", kind},
                          {"a", a->second},
                          {"b", b->second},
                          {"la", pair(la)},
                          {"lb", pair(lb)}});
    }

    const json fixed = {{"format", 1},
                        {"encoding", "deflate-raw"}, // of every base64 stream
                        {"title", options_.title},
                        {"description", scene.description},
                        {"dt", scene.dt},
                        {"every", options_.every},
                        {"gravity", pair(scene.world.gravity)},
                        {"quantum",
                         {{"position", position_quantum},
                          {"angle", angle_quantum},
                          {"velocity", velocity_quantum},
                          {"angular_velocity", angular_velocity_quantum},
                          {"contact", contact_quantum}}},
                        {"geoms", std::move(geoms)},
                        {"bodies", std::move(bodies)},
                        {"joints", std::move(joints)}};
    scene_json_ = fixed.dump(-1, ' ', false, json::error_handler_t::replace);
}

void Recording::add_frame(int step, const World& world) {
    const double time = world.time();
    const double interval = steps_.empty() ? 0.0 : time - times_.back();
    static constexpr std::array<double, 6> quanta = {position_quantum, position_quantum,
                                                     angle_quantum,    velocity_quantum,
                                                     velocity_quantum, angular_velocity_quantum};
    for (std::size_t i = 0; i < ids_.size(); ++i) {
        const BodyState s = world.state(ids_[i]);
        check_outputs(s, step, i, names_[i]);
        // The angle is unwrapped (phi + 2 pi k nearest the turn omega predicts) so that a
        // spinning body's angle stays predictable; the page wraps it back to [0, 2 pi).
        double angle = s.orientation;
        if (!steps_.empty()) {
            const double expected =
                unwrapped_angle_[i] + 0.5 * (last_omega_[i] + s.angular_velocity) * interval;
            angle += two_pi * std::round((expected - angle) / two_pi);
        }
        unwrapped_angle_[i] = angle;
        last_omega_[i] = s.angular_velocity;
        const std::array<double, 6> values = {s.position.x, s.position.y, angle,
                                              s.velocity.x, s.velocity.y, s.angular_velocity};
        try {
            for (std::size_t c = 0; c < values.size(); ++c)
                channels_[c].add(i, quantise(values[c], quanta[c]));
        } catch (const OutOfRange&) {
            throw std::runtime_error("step " + std::to_string(step) + ": body " +
                                     std::to_string(i) +
                                     (names_[i].empty() ? std::string{} : " '" + names_[i] + "'") +
                                     " is too far away or too fast for the player (more than "
                                     "1e11 m, m/s or rad from 0)");
        }
        all_bounds_.add(s.position.x, s.position.y, radius_[i]);
        if (world.type(ids_[i]) != BodyType::static_body) // the page fits its view to these
            moving_bounds_.add(s.position.x, s.position.y, radius_[i]);
    }
    for (ResidualStream& c : channels_)
        c.end_frame();
    steps_.push_back(step);
    times_.push_back(time);
    kinetic_.push_back(world.kinetic_energy());
    potential_.push_back(world.potential_energy());

    if (contacts_dropped_ || options_.max_contact_points == 0)
        return;
    const auto contacts = world.contacts();
    std::size_t points = 0;
    for (const ContactInfo& c : contacts)
        points += static_cast<std::size_t>(std::clamp(c.point_count, 0, 2));
    if (contact_points_ + points > options_.max_contact_points) {
        contacts_dropped_ = true; // all or nothing: a player showing some frames' would mislead
        contacts_.clear();
        contacts_.shrink_to_fit();
        return;
    }
    contact_points_ += points;
    max_contacts_in_frame_ = std::max(max_contacts_in_frame_, points);
    put_varint(contacts_, points);
    std::vector<std::array<std::int64_t, 3>> current;
    current.reserve(points);
    for (const ContactInfo& c : contacts) {
        // The normal as an angle in 256ths of a turn: enough to draw it.
        const double angle = std::atan2(c.normal.y, c.normal.x);
        const double turn = std::isfinite(angle) ? angle / two_pi : 0.0;
        const auto code = static_cast<std::int64_t>(
            static_cast<int>(std::floor(turn * 256.0 + 0.5) + 256.0) % 256);
        for (int k = 0; k < std::clamp(c.point_count, 0, 2); ++k) {
            const Vec2d p = c.points[k].point;
            try {
                current.push_back(
                    {quantise(p.x, contact_quantum), quantise(p.y, contact_quantum), code});
            } catch (const OutOfRange&) {
                throw std::runtime_error("step " + std::to_string(step) +
                                         ": a contact point is too far away for the player");
            }
        }
    }
    // Each point against the previous frame's point at its place, or else the point before
    // it in this frame; the normal's code as a difference modulo 256.
    for (std::size_t k = 0; k < current.size(); ++k) {
        const std::array<std::int64_t, 3> predicted = k < last_contacts_.size() ? last_contacts_[k]
                                                      : k > 0
                                                          ? current[k - 1]
                                                          : std::array<std::int64_t, 3>{0, 0, 0};
        put_varint(contacts_, zigzag(current[k][0] - predicted[0]));
        put_varint(contacts_, zigzag(current[k][1] - predicted[1]));
        contacts_.push_back(static_cast<std::uint8_t>((current[k][2] - predicted[2] + 256) % 256));
    }
    last_contacts_ = std::move(current);
}

std::string Recording::data_json() const {
    static constexpr const char* channel_names[] = {"x", "y", "phi", "vx", "vy", "omega"};
    json channels = json::object();
    for (std::size_t c = 0; c < channels_.size(); ++c)
        channels[channel_names[c]] = base64(deflate_literals(channels_[c].bytes()));
    const bool recorded = options_.max_contact_points > 0 && !contacts_dropped_;
    const json contacts = {
        {"recorded", recorded},
        {"limit", options_.max_contact_points},
        {"points", recorded ? contact_points_ : 0},
        {"max_in_frame", recorded ? max_contacts_in_frame_ : 0},
        {"data", recorded ? base64(deflate_literals(contacts_)) : std::string{}}};
    const auto box = [](const Box& b) -> json {
        if (b.empty)
            return nullptr;
        return {b.min_x, b.min_y, b.max_x, b.max_y};
    };
    const json rest = {
        {"frames",
         {{"step", steps_}, {"time", times_}, {"kinetic", kinetic_}, {"potential", potential_}}},
        {"bounds", {{"moving", box(moving_bounds_)}, {"all", box(all_bounds_)}}},
        {"contacts", contacts},
        {"channels", std::move(channels)}};
    std::string text = scene_json_;
    text.pop_back(); // the closing brace: the two objects' members are joined
    const std::string more = rest.dump(-1, ' ', false, json::error_handler_t::replace);
    text += ',';
    text.append(more, 1, std::string::npos);
    // Inside <script>, "</script>" in a body's name would end the element: '<' is written as
    // its JSON escape, which JSON.parse reads back unchanged.
    std::string safe;
    safe.reserve(text.size());
    for (const char c : text) {
        if (c == '<')
            safe += "\\u003c";
        else
            safe += c;
    }
    return safe;
}

void Recording::write_html(std::ostream& out) const {
    const std::string_view page(reinterpret_cast<const char*>(player::player_html),
                                sizeof player::player_html);
    const std::string_view marker = "<!--TAMIAS:";
    std::size_t at = 0;
    while (true) {
        const std::size_t m = page.find(marker, at);
        out << page.substr(at, m == std::string_view::npos ? std::string_view::npos : m - at);
        if (m == std::string_view::npos)
            break;
        const std::size_t end = page.find("-->", m);
        if (end == std::string_view::npos)
            throw std::logic_error("player template: unterminated marker");
        const std::string_view name = page.substr(m + marker.size(), end - m - marker.size());
        if (name == "TITLE")
            out << html_escape(options_.title);
        else if (name == "CSS")
            out.write(reinterpret_cast<const char*>(player::player_css), sizeof player::player_css);
        else if (name == "JS")
            out.write(reinterpret_cast<const char*>(player::player_js), sizeof player::player_js);
        else if (name == "DATA")
            out << data_json();
        else
            throw std::logic_error("player template: unknown marker " + std::string(name));
        at = end + 3;
    }
}

} // namespace tamias2d::cli
