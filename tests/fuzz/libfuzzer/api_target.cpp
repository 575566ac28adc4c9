// libFuzzer target: the input bytes drive a sequence of World calls (bodies of every type,
// circles, boxes, polygons, capsules, segments and chains, every joint kind but the target,
// velocities, transforms, damping, forces, torques, impulses, gravity, filters, sleep, motors,
// queries, ray casts and steps, and the run-time control of bodies, shapes, joints and the
// world's settings, user data, event readings and filtered queries) whose arguments are any doubles
// (NaN, infinities, denormals, 1e308, any bit pattern), and whose handles are live, destroyed,
// stale, forged, null or a second world's.
//
// Oracle: the library's stated promises (docs/user-guide.md, "Errors" and "Handles"): no crash
// and no sanitizer report; a refusal is a ValidationError (non-empty field and message), an
// InvalidHandle (non-empty message) or a WrongKind (non-empty subject and message) and leaves
// World::state_hash() unchanged; after every accepted call every body state, energy and
// momentum is finite, and a ray cast's result is well formed. No finding is excused
// (docs/verification.md, "Findings (fixed)").
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <span>
#include <string>
#include <vector>

#include "fuzz/fuzz_support.hpp"
#include "fuzz/libfuzzer/byte_source.hpp"
#include "fuzz/libfuzzer/promise.hpp"
#include "tamias2d/errors.hpp"
#include "tamias2d/tamias2d.hpp"
#include "tamias2d/world.hpp"

using namespace tamias2d;
using namespace tamias2d::fuzz;

namespace {

// Bounds that keep one input fast (a few milliseconds under the sanitizers).
constexpr int max_calls = 256;
constexpr int max_steps = 48;
constexpr std::size_t max_bodies = 48;
constexpr std::size_t max_chain_points = 12;

/// The world under test, a foreign world whose handles it must refuse (WrongWorld, an
/// InvalidHandle), and every handle made (destroyed ones kept).
struct Session {
    ByteSource& in;
    World world;
    World foreign;
    std::vector<BodyId> bodies, foreign_bodies;
    std::vector<ShapeId> shapes, foreign_shapes;
    std::vector<JointId> joints;
    int steps = 0;
    int op = -1; ///< the last call's number in call()'s switch, for the trace

    Session(ByteSource& source, const WorldDef& def) : in(source), world(def), foreign(def) {
        for (int i = 0; i < 2; ++i) {
            const BodyId b = foreign.create_body(BodyDef{});
            foreign_bodies.push_back(b);
            foreign_shapes.push_back(foreign.create_shape(b, circle_shape(0.5)));
        }
    }

    template <class Id> Id forged() {
        Id id;
        id.index = in.flag() ? in.byte() % 8u : null_index - in.byte() % 2u;
        id.generation = in.byte() % 4u;
        id.world = world.tag(); // forged for this world: the slot and generation checks decide
        return id;
    }

    template <class Id> Id pick(const std::vector<Id>& mine, const std::vector<Id>& theirs) {
        const std::uint8_t how = in.byte();
        if (how < 200 && !mine.empty())
            return mine[in.below(mine.size())];
        if (how < 225 && !theirs.empty())
            return theirs[in.below(theirs.size())];
        if (how < 250)
            return forged<Id>();
        return Id{};
    }
    BodyId body() { return pick(bodies, foreign_bodies); }
    ShapeId shape() { return pick(shapes, foreign_shapes); }
    JointId joint() { return pick(joints, std::vector<JointId>{}); }

    double dt() {
        const std::uint8_t how = in.byte();
        if (how < 160)
            return 1.0 / 60.0;
        if (how < 200)
            return 1.0 / static_cast<double>(1 + in.byte());
        return in.real();
    }

    Material material() {
        Material m;
        m.density = in.flag() ? 1.0 : in.real();
        m.restitution = in.flag() ? 0.2 : in.real();
        m.friction = in.flag() ? 0.6 : in.real();
        return m;
    }

