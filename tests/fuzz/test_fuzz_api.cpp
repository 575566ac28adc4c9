// Seeded fuzzing of the World API (R4): random sequences of calls with extreme arguments
// (NaN, infinities, denormals, 1e308, the supported range's bounds), stale, destroyed and
// forged handles, odd time steps, and queries and ray casts of zero, huge and NaN vectors.
//
// Oracle: the library's stated promises (docs/user-guide.md, "Errors" and "Handles"): no crash
// and no sanitizer report; every rejection is a ValidationError (non-empty field and message),
// an InvalidHandle (non-empty message) or a WrongKind (non-empty subject and message); a
// rejected call leaves World::state_hash() unchanged; after every accepted call every state,
// energy and ray-cast result is finite. Hand-made geometry (every field of every shape kind,
// the other kinds' members included) must not be read out of bounds (the sanitizer build), and
// an accepted hand-made polygon must be simple and convex (its total turning 2 pi, by atan2)
// with the shoelace centroid (DCX_shape).
//
// TAMIAS_FUZZ_API_ITERATIONS=<n> runs more sequences (the default is printed); a failure
// prints its seed, replayed alone with TAMIAS_FUZZ_SEED=<seed> TAMIAS_FUZZ_API_ITERATIONS=1.
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <iterator>
#include <numbers>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "fuzz/fuzz_support.hpp"
#include "tamias2d/errors.hpp"
#include "tamias2d/recorder.hpp"
#include "tamias2d/replay.hpp"
#include "tamias2d/world.hpp"

namespace utf = boost::unit_test;
using namespace tamias2d;
using namespace tamias2d::fuzz;

namespace {

// About a second in Release and a few seconds under ASan/UBSan at -O1.
constexpr long default_iterations = 1000;
constexpr int calls_per_sequence = 120;

struct Driver {
    Rng r;
    /// Capsules, segments, chain segments and bullets are drawn from a stream of their own, so
    /// that the main stream's draws (and the calls a seed in docs/verification.md replays) are
    /// the ones the seed was found with.
    Rng kinds;
    /// Hand-made geometry (hand_made), from a third stream for the same reason.
    Rng hand;
    /// The queries' block (query_block), from a fourth stream.
    Rng queries;
    /// The event calls (events_call), from a fourth stream: drawn before the main stream's
    /// choice, they leave its draws as they were.
    Rng events_stream;
    /// debug_draw, profile and explosion calls (draw_profile_explode), from a stream of their own.
    Rng area46;
    /// The bodies' and world's run-time control and identity calls (body_world_call), from a
    /// stream of their own for the same reason.
    Rng body_world;
    /// The contact hooks' calls (contact_hooks_call), from a stream of their own.
    Rng hooks;
    /// What the oracle of an accepted hand-made polygon found wrong (empty: nothing).
    std::string shape_problem;
    World world;
    std::vector<BodyId> bodies;  // every body created, destroyed ones kept (stale handles)
    std::vector<ShapeId> shapes; // likewise
    std::vector<JointId> joints; // likewise
    long accepted = 0, rejected = 0;
    explicit Driver(std::uint64_t seed)
        : r(seed), kinds(seed ^ 0x9e3779b97f4a7c15u), hand(seed ^ 0xc2b2ae3d27d4eb4fu),
          queries(seed ^ 0x165667b19e3779f9u), events_stream(seed ^ 0x27d4eb2f165667c5u),
          area46(seed ^ 0x94d049bb133111ebu), body_world(seed ^ 0xbf58476d1ce4e5b9u),
          hooks(seed ^ 0xd6e8feb86659fd93u), world(make_def(r)),
          control(seed ^ 0x5851f42d4c957f2du), character(seed ^ 0xd1342543de82ef95u),
          definitions_stream(seed ^ 0x2545f4914f6cdd1du),
          recording_stream(seed ^ 0x9fb21c651e98df25u), surface_stream(seed ^ 0x8cb92ba72f3d8dd7u) {
    }

    static WorldDef make_def(Rng& r) {
        WorldDef d;
        // Valid settings: the constructor's own rejections are tested elsewhere.
        d.gravity = {0.0, r.chance(80) ? -10.0 : r.between(-100.0, 100.0)};
        d.enable_sleep = r.chance(50);
        return d;
    }

    Vec2d vec() { return {any_double(r), any_double(r)}; }

    BodyId body() {
        if (bodies.empty() || r.chance(5))
            return BodyId{static_cast<std::uint32_t>(r.below(8)),
                          static_cast<std::uint32_t>(r.below(3)), world.tag()}; // forged
        return bodies[r.below(bodies.size())];
    }
    ShapeId shape() {
        if (shapes.empty() || r.chance(5))
            return ShapeId{static_cast<std::uint32_t>(r.below(8)), 0, world.tag()};
        return shapes[r.below(shapes.size())];
    }
    JointId joint() {
        if (joints.empty() || r.chance(5))
            return JointId{static_cast<std::uint32_t>(r.below(4)), 0, world.tag()};
        return joints[r.below(joints.size())];
    }

    Material material() {
        Material m;
        m.density = r.chance(85) ? r.between(0.1, 5.0) : any_double(r);
        m.restitution = r.chance(85) ? r.unit() : any_double(r);
        m.friction = r.chance(85) ? r.unit() : any_double(r);
        return m;
    }

    Vec2d near_point() {
        if (!kinds.chance(80))
            return {any_double(kinds), any_double(kinds)};
        const double x = kinds.between(-1, 1);
        return {x, kinds.between(-1, 1)};
    }

    /// A capsule, a segment or one segment of a chain, drawn from `kinds` in a fixed order.
    ShapeDef rounded_shape_def() {
        const Material m{kinds.chance(85) ? kinds.between(0.1, 5.0) : any_double(kinds),
                         kinds.unit(), kinds.unit()};
        switch (kinds.below(3)) {
        case 0: {
            const Vec2d a = near_point();
            const Vec2d b = near_point();
            return capsule_shape(a, b, positive_size(kinds), m);
        }
        case 1: {
            const Vec2d a = near_point();
            return segment_shape(a, near_point(), m);
        }
        default: {
            std::vector<Vec2d> pts;
            const std::size_t n = 1 + kinds.below(6);
            for (std::size_t i = 0; i < n; ++i)
                pts.push_back(near_point());
            const std::vector<ShapeDef> chain = chain_shapes(pts, kinds.chance(30), m);
            return chain[kinds.below(chain.size())];
        }
        }
    }

    /// TAMIAS_FUZZ_SHAPES=classic: circles, boxes and polygons only and no bullets, the calls
    /// the seeds of docs/verification.md's findings were found with.
    static bool classic_only() {
        const char* v = std::getenv("TAMIAS_FUZZ_SHAPES");
        return v != nullptr && std::string_view(v) == "classic";
    }

    /// A circle, box or polygon, replaced two times in five by a rounded shape; one time in
    /// five made by hand (hand_made).
    ShapeDef shape_def() {
        const bool rounded = kinds.chance(40) && !classic_only();
        const ShapeDef classic = classic_shape_def();
        ShapeDef def = rounded ? rounded_shape_def() : classic;
        if (!classic_only() && hand.chance(20))
            hand_made(def);
        return def;
    }

