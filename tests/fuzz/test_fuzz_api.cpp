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
#include <cmath>
#include <cstdlib>
#include <functional>
#include <iterator>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "fuzz/fuzz_support.hpp"
#include "tamias2d/errors.hpp"
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
    /// The run-time control and identity calls (control_call), from a fourth stream for the
    /// same reason.
    Rng control;
    /// What the oracle of an accepted hand-made polygon found wrong (empty: nothing).
    std::string shape_problem;
    World world;
    std::vector<BodyId> bodies;  // every body created, destroyed ones kept (stale handles)
    std::vector<ShapeId> shapes; // likewise
    std::vector<JointId> joints; // likewise
    long accepted = 0, rejected = 0;
    explicit Driver(std::uint64_t seed)
        : r(seed), kinds(seed ^ 0x9e3779b97f4a7c15u), hand(seed ^ 0xc2b2ae3d27d4eb4fu),
          control(seed ^ 0x165667b19e3779f9u), world(make_def(r)) {}

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
                          static_cast<std::uint32_t>(r.below(3))}; // forged
        return bodies[r.below(bodies.size())];
    }
    ShapeId shape() {
        if (shapes.empty() || r.chance(5))
            return ShapeId{static_cast<std::uint32_t>(r.below(8)), 0};
        return shapes[r.below(shapes.size())];
    }
    JointId joint() {
        if (joints.empty() || r.chance(5))
            return JointId{static_cast<std::uint32_t>(r.below(4)), 0};
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

    // --- body_control, world_settings, identity: their calls, drawn from `control` ---
    BodyId control_body() {
        if (bodies.empty() || control.chance(5))
            return BodyId{static_cast<std::uint32_t>(control.below(8)),
                          static_cast<std::uint32_t>(control.below(3))};
        return bodies[control.below(bodies.size())];
    }
    ShapeId control_shape() {
        if (shapes.empty() || control.chance(5))
            return ShapeId{static_cast<std::uint32_t>(control.below(8)), 0};
        return shapes[control.below(shapes.size())];
    }
    JointId control_joint() {
        if (joints.empty() || control.chance(5))
            return JointId{static_cast<std::uint32_t>(control.below(4)), 0};
        return joints[control.below(joints.size())];
    }
    double control_value(double lo, double hi) {
        return control.chance(75) ? control.between(lo, hi) : any_double(control);
    }
    void control_call() {
        const BodyId b = control_body();
        switch (control.below(14)) {
        case 0: {
            const auto type = static_cast<BodyType>(control.below(4)); // 3: out of the enum
            last << "set_body_type(" << str(b) << ", " << static_cast<int>(type) << ")";
            world.set_body_type(b, type);
            break;
        }
        case 1: {
            const bool on = control.chance(60);
            last << "set_enabled(" << str(b) << ", " << on << ")";
            world.set_enabled(b, on);
            break;
        }
        case 2: {
            const double scale = control_value(-2.0, 2.0);
            last << "set_gravity_scale(" << str(b) << ", " << scale << ")";
            world.set_gravity_scale(b, scale);
            break;
        }
        case 3: {
            const bool on = control.chance(50);
            last << "set_bullet(" << str(b) << ", " << on << ")";
            world.set_bullet(b, on);
            break;
        }
        case 4: {
            const MotionLocks locks{control.chance(30), control.chance(30), control.chance(30)};
            last << "set_motion_locks(" << str(b) << ", " << locks.linear_x << locks.linear_y
                 << locks.angular << ")";
            world.set_motion_locks(b, locks);
            break;
        }
        case 5: {
            const double inertia = control_value(0.01, 10.0);
            const Vec2d center{control_value(-1.0, 1.0), control_value(-1.0, 1.0)};
            const double mass = control_value(0.01, 10.0);
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
            const double speed = control_value(0.0, 2.0);
            last << "set_sleep_threshold(" << str(b) << ", " << speed << ")";
            world.set_sleep_threshold(b, speed);
            break;
        }
        case 8:
            last << "wake_touching(" << str(b) << ")";
            world.wake_touching(b);
            break;
        case 9: {
            const auto data = static_cast<UserData>(control.bits());
            const ShapeId s = control_shape();
            const JointId j = control_joint();
            last << "set_user_data(" << str(b) << ", shape#" << s.index << ", joint#" << j.index
                 << ")";
            world.set_user_data(data);
            world.set_user_data(b, data);
            world.set_user_data(s, data);
            world.set_user_data(j, data);
            break;
        }
        case 10: { // the identity readings are const: they may refuse, never change the world
            const ShapeId s = control_shape();
            const JointId j = control_joint();
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
            const double speed = control.chance(20) ? inf : control_value(0.1, 50.0);
            last << "set_maximum_linear_speed(" << speed << ")";
            world.set_maximum_linear_speed(speed);
            break;
        }
        case 12: {
            const double push = control_value(0.1, 5.0), zeta = control_value(0.1, 20.0);
            const double hertz = control_value(1.0, 60.0);
            last << "set_contact_tuning(" << hertz << ", " << zeta << ", " << push << ")";
            world.set_contact_tuning(hertz, zeta, push);
            break;
        }
        default: // one setting per call, so that a refusal is the whole call's
            switch (control.below(4)) {
            case 0: {
                const int workers =
                    control.chance(90) ? 1 + int(control.below(4)) : int(control.below(400)) - 100;
                last << "set_workers(" << workers << ")";
                world.set_workers(workers);
                break;
            }
            case 1: {
                const bool on = control.chance(50);
                last << "set_sleeping(" << on << ")";
                world.set_sleeping(on);
                break;
            }
            case 2: {
                const bool on = control.chance(80);
                last << "set_continuous(" << on << ")";
                world.set_continuous(on);
                break;
            }
            default: {
                const double threshold = control_value(0.0, 2.0);
                last << "set_restitution_threshold(" << threshold << ")";
                world.set_restitution_threshold(threshold);
                break;
            }
            }
            break;
        }
    }

    /// One random call; throws what the library throws.
    void call() {
        last.str("");
        last.precision(17);
        if (control.chance(15)) {
            control_call();
            return;
        }
        switch (r.below(22)) {
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