    BodyDef body_def() {
        BodyDef d;
        const std::uint8_t t = in.byte();
        d.type =
            t < 200 ? BodyType::dynamic : (t < 230 ? BodyType::static_body : BodyType::kinematic);
        d.position = in.point();
        d.angle = in.flag() ? 0.0 : in.real();
        const std::uint8_t extras = in.byte(); // one bit per optional setting
        if (extras & 0x01u)
            d.linear_velocity = in.vec();
        if (extras & 0x02u)
            d.angular_velocity = in.real();
        if (extras & 0x04u)
            d.force = in.vec();
        if (extras & 0x08u)
            d.mass = in.real();
        if (extras & 0x10u)
            d.inertia = in.real();
        if (extras & 0x20u)
            d.gravity_scale = in.real();
        if (extras & 0x40u) {
            d.linear_damping = in.real();
            d.angular_damping = in.real();
        }
        if (extras & 0x80u) {
            d.torque = in.real();
            d.fixed_rotation = in.flag();
            d.bullet = in.flag();
            d.awake = in.flag();
            // The run-time controls' fields (BodyDef::enabled, motion_locks, sleep_threshold).
            d.enabled = !in.flag();
            d.motion_locks = {in.flag(), in.flag(), in.flag()};
            if (in.flag())
                d.sleep_threshold = in.real();
        }
        return d;
    }

    std::vector<Vec2d> points(std::size_t most) {
        std::vector<Vec2d> pts(in.below(most + 1));
        for (Vec2d& p : pts)
            p = in.point();
        return pts;
    }

    /// One shape definition of each kind; chains are made by make_chain.
    ShapeDef shape_def() {
        switch (in.below(5)) {
        case 0: {
            const double r = in.size();
            const Material m = material();
            return circle_shape(r, m, in.flag() ? Vec2d{} : in.point());
        }
        case 1: {
            const double w = in.size();
            const double h = in.size();
            const Material m = material();
            const Vec2d c = in.flag() ? Vec2d{} : in.point();
            return box_shape(w, h, m, c, in.flag() ? 0.0 : in.real());
        }
        case 2: {
            const std::vector<Vec2d> pts = points(max_polygon_vertices + 2);
            return polygon_shape(pts, material());
        }
        case 3: {
            const Vec2d a = in.point();
            const Vec2d b = in.point();
            const double r = in.size();
            return capsule_shape(a, b, r, material());
        }
        default: {
            const Vec2d a = in.point();
            const Vec2d b = in.point();
            return segment_shape(a, b, material());
        }
        }
    }

