// The world's bodies (internal): their storage, slots and handles, per-body settings and sleep
// states, indexed alike. Box2D keeps the same concerns in body.c.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "tamias2d/body_def.hpp"
#include "tamias2d/dynamics/body.hpp"
#include "tamias2d/dynamics/sleep.hpp"
#include "tamias2d/handles.hpp"
#include "tamias2d/memory/allocator.hpp"
#include "tamias2d/memory/large_array.hpp"
#include "tamias2d/memory/slot_map.hpp"

namespace tamias2d {

struct StateHasher;
class ShapeStore;
class SnapshotWriter;
class SnapshotReader;

struct BodyStore {
    /// The bodies of the world tagged `world` (World::tag).
    explicit BodyStore(std::uint32_t world) : slots(world) {}
    /// Room for n bodies without growing (WorldDef::capacity).
    void reserve(std::size_t n) {
        slots.reserve(n);
        bodies.reserve(n);
        settings.reserve(n);
        sleep_states.reserve(n);
        mass_pending_.reserve(n);
        mass_pending_flag_.reserve(n);
    }

    /// Which bodies live, their handles' generations and the free slots (only handle checks and
    /// the hash read the generations, so they are kept out of Body, which a step streams three
    /// times).
    SlotMap<BodyId> slots;
    LargeArray<Body> bodies;
    memory::vector<BodySettings> settings; ///< per body, indexed alike
    /// Per body, indexed alike: awake or asleep, and for how long at rest (read by the step only
    /// with sleeping on, WorldDef::enable_sleep).
    memory::vector<SleepState> sleep_states;
    std::uint32_t loaded_bodies = 0; ///< live bodies with a load function
    /// Counts the changes of any body's mass properties (update_mass, read; a change put back
    /// counts too): JointStore::check_levers checks again only after one.
    std::uint64_t mass_epoch = 0;

  private:
    /// The bodies whose mass attach_shape left pending (settle, get), flagged per body; the
    /// shapes they read. Mutable: a const query brings them up to date before it reads them.
    mutable memory::vector<std::uint32_t> mass_pending_;
    mutable memory::vector<bool> mass_pending_flag_;
    mutable ShapeStore* pending_shapes_ = nullptr;
    void settle(std::uint32_t i) const;

  public:
    /// The body of a handle, its mass brought up to date (settle); throws InvalidHandle for a
    /// stale or unknown one, WrongWorld for one of another world.
    Body& get(BodyId id);
    const Body& get(BodyId id) const { return const_cast<BodyStore*>(this)->get(id); }
    /// As get, but a mass left pending by attach_shape stays pending: for adding a shape, so that
    /// N shapes added to one body cost O(N), not N mass updates of O(N) each.
    Body& get_for_attach(BodyId id);
    bool is_valid(BodyId id) const { return slots.is_valid(id); }
    BodyId id(std::uint32_t i) const { return slots.id(i); }
    /// Whether slot i holds a body (a destroyed body's slot does not, until it is reused).
    bool alive(std::uint32_t i) const { return slots.live(i); }
    std::uint32_t size() const { return std::uint32_t(bodies.size()); }
    std::size_t count() const { return slots.live_count(); }
    /// The handles of the live bodies, in index order.
    std::vector<BodyId> live_ids() const;
    /// How messages name body i: "body[3]", or "body[3 'slider']" when it has a name.
    std::string label(std::uint32_t i) const;

    /// A slot for a new body made from a validated definition; its mass is not set yet
    /// (update_mass). With sleeping off every body is awake, whatever `def` asks.
    std::uint32_t create(const BodyDef& def, bool sleeping);
    /// Frees the body's slot and settings (its shapes and contacts must be gone first).
    void destroy(std::uint32_t i);

    /// Mass, centre of mass and inertia from the shapes (DD1, DD14) or the overrides; copies
    /// the body's pose into its shapes.
    void update_mass(std::uint32_t i, ShapeStore& shapes);
    /// After ShapeStore::create put shape `s` on body i: O(1). The shape gets the body's pose; a
    /// static or kinematic body's mass stays zero (update_mass would change nothing else), and
    /// a dynamic body's mass update is left pending until the body is next read: by get, or by
    /// settle, which whatever reads the bodies by index (a step, the state hash, the energies)
    /// calls first. The update then sums the same shapes in the same order: the same bits.
    void attach_shape(std::uint32_t i, ShapeStore& shapes, std::uint32_t s);
    /// Brings every pending mass up to date, in the order the bodies were first left pending.
    void settle() const;

