// The world's shapes (internal): their storage and slots, the definitions they were made from,
// the broad phase over their fat boxes, and the copies of their bodies' poses that the narrow
// phase reads. Box2D keeps the same concerns in shape.c.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "tamias2d/collision/broad_phase.hpp"
#include "tamias2d/dynamics/body.hpp"
#include "tamias2d/dynamics/shape.hpp"
#include "tamias2d/handles.hpp"
#include "tamias2d/memory/allocator.hpp"
#include "tamias2d/memory/large_array.hpp"
#include "tamias2d/memory/slot_map.hpp"
#include "tamias2d/shape_def.hpp"
#include "tamias2d/world.hpp"

namespace tamias2d {

struct BodyStore;
struct StateHasher;
class SnapshotWriter;
class SnapshotReader;

class ShapeStore {
  public:
    /// The shapes of the world tagged `world` (World::tag).
    explicit ShapeStore(std::uint32_t world) : slots(world) {}
    /// Room for n shapes on up to `bodies` bodies without growing (WorldDef::capacity).
    void reserve(std::size_t n, std::size_t bodies) {
        slots.reserve(n);
        shapes.reserve(n);
        defs.reserve(n);
        last_of_body.reserve(bodies);
        broad_phase.reserve(n);
        proxy_moves_.reserve(n);
        undecided_.reserve(n);
    }

    /// Which shapes live, their handles' generations and the free slots.
    SlotMap<ShapeId> slots;
    LargeArray<Shape> shapes;
    memory::vector<ShapeDef> defs; ///< per shape, indexed alike: what it was made from
    /// Per body index: its last shape, valid while the body's first_shape is not null_index.
    memory::vector<std::uint32_t> last_of_body;
    BroadPhase broad_phase;
    /// DD46, DD47: whether a shape has had a rolling resistance or a tangent speed since the
    /// store was made (a snapshot keeps it): until then the steps solve no surface motion (and
    /// pay nothing for it); then every step does, with 0 for the contacts of shapes without.
    bool surface_motion = false;
    /// Sets surface_motion if material m has surface motion.
    void note_surface_motion(const Material& m) {
        if (m.rolling_resistance != 0.0 || m.tangent_speed != 0.0)
            surface_motion = true;
    }

    /// The shape of a handle; throws InvalidHandle for a stale or unknown one, WrongWorld for
    /// one of another world.
    Shape& get(ShapeId id) {
        slots.check(id);
        return shapes[id.index];
    }
    bool is_valid(ShapeId id) const { return slots.is_valid(id); }
    ShapeId id(std::uint32_t i) const { return slots.id(i); }

    /// A new shape on body `body_index` (whose Body is `b`), appended to its list in O(1) (the
    /// list's last shape is kept per body) so that the body's shapes (and the mass summed over
    /// them) keep creation order. Its geometry is stored canonical (only its kind's member
    /// set). The body's mass is not updated here (BodyStore::attach_shape, update_mass).
    std::uint32_t create(std::uint32_t body_index, Body& b, const ShapeDef& def);
    /// Unlinks the shape from its body `b` and frees its proxy and slot (its contacts must be
    /// gone first).
    void destroy(std::uint32_t i, Body& b);
    /// Frees the proxy and slot of a shape whose body is being destroyed whole.
    void release(std::uint32_t i);

    Aabb box(const Shape& s, const Body& b) const { return compute_aabb(s.collider, b.xf); }