    /// Geometry made by hand, as a user may fill a Geometry's fields: every field of every
    /// shape kind, the other kinds' members included. One of: the other kinds' members
    /// scribbled (a polygon.count of 9 or 1e8 on a circle); one field of the shape's own kind
    /// replaced by an extreme value; a polygon of 3 to 8 points on a circle in their order, a
    /// star's order (a pentagram) or any order, with exact normals and a centroid that is or
    /// is not its own.
    void hand_made(ShapeDef& def) {
        Geometry& g = def.geometry;
        const auto any = [&] { return hand.chance(50) ? hand.between(-3, 3) : any_double(hand); };
        const auto any_vec = [&] { return Vec2d{any(), any()}; };
        const int counts[] = {-1, 0, 2, 3, 8, 9, 100000000, 2147483647};
        switch (hand.below(3)) {
        case 0: // the other kinds' members
            if (g.type != ShapeType::polygon) {
                g.polygon.count = counts[hand.below(std::size(counts))];
                for (Vec2d& v : g.polygon.vertices)
                    v = any_vec();
                for (Vec2d& n : g.polygon.normals)
                    n = any_vec();
                g.polygon.centroid = any_vec();
            } else {
                g.polygon.vertices[std::size_t(max_polygon_vertices - 1)] = any_vec();
            }
            if (g.type != ShapeType::circle)
                g.circle = {any_vec(), any()};
            if (g.type != ShapeType::capsule)
                g.capsule = {any_vec(), any_vec(), any()};
            if (g.type != ShapeType::segment)
                g.segment = {any_vec(), any_vec()};
            if (g.type != ShapeType::chain_segment)
                g.chain_segment = {any_vec(), any_vec(), any_vec(), any_vec()};
            return;
        case 1: // one field of its own kind
            switch (g.type) {
            case ShapeType::circle:
                (hand.chance(50) ? g.circle.radius : g.circle.center.x) = any();
                return;
            case ShapeType::polygon: {
                const std::size_t i = hand.below(std::size_t(max_polygon_vertices));
                switch (hand.below(4)) {
                case 0:
                    g.polygon.vertices[i].y = any();
                    return;
                case 1:
                    g.polygon.normals[i].x = any();
                    return;
                case 2:
                    g.polygon.centroid = any_vec();
                    return;
                default:
                    g.polygon.count = counts[hand.below(std::size(counts))];
                    return;
                }
            }
            case ShapeType::capsule:
                (hand.chance(50) ? g.capsule.radius : g.capsule.center2.y) = any();
                return;
            case ShapeType::segment:
                g.segment.point2.x = any();
                return;
            case ShapeType::chain_segment:
                (hand.chance(50) ? g.chain_segment.ghost1.x : g.chain_segment.point2.y) = any();
                return;
            }
            return;
        default: { // a polygon of points on a circle, in some order
            const int n = 3 + int(hand.below(6));
            std::vector<double> angles(std::size_t(n), 0.0);
            for (double& a : angles)
                a = hand.between(0.0, 2.0 * std::numbers::pi);
            std::sort(angles.begin(), angles.end());
            std::vector<int> order(static_cast<std::size_t>(n));
            const int step = hand.chance(50) ? 1 : 2 + int(hand.below(std::size_t(n - 2)));
            for (int k = 0; k < n; ++k)
                order[std::size_t(k)] = (k * step) % n; // a star for a step prime to n
            if (hand.chance(20)) // any order (Fisher-Yates: the same on every standard library)
                for (std::size_t k = order.size() - 1; k > 0; --k)
                    std::swap(order[k], order[hand.below(k + 1)]);
            const double radius = hand.chance(80) ? hand.between(0.1, 3.0) : positive_size(hand);
            g = Geometry{};
            g.type = ShapeType::polygon;
            Polygon& p = g.polygon;
            p.count = n;
            for (int k = 0; k < n; ++k) {
                const double a = angles[std::size_t(order[std::size_t(k)])];
                p.vertices[std::size_t(k)] = {radius * std::cos(a), radius * std::sin(a)};
            }
            for (int k = 0; k < n; ++k) {
                const Vec2d e = p.vertices[std::size_t((k + 1) % n)] - p.vertices[std::size_t(k)];
                const double len = std::hypot(e.x, e.y);
                p.normals[std::size_t(k)] = {e.y / len, -e.x / len};
            }
            p.centroid = hand.chance(70) ? shoelace_centroid(p) : any_vec();
            hand_made_polygon = true;
            ++hand_polygons;
            return;
        }
        }
    }
    bool hand_made_polygon = false; ///< the last shape_def was hand_made's polygon
    long hand_polygons = 0, hand_polygons_accepted = 0;

    /// Oracle for hand-made polygons: the area centroid by the shoelace formula (rooted at the
    /// first vertex), independent of the library's triangle fan.
    static Vec2d shoelace_centroid(const Polygon& p) {
        double a2 = 0.0, cx = 0.0, cy = 0.0;
        const Vec2d o = p.vertices[0];
        for (int k = 0; k < p.count; ++k) {
            const Vec2d u = p.vertices[std::size_t(k)] - o;
            const Vec2d v = p.vertices[std::size_t((k + 1) % p.count)] - o;
            const double c = u.x * v.y - u.y * v.x;
            a2 += c;
            cx += (u.x + v.x) * c;
            cy += (u.y + v.y) * c;
        }
        return {o.x + cx / (3.0 * a2), o.y + cy / (3.0 * a2)};
    }

    /// What is wrong with an accepted hand-made polygon: it must turn left at every vertex and
    /// round exactly once (total turning 2 pi, summed by atan2: a simple convex polygon), and its
    /// centroid must be the shoelace centroid (to 1e-5 of its extent).
    static std::string polygon_problem(const Polygon& p) {
        double turning = 0.0, extent = 0.0;
        for (int k = 0; k < p.count; ++k) {
            const Vec2d a = p.vertices[std::size_t(k)];
            const Vec2d b = p.vertices[std::size_t((k + 1) % p.count)];
            const Vec2d c = p.vertices[std::size_t((k + 2) % p.count)];
            const Vec2d e1 = b - a, e2 = c - b;
            const double cr = e1.x * e2.y - e1.y * e2.x;
            if (!(cr > 0.0))
                return "an accepted polygon turns right or goes straight at a vertex";
            turning += std::atan2(cr, e1.x * e2.x + e1.y * e2.y);
            extent = std::max({extent, std::abs(e1.x), std::abs(e1.y)});
        }
        if (!(std::abs(turning - 2.0 * std::numbers::pi) < 1e-6))
            return "an accepted polygon turns round " + std::to_string(turning) +
                   " rad, not 2 pi: not simple";
        const Vec2d c = shoelace_centroid(p);
        if (!(std::hypot(p.centroid.x - c.x, p.centroid.y - c.y) <= 1e-5 * extent))
            return "an accepted polygon's centroid is not its vertices' centroid";
        return {};
    }

    ShapeDef classic_shape_def() {
        switch (r.below(3)) {
        // The arguments drawn one by one, last first: the order GCC evaluated them in when the
        // seeds in docs/verification.md were found (Clang's is the reverse; the standard's is
        // unspecified), so that a seed replays the same calls whatever the compiler.
        case 0: {
            const Vec2d center = r.chance(80) ? Vec2d{} : vec();
            const Material m = material();
            return circle_shape(positive_size(r), m, center);
        }
        case 1: {
            const double angle = r.chance(80) ? 0.0 : any_double(r);
            const Vec2d center = r.chance(80) ? Vec2d{} : vec();
            const Material m = material();
            const double height = positive_size(r);
            return box_shape(positive_size(r), height, m, center, angle);
        }
        default: {
            std::vector<Vec2d> pts;
            const std::size_t n = 1 + r.below(9);
            for (std::size_t i = 0; i < n; ++i)
                pts.push_back(r.chance(80) ? Vec2d{r.between(-1, 1), r.between(-1, 1)} : vec());
            return polygon_shape(pts, material());
        }
        }
    }

    BodyDef body_def() {
        BodyDef d;
        d.type = r.chance(15) ? BodyType::static_body
                              : (r.chance(10) ? BodyType::kinematic : BodyType::dynamic);
        d.position = r.chance(70) ? Vec2d{r.between(-20, 20), r.between(-5, 20)} : vec();
        d.angle = r.chance(70) ? r.between(-4, 4) : any_double(r);
        d.linear_velocity = r.chance(70) ? Vec2d{} : vec();
        d.angular_velocity = r.chance(70) ? 0.0 : any_double(r);
        if (r.chance(10))
            d.force = vec();
        if (r.chance(10))
            d.mass = any_double(r);
        if (r.chance(10))
            d.inertia = any_double(r);
        if (r.chance(10))
            d.gravity_scale = any_double(r);
        if (r.chance(10))
            d.linear_damping = any_double(r);
        d.awake = r.chance(90);
        d.bullet = kinds.chance(10) && !classic_only();
        return d;
    }