    void make_joint() {
        const BodyId a = body();
        const BodyId b = in.below(8) == 0 ? a : body();
        switch (in.below(7)) {
        case 0: {
            RevoluteJointDef d;
            d.body_a = a;
            d.body_b = b;
            d.anchor = in.point();
            const std::uint8_t extras = in.byte();
            if (extras & 0x01u)
                d.break_force = in.real();
            if (extras & 0x02u) {
                d.enable_limit = true;
                d.lower_angle = in.real();
                d.upper_angle = in.real();
            }
            if (extras & 0x04u) {
                d.enable_motor = true;
                d.motor_speed = in.real();
                d.max_motor_torque = in.real();
            }
            if (extras & 0x08u) {
                d.enable_spring = true;
                d.hertz = in.real();
                d.damping_ratio = in.real();
            }
            d.collide_connected = (extras & 0x10u) != 0;
            joints.push_back(world.create_joint(d));
            break;
        }
        case 1: {
            DistanceJointDef d;
            d.body_a = a;
            d.body_b = b;
            d.anchor_a = in.point();
            d.anchor_b = in.point();
            const std::uint8_t extras = in.byte();
            if (extras & 0x01u)
                d.length = in.real();
            if (extras & 0x02u) {
                d.hertz = in.real();
                d.damping_ratio = in.real();
            }
            if (extras & 0x04u) {
                d.enable_limit = true;
                d.min_length = in.real();
                d.max_length = in.real();
            }
            if (extras & 0x08u)
                d.break_force = in.real();
            joints.push_back(world.create_joint(d));
            break;
        }
        case 2: {
            PrismaticJointDef d;
            d.body_a = a;
            d.body_b = b;
            d.anchor = in.point();
            d.axis = in.flag() ? Vec2d{1.0, 0.0} : in.vec();
            const std::uint8_t extras = in.byte();
            if (extras & 0x01u) {
                d.enable_limit = true;
                d.lower_translation = in.real();
                d.upper_translation = in.real();
            }
            if (extras & 0x02u) {
                d.enable_motor = true;
                d.motor_speed = in.real();
                d.max_motor_force = in.real();
            }
            if (extras & 0x04u) {
                d.enable_spring = true;
                d.hertz = in.real();
                d.damping_ratio = in.real();
            }
            joints.push_back(world.create_joint(d));
            break;
        }
        case 3: {
            WeldJointDef d;
            d.body_a = a;
            d.body_b = b;
            d.anchor = in.point();
            if (in.flag()) {
                d.linear_hertz = in.real();
                d.linear_damping_ratio = in.real();
                d.angular_hertz = in.real();
                d.angular_damping_ratio = in.real();
            }
            joints.push_back(world.create_joint(d));
            break;
        }
        case 4: {
            WheelJointDef d;
            d.body_a = a;
            d.body_b = b;
            d.anchor = in.point();
            d.axis = in.flag() ? Vec2d{0.0, 1.0} : in.vec();
            const std::uint8_t extras = in.byte();
            if (extras & 0x01u) {
                d.hertz = in.real();
                d.damping_ratio = in.real();
            }
            if (extras & 0x02u) {
                d.enable_limit = true;
                d.lower_translation = in.real();
                d.upper_translation = in.real();
            }
            if (extras & 0x04u) {
                d.enable_motor = true;
                d.motor_speed = in.real();
                d.max_motor_torque = in.real();
            }
            joints.push_back(world.create_joint(d));
            break;
        }
        case 5: {
            MotorJointDef d;
            d.body_a = a;
            d.body_b = b;
            d.linear_offset = in.flag() ? Vec2d{} : in.vec();
            d.angular_offset = in.flag() ? 0.0 : in.real();
            if (in.flag()) {
                d.max_force = in.real();
                d.max_torque = in.real();
                d.correction_factor = in.real();
            }
            joints.push_back(world.create_joint(d));
            break;
        }
        default:
            joints.push_back(world.create_joint(FilterJointDef{.body_a = a, .body_b = b}));
            break;
        }
    }

    void make_chain() {
        const BodyId b = body();
        const std::vector<Vec2d> pts = points(max_chain_points);
        const bool loop = in.flag();
        const std::vector<ShapeDef> segments = chain_shapes(pts, loop, material());
        for (const ShapeId s : world.create_chain(b, segments))
            shapes.push_back(s);
    }

    void query() {
        switch (in.below(3)) {
        case 0: {
            const Aabb box{in.real(), in.real(), in.real(), in.real()};
            (void)world.query_aabb(box);
            break;
        }
        case 1:
            (void)world.query_point(in.vec());
            break;
        default: {
            const Vec2d origin = in.point();
            const Vec2d translation = in.flag() ? Vec2d{in.real(), in.real()} : in.point();
            if (const std::string bad = bad_ray_cast(world, origin, translation); !bad.empty())
                broken_promise(bad);
        }
        }
    }

    void read_joint() {
        const JointId j = joint();
        (void)world.joint_reaction_force(j);
        (void)world.joint_reaction_torque(j);
        (void)world.joint_angle(j);
        (void)world.joint_translation(j);
    }

    // --- run-time control ---
    // The calls that change a body, shape, joint or the world's settings after creation, read
    // events and run the filtered queries: each with any double, handle or flag.
    Vec2d any_point() { return in.flag() ? in.point() : in.vec(); }

    void body_control() {
        const BodyId b = body();
        switch (in.below(12)) {
        case 0:
            world.set_body_type(b, static_cast<BodyType>(in.byte() % 4u)); // 3: out of range
            break;
        case 1:
            world.set_enabled(b, in.flag());
            break;
        case 2:
            world.set_gravity_scale(b, in.real());
            break;
        case 3:
            world.set_bullet(b, in.flag());
            break;
        case 4:
            world.set_motion_locks(b, MotionLocks{in.flag(), in.flag(), in.flag()});
            break;
        case 5: {
            const double m = in.real();
            const Vec2d c = any_point();
            world.set_mass_data(b, BodyMassData{m, c, in.real()});
            break;
        }
        case 6:
            world.reset_mass_data(b);
            break;
        case 7:
            world.set_sleep_threshold(b, in.real());
            break;
        case 8:
            world.wake_touching(b);
            break;
        case 9:
            world.set_move_events_enabled(b, in.flag());
            break;
        case 10:
            world.set_user_data(b, static_cast<UserData>(in.word()));
            break;
        default:
            (void)world.body_aabb(b);
            (void)world.joints(b);
            (void)world.contacts(b);
            (void)world.mass_data(b);
            break;
        }
    }

