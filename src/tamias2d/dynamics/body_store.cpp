#include "tamias2d/dynamics/body_store.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "tamias2d/dynamics/bridge/typing.hpp"
#include "tamias2d/dynamics/bridge/velocity_control.hpp"
#include "tamias2d/dynamics/shape_store.hpp"
#include "tamias2d/dynamics/snapshot_io.hpp"
#include "tamias2d/dynamics/state_hasher.hpp"
#include "tamias2d/errors.hpp"
#include "tamias2d/geometry/mass_properties.hpp"
#include "tamias2d/memory/allocator.hpp"
#include "tamias2d/model/dd15_kinetic_energy.hpp"
#include "tamias2d/model/dd16_potential_energy.hpp"
#include "tamias2d/model/gd1_conservation_of_momentum.hpp"
#include "tamias2d/validation.hpp"

namespace tamias2d {

namespace {

/// Calls f on every live dynamic body of the store, in index order (the energies, momentum).
template <class F> void each_dynamic(const BodyStore& store, F f) {
    for (std::uint32_t i = 0; i < store.size(); ++i) {
        if (store.alive(i) && store.bodies[i].type == BodyType::dynamic)
            f(store.bodies[i]);
    }
}

} // namespace

Body& BodyStore::get_for_attach(BodyId id) {
    slots.check(id);
    return bodies[id.index];
}

Body& BodyStore::get(BodyId id) {
    Body& b = get_for_attach(id);
    settle(id.index);
    return b;
}

void BodyStore::attach_shape(std::uint32_t i, ShapeStore& shapes, std::uint32_t s) {
    const Body& b = bodies[i];
    shapes.shapes[s].body_xf = b.xf;
    shapes.shapes[s].body_center = b.center;
    if (b.type != BodyType::dynamic)
        return;
    if (mass_pending_flag_.size() < bodies.size())
        mass_pending_flag_.resize(bodies.size(), false);
    if (!mass_pending_flag_[i]) {
        mass_pending_flag_[i] = true;
        mass_pending_.push_back(i);
    }
    pending_shapes_ = &shapes;
}

void BodyStore::settle(std::uint32_t i) const {
    if (i < mass_pending_flag_.size() && mass_pending_flag_[i])
        const_cast<BodyStore*>(this)->update_mass(i, *pending_shapes_); // clears the flag
}

void BodyStore::settle() const {
    for (const std::uint32_t i : mass_pending_)
        settle(i);
    mass_pending_.clear();
}

/// \srs{R2} A new body starts from the state its input gives: position, orientation,
/// velocities, applied force and torque (a static body never moves, whatever it is given).
std::uint32_t BodyStore::create(const BodyDef& def, bool sleeping) {
    const std::uint32_t i = slots.acquire();
    if (i == bodies.size()) {
        bodies.emplace_back();
        settings.emplace_back();
        sleep_states.emplace_back();
    }
    Body& b = bodies[i];
    b = Body{};
    b.type = def.type;
    b.angle = def.angle;
    b.xf = {def.position, Rot::from_angle(def.angle)};
    b.v = def.type == BodyType::static_body ? Vec2d{} : def.linear_velocity;
    b.w = def.type == BodyType::static_body ? 0.0 : def.angular_velocity;
    b.force = def.force;
    b.torque = def.torque;
    b.loaded = !b.unloaded();
    b.gravity_scale = def.gravity_scale;
    settings[i] = {def.name,           def.load,   def.mass,           def.inertia,
                   def.fixed_rotation, def.bullet, def.linear_damping, def.angular_damping};
    settings[i].user_data = def.user_data;
    // \srs{IM5} A dynamic body with either damping coefficient non-zero moves by IM5.
    b.damped =
        def.type == BodyType::dynamic && (def.linear_damping != 0.0 || def.angular_damping != 0.0);
    const bool movable = def.type != BodyType::static_body;
    sleep_states[i] = {0.0, movable && (def.awake || !sleeping), def.enable_sleep, movable};
    loaded_bodies += def.load ? 1 : 0;
    create_controls(i, def);
    return i;
}

void BodyStore::destroy(std::uint32_t i) {
    Body& b = bodies[i];
    disabled_bodies -= sleep_states[i].disabled ? 1 : 0;
    locked_bodies -= linearly_locked(i) ? 1 : 0;
    b.first_shape = null_index;
    sleep_states[i] = SleepState{}; // neither awake nor movable
    BodySettings& set = settings[i];
    loaded_bodies -= set.load ? 1 : 0;
    set = BodySettings{};
    // No mass pending (its entry in mass_pending_, if any, is then skipped).
    if (i < mass_pending_flag_.size())
        mass_pending_flag_[i] = false;
    slots.release(i);
}

/// \srs{R2} The body's mass and moment of inertia: its shapes' (or the input's, where given;
/// an overridden mass scales the shapes' inertia with it).
void BodyStore::update_mass(std::uint32_t i, ShapeStore& shapes) {
    if (i < mass_pending_flag_.size())
        mass_pending_flag_[i] = false;
    Body& b = bodies[i];
    const BodySettings& set = settings[i];
    ++mass_epoch;
    b.mass = b.inv_mass = b.inertia = b.inv_inertia = 0.0;
    b.local_center = {};
    if (b.type == BodyType::dynamic) {
        std::size_t count = 0;
        for (std::uint32_t s = b.first_shape; s != null_index; s = shapes.shapes[s].next)
            ++count;
        memory::Scratch<MassData, 8> parts(count);
        std::size_t k = 0;
        for (std::uint32_t s = b.first_shape; s != null_index; s = shapes.shapes[s].next) {
            const ShapeDef& d = shapes.defs[s];
            parts[k++] = compute_mass(d.geometry, d.material.density);
        }
        MassData md{};
        if (count != 0)
            md = combine({parts.data(), count});
        b.local_center = set.center_override.value_or(md.center);
        const double shape_mass = md.mass;
        // No shape, or only shapes of no area (segments, chains): the shapeless default.
        b.mass = set.mass_override.value_or(shape_mass > 0.0 ? shape_mass : 1.0);
        // With the mass overridden, keep the shapes' distribution: scale I with the mass.
        double inertia = md.inertia;
        if (set.mass_override && shape_mass > 0.0)
            inertia *= b.mass / shape_mass;
        b.inertia = set.inertia_override.value_or(inertia);
        b.inv_mass = 1.0 / b.mass;
        b.inv_inertia = (set.fixed_rotation || !(b.inertia > 0.0)) ? 0.0 : 1.0 / b.inertia;
    }
    b.center = transform_point(b.xf, b.local_center);
    shapes.sync_poses(b);
}

void BodyStore::evaluate_loads(double time, memory::vector<Load>& loads) const {
    loads.clear();
    if (loaded_bodies > 0)
        loads.assign(size(), Load{});
    for (std::uint32_t i = 0; i < loads.size(); ++i) {
        const Body& b = bodies[i];
        const LoadFunction& load = settings[i].load;
        if (!alive(i) || !load || b.type != BodyType::dynamic)
            continue;
        const Load l = load(time);
        require_within("load(t).force", l.force, supported::input_max, "N");
        require_within("load(t).torque", l.torque, supported::input_max, "N m");
        loads[i] = l;
    }
}

void BodyStore::check_state() const {
    constexpr double m = supported::state_max;
    for (std::uint32_t i = 0; i < size(); ++i) {
        const Body& b = bodies[i];
        if (!alive(i) || b.type == BodyType::static_body)
            continue;
        if (std::abs(b.center.x) <= m && std::abs(b.center.y) <= m && std::abs(b.v.x) <= m &&
            std::abs(b.v.y) <= m && std::abs(b.w) <= m && std::abs(b.angle) <= m)
            continue;
        const std::string at = label(i) + ".";
        require_within(at + "position", b.center, m, "m");
        require_within(at + "velocity", b.v, m, "m s^-1");
        require_within(at + "angular_velocity", b.w, m, "rad s^-1");
        require_within(at + "angle", b.angle, m, "rad");
    }
}

double BodyStore::kinetic_energy() const {
    namespace u = tamias2d::units;
    double e = 0.0;
    each_dynamic(*this, [&](const Body& b) {
        const double inertia = b.inv_inertia > 0.0 ? b.inertia : 0.0;
        e += model::dd15::kinetic_energy(
                 u::from_value<u::Mass>(b.mass), bridge::typed<u::Velocity>(b.v),
                 u::from_value<u::MomentOfInertia>(inertia), u::from_value<u::AngularVelocity>(b.w))
                 .value();
    });
    return e;
}

double BodyStore::potential_energy(Vec2d g) const {
    namespace u = tamias2d::units;
    double e = 0.0;
    each_dynamic(*this, [&](const Body& b) {
        e += model::dd16::potential_energy(u::from_value<u::Mass>(b.mass),
                                           bridge::typed<u::Acceleration>(b.gravity_scale * g),
                                           bridge::typed<u::Length>(b.center))
                 .value();
    });
    return e;
}

Vec2d BodyStore::linear_momentum() const {
    namespace u = tamias2d::units;
    memory::vector<model::gd1::MassVelocity> mv;
    each_dynamic(*this, [&](const Body& b) {
        mv.push_back({u::from_value<u::Mass>(b.mass), bridge::typed<u::Velocity>(b.v)});
    });
    return bridge::plain(model::gd1::total_momentum(mv));
}

std::vector<BodyId> BodyStore::live_ids() const {
    std::vector<BodyId> out;
    for (std::uint32_t i = 0; i < size(); ++i) {
        if (alive(i))
            out.push_back(id(i));
    }
    return out;
}

std::string BodyStore::label(std::uint32_t i) const {
    const std::string& name = settings[i].name;
    return "body[" + std::to_string(i) + (name.empty() ? "" : " '" + name + "'") + "]";
}

bool BodyStore::any_awake() const {
    return std::any_of(sleep_states.begin(), sleep_states.end(),
                       [](const SleepState& st) { return st.awake; });
}

void BodyStore::put_to_sleep(std::uint32_t i) {
    sleep_states[i].awake = false;
    sleep_states[i].sleep_time = 0.0;
    Body& b = bodies[i];
    b.v = {};
    b.w = 0.0;
    b.force_once = {};
    b.torque_once = 0.0;
}

void BodyStore::wake(std::uint32_t i) {
    SleepState& st = sleep_states[i];
    if (!st.movable)
        return;
    st.awake = true;
    st.sleep_time = 0.0;
}

void BodyStore::hash(StateHasher& hs, const ShapeStore& shapes, bool sleeping) const {
    hs(std::uint64_t(size()));
    for (std::uint32_t i = 0; i < size(); ++i) {
        const Body& b = bodies[i];
        const BodySettings& set = settings[i];
        hs(std::uint64_t(slots.generation(i)) << 8 | std::uint64_t(alive(i)) << 4 |
           std::uint64_t(b.type));
        if (!alive(i))
            continue;
        hs(b.xf.p);
        hs(b.xf.q.c);
        hs(b.xf.q.s);
        hs(b.angle);
        hs(b.center);
        hs(b.local_center);
        hs(b.v);
        hs(b.w);
        hs(b.force);
        hs(b.torque);
        hs(b.force_once);
        hs(b.torque_once);
        hs(b.mass);
        hs(b.inertia);
        hs(b.inv_mass);
        hs(b.inv_inertia);
        hs(b.gravity_scale);
        hs(std::uint64_t(set.fixed_rotation) << 1 | std::uint64_t(bool(set.load)));
        if (set.bullet) // (other bodies hash as they always did)
            hs(std::uint64_t(1) << 2);
        // The run-time controls, each only when set (so that other bodies hash as before).
        if (sleep_states[i].disabled)
            hs(std::uint64_t(1) << 3);
        if (set.lock_linear_x || set.lock_linear_y)
            hs(std::uint64_t(set.lock_linear_x) << 4 | std::uint64_t(set.lock_linear_y) << 5);
        if (set.center_override)
            hs(*set.center_override);
        if (set.sleep_threshold)
            hs(*set.sleep_threshold);
        if (b.damped) { // (so that undamped worlds hash as they always did)
            hs(set.linear_damping);
            hs(set.angular_damping);
        }
        if (sleeping) { // (so that worlds without sleeping hash as they always did)
            const SleepState& st = sleep_states[i];
            hs(st.sleep_time);
            hs(std::uint64_t(st.awake) << 1 | std::uint64_t(st.enabled));
        }
        hs.bytes(set.name.data(), set.name.size());
        for (std::uint32_t s = b.first_shape; s != null_index; s = shapes.shapes[s].next)
            hs(std::uint64_t(s));
    }
}

// --- snapshot ---

namespace {

/// Every field of a body slot, in the snapshot's order: the one place a field added to Body,
/// BodySettings or SleepState is added to snapshots (the writer and the reader both call it).
/// The load function is not data: only whether there is one.
template <class IO, class B, class S, class Z>
void body_fields(IO& io, B& b, S& set, Z& sleep, bool& has_load) {
    io.enumeration("type", b.type, BodyType::dynamic);
    io("loaded", b.loaded);
    io("damped", b.damped);
    io.index("first_shape", b.first_shape, 0xFFFFFFFFu, true); // (checked by check_links)
    io("xf", b.xf);
    io("angle", b.angle);
    io("center", b.center);
    io("local_center", b.local_center);
    io("v", b.v);
    io("w", b.w);
    io("inv_mass", b.inv_mass);
    io("inv_inertia", b.inv_inertia);
    io("gravity_scale", b.gravity_scale);
    io("force", b.force);
    io("torque", b.torque);
    io("force_once", b.force_once);
    io("torque_once", b.torque_once);
    io("mass", b.mass);
    io("inertia", b.inertia);
    io("name", set.name);
    io("has_load", has_load);
    io("mass_override", set.mass_override);
    io("inertia_override", set.inertia_override);
    io("fixed_rotation", set.fixed_rotation);
    io("bullet", set.bullet);
    io("linear_damping", set.linear_damping);
    io("angular_damping", set.angular_damping);
    io.user_data("user_data", set.user_data);
    io("lock_linear_x", set.lock_linear_x);
    io("lock_linear_y", set.lock_linear_y);
    io("center_override", set.center_override);
    io("sleep_threshold", set.sleep_threshold);
    io("sleep_time", sleep.sleep_time);
    io("awake", sleep.awake);
    io("sleep_enabled", sleep.enabled);
    io("movable", sleep.movable);
    io("disabled", sleep.disabled);
}

/// Whether a live body's record read from a snapshot is one a world can hold: the field of the
/// first rule it breaks, or nullptr. Every number finite (DCX_finite); those set only from
/// validated inputs (the persistent loads, the scales, the settings) within the supported
/// ranges (validation.hpp, DCX_range); the mass properties as update_mass computes them; the
/// state a simulation grows into (pose, velocities, summed one-step loads) finite only, as a
/// world may hold it beyond those (the step then refuses to start from it). A forged record
/// breaking one would start the steps from numbers they cannot hold and turn into inf or NaN.
/// Each check is false for NaN.
const char* unsupported_field(const Body& b, const BodySettings& set, const SleepState& sleep) {
    namespace s = supported;
    constexpr double inf = std::numeric_limits<double>::infinity();
    constexpr double finite_max = std::numeric_limits<double>::max();
    const auto within = [](double v, double most) { return std::abs(v) <= most; };
    const auto within2 = [&](Vec2d v, double most) {
        return within(v.x, most) && within(v.y, most);
    };
    const auto in_range = [](double v, double least, double most) {
        return v >= least && v <= most;
    };
    // A rotation is (cos, sin) of the angle: unit to far better than this.
    const double unit = b.xf.q.c * b.xf.q.c + b.xf.q.s * b.xf.q.s;
    if (!within2(b.xf.p, finite_max) || !(std::abs(unit - 1.0) <= 1e-6))
        return "xf";
    if (!within(b.angle, finite_max))
        return "angle";
    if (!within2(b.center, finite_max))
        return "center";
    if (!within2(b.v, finite_max))
        return "v";
    if (!within(b.w, finite_max))
        return "w";
    if (!within2(b.force_once, finite_max))
        return "force_once";
    if (!within(b.torque_once, finite_max))
        return "torque_once";
    if (!(sleep.sleep_time >= 0.0 && sleep.sleep_time < inf))
        return "sleep_time";
    if (!within2(b.local_center, s::state_max))
        return "local_center";
    if (!within(b.gravity_scale, s::input_max))
        return "gravity_scale";
    if (!within2(b.force, s::input_max))
        return "force";
    if (!within(b.torque, s::input_max))
        return "torque";
    // The mass properties as update_mass leaves them (a snapshot is written settled): none
    // unless dynamic; then a positive mass, and the inverses its own.
    const bool dynamic = b.type == BodyType::dynamic;
    if (dynamic ? !(b.mass > 0.0 && b.mass <= finite_max) : b.mass != 0.0)
        return "mass";
    if (dynamic ? !(b.inertia >= 0.0 && b.inertia <= finite_max) : b.inertia != 0.0)
        return "inertia";
    if (b.inv_mass != (dynamic ? 1.0 / b.mass : 0.0))
        return "inv_mass";
    if (b.inv_inertia !=
        (dynamic && !set.fixed_rotation && b.inertia > 0.0 ? 1.0 / b.inertia : 0.0))
        return "inv_inertia";
    if (set.mass_override && !in_range(*set.mass_override, 0.0, s::mass_max))
        return "mass_override";
    if (set.inertia_override && !in_range(*set.inertia_override, 0.0, s::inertia_max))
        return "inertia_override";
    if (!in_range(set.linear_damping, 0.0, s::input_max))
        return "linear_damping";
    if (!in_range(set.angular_damping, 0.0, s::input_max))
        return "angular_damping";
    if (set.center_override && !within2(*set.center_override, s::state_max))
        return "center_override";
    if (set.sleep_threshold && !in_range(*set.sleep_threshold, 0.0, s::input_max))
        return "sleep_threshold";
    return nullptr;
}

/// Whether a live body's sleep state read from a snapshot is one the store holds: the field and
/// the rule it breaks, or nulls. A body is movable exactly when it is neither static nor disabled
/// (the step moves only those), only a movable body is awake, and with sleeping off every movable
/// body is (create, set_sleeping). A forged flag would have the step move a static body or
/// hold still one that the world says cannot sleep.
std::pair<const char*, const char*> unheld_sleep_state(const Body& b, const SleepState& sleep,
                                                       bool sleeping) {
    if (sleep.movable != (b.type != BodyType::static_body && !sleep.disabled))
        return {"movable", "must be true exactly for a body neither static nor disabled"};
    if (sleep.awake && !sleep.movable)
        return {"awake", "must be false for a body that is not movable"};
    if (!sleeping && sleep.movable && !sleep.awake)
        return {"awake", "must be true for a movable body in a world with sleeping off"};
    return {nullptr, nullptr};
}

} // namespace

void BodyStore::write(SnapshotWriter& out) const {
    out.section("BODY");
    slots.write(out);
    for (std::uint32_t i = 0; i < size(); ++i) {
        bool has_load = bool(settings[i].load);
        body_fields(out, bodies[i], settings[i], sleep_states[i], has_load);
    }
}

void BodyStore::read(SnapshotReader& in, memory::vector<std::uint32_t>& had_load, bool sleeping) {
    in.section("BODY");
    ++mass_epoch;
    in.in("bodies");
    slots.read(in);
    const std::size_t n = slots.size();
    bodies.resize(n);
    settings.resize(n);
    sleep_states.resize(n);
    for (std::uint32_t i = 0; i < n; ++i) {
        in.in("bodies", i);
        Body& b = bodies[i];
        b = Body{};
        bool has_load = false;
        const std::size_t at = in.offset();
        body_fields(in, b, settings[i], sleep_states[i], has_load);
        in.require(alive(i) || (!has_load && b.first_shape == null_index && !sleep_states[i].awake),
                   "first_shape", "a dead slot has no shapes, load or wake", at);
        in.require(alive(i) || !sleep_states[i].disabled, "disabled", "a dead slot is not disabled",
                   at);
        if (alive(i))
            if (const char* field = unsupported_field(b, settings[i], sleep_states[i]))
                in.fail_at(at, field,
                           "must be finite, and within the supported ranges where only inputs set "
                           "it (DCX_finite, DCX_range)");
        if (alive(i))
            if (const auto [field, rule] = unheld_sleep_state(b, sleep_states[i], sleeping); field)
                in.fail_at(at, field, rule);
        if (has_load)
            had_load.push_back(i);
        disabled_bodies += sleep_states[i].disabled ? 1 : 0;
        locked_bodies += alive(i) && linearly_locked(i) ? 1 : 0;
    }
    in.in(nullptr);
    loaded_bodies = 0;
}

void BodyStore::check_links(SnapshotReader& in, ShapeStore& shapes) const {
    const std::uint32_t ns = std::uint32_t(shapes.shapes.size());
    memory::vector<std::uint8_t> seen(ns, 0);
    shapes.last_of_body.assign(size(), null_index);
    for (std::uint32_t i = 0; i < size(); ++i) {
        in.in("bodies", i);
        const Body& b = bodies[i];
        for (std::uint32_t s = b.first_shape; s != null_index; s = shapes.shapes[s].next) {
            if (s >= ns || seen[s] || !shapes.shapes[s].alive() || shapes.shapes[s].body != i)
                in.fail("first_shape",
                        "the body's shape list must hold live shapes of this body, each once "
                        "(at shape " +
                            decimal(std::uint64_t(s)) + ")");
            seen[s] = 1;
            shapes.last_of_body[i] = s;
        }
    }
    for (std::uint32_t s = 0; s < ns; ++s) {
        in.in("shapes", s);
        const Shape& sh = shapes.shapes[s];
        if (sh.alive() && (sh.body >= size() || !alive(sh.body) || !seen[s]))
            in.fail("body", "a live shape must be on the shape list of a live body");
    }
    in.in(nullptr);
}

// --- run-time control ---

void BodyStore::change_type(std::uint32_t i, BodyType type, ShapeStore& shapes) {
    Body& b = bodies[i];
    b.type = type;
    if (type == BodyType::static_body) { // a static body never moves (R2)
        b.v = {};
        b.w = 0.0;
        b.force_once = {};
        b.torque_once = 0.0;
        b.loaded = !b.unloaded();
    }
    const BodySettings& set = settings[i];
    b.damped =
        type == BodyType::dynamic && (set.linear_damping != 0.0 || set.angular_damping != 0.0);
    update_mass_keeping_motion(i, shapes);
    SleepState& st = sleep_states[i];
    st.movable = type != BodyType::static_body && !st.disabled;
    st.awake = st.movable;
    st.sleep_time = 0.0;
}

void BodyStore::set_disabled(std::uint32_t i, bool disabled) {
    SleepState& st = sleep_states[i];
    if (st.disabled == disabled)
        return;
    st.disabled = disabled;
    disabled_bodies += disabled ? 1 : std::uint32_t(-1);
    st.movable = !disabled && bodies[i].type != BodyType::static_body;
    st.awake = st.movable;
    st.sleep_time = 0.0;
}

/// \srs{DD39} A linear lock set now stops the body along its axis at once.
void BodyStore::set_linear_locks(std::uint32_t i, bool x, bool y) {
    const bool before = linearly_locked(i);
    settings[i].lock_linear_x = x;
    settings[i].lock_linear_y = y;
    locked_bodies += std::uint32_t(linearly_locked(i)) - std::uint32_t(before);
    Body& b = bodies[i];
    if (b.type == BodyType::dynamic)
        b.v = bridge::locked_velocity(b.v, x, y);
}

/// \srs{DD41} The body's new centre keeps the velocity it had as a point of the body; the
/// angular velocity stays (zero under the angular lock, which nothing may turn).
void BodyStore::update_mass_keeping_motion(std::uint32_t i, ShapeStore& shapes) {
    Body& b = bodies[i];
    const Vec2d center_before = b.center;
    update_mass(i, shapes);
    if (b.type == BodyType::static_body)
        return;
    const Vec2d shift = b.center - center_before;
    if (shift.x != 0.0 || shift.y != 0.0) // (else v + 0 could turn a -0 into +0)
        b.v = bridge::shifted_center_velocity(b.v, b.w, shift);
    if (angularly_locked(i))
        b.w = 0.0;
    if (b.type == BodyType::dynamic)
        b.v = bridge::locked_velocity(b.v, settings[i].lock_linear_x, settings[i].lock_linear_y);
}

// --- definitions: the run-time controls a BodyDef sets at creation ---

/// \srs{DD39} A body made with the controls its definition asks for, as World's setters would
/// set them on it: the rotation locked by either fixed_rotation or motion_locks.angular (a
/// dynamic body's angular velocity zero from the start), the linear locks (a locked velocity
/// component zero from the start), its own sleep threshold,
/// and disabled if the definition says so (neither awake nor movable until enabled).
void BodyStore::create_controls(std::uint32_t i, const BodyDef& def) {
    BodySettings& set = settings[i];
    set.fixed_rotation = def.fixed_rotation || def.motion_locks.angular;
    if (set.fixed_rotation && def.type == BodyType::dynamic)
        bodies[i].w = 0.0; // a locked motion is held at zero velocity, as set_motion_locks does
    if (def.motion_locks.linear_x || def.motion_locks.linear_y)
        set_linear_locks(i, def.motion_locks.linear_x, def.motion_locks.linear_y);
    set.sleep_threshold = def.sleep_threshold;
    if (!def.enabled)
        set_disabled(i, true);
}

} // namespace tamias2d