    double dt() { return r.chance(80) ? 1.0 / 60.0 : any_double(r); }

    /// The call about to be made, for the failure message and TAMIAS_FUZZ_TRACE.
    std::ostringstream last;
    static std::string str(Vec2d v) {
        std::ostringstream o;
        o.precision(17);
        o << "(" << v.x << ", " << v.y << ")";
        return o.str();
    }
    static std::string str(double v) { return str(Vec2d{v, 0.0}).substr(1, std::string::npos); }
    static std::string str(BodyId b) {
        return "body#" + std::to_string(b.index) + "." + std::to_string(b.generation);
    }

    // --- queries ---
    // Before every call, now and then, a query of World's "queries" section with arguments of
    // its own stream (extreme values, stale handles, invalid shapes among them). A query
    // changes nothing, so the main stream's calls (and the seeds docs/verification.md replays)
    // are the same with it: its promises are checked here. A refusal is a named error that
    // leaves state_hash() unchanged; an answer is finite, its fractions in [0, 1].
    Vec2d query_vec() {
        return queries.chance(80) ? Vec2d{queries.between(-30, 30), queries.between(-10, 30)}
                                  : Vec2d{any_double(queries), any_double(queries)};
    }
    QueryFilter query_filter() {
        QueryFilter f;
        if (queries.chance(30)) {
            f.category_bits = std::uint32_t(queries.bits());
            f.mask_bits = std::uint32_t(queries.bits());
        }
        if (queries.chance(20) && !bodies.empty())
            f.exclude_body = queries.chance(90) ? bodies[queries.below(bodies.size())]
                                                : BodyId{std::uint32_t(queries.below(8)), 7};
        return f;
    }
    Geometry query_geometry() {
        Geometry g;
        switch (queries.below(4)) {
        case 0:
            g = circle_shape(positive_size(queries)).geometry;
            break;
        case 1:
            g = box_shape(positive_size(queries), positive_size(queries)).geometry;
            break;
        case 2:
            g.type = ShapeType::capsule;
            g.capsule = {query_vec(), query_vec(), positive_size(queries)};
            break;
        default:
            g.type = ShapeType::segment;
            g.segment = {query_vec(), query_vec()};
            break;
        }
        return g;
    }
    static bool good(const RayCastHit& h) {
        return h.fraction >= 0.0 && h.fraction <= 1.0 && finite(h.point) && finite(h.normal);
    }
    static bool good(const ShapeCastHit& h) {
        return h.fraction >= 0.0 && h.fraction <= 1.0 && finite(h.point) && finite(h.normal);
    }
    static bool good(const ClosestPoints& c) {
        return std::isfinite(c.distance) && c.distance >= 0.0 && finite(c.point_a) &&
               finite(c.point_b) && finite(c.normal);
    }
    /// One query; returns what is wrong with its answer (empty: nothing); throws its refusal.
    std::string query() {
        const Vec2d o = query_vec(), d = query_vec();
        const QueryFilter f = query_filter();
        switch (queries.below(9)) {
        case 0:
            if (const auto h = world.ray_cast(o, d, f); h && !good(*h))
                return "ray_cast (filtered): a hit out of range";
            return {};
        case 1:
            for (const RayCastHit& h : world.ray_cast_all(o, d, f))
                if (!good(h))
                    return "ray_cast_all: a hit out of range";
            return {};
        case 2: {
            std::array<RayCastHit, 2> buf{};
            const std::size_t n = world.ray_cast_all(o, d, f, buf);
            for (std::size_t i = 0; i < std::min(n, buf.size()); ++i)
                if (!good(buf[i]))
                    return "ray_cast_all (span): a hit out of range";
            if (const auto h = world.ray_cast_any(o, d, f); h && !good(*h))
                return "ray_cast_any: a hit out of range";
            return {};
        }
        case 3: {
            bool bad = false;
            world.ray_cast(o, d, f, [&](const RayCastHit& h) {
                bad = bad || !good(h);
                return queries.chance(50) ? h.fraction : 1.0;
            });
            return bad ? "ray_cast (callback): a hit out of range" : "";
        }
        case 4:
            if (shapes.empty())
                return {};
            if (const auto h = world.ray_cast(shapes[queries.below(shapes.size())], o, d);
                h && !good(*h))
                return "ray_cast (shape): a hit out of range";
            return {};
        case 5:
            if (const auto h = world.shape_cast(
                    query_geometry(), o,
                    queries.chance(80) ? queries.between(-4, 4) : any_double(queries), d, f);
                h && !good(*h))
                return "shape_cast: a hit out of range";
            return {};
        case 6:
            (void)world.overlap_shape(query_geometry(), o, queries.between(-4, 4), f);
            (void)world.query_aabb(Aabb{o.x, o.y, o.x + d.x, o.y + d.y}, f);
            (void)world.query_point(o, f);
            return {};
        default: {
            if (shapes.empty())
                return {};
            const ShapeId a = shapes[queries.below(shapes.size())];
            const ShapeId b = shapes[queries.below(shapes.size())];
            if (!good(world.distance(a, b)))
                return "distance: not finite";
            if (!good(world.closest_point(a, o)))
                return "closest_point: not finite";
            return {};
        }
        }
    }
    void query_block() {
        if (!queries.chance(25))
            return;
        const std::uint64_t before = world.state_hash();
        std::string problem;
        try {
            problem = query();
        } catch (const ValidationError& e) {
            if (e.field.empty())
                problem = std::string("a query's ValidationError without a field: ") + e.what();
        } catch (const InvalidHandle& e) {
            if (std::string(e.what()).empty())
                problem = "a query's InvalidHandle with an empty message";
        } catch (const std::exception& e) {
            problem = std::string("a query threw an exception of another kind: ") + e.what();
        }
        if (problem.empty() && world.state_hash() != before)
            problem = "a query changed the world";
        if (!problem.empty())
            BOOST_ERROR("queries (before " << last.str() << "): " << problem);
    }

    // --- events ---
    /// One in ten calls: an event switch or threshold (any value, stale and forged handles
    /// among them), or a reading of every event list, whose numbers must be finite (a problem
    /// goes to shape_problem, which the check after an accepted call reports). All drawn from
    /// events_stream. Returns whether it made a call; throws what the library throws.
    bool events_call() {
        Rng& e = events_stream;
        if (!e.chance(10))
            return false;
        auto pick_body = [&] {
            return bodies.empty() || e.chance(5)
                       ? BodyId{std::uint32_t(e.below(8)), std::uint32_t(e.below(3))}
                       : bodies[e.below(bodies.size())];
        };
        auto pick_shape = [&] {
            return shapes.empty() || e.chance(5) ? ShapeId{std::uint32_t(e.below(8)), 0}
                                                 : shapes[e.below(shapes.size())];
        };
        auto pick_joint = [&] {
            return joints.empty() || e.chance(5) ? JointId{std::uint32_t(e.below(4)), 0}
                                                 : joints[e.below(joints.size())];
        };
        auto threshold = [&] { return e.chance(60) ? e.between(0.0, 50.0) : any_double(e); };
        const bool on = e.chance(50);
        switch (e.below(7)) {
        case 0: {
            const double v = threshold();
            last << "set_hit_event_threshold(" << v << ")";
            world.set_hit_event_threshold(v);
            break;
        }
        case 1: {
            const ShapeId s = pick_shape();
            last << "set_hit_events_enabled(shape#" << s.index << ", " << on << ")";
            world.set_hit_events_enabled(s, on);
            break;
        }
        case 2: {
            const ShapeId s = pick_shape();
            last << "set_contact_events_enabled(shape#" << s.index << ", " << on << ")";
            world.set_contact_events_enabled(s, on);
            break;
        }
        case 3: {
            const ShapeId s = pick_shape();
            last << "set_sensor_events_enabled(shape#" << s.index << ", " << on << ")";
            world.set_sensor_events_enabled(s, on);
            break;
        }
        case 4: {
            const BodyId b = pick_body();
            last << "set_move_events_enabled(" << str(b) << ", " << on << ")";
            world.set_move_events_enabled(b, on);
            break;
        }
        case 5: {
            const JointId j = pick_joint();
            const double force = threshold(), torque = threshold();
            last << "set_joint_event_thresholds(joint#" << j.index << ", " << force << ", "
                 << torque << ")";
            world.set_joint_event_thresholds(j, force, torque);
            break;
        }
        default: { // readings: const, they may refuse (sensor_overlaps), never change the world
            last << "event lists, sensor_overlaps";
            (void)world.sensor_overlaps(pick_shape());
            for (const ContactHitEvent& h : world.contact_hit_events())
                if (!(std::isfinite(h.approach_speed) && h.approach_speed > 0.0 &&
                      finite(h.point) && finite(h.normal)))
                    shape_problem = "a hit event with a non-finite or non-positive number";
            for (const BodyMoveEvent& m : world.body_move_events())
                if (!(finite(m.origin) && std::isfinite(m.angle)))
                    shape_problem = "a move event with a non-finite pose";
            for (const JointEvent& j : world.joint_events())
                if (!(finite(j.force) && std::isfinite(j.torque)))
                    shape_problem = "a joint event with a non-finite force or torque";
            break;
        }
        }
        return true;
    }