    /// Copies the body's pose into its shapes (Shape::body_xf, body_center) after a mass update
    /// moved its centre, so that the narrow phase may read the shapes' copies.
    void sync_poses(const Body& b);
    /// Brings a shape's copies up to its body after the body moved: the pose, and the fat box
    /// if the shape left it (the common case, still inside, reads no tree node).
    void follow_body(Shape& sh, const Body& b) {
        if (!follow_pose(sh, b))
            refit_fat_box(sh);
    }
    /// follow_body's first half: the pose, and whether the shape surely stayed inside its fat
    /// box, decided from the collider's header without the vertex lines (if not, refit_fat_box
    /// must follow).
    bool follow_pose(Shape& sh, const Body& b) {
        sh.body_xf = b.xf;
        sh.body_center = b.center; // \srs{DD8} the centre of mass the contact arms start from
        return surely_inside(sh.collider, b.xf, sh.fat_box);
    }
    /// follow_body's second half: the tight box from the vertex lines, and a new fat box if the
    /// shape left the old one.
    void refit_fat_box(Shape& sh) {
        const Aabb tight = compute_aabb(sh.collider, sh.body_xf);
        if (!contains(sh.fat_box, tight)) {
            sh.fat_box = broad_phase.fattened(tight);
            proxy_moves_.push_back({sh.proxy, sh.fat_box});
        }
    }
    /// Refits the shapes follow_pose could not decide, marked by mark_undecided, then moves
    /// every proxy that left its fat box (apply_moves).
    void mark_undecided(std::uint32_t s) { undecided_.push_back(s); }
    void reserve_undecided() { undecided_.reserve(shapes.size()); }
    void refit_undecided();
    /// Hands the proxies follow_body moved to the broad phase in one call.
    void apply_moves() {
        broad_phase.move_proxies(proxy_moves_);
        proxy_moves_.clear();
    }
    /// Drops shape s's entries from the lists above, which are empty between steps unless a
    /// bad_alloc stopped the last one: its proxy is about to be destroyed, and the next step
    /// must not refit or move it.
    void forget_pending(std::uint32_t s);

    /// The handles of body b's shapes, in its list's order.
    std::vector<ShapeId> ids_of(const Body& b) const;
    /// After body b was placed through the API: its shapes' copies follow it and the broad
    /// phase's proxies that left their fat boxes move.
    void move_with(const Body& b);
    /// The live shapes whose boxes overlap `box` (IM4), in index order.
    std::vector<ShapeId> overlapping(const Aabb& box, const BodyStore& bodies) const;
    /// The live shapes containing point p (T5), in index order.
    std::vector<ShapeId> containing(Vec2d p, const BodyStore& bodies) const;
    /// The first non-sensor shape the segment origin -> origin + translation hits (DD28: a
    /// sensor is not there for rays); at equal fractions the lowest shape index. Found by
    /// walking the broad phase's trees along the ray, clipped at each hit.
    std::optional<RayCastHit> ray_cast(Vec2d origin, Vec2d translation,
                                       const BodyStore& bodies) const;

    /// Feeds the shapes to the state hash (World::state_hash): each slot's generation and
    /// life, a live shape's body, geometry, material and (when not the default) filter.
    void hash(StateHasher& hs) const;

    // --- snapshot (World::snapshot, World::restore; dynamics/snapshot_io.hpp) ---
    /// Writes every slot (its definition, generation, body, links, proxy, fat box and pose
    /// copies), the free slots and the broad phase. The collider is not written: read rebuilds
    /// it from the definition, as create made it (the same bits).
    void write(SnapshotWriter& out) const;
    /// Reads what write wrote into this empty store; throws SnapshotError for a defect (a live
    /// shape's definition that validate() refuses, a proxy that is not the shape's leaf). The
    /// shape lists are checked, and last_of_body rebuilt, by BodyStore::check_links.
    void read(SnapshotReader& in);
    // --- shape_control ---
    /// Gives shape i a new (validated) geometry, stored canonical, and its collider. Its
    /// proxy, contacts and body's mass are the caller's to bring up to date.
    void reshape(std::uint32_t i, const Geometry& geometry);
    /// Shape i's proxy refitted to its geometry now on body `b`: a new fat box around the
    /// tight one (smaller too, where move_proxy keeps one that contains it), marked moved so
    /// that the next step finds its pairs.
    void refit_proxy(std::uint32_t i, const Body& b);
    // --- run-time control (World::set_body_type, set_enabled) ---
    /// Body b's shapes' proxies moved to the tree of its type now (static or not) when they
    /// are in the other, else marked moved: the next step's broad phase reports their pairs.
    void refile_proxies(const Body& b);

  private:
    /// The proxies refit_fat_box moved, for one BroadPhase::move_proxies call.
    memory::vector<BroadPhase::ProxyMove> proxy_moves_;
    /// The shapes follow_pose could not decide, for refit_undecided (step scratch).
    memory::vector<std::uint32_t> undecided_;
};

} // namespace tamias2d