    void shape_control() {
        const ShapeId s = shape();
        switch (in.below(12)) {
        case 0:
            world.set_friction(s, in.real());
            break;
        case 1:
            world.set_restitution(s, in.real());
            break;
        case 2:
            world.set_density(s, in.real(), in.flag());
            break;
        case 3: {
            const Vec2d c = any_point();
            world.set_circle(s, Circle{c, in.size()});
            break;
        }
        case 4: {
            const Vec2d a = any_point();
            const Vec2d b = any_point();
            world.set_capsule(s, Capsule{a, b, in.size()});
            break;
        }
        case 5: {
            const std::vector<Vec2d> pts = points(max_polygon_vertices);
            world.set_polygon(s, polygon_shape(pts).geometry.polygon);
            break;
        }
        case 6: {
            const Vec2d a = any_point();
            world.set_segment(s, Segment{a, any_point()});
            break;
        }
        case 7:
            world.set_sensor(s, in.flag());
            break;
        case 8:
            world.set_hit_events_enabled(s, in.flag());
            break;
        case 9:
            world.set_contact_events_enabled(s, in.flag());
            break;
        case 10:
            world.set_sensor_events_enabled(s, in.flag());
            break;
        default:
            (void)world.body(s);
            (void)world.shape_aabb(s);
            (void)world.geometry(s);
            (void)world.sensor_overlaps(s); // WrongKind for a solid shape
            break;
        }
    }

    void joint_control() {
        const JointId j = joint();
        switch (in.below(16)) {
        case 0:
            world.enable_joint_limit(j, in.flag());
            break;
        case 1: {
            const double lower = in.real();
            world.set_joint_limits(j, lower, in.real());
            break;
        }
        case 2:
            world.enable_joint_motor(j, in.flag());
            break;
        case 3:
            world.set_joint_max_motor_torque(j, in.real());
            break;
        case 4:
            world.set_joint_max_motor_force(j, in.real());
            break;
        case 5:
            world.enable_joint_spring(j, in.flag());
            break;
        case 6: {
            const double hertz = in.real();
            world.set_joint_spring(j, hertz, in.real());
            break;
        }
        case 7:
            world.set_joint_spring_target(j, in.real());
            break;
        case 8:
            world.set_distance_joint_length(j, in.real());
            break;
        case 9: {
            const double hertz = in.real();
            world.set_constraint_tuning(j, hertz, in.real());
            break;
        }
        case 10:
            world.set_joint_collide_connected(j, in.flag());
            break;
        case 11:
            world.set_joint_break_force(j, in.real());
            break;
        case 12:
            world.set_joint_break_torque(j, in.real());
            break;
        case 13: {
            const double force = in.real();
            world.set_joint_event_thresholds(j, force, in.real());
            break;
        }
        case 14:
            world.set_joint_target(j, any_point());
            break;
        default:
            (void)world.joint_kind(j);
            (void)world.joint_body_a(j);
            (void)world.joint_limits(j);
            (void)world.constraint_tuning(j);
            break;
        }
    }

    void settings_control() {
        switch (in.below(10)) {
        case 0:
            world.set_continuous(in.flag());
            break;
        case 1:
            world.set_sleeping(in.flag());
            break;
        case 2: {
            const double hertz = in.real();
            const double ratio = in.real();
            world.set_contact_tuning(hertz, ratio, in.real());
            break;
        }
        case 3: {
            const double hertz = in.real();
            world.set_joint_tuning(hertz, in.real());
            break;
        }
        case 4:
            world.set_restitution_threshold(in.real());
            break;
        case 5:
            world.set_maximum_linear_speed(in.real());
            break;
        case 6:
            world.set_warm_starting(in.flag());
            break;
        case 7:
            world.set_hit_event_threshold(in.real());
            break;
        case 8:
            world.set_user_data(static_cast<UserData>(in.word()));
            break;
        default:
            (void)world.contact_hit_events();
            (void)world.body_move_events();
            (void)world.joint_events();
            (void)world.contacts();
            (void)world.awake_body_count();
            break;
        }
    }