    // --- debug_draw, profile, explosion ---
    /// A draw (const: may refuse, never changes the world), the profiling switch with the
    /// profile and the counters read, or an explosion, all drawn from `area46` so that the main
    /// stream's calls stay those its seeds were found with.
    void draw_profile_explode() {
        Rng& a = area46;
        switch (a.below(4)) {
        case 0: {
            struct Null : DebugDraw {};
            Null d;
            d.draw_contacts = a.chance(50);
            d.draw_contact_normals = a.chance(50);
            d.draw_aabbs = a.chance(50);
            d.draw_mass_centers = a.chance(50);
            d.contact_normal_length = a.chance(80) ? 0.25 : any_double(a);
            d.axis_length = a.chance(80) ? 0.2 : any_double(a);
            if (a.chance(50))
                d.bounds = a.chance(70)
                               ? Aabb{-10.0, -10.0, 10.0, 10.0}
                               : Aabb{any_double(a), any_double(a), any_double(a), any_double(a)};
            last << "draw(normal length " << d.contact_normal_length << ", axis length "
                 << d.axis_length << ")";
            world.draw(d);
            break;
        }
        case 1: {
            const bool on = a.chance(50);
            last << "set_profiling(" << on << "), profile, counters";
            world.set_profiling(on);
            (void)world.profile();
            (void)world.counters();
            break;
        }
        default: {
            ExplosionDef e;
            e.position = a.chance(70) ? Vec2d{a.between(-20, 20), a.between(-5, 20)}
                                      : Vec2d{any_double(a), any_double(a)};
            e.radius = a.chance(70) ? a.between(0, 10) : any_double(a);
            e.falloff = a.chance(50) ? 0.0 : (a.chance(70) ? a.between(0, 5) : any_double(a));
            e.impulse_per_length = a.chance(70) ? a.between(-50, 50) : any_double(a);
            e.impulse_per_body =
                a.chance(50) ? 0.0 : (a.chance(70) ? a.between(-50, 50) : any_double(a));
            e.mask_bits = a.chance(70) ? 0xFFFFFFFFu : std::uint32_t(a.below(1u << 16));
            last << "explode(" << str(e.position) << ", radius " << e.radius << ", falloff "
                 << e.falloff << ", per length " << e.impulse_per_length << ", per body "
                 << e.impulse_per_body << ", mask " << e.mask_bits << ")";
            (void)world.explode(e);
            break;
        }
        }
    }

    // --- shape_control, joint_control ---
    /// The run-time changes of shapes and joints, drawn from a stream of their own (so that the
    /// main stream's calls stay those the seeds of docs/verification.md replay) one call in
    /// five, none with TAMIAS_FUZZ_SHAPES=classic. Values: in range mostly, any double else.
    Rng control;
    double control_value(double lo, double hi) {
        return control.chance(80) ? control.between(lo, hi) : any_double(control);
    }
    JointId control_joint() {
        if (joints.empty() || control.chance(5))
            return JointId{static_cast<std::uint32_t>(control.below(4)), 0};
        return joints[control.below(joints.size())];
    }
    ShapeId control_shape() {
        if (shapes.empty() || control.chance(5))
            return ShapeId{static_cast<std::uint32_t>(control.below(8)), 0};
        return shapes[control.below(shapes.size())];
    }
    Vec2d control_point() { return {control_value(-1.0, 1.0), control_value(-1.0, 1.0)}; }
    /// One run-time change; true if one was made (throws what the library throws).
    bool control_call() {
        if (classic_only() || !control.chance(20))
            return false;
        const ShapeId s = control_shape();
        const JointId j = control_joint();
        const bool on = control.chance(50);
        const double a = control_value(-2.0, 2.0), b = control_value(-2.0, 4.0);
        last << "control " << s.index << "." << s.generation << " joint " << j.index << "."
             << j.generation << " (" << on << ", " << a << ", " << b << "): ";
        switch (control.below(26)) {
        case 0:
            last << "set_friction";
            return world.set_friction(s, std::abs(a)), true;
        case 1:
            last << "set_restitution";
            return world.set_restitution(s, std::abs(a) / 2.0), true;
        case 2:
            last << "set_density";
            return world.set_density(s, b, on), true;
        case 3:
            last << "set_circle";
            return world.set_circle(s, Circle{control_point(), b}), true;
        case 4:
            last << "set_capsule";
            return world.set_capsule(s, Capsule{control_point(), control_point(), b}), true;
        case 5: {
            last << "set_polygon";
            std::vector<Vec2d> pts;
            for (std::size_t k = 0, n = 3 + control.below(4); k < n; ++k)
                pts.push_back(control_point());
            ShapeDef def;
            try {
                def = polygon_shape(pts);
            } catch (const ValidationError&) {
                def = box_shape(std::abs(a) + 0.1, std::abs(b) + 0.1);
            }
            return world.set_polygon(s, def.geometry.polygon), true;
        }
        case 6:
            last << "set_segment";
            return world.set_segment(s, Segment{control_point(), control_point()}), true;
        case 7:
            last << "set_sensor";
            return world.set_sensor(s, on), true;
        case 8:
            last << "enable_joint_limit";
            return world.enable_joint_limit(j, on), true;
        case 9:
            last << "set_joint_limits";
            return world.set_joint_limits(j, a, b), true;
        case 10:
            last << "enable_joint_motor";
            return world.enable_joint_motor(j, on), true;
        case 11:
            last << "set_joint_motor_speed";
            return world.set_joint_motor_speed(j, a), true;
        case 12:
            last << "set_joint_max_motor_torque";
            return world.set_joint_max_motor_torque(j, b), true;
        case 13:
            last << "set_joint_max_motor_force";
            return world.set_joint_max_motor_force(j, b), true;
        case 14:
            last << "enable_joint_spring";
            return world.enable_joint_spring(j, on), true;
        case 15:
            last << "set_joint_spring";
            return world.set_joint_spring(j, b, std::abs(a)), true;
        case 16:
            last << "set_joint_spring_target";
            return world.set_joint_spring_target(j, a), true;
        case 17:
            last << "set_distance_joint_length";
            return world.set_distance_joint_length(j, b), true;
        case 18:
            last << "set_constraint_tuning";
            return world.set_constraint_tuning(j, b * 20.0, std::abs(a)), true;
        case 19:
            last << "set_joint_collide_connected";
            return world.set_joint_collide_connected(j, on), true;
        case 20:
            last << "set_joint_break_force";
            return world.set_joint_break_force(j, b * 50.0), true;
        case 21:
            last << "set_joint_break_torque";
            return world.set_joint_break_torque(j, b * 50.0), true;
        case 22: { // getters are const: they may refuse, never change the world
            last << "joint getters";
            (void)world.joint_kind(j);
            (void)world.joint_body_a(j);
            (void)world.constraint_tuning(j);
            (void)world.joint_limits(j);
            return true;
        }
        case 23:
            last << "shape getters";
            (void)world.shape_geometry(s);
            (void)world.friction(s);
            return (void)world.is_sensor(s), true;
        default: {
            DistanceJointDef d; // a distance joint with a motor, for the calls above
            d.body_a = body();
            d.body_b = body();
            d.anchor_a = control_point();
            d.anchor_b = control_point() + Vec2d{1.0, 0.0};
            d.enable_motor = on;
            d.motor_speed = a;
            d.max_motor_force = b;
            last << "create_joint(distance with a motor)";
            joints.push_back(world.create_joint(d));
            return true;
        }
        }
    }