    /// Moves this step: alive, not static, and awake (every such body is, with sleeping off).
    bool active(std::uint32_t i) const { return sleep_states[i].awake; }
    bool any_awake() const;
    /// Wakes the body (and so, at the next step, its island); its time at rest starts again.
    void wake(std::uint32_t i);
    /// Puts body i (movable, with sleeping on) to sleep: its velocities and one-step loads zero.
    void put_to_sleep(std::uint32_t i);

    /// The time-varying loads at time `time` (the step's start) into `loads`, per body: a
    /// user function returning NaN is rejected before anything has changed. Most worlds have
    /// none: then no setting is read and `loads` stays empty.
    void evaluate_loads(double time, memory::vector<Load>& loads) const;
    /// \srs{DCX_range} A step starts only from a state within supported::state_max, the
    /// headroom a simulation of in-range inputs may grow into; from there no product of one
    /// step overflows (docs/design.md, "Supported ranges"). One pass over the bodies, before
    /// anything changes.
    void check_state() const;

    /// DD15's kinetic energy of the dynamic bodies (J).
    double kinetic_energy() const;
    /// DD16's potential energy of the dynamic bodies in gravity g, each scaled by its
    /// gravity scale (J).
    double potential_energy(Vec2d g) const;
    /// GD1's total momentum of the dynamic bodies (kg m s^-1).
    Vec2d linear_momentum() const;

    /// Feeds the bodies' state to the state hash (World::state_hash): each slot's generation,
    /// life and type, a live body's pose, velocities, loads, masses and settings, its sleep
    /// state with sleeping on, its name and its shapes.
    void hash(StateHasher& hs, const ShapeStore& shapes, bool sleeping) const;

    // --- snapshot (World::snapshot, World::restore; dynamics/snapshot_io.hpp) ---
    /// Writes every slot (its generation, its Body, settings and sleep state, whether it had a
    /// load function) and the free slots. Pending masses must be settled first (settle).
    void write(SnapshotWriter& out) const;
    /// Reads what write wrote into this empty store, for a world with sleeping on or off (the
    /// sleep states must be ones such a world holds). A load function cannot be written: the
    /// bodies that had one are listed in `had_load` (World::restore gives them the target's).
    /// Throws SnapshotError for a defect in the bytes (link_shapes checks the shape lists).
    void read(SnapshotReader& in, memory::vector<std::uint32_t>& had_load, bool sleeping);
    /// After both stores are read: each live body's shape list holds live shapes of that body
    /// (each once, ending in null_index), every live shape is on its body's list, and the free
    /// slots are dead and distinct. Rebuilds ShapeStore::last_of_body.
    void check_links(SnapshotReader& in, ShapeStore& shapes) const;
    // --- run-time control (World::set_body_type, set_enabled, set_motion_locks, ...) ---
    std::uint32_t disabled_bodies = 0; ///< live bodies disabled (World::set_enabled)
    std::uint32_t locked_bodies = 0;   ///< live bodies with a linear motion lock (DD39)
    /// Whether body i is disabled: one flag read only while some body is.
    bool disabled(std::uint32_t i) const { return disabled_bodies > 0 && sleep_states[i].disabled; }
    /// Whether body i has a linear lock (DD39).
    bool linearly_locked(std::uint32_t i) const {
        return settings[i].lock_linear_x || settings[i].lock_linear_y;
    }
    /// Whether body i is dynamic under the angular lock (DD39): nothing turns it.
    bool angularly_locked(std::uint32_t i) const {
        return bodies[i].type == BodyType::dynamic && settings[i].fixed_rotation;
    }
    /// Body i's type becomes `type`: velocities and one-step loads zero for a static body, the
    /// mass recomputed (update_mass), the damping flag and the sleep state to match (woken if
    /// movable and enabled; neither awake nor movable if static).
    void change_type(std::uint32_t i, BodyType type, ShapeStore& shapes);
    /// Body i disabled or enabled (the counts, the flags; enabled and movable: woken).
    void set_disabled(std::uint32_t i, bool disabled);
    /// Body i's linear locks (the count kept); the locked velocity components zeroed.
    void set_linear_locks(std::uint32_t i, bool x, bool y);
    /// Body i's mass recomputed with set_mass_data's rule: the origin stays, the centre moves
    /// with the body's rigid motion (DD41: it keeps the velocity it had as a point of the
    /// body), the angular velocity stays (zero if the rotation is now locked).
    void update_mass_keeping_motion(std::uint32_t i, ShapeStore& shapes);
    // --- definitions ---
    /// At creation (create): body i's motion locks, sleep threshold and enabled state as its
    /// definition sets them (World::set_motion_locks, set_sleep_threshold, set_enabled).
    void create_controls(std::uint32_t i, const BodyDef& def);
};

} // namespace tamias2d