    void filtered_query() {
        QueryFilter f;
        if (in.flag()) {
            f.category_bits = in.word();
            f.mask_bits = in.word();
        }
        const Vec2d o = any_point();
        const Vec2d d = any_point();
        switch (in.below(5)) {
        case 0:
            (void)world.ray_cast_all(o, d, f);
            break;
        case 1:
            (void)world.ray_cast_any(o, d, f);
            break;
        case 2:
            (void)world.overlap_shape(circle_shape(in.size()).geometry, o, in.real(), f);
            break;
        case 3:
            (void)world.shape_cast(box_shape(in.size(), in.size()).geometry, o, in.real(), d, f);
            break;
        default:
            (void)world.closest_point(shape(), o);
            (void)world.distance(shape(), shape());
            break;
        }
    }

    /// One run-time control call (an op above 31).
    void control() {
        switch (in.below(5)) {
        case 0:
            body_control();
            break;
        case 1:
            shape_control();
            break;
        case 2:
            joint_control();
            break;
        case 3:
            settings_control();
            break;
        default:
            filtered_query();
            break;
        }
    }

    /// One call, chosen by the next byte; throws what the library throws. Returns the time
    /// step when the call was a step, else 0.
    double call() {
        op = in.byte() % 44;
        if (op >= 32) { // the run-time control calls
            control();
            return 0.0;
        }
        switch (op) {
        case 0:
        case 1:
        case 2:
            if (bodies.size() < max_bodies)
                bodies.push_back(world.create_body(body_def()));
            return 0.0;
        case 3:
        case 4:
        case 5: {
            const BodyId b = body();
            shapes.push_back(world.create_shape(b, shape_def()));
            return 0.0;
        }
        case 6:
            make_chain();
            return 0.0;
        case 7:
            world.destroy_body(body());
            return 0.0;
        case 8:
            world.destroy_shape(shape());
            return 0.0;
        case 9: {
            const BodyId b = body();
            world.set_velocity(b, in.vec());
            return 0.0;
        }
        case 10: {
            const BodyId b = body();
            const Vec2d p = in.point();
            world.set_transform(b, p, in.real());
            return 0.0;
        }
        case 11: {
            const BodyId b = body();
            world.set_angular_velocity(b, in.real());
            return 0.0;
        }
        case 12: {
            const BodyId b = body();
            const double l = in.real();
            world.set_damping(b, l, in.real());
            return 0.0;
        }
        case 13: {
            const BodyId b = body();
            world.set_force(b, in.vec());
            return 0.0;
        }
        case 14: {
            const BodyId b = body();
            world.set_torque(b, in.real());
            return 0.0;
        }
        case 15: {
            const BodyId b = body();
            const Vec2d f = in.vec();
            world.apply_force(b, f, in.point());
            return 0.0;
        }
        case 16: {
            const BodyId b = body();
            const Vec2d j = in.vec();
            world.apply_impulse(b, j, in.point());
            return 0.0;
        }
        case 17: {
            const BodyId b = body();
            world.apply_torque(b, in.real());
            return 0.0;
        }
        case 18:
            world.set_gravity(in.flag() ? Vec2d{0.0, -10.0} : in.vec());
            return 0.0;
        case 19:
        case 20:
            make_joint();
            return 0.0;
        case 21:
            world.destroy_joint(joint());
            return 0.0;
        case 22: {
            const BodyId b = body();
            world.set_awake(b, in.flag());
            return 0.0;
        }
        case 23: {
            const ShapeId s = shape();
            Filter f;
            f.category_bits = in.word();
            f.mask_bits = in.flag() ? 0xFFFFFFFFu : in.word();
            f.group_index = static_cast<std::int8_t>(in.byte());
            world.set_filter(s, f);
            return 0.0;
        }
        case 24: {
            const JointId j = joint();
            if (in.flag()) {
                world.set_joint_motor_speed(j, in.real());
            } else {
                const Vec2d o = in.vec();
                world.set_motor_joint_offsets(j, o, in.real());
            }
            return 0.0;
        }
        case 25:
            read_joint();
            return 0.0;
        case 26:
        case 27:
            query();
            return 0.0;
        default: {
            if (steps >= max_steps)
                return 0.0;
            ++steps;
            const double h = dt();
            world.step(h);
            return h;
        }
        }
    }
};

WorldDef world_def(ByteSource& in) {
    WorldDef d;
    const std::uint8_t g = in.byte();
    d.gravity = g < 200 ? Vec2d{0.0, -10.0} : Vec2d{0.0, -static_cast<double>(g)};
    d.enable_sleep = in.flag();
    d.enable_continuous = !in.flag() || in.flag();
    return d;
}

/// After a refused call: the refusal is of a documented kind and the world is as it was.
bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

void check_refusal(const std::exception_ptr& error, std::uint64_t before,
                   const std::vector<double>& states_before, const World& w,
                   std::span<const JointId> joints) {
    try {
        std::rethrow_exception(error);
    } catch (const SolverDivergence& e) {
        // Its own promise (errors.hpp): bodies, joints and clock as they were, contacts
        // updated.
        if (e.field.empty() || std::string(e.what()).empty())
            broken_promise("SolverDivergence with an empty field or message");
        if (!same_bits(body_states(w, joints), states_before))
            broken_promise(std::string("a diverged step changed the bodies or the joints: ") +
                           e.what());
        return;
    } catch (const ValidationError& e) {
        if (e.field.empty() || std::string(e.what()).empty())
            broken_promise("ValidationError with an empty field or message: " +
                           std::string(e.what()));
    } catch (const InvalidHandle& e) {
        if (std::string(e.what()).empty())
            broken_promise("InvalidHandle with an empty message");
    } catch (const WrongKind& e) { // a load on a body no load moves, a joint of another kind
        if (e.subject.empty() || std::string(e.what()).empty())
            broken_promise("WrongKind with an empty subject or message");
    } catch (const std::exception& e) {
        broken_promise(std::string("a refusal of another kind: ") + e.what());
    } catch (...) {
        broken_promise("a refusal that is no std::exception");
    }
    if (w.state_hash() != before)
        broken_promise("a refused call changed the world");
}

void print_trace(const Session& s, bool refused, double stepped) {
    std::fprintf(stderr, "call %d%s", s.op, refused ? " refused" : "");
    if (stepped != 0.0)
        std::fprintf(stderr, " step(%.17g)", stepped);
    const Vec2d g = s.world.gravity();
    std::fprintf(stderr, ", gravity (%g, %g), joints %zu\n", g.x, g.y, s.world.joint_count());
    for (const BodyId b : s.world.bodies())
        std::fprintf(stderr,
                     "  body %u: type %d mass %.17g inertia %.17g at (%.17g, %.17g) v (%.17g, "
                     "%.17g) w %.17g\n",
                     b.index, static_cast<int>(s.world.type(b)), s.world.mass(b),
                     s.world.inertia(b), s.world.position(b).x, s.world.position(b).y,
                     s.world.velocity(b).x, s.world.velocity(b).y, s.world.angular_velocity(b));
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    // TAMIAS_FUZZ_TRACE=1: each call's number (call()'s switch), outcome and the bodies' states.
    static const bool trace = std::getenv("TAMIAS_FUZZ_TRACE") != nullptr;
    ByteSource in(data, size);
    Session s(in, world_def(in));
    for (int c = 0; c < max_calls && !in.empty(); ++c) {
        const std::uint64_t before = s.world.state_hash();
        const std::vector<double> states_before = body_states(s.world, s.joints);
        const World& w = s.world;
        std::exception_ptr error;
        double stepped = 0.0;
        try {
            stepped = s.call();
        } catch (...) {
            error = std::current_exception();
        }
        if (trace)
            print_trace(s, error != nullptr, stepped);
        if (error) {
            check_refusal(error, before, states_before, w, s.joints);
            continue;
        }
        if (const std::string bad = non_finite_state(w); !bad.empty())
            broken_promise("non-finite state after an accepted call: " + bad);
    }
    return 0;
}