    // --- body_control, world_settings, identity: their calls, drawn from `body_world` ---
    BodyId body_world_body() {
        if (bodies.empty() || body_world.chance(5))
            return BodyId{static_cast<std::uint32_t>(body_world.below(8)),
                          static_cast<std::uint32_t>(body_world.below(3))};
        return bodies[body_world.below(bodies.size())];
    }
    ShapeId body_world_shape() {
        if (shapes.empty() || body_world.chance(5))
            return ShapeId{static_cast<std::uint32_t>(body_world.below(8)), 0};
        return shapes[body_world.below(shapes.size())];
    }
    JointId body_world_joint() {
        if (joints.empty() || body_world.chance(5))
            return JointId{static_cast<std::uint32_t>(body_world.below(4)), 0};
        return joints[body_world.below(joints.size())];
    }
    double body_world_value(double lo, double hi) {
        return body_world.chance(75) ? body_world.between(lo, hi) : any_double(control);
    }
    void body_world_call() {
        const BodyId b = body_world_body();
        switch (body_world.below(14)) {
        case 0: {
            const auto type = static_cast<BodyType>(body_world.below(4)); // 3: out of the enum
            last << "set_body_type(" << str(b) << ", " << static_cast<int>(type) << ")";
            world.set_body_type(b, type);
            break;
        }
        case 1: {
            const bool on = body_world.chance(60);
            last << "set_enabled(" << str(b) << ", " << on << ")";
            world.set_enabled(b, on);
            break;
        }
        case 2: {
            const double scale = body_world_value(-2.0, 2.0);
            last << "set_gravity_scale(" << str(b) << ", " << scale << ")";
            world.set_gravity_scale(b, scale);
            break;
        }
        case 3: {
            const bool on = body_world.chance(50);
            last << "set_bullet(" << str(b) << ", " << on << ")";
            world.set_bullet(b, on);
            break;
        }
        case 4: {
            const MotionLocks locks{body_world.chance(30), body_world.chance(30),
                                    body_world.chance(30)};
            last << "set_motion_locks(" << str(b) << ", " << locks.linear_x << locks.linear_y
                 << locks.angular << ")";
            world.set_motion_locks(b, locks);
            break;
        }
        case 5: {
            const double inertia = body_world_value(0.01, 10.0);
            const Vec2d center{body_world_value(-1.0, 1.0), body_world_value(-1.0, 1.0)};
            const double mass = body_world_value(0.01, 10.0);
            last << "set_mass_data(" << str(b) << ", " << mass << ", " << str(center) << ", "
                 << inertia << ")";
            world.set_mass_data(b, BodyMassData{mass, center, inertia});
            break;
        }
        case 6:
            last << "reset_mass_data(" << str(b) << ")";
            world.reset_mass_data(b);
            break;
        case 7: {
            const double speed = body_world_value(0.0, 2.0);
            last << "set_sleep_threshold(" << str(b) << ", " << speed << ")";
            world.set_sleep_threshold(b, speed);
            break;
        }
        case 8:
            last << "wake_touching(" << str(b) << ")";
            world.wake_touching(b);
            break;
        case 9: {
            const auto data = static_cast<UserData>(body_world.bits());
            const ShapeId s = body_world_shape();
            const JointId j = body_world_joint();
            last << "set_user_data(" << str(b) << ", shape#" << s.index << ", joint#" << j.index
                 << ")";
            world.set_user_data(data);
            world.set_user_data(b, data);
            world.set_user_data(s, data);
            world.set_user_data(j, data);
            break;
        }
        case 10: { // the identity readings are const: they may refuse, never change the world
            const ShapeId s = body_world_shape();
            const JointId j = body_world_joint();
            last << "identity readings(" << str(b) << ", shape#" << s.index << ", joint#" << j.index
                 << ")";
            (void)world.body_aabb(b);
            (void)world.joints(b);
            (void)world.contacts(b);
            (void)world.mass_data(b);
            (void)world.motion_locks(b);
            (void)world.body(s);
            (void)world.shape_aabb(s);
            (void)world.geometry(s);
            (void)world.joint_kind(j);
            (void)world.joint_body_a(j);
            break;
        }
        case 11: {
            const double speed = body_world.chance(20) ? inf : body_world_value(0.1, 50.0);
            last << "set_maximum_linear_speed(" << speed << ")";
            world.set_maximum_linear_speed(speed);
            break;
        }
        case 12: {
            const double push = body_world_value(0.1, 5.0), zeta = body_world_value(0.1, 20.0);
            const double hertz = body_world_value(1.0, 60.0);
            last << "set_contact_tuning(" << hertz << ", " << zeta << ", " << push << ")";
            world.set_contact_tuning(hertz, zeta, push);
            break;
        }
        default: // one setting per call, so that a refusal is the whole call's
            switch (body_world.below(4)) {
            case 0: {
                const int workers = body_world.chance(90) ? 1 + int(body_world.below(4))
                                                          : int(body_world.below(400)) - 100;
                last << "set_workers(" << workers << ")";
                world.set_workers(workers);
                break;
            }
            case 1: {
                const bool on = body_world.chance(50);
                last << "set_sleeping(" << on << ")";
                world.set_sleeping(on);
                break;
            }
            case 2: {
                const bool on = body_world.chance(80);
                last << "set_continuous(" << on << ")";
                world.set_continuous(on);
                break;
            }
            default: {
                const double threshold = body_world_value(0.0, 2.0);
                last << "set_restitution_threshold(" << threshold << ")";
                world.set_restitution_threshold(threshold);
                break;
            }
            }
            break;
        }
    }

    // --- character ---
    /// The character calls (a mover collided and cast, a kinematic target pose, wind), from a
    /// stream of their own so that the main stream's calls stay those its seeds were found
    /// with. Values: in range mostly, any double else.
    Rng character;
    double character_value(double lo, double hi) {
        return character.chance(80) ? character.between(lo, hi) : any_double(character);
    }
    Capsule character_capsule() {
        const Vec2d a{character_value(-20.0, 20.0), character_value(-5.0, 20.0)};
        const Vec2d b = character.chance(90) ? Vec2d{a.x + character_value(-1.0, 1.0),
                                                     a.y + character_value(0.0, 2.0)}
                                             : a;
        return {a, b, character_value(-0.1, 1.0)};
    }
    void character_call() {
        Rng& c = character;
        QueryFilter f;
        if (c.chance(20) && !bodies.empty())
            f.exclude_body = bodies[c.below(bodies.size())];
        switch (c.below(4)) {
        case 0: {
            const Capsule m = character_capsule();
            last << "collide_mover(" << str(m.center1) << " " << str(m.center2) << " " << m.radius
                 << ")";
            (void)world.collide_mover(m, f);
            break;
        }
        case 1: {
            const Capsule m = character_capsule();
            const Vec2d t{character_value(-10.0, 10.0), character_value(-10.0, 10.0)};
            last << "cast_mover(" << str(m.center1) << " " << str(m.center2) << " " << m.radius
                 << ", " << str(t) << ")";
            (void)world.cast_mover(m, t, f);
            break;
        }
        case 2: {
            const BodyId b = bodies.empty() || c.chance(5)
                                 ? BodyId{std::uint32_t(c.below(8)), 0, world.tag()}
                                 : bodies[c.below(bodies.size())];
            const Vec2d o{character_value(-20.0, 20.0), character_value(-5.0, 20.0)};
            const double a = character_value(-10.0, 10.0), dt = character_value(0.0, 0.1);
            last << "set_target_transform(" << str(b) << ", " << str(o) << ", " << a << ", " << dt
                 << ")";
            world.set_target_transform(b, o, a, dt);
            break;
        }
        default: {
            const ShapeId s = shapes.empty() || c.chance(5)
                                  ? ShapeId{std::uint32_t(c.below(8)), 0, world.tag()}
                                  : shapes[c.below(shapes.size())];
            const Vec2d wind{character_value(-50.0, 50.0), character_value(-50.0, 50.0)};
            const double drag = character_value(-0.1, 2.0), lift = character_value(-1.0, 1.0);
            const bool wake = c.chance(70);
            last << "apply_wind(" << s.index << "." << s.generation << ", " << str(wind) << ", "
                 << drag << ", " << lift << ", " << wake << ")";
            world.apply_wind(s, wind, drag, lift, wake);
            break;
        }
        }
    }

    // --- definitions ---
    /// Bodies and joints made with the definition fields the run-time controls also set
    /// (BodyDef::enabled, motion_locks, sleep_threshold; spring_target, constraint_tuning) and
    /// the warm-starting switch, drawn from a stream of their own (so that the main stream's
    /// calls stay those the seeds of docs/verification.md replay). Values: in range mostly,
    /// any double else.
    Rng definitions_stream;
    double definition_value(double lo, double hi) {
        Rng& d = definitions_stream;
        return d.chance(80) ? d.between(lo, hi) : any_double(d);
    }
    BodyId definitions_body() {
        Rng& d = definitions_stream;
        if (bodies.empty() || d.chance(5))
            return BodyId{static_cast<std::uint32_t>(d.below(8)), 0};
        return bodies[d.below(bodies.size())];
    }
    void definitions_call() {
        Rng& d = definitions_stream;
        switch (d.below(4)) {
        case 0: {
            BodyDef def;
            def.type = static_cast<BodyType>(d.below(3));
            def.position = {definition_value(-20.0, 20.0), definition_value(0.0, 20.0)};
            def.linear_velocity = {definition_value(-5.0, 5.0), definition_value(-5.0, 5.0)};
            def.enabled = d.chance(70);
            def.motion_locks = {d.chance(30), d.chance(30), d.chance(30)};
            if (d.chance(50))
                def.sleep_threshold = definition_value(0.0, 1.0);
            last << "create_body(definitions: type " << static_cast<int>(def.type) << ", enabled "
                 << def.enabled << ", locks " << def.motion_locks.linear_x
                 << def.motion_locks.linear_y << def.motion_locks.angular << ", sleep_threshold "
                 << def.sleep_threshold.value_or(-1) << ")";
            bodies.push_back(world.create_body(def));
            break;
        }
        case 1:
        case 2: {
            const BodyId a = definitions_body(), b = definitions_body();
            const Vec2d anchor{definition_value(-5.0, 5.0), definition_value(0.0, 10.0)};
            std::optional<ConstraintTuning> tuning;
            if (d.chance(60))
                tuning = ConstraintTuning{definition_value(1.0, 120.0), definition_value(0.1, 5.0)};
            const double target = definition_value(-2.0, 2.0);
            last << "create_joint(definitions: " << str(a) << ", " << str(b) << ", target "
                 << target << ", tuning " << (tuning ? tuning->hertz : -1.0) << " "
                 << (tuning ? tuning->damping_ratio : -1.0) << ", kind ";
            switch (d.below(5)) {
            case 0: {
                RevoluteJointDef j{.body_a = a, .body_b = b, .anchor = anchor};
                j.enable_spring = d.chance(50);
                j.hertz = 2.0;
                j.spring_target = target;
                j.constraint_tuning = tuning;
                last << "revolute)";
                joints.push_back(world.create_joint(j));
                break;
            }
            case 1: {
                PrismaticJointDef j{.body_a = a, .body_b = b, .anchor = anchor};
                j.enable_spring = d.chance(50);
                j.hertz = 2.0;
                j.spring_target = target;
                j.constraint_tuning = tuning;
                last << "prismatic)";
                joints.push_back(world.create_joint(j));
                break;
            }
            case 2: {
                WheelJointDef j{.body_a = a, .body_b = b, .anchor = anchor};
                j.spring_target = target;
                j.constraint_tuning = tuning;
                last << "wheel)";
                joints.push_back(world.create_joint(j));
                break;
            }
            case 3: {
                DistanceJointDef j{.body_a = a,
                                   .body_b = b,
                                   .anchor_a = anchor,
                                   .anchor_b = {anchor.x + 1.0, anchor.y}};
                j.constraint_tuning = tuning;
                last << "distance)";
                joints.push_back(world.create_joint(j));
                break;
            }
            default: {
                WeldJointDef j{.body_a = a, .body_b = b, .anchor = anchor};
                j.constraint_tuning = tuning;
                last << "weld)";
                joints.push_back(world.create_joint(j));
                break;
            }
            }
            break;
        }
        default: {
            const bool on = d.chance(60);
            last << "set_warm_starting(" << on << ")";
            world.set_warm_starting(on);
            break;
        }
        }
    }

    // --- contact_hooks ---
    // A shape's user material id, the mixing functions (valid rules, and values no friction or
    // restitution is: refused when a contact meets them, removed at once when none does, so
    // that no later step throws) and the pre-solve callback, from the hooks' own stream.
    void contact_hooks_call() {
        switch (hooks.below(4)) {
        case 0: {
            const ShapeId s = shapes.empty() || hooks.chance(5)
                                  ? ShapeId{std::uint32_t(hooks.below(8)), 0, world.tag()}
                                  : shapes[hooks.below(shapes.size())];
            const std::uint64_t id = hooks.chance(50) ? hooks.below(4) : hooks.bits();
            last << "set_user_material(shape#" << s.index << "." << s.generation << ", " << id
                 << ")";
            world.set_user_material(s, id);
            break;
        }
        case 1:
        case 2: {
            const bool friction = hooks.below(2) == 0;
            const int rule = int(hooks.below(5));
            const double bad = any_double(hooks);
            last << (friction ? "set_friction_mixing(" : "set_restitution_mixing(") << rule << ", "
                 << bad << ")";
            MaterialMixFunction mix;
            switch (rule) {
            case 0:
                break; // the default rule
            case 1:
                mix = [](double a, std::uint64_t, double b, std::uint64_t) {
                    return std::min(a, b);
                };
                break;
            case 2:
                mix = [](double a, std::uint64_t ia, double b, std::uint64_t ib) {
                    return (ia ^ ib) % 2 == 0 ? std::max(a, b) : 0.5 * (a + b);
                };
                break;
            default:
                mix = [bad](double, std::uint64_t, double, std::uint64_t) { return bad; };
                break;
            }
            const bool valid = rule < 3 || (friction ? std::isfinite(bad) && bad >= 0.0
                                                     : bad >= 0.0 && bad <= 1.0);
            if (friction)
                world.set_friction_mixing(mix);
            else
                world.set_restitution_mixing(mix);
            if (!valid) { // accepted: no contact met it; a step would
                if (friction)
                    world.set_friction_mixing({});
                else
                    world.set_restitution_mixing({});
            }
            break;
        }
        default: {
            const int rule = int(hooks.below(3));
            last << "set_pre_solve(" << rule << ")";
            if (rule == 0)
                world.set_pre_solve({});
            else
                world.set_pre_solve([rule](const PreSolveContact& c) {
                    return rule == 1 ? c.normal.y > -0.5
                                     : (c.shape_a.index + c.shape_b.index) % 3 != 0;
                });
            break;
        }
        }
    }

    // --- recording ---
    // Before every call, now and then, a copy of the world (World::from_snapshot: no functions,
    // so a Recorder takes it) recorded through a Recorder for a few impulses and steps drawn
    // from a stream of its own, then replayed: every step must match bit for bit, and a call
    // the copy refuses must leave its state_hash() and the recording unchanged. The world itself
    // is not touched.
    Rng recording_stream;

    // --- surface motion ---
    // A shape's rolling resistance and tangent speed (DD46, DD47), set at run time or given to
    // a new circle, from a stream of their own (so that the main stream's calls stay those the
    // seeds of docs/verification.md replay). Values: in range mostly, any double else.
    Rng surface_stream;
    void surface_call() {
        Rng& u = surface_stream;
        const auto value = [&](double lo, double hi) {
            return u.chance(85) ? u.between(lo, hi) : any_double(u);
        };
        switch (u.below(3)) {
        case 0: {
            const ShapeId s = shapes.empty() || u.chance(5)
                                  ? ShapeId{std::uint32_t(u.below(8)), 0, world.tag()}
                                  : shapes[u.below(shapes.size())];
            const double c = value(0.0, 1.0);
            last << "set_rolling_resistance(shape#" << s.index << "." << s.generation << ", " << c
                 << ")";
            world.set_rolling_resistance(s, c);
            break;
        }
        case 1: {
            const ShapeId s = shapes.empty() || u.chance(5)
                                  ? ShapeId{std::uint32_t(u.below(8)), 0, world.tag()}
                                  : shapes[u.below(shapes.size())];
            const double v = value(-5.0, 5.0);
            last << "set_tangent_speed(shape#" << s.index << "." << s.generation << ", " << v
                 << ")";
            world.set_tangent_speed(s, v);
            break;
        }
        default: {
            if (bodies.empty())
                break;
            const BodyId b = bodies[u.below(bodies.size())];
            Material m{.friction = u.between(0.0, 1.0)};
            m.rolling_resistance = value(0.0, 1.0);
            m.tangent_speed = value(-5.0, 5.0);
            last << "create_shape(" << str(b) << ", circle, surface: " << m.rolling_resistance
                 << ", " << m.tangent_speed << ")";
            shapes.push_back(world.create_shape(b, circle_shape(u.between(0.1, 1.0), m)));
            break;
        }
        }
    }
    void recording_block() {
        if (!recording_stream.chance(2))
            return;
        try {
            World copy = World::from_snapshot(world.snapshot());
            Recorder rec(copy);
            const std::vector<BodyId> ids = copy.bodies();
            for (int k = 0; k < 4; ++k) {
                const std::uint64_t hash = copy.state_hash();
                const std::vector<std::byte> before = rec.bytes();
                try {
                    if (!ids.empty() && recording_stream.chance(40)) {
                        const BodyId b = ids[recording_stream.below(ids.size())];
                        const Vec2d j{recording_stream.chance(80) ? recording_stream.between(-2, 2)
                                                                  : any_double(recording_stream),
                                      recording_stream.between(-2, 2)};
                        rec.apply_impulse(b, j, copy.origin(b));
                    } else {
                        rec.step(recording_stream.chance(90) ? 1.0 / 60.0
                                                             : any_double(recording_stream));
                    }
                } catch (const std::exception& e) {
                    if (copy.state_hash() != hash || rec.bytes() != before)
                        BOOST_ERROR("recording (before " << last.str() << "): a refused call ("
                                                         << e.what()
                                                         << ") changed the copy or its recording");
                }
            }
            const ReplayReport report = replay(rec.bytes());
            if (!report.matched())
                BOOST_ERROR("recording (before "
                            << last.str() << "): replay departs: " << report.divergence->message);
        } catch (const std::exception& e) {
            BOOST_ERROR("recording (before " << last.str() << "): " << e.what());
        }
    }

    /// One random call; throws what the library throws.
    void call() {
        recording_block();
        query_block();
        last.str("");
        last.precision(17);
        if (events_call())
            return;
        if (area46.chance(10)) {
            draw_profile_explode();
            return;
        }
        if (control_call())
            return;
        if (character.chance(8)) {
            character_call();
            return;
        }
        if (body_world.chance(15)) {
            body_world_call();
            return;
        }
        if (hooks.chance(6)) {
            contact_hooks_call();
            return;
        }
        if (definitions_stream.chance(6)) {
            definitions_call();
            return;
        }
        if (surface_stream.chance(5)) {
            surface_call();
            return;
        }
        switch (r.below(24)) {
        case 0:
        case 1: {
            const BodyDef def = body_def();
            last << "create_body(type " << static_cast<int>(def.type) << ", position "
                 << str(def.position) << ", angle " << def.angle << ", velocity "
                 << str(def.linear_velocity) << ", omega " << def.angular_velocity << ", force "
                 << str(def.force) << ", mass " << def.mass.value_or(-1) << ", inertia "
                 << def.inertia.value_or(-1) << ", gravity_scale " << def.gravity_scale
                 << ", damping " << def.linear_damping << ")";
            bodies.push_back(world.create_body(def));
            break;
        }
        case 2:
        case 3: {
            const BodyId b = body();
            hand_made_polygon = false;
            const ShapeDef def = shape_def();
            last << "create_shape(" << str(b) << ", geometry kind "
                 << static_cast<int>(def.geometry.type) << ", radius " << def.geometry.circle.radius
                 << ", capsule " << str(def.geometry.capsule.center1) << " "
                 << str(def.geometry.capsule.center2) << " " << def.geometry.capsule.radius
                 << ", segment " << str(def.geometry.segment.point1) << " "
                 << str(def.geometry.segment.point2) << ", chain segment "
                 << str(def.geometry.chain_segment.point1) << " "
                 << str(def.geometry.chain_segment.point2) << ", vertices "
                 << def.geometry.polygon.count << ", density " << def.material.density << ")";
            shapes.push_back(world.create_shape(b, def));
            if (std::exchange(hand_made_polygon, false)) {
                ++hand_polygons_accepted;
                shape_problem = polygon_problem(def.geometry.polygon);
            }
            break;
        }
        case 4: {
            const BodyId b = body();
            last << "destroy_body(" << str(b) << ")";
            world.destroy_body(b);
            break;
        }
        case 5:
            last << "destroy_shape";
            world.destroy_shape(shape());
            break;
        case 6: {
            const BodyId b = body();
            const Vec2d v = vec();
            last << "set_velocity(" << str(b) << ", " << str(v) << ")";
            world.set_velocity(b, v);
            break;
        }
        case 7: {
            const BodyId b = body();
            const Vec2d p = vec();
            const double a = any_double(r);
            last << "set_transform(" << str(b) << ", " << str(p) << ", " << a << ")";
            world.set_transform(b, p, a);
            break;
        }
        case 8: {
            const BodyId b = body();
            const double w = any_double(r);
            last << "set_angular_velocity(" << str(b) << ", " << w << ")";
            world.set_angular_velocity(b, w);
            break;
        }
        case 9: {
            const BodyId b = body();
            const double l = any_double(r), a = any_double(r);
            last << "set_damping(" << str(b) << ", " << l << ", " << a << ")";
            world.set_damping(b, l, a);
            break;
        }
        case 10: {
            const BodyId b = body();
            const Vec2d f = vec();
            last << "set_force(" << str(b) << ", " << str(f) << ")";
            world.set_force(b, f);
            break;
        }
        case 11: {
            const BodyId b = body();
            const Vec2d f = vec(), p = vec();
            last << "apply_force(" << str(b) << ", " << str(f) << ", " << str(p) << ")";
            world.apply_force(b, f, p);
            break;
        }
        case 12: {
            const BodyId b = body();
            const Vec2d j = vec(), p = vec();
            last << "apply_impulse(" << str(b) << ", " << str(j) << ", " << str(p) << ")";
            world.apply_impulse(b, j, p);
            break;
        }
        case 13: {
            const BodyId b = body();
            const double t = any_double(r);
            last << "apply_torque(" << str(b) << ", " << t << ")";
            world.apply_torque(b, t);
            break;
        }
        case 14: {
            const Vec2d g = vec();
            last << "set_gravity(" << str(g) << ")";
            world.set_gravity(g);
            break;
        }
        case 15: {
            RevoluteJointDef d;
            d.body_a = body();
            d.body_b = body();
            d.anchor = r.chance(80) ? Vec2d{r.between(-5, 5), r.between(0, 10)} : vec();
            if (r.chance(20))
                d.break_force = any_double(r);
            last << "create_joint(revolute " << str(d.body_a) << ", " << str(d.body_b)
                 << ", anchor " << str(d.anchor) << ", break_force " << d.break_force << ")";
            joints.push_back(world.create_joint(d));
            break;
        }
        case 16: {
            DistanceJointDef d;
            d.body_a = body();
            d.body_b = body();
            d.anchor_a = r.chance(80) ? Vec2d{r.between(-5, 5), r.between(0, 10)} : vec();
            d.anchor_b = r.chance(80) ? Vec2d{r.between(-5, 5), r.between(0, 10)} : vec();
            if (r.chance(30))
                d.length = any_double(r);
            last << "create_joint(distance " << str(d.body_a) << ", " << str(d.body_b) << ", "
                 << str(d.anchor_a) << ", " << str(d.anchor_b) << ", length "
                 << d.length.value_or(-1) << ")";
            joints.push_back(world.create_joint(d));
            break;
        }
        case 17:
            last << "destroy_joint";
            world.destroy_joint(joint());
            break;
        case 18: {
            const BodyId b = body();
            const bool awake = r.chance(50);
            last << "set_awake(" << str(b) << ", " << awake << ")";
            world.set_awake(b, awake);
            break;
        }
        case 19: { // queries are const: they may refuse, never change the world
            last << "query_aabb, query_point";
            (void)world.query_aabb(
                Aabb{any_double(r), any_double(r), any_double(r), any_double(r)});
            (void)world.query_point(vec());
            break;
        }
        // --- snapshot ---
        case 22:
        case 23: {
            // The world's snapshot restored into it changes no bit; with one bit flipped (or cut
            // short) it is refused with a SnapshotError and changes nothing. A broken promise
            // is thrown as a logic_error (the driver reports an exception of another kind).
            const std::uint64_t hash = world.state_hash();
            std::vector<std::byte> bytes = world.snapshot();
            const bool cut = r.chance(30);
            const std::size_t at = r.below(bytes.size());
            last << "restore(snapshot " << (cut ? "cut to " : "with a bit flipped at byte ") << at
                 << " of " << bytes.size() << ", then the snapshot itself)";
            std::vector<std::byte> bad = bytes;
            if (cut)
                bad.resize(at);
            else
                bad[at] ^= std::byte(1u << r.below(8));
            try {
                world.restore(bad);
                throw std::logic_error("a corrupted snapshot was accepted");
            } catch (const SnapshotError& e) {
                if (e.field.empty() || world.state_hash() != hash)
                    throw std::logic_error(std::string("a refused restore changed the world or "
                                                       "named no field: ") +
                                           e.what());
            }
            world.restore(bytes);
            if (world.state_hash() != hash || world.snapshot() != bytes)
                throw std::logic_error("restoring the world's own snapshot changed it");
            break;
        }
        default: {
            const double h = dt();
            last << "step(" << h << ")";
            world.step(h);
            break;
        }
        }
    }
};

std::string check_after_accepted(Driver& d) {
    if (std::string bad = std::exchange(d.shape_problem, {}); !bad.empty())
        return bad;
    if (std::string bad = non_finite_state(d.world); !bad.empty())
        return "non-finite state: " + bad;
    const Vec2d origin = d.r.chance(70) ? Vec2d{d.r.between(-30, 30), 30.0} : d.vec();
    const Vec2d translation = d.r.chance(70) ? Vec2d{d.r.between(-5, 5), -60.0} : d.vec();
    try {
        return bad_ray_cast(d.world, origin, translation);
    } catch (const ValidationError& e) {
        if (e.field.empty())
            return std::string("ray_cast: ValidationError without a field: ") + e.what();
        return {}; // a NaN or out-of-range ray is refused: allowed
    }
}

struct Tally {
    long accepted = 0, rejected = 0;
    long hand_polygons = 0, hand_polygons_accepted = 0; ///< hand_made's polygons
};

void run_sequence(std::uint64_t seed, Tally& tally) {
    Driver d(seed);
    const bool trace = std::getenv("TAMIAS_FUZZ_TRACE") != nullptr;
    for (int c = 0; c < calls_per_sequence; ++c) {
        const std::uint64_t before = d.world.state_hash();
        const std::vector<double> states_before = body_states(d.world, d.joints);
        std::string problem;
        bool refused = true;
        bool diverged = false; // SolverDivergence: its own promise (errors.hpp)
        std::string why;       // the refusal's message, for the trace
        try {
            d.call();
            refused = false;
        } catch (const SolverDivergence& e) {
            why = e.what();
            diverged = true;
            if (e.field.empty() || why.empty())
                problem = "SolverDivergence with an empty field or message";
        } catch (const ValidationError& e) {
            why = e.what();
            if (e.field.empty() || std::string(e.what()).empty())
                problem = "ValidationError with an empty field or message";
        } catch (const InvalidHandle& e) {
            why = e.what();
            if (why.empty())
                problem = "InvalidHandle with an empty message";
        } catch (const WrongKind& e) { // a load on a body no load moves: refused
            why = e.what();
            if (e.subject.empty() || why.empty())
                problem = "WrongKind with an empty subject or message";
        } catch (const std::exception& e) {
            problem = std::string("an exception of another kind: ") + e.what();
        }
        if (refused) {
            ++tally.rejected;
            if (problem.empty() && diverged && body_states(d.world, d.joints) != states_before)
                problem = "a diverged step changed the bodies or the joints";
            if (problem.empty() && !diverged && d.world.state_hash() != before)
                problem = "a rejected call changed the world";
        } else {
            ++tally.accepted;
            problem = check_after_accepted(d);
        }
        if (trace)
            BOOST_TEST_MESSAGE("call " << c << ": " << d.last.str()
                                       << (refused ? " refused: " + why : std::string()));
        if (!problem.empty()) {
            BOOST_ERROR("seed " << seed << ", call " << c << " " << d.last.str() << ": "
                                << problem);
            break;
        }
    }
    tally.hand_polygons += d.hand_polygons;
    tally.hand_polygons_accepted += d.hand_polygons_accepted;
}

} // namespace

BOOST_AUTO_TEST_SUITE(fuzz)

// Oracle: R4's promise as the user guide states it (this file's head): a call outside the data
// constraints is refused with a named error and leaves state_hash() unchanged; an accepted one
// leaves every state finite.
BOOST_AUTO_TEST_CASE(random_api_sequences_keep_the_promises, *utf::label("R4")) {
    const long n = iterations("TAMIAS_FUZZ_API_ITERATIONS", default_iterations);
    const std::uint64_t first = base_seed(20261000);
    BOOST_TEST_MESSAGE("API fuzz: " << n << " sequences of " << calls_per_sequence
                                    << " calls, seeds " << first << ".." << first + n - 1
                                    << " (TAMIAS_FUZZ_API_ITERATIONS, TAMIAS_FUZZ_SEED)");
    Tally tally;
    for (long i = 0; i < n; ++i) {
        const std::uint64_t seed = first + static_cast<std::uint64_t>(i);
        BOOST_TEST_CHECKPOINT("API fuzz seed " << seed);
        run_sequence(seed, tally);
    }
    BOOST_TEST_MESSAGE("API fuzz: " << tally.accepted << " calls accepted, " << tally.rejected
                                    << " rejected");
    BOOST_TEST_MESSAGE("API fuzz: " << tally.hand_polygons << " hand-made polygons, "
                                    << tally.hand_polygons_accepted << " accepted");
    // Both paths must be exercised, or the driver proves little.
    BOOST_TEST(tally.accepted > n * calls_per_sequence / 5);
    BOOST_TEST(tally.rejected > n);
    BOOST_TEST(tally.hand_polygons_accepted > 0);
    BOOST_TEST(tally.hand_polygons_accepted < tally.hand_polygons);
}

BOOST_AUTO_TEST_SUITE_END()
